#pragma once
/// \file analysis.hpp
/// \brief The reduction of a parsed scene with its uncertainties and the
/// status of every correction: what `pendulum-g reduce` prints.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/reduction.hpp"
#include "pendulum/scene_json.hpp"

namespace pendulum {

struct AnalysisOptions {
  ReductionOptions reduction;
  /// A correction smaller than this fraction of the period's uncertainty is
  /// flagged negligible (it is still applied).
  double negligible_fraction = 0.1;
  /// With the automatic amplitude method, the chosen method's error bound
  /// stays below this fraction of the period's uncertainty.
  double amplitude_fraction = 0.01;
  /// JSON paths of the inputs whose uncertainties are propagated to g.
  /// Nelson & Olsson's Eq. (91) uses the period and the length only.
  std::vector<std::string> propagated_inputs = {"timing.trials", "length"};
};

enum class Status { applied, negligible, skipped };
const char* status_name(Status s);

struct CorrectionRow {
  CorrectionInfo info;
  Status status = Status::skipped;
  std::string method;
  std::string reason;                 ///< why skipped or negligible
  std::optional<double> ratio;        ///< DeltaT/T0
  std::optional<double> delta_T;      ///< (s)
  std::optional<double> delta_g;      ///< (m/s^2), linearised: 2 g DeltaT/T0
  std::optional<double> error_bound_delta_T;  ///< (s), bound on the formula's error
  int series_terms = 0;               ///< terms of a truncated series, 0 otherwise
};

/// One input's share of the uncertainty of g.
struct BudgetEntry {
  std::string input;   ///< JSON path
  std::string unit;    ///< SI unit of value and uncertainty
  double value;
  double uncertainty;
  double sensitivity;   ///< dg/d(input) (m/s^2 per unit)
  double contribution;  ///< |sensitivity| x uncertainty (m/s^2)
};

struct ValueWithUncertainty {
  double value;
  double uncertainty;
};

struct Analysis {
  std::vector<CorrectionRow> corrections;
  ValueWithUncertainty period_measured;  ///< (s)
  ValueWithUncertainty period_ideal;     ///< (s)
  ValueWithUncertainty g;                ///< (m/s^2)
  ValueWithUncertainty g_uncorrected;    ///< (m/s^2), Eq. (5)
  double total_delta_T;                  ///< (s)
  double total_delta_g;                  ///< (m/s^2)
  double negligible_below;               ///< (s)
  std::vector<BudgetEntry> budget;
};

/// Reduces the scene and propagates the chosen inputs' uncertainties by
/// automatic differentiation through the whole reduction.
Analysis analyse(const ParsedScene& scene, const AnalysisOptions& options = {});

}  // namespace pendulum
