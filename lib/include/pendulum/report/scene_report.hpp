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

namespace pendulum::report {

struct Measured {
  double value;
  double uncertainty;
};

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

struct FitParameterText {
  std::string name, unit;
  double value;
  std::optional<double> uncertainty;  ///< empty when held fixed
};

/// A decay record and its fit of Nelson & Olsson (1986) Eq. (25).
struct DecayRecord {
  std::vector<double> times;       ///< (s)
  std::vector<double> amplitudes;  ///< (rad)
  std::vector<double> sigmas;      ///< (rad); empty when the record states none
  /// theta0(t) of the fit at the record's times and on a fine grid, with its
  /// standard uncertainty from the fit's covariance (rad).
  std::vector<double> fitted;
  std::vector<double> grid, grid_fit, grid_uncertainty;
  std::vector<FitParameterText> parameters;
  std::string model;  ///< which terms were fitted, and why
  double chi2 = 0.0;
  int dof = 0;
  std::string uncertainty_scaling;
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
  double textbook_g = 0.0;            ///< (m/s^2)
  double textbook_length_offset = 0.0;  ///< (m), 0 unless fitted
};

struct SceneReport {
  std::string input;  ///< the file as the user named it
  std::string title, source;
  Measured g, g_uncorrected;     ///< (m/s^2)
  Measured period_measured, period_ideal;  ///< (s)
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
  std::vector<std::string> warnings;  ///< the scene's and the analysis's
};

/// The report data of an analysed scene; `input` names its file.
SceneReport make_scene_report(const std::string& input, const ParsedScene& scene, const Analysis& analysis);

}  // namespace pendulum::report
