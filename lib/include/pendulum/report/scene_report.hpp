#pragma once
/// \file scene_report.hpp
/// \brief What a report shows of one reduced scene, as plain data in SI
/// units. `make_scene_report` (src/report/scene_report.cpp) is the only
/// place in the report code that reads ParsedScene, Analysis and DecayFit,
/// so that a change to those touches one file.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/analysis.hpp"
#include "pendulum/parsed_scene.hpp"
#include "pendulum/report/decay_record.hpp"
#include "pendulum/report/recording_report.hpp"

namespace pendulum::report {


struct CorrectionEntry {
  std::string id, title, status, method, reason, equation;
  std::optional<double> delta_T;              ///< (s)
  std::optional<double> delta_T_uncertainty;  ///< (s)
  std::optional<double> delta_g;              ///< (m/s^2)
};

struct BudgetShare {
  std::string input;  ///< JSON path
  std::string unit;   ///< SI unit of value and uncertainty
  double value, uncertainty;
  double contribution;  ///< to u(g) (m/s^2)
};

/// A series of observations (lengths or pivot positions) and the fit of
/// the period model to them, with the textbook line T^2 = (4 pi^2/g)(L + L0).
struct SeriesRecord {
  std::vector<double> lengths, length_uncertainties;  ///< (m)
  std::vector<double> periods;              ///< measured (s)
  std::vector<double> period_uncertainties; ///< of the measured periods (s)
  std::vector<double> periods_model;        ///< the fitted model's T at each (s)
  std::vector<FitParameterText> parameters;
  double chi2 = 0.0;
  int dof = 0;
  std::optional<double> probability;
  /// (m/s^2); empty when the lengths determine no line (all equal, with
  /// the offset fitted).
  std::optional<double> textbook_g;
  double textbook_length_offset = 0.0;  ///< (m), 0 unless fitted
};

struct SceneReport {
  std::string input;  ///< the file as the user named it
  std::string title, source;
  /// An uncertainty is empty when unknown (a singular fit): the report draws
  /// no error bar and says "uncertainty unknown".
  Estimate g;                 ///< (m/s^2)
  /// g of Eq. 5, or of the textbook line of a series (m/s^2); empty when
  /// the lengths determine no line.
  std::optional<Estimate> g_uncorrected;
  Measured period_measured;   ///< (s)
  Estimate period_ideal;      ///< (s)
  int trials = 0;
  int oscillations_per_trial = 1;
  /// A series: the corrections above are its first observation's.
  std::optional<SeriesRecord> series;
  std::optional<Measured> expected_g;  ///< (m/s^2)
  std::string expected_source, expected_note;
  std::optional<double> z;
  double negligible_below = 0.0;  ///< (s)
  std::vector<CorrectionEntry> corrections;  ///< Table II order
  std::vector<BudgetShare> budget;           ///< largest first
  /// The alpha-beta cross term's share of u(g)^2 (m^2/s^4), may be negative.
  std::optional<double> budget_correlation_variance;
  std::vector<std::string> inputs_without_uncertainty;
  std::optional<DecayRecord> decay;
  /// The recordings behind the scene's timing or decay record, each drawn
  /// in the scene's section (make_recording_record).
  std::vector<RecordingRecord> recordings;
  std::vector<std::string> warnings;  ///< the scene's and the analysis's
};

/// The report data of an analysed scene; `input` names its file.
SceneReport make_scene_report(const std::string& input, const ParsedScene& scene, const Analysis& analysis);

}  // namespace pendulum::report
