#pragma once
/// \file parsed_scene.hpp
/// \brief A scene as read from its file (scene_json.hpp): the apparatus and
/// its observations with their uncertainties, and what the file says besides.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/apparatus.hpp"
#include "pendulum/decay_fit.hpp"
#include "pendulum/monte_carlo_result.hpp"
#include "pendulum/observation.hpp"
#include "pendulum/period_model.hpp"
#include "pendulum/recordings/swing_series.hpp"
#include "pendulum/site.hpp"
#include "pendulum/uncertainty.hpp"

namespace pendulum {

/// What the file says about one observation beyond its values.
struct ObservationSource {
  /// Prefix of its JSON paths: "" for a scene of one observation (its keys at
  /// the top level), "observations[3]." in a series.
  std::string path;
  int trial_count = 0;
  /// The amplitude as written, for the degrees-and-radians check.
  double amplitude_raw = 0.0;
  std::string amplitude_unit;
  /// What the length was measured to: "center" (the default), "top_of_bob"
  /// or "bottom_of_bob"; the reader adds or subtracts the bob's radius.
  std::string measured_to = "center";
  /// +1 where the reader added the bob's knot-to-centre distance (a ball's
  /// radius, a box's half height) to the length, -1 where it subtracted it,
  /// 0 otherwise. The analysis propagates the bob's dimensions through every
  /// such length together: one measurement of the bob, not one per length.
  double knot_to_center_sign = 0.0;
  /// Keys a series gives once at its top level ("length", "amplitude"),
  /// shared by every observation: one measurement, one input of the budget.
  std::vector<std::string> shared{};

  /// Whether `key` ("length", or a path below it: "length.value") is shared.
  bool is_shared(const std::string& key) const;
  /// The JSON path of one of its keys ("amplitude", "length.value"): at the
  /// top level where it is shared.
  std::string path_of(const std::string& key) const;
  /// Index in ParsedScene::recordings when the timing names a recording.
  std::optional<std::size_t> recording = std::nullopt;
  /// The amplitude is the recording's, not the scene's own.
  bool amplitude_from_recording = false;
  /// Two trials or more: their standard deviation and the floor under it
  /// (the resolution/sqrt(12) or a one-trial uncertainty), in seconds of a
  /// trial; a series pools the scatter (pool_trial_scatter).
  struct TrialScatter {
    double spread, floor;
    bool floor_is_resolution;  ///< the floor's distribution: rectangular, else normal
  };
  std::optional<TrialScatter> trial_scatter = std::nullopt;
};

/// How a recording named by a scene's timing was reduced (docs/recordings.md,
/// "A long decay, swing by swing").
struct RecordingReduction {
  std::string requested = "auto";  ///< the timing's "reduce": auto, mean_period or swing_by_swing
  bool swing_by_swing = false;
  /// amplitude_shift_sigmas() of the record, against kSwingBySwingShift; NaN without amplitudes.
  double shift_sigmas = 0.0;
  bool decay_corrected = false;  ///< the shift is of the part Eq. 50 leaves out
  std::vector<SwingGroup> groups;  ///< the series' observations, when swing by swing
};

/// A recording a scene names in place of numbers (`timing` or `decay.data`,
/// docs/recordings.md), as read and analysed.
struct SceneRecording {
  std::string path;  ///< JSON path of the object naming it: "timing", "observations[2].timing", "decay.data"
  std::string name;  ///< as written in the scene; summary.file is the path opened
  RecordingSummary summary;
  /// For a timing (not a decay record): how its periods were reduced.
  std::optional<RecordingReduction> reduction = std::nullopt;
};

/// A sweep's "length" when nobody measured it (docs/series.md, "Amplitude sweeps").
inline constexpr const char* kLengthNotMeasured = "not measured";

struct ParsedScene {
  PeriodModelKind model;  ///< the registry's first, the ball, unless the observations say otherwise
  Apparatus<double> apparatus;              ///< SI values
  Apparatus<double> apparatus_uncertainty;  ///< same shape; 0 where the file states none
  std::vector<Observation<double>> observations;  ///< one, or a series
  std::vector<Observation<double>> observation_uncertainties;
  std::vector<ObservationSource> sources;  ///< one per observation
  /// The file holds "observations" (a series), not one observation's keys at the top.
  bool series = false;
  /// The series is one recording's groups of swings (RecordingReduction):
  /// Eq. (50) is not applied over them (Decay::over_timing).
  bool swing_by_swing = false;
  /// False for an amplitude sweep whose "length" is "not measured": the
  /// observations' lengths are 0, and it gives T0 alone (amplitude_sweep.hpp),
  /// never g (analyse() refuses it).
  bool length_measured = true;
  /// Unknowns besides g ("fit"), by the period model's parameter names.
  std::vector<std::string> fit;
  /// "period_uncertainty": "scatter_about_fit": single timings without an
  /// uncertainty (a table's, docs/series.md "Single timings"); their stated
  /// ones are a floor (the printed digits'), the fit scales them by the
  /// Birge ratio S wherever S > 1, and chi2 gives no verdict.
  bool period_uncertainty_from_scatter = false;
  std::string title;
  std::string source;
  /// A decay record to fit alpha and beta from (decay.data); the fit
  /// replaces any alpha and beta given beside it.
  std::optional<DecayData> decay_data;
  /// The recordings the scene's timing and decay record came from, in the
  /// order read; empty when the scene gives numbers.
  std::vector<SceneRecording> recordings;
  /// Where the experiment was done, to compare g with.
  std::optional<Site> site;
  /// Inputs whose errors are correlated (alpha and beta of a decay fit), by
  /// their JSON paths, with their covariance (SI).
  struct Covariance {
    std::string first, second;
    double covariance;
  };
  std::vector<Covariance> input_covariances;
  /// How inputs' uncertainties were evaluated (Type A or B, distribution,
  /// degrees of freedom), by JSON path; an input not listed is Type B,
  /// normal, with infinite degrees of freedom (a stated uncertainty).
  std::vector<InputEvaluation> evaluations;
  /// "uncertainty": {"method": "monte-carlo", ...}: GUM Supplement 1 beside the budget.
  std::optional<MonteCarloOptions> monte_carlo;
  /// A physical pendulum's body as its parts give it (docs/physical.md),
  /// also where the fit replaces k or the centre: the fit is checked against it.
  std::optional<RigidBody<double>> body_from_parts;
  std::vector<std::string> assumptions;  ///< defaults the reduction used
  std::vector<std::string> warnings;     ///< legal but suspicious input
  /// Findings of the reader that make the result suspect (status.hpp): a
  /// trial far from the others. Each names the input to fix.
  std::vector<std::string> suspicions;
};

/// Whose angle the scene's decay record followed, and so the angle its
/// fitted beta is of: the bob's for a sensor in it, else the pendulum's.
AngleOf decay_angle_of(const ParsedScene& scene);

}  // namespace pendulum
