#pragma once
/// \file scene_report.hpp
/// \brief What a report shows of one reduced scene, as plain data in SI
/// units. `make_scene_report` (src/report/scene_report.cpp) and, for a
/// physical pendulum, `pivot_scan_record` (src/report/pivot_scan_record.cpp)
/// are the only places in the report code that read ParsedScene, Analysis
/// and DecayFit, so that a change to those touches two files.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/amplitude.hpp"
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
  /// GUM's description of the uncertainty (uncertainty.hpp): "A" or "B", the
  /// distribution's name, the degrees of freedom ("9", "∞" for Type B).
  std::string type, distribution, dof;
  double variance_share;  ///< of u(g)^2 from the stated uncertainties
  /// The budget's rows this one stands for: a series' rows of one field are
  /// one ("57 observations' timing.period", their contributions in
  /// quadrature; value and uncertainty then those of its largest row), with
  /// "A/B" and "4 to 9" where they differ.
  int rows = 1;
};

/// A series of observations (lengths or pivot positions) and the fit of
/// the period model to them, with the textbook line T^2 = (4 pi^2/g)(L + L0).
struct SeriesRecord {
  std::vector<double> lengths, length_uncertainties;  ///< (m)
  /// What `lengths` are, for the plot's axis: a series of rods plots each
  /// rod's equivalent length 2L/3, against which T^2 is the textbook line.
  std::string length_words = "length L";
  std::vector<double> periods;              ///< measured (s)
  std::vector<double> period_uncertainties; ///< of the measured periods (s)
  /// The fit's effective uncertainty of each period (s): its own, its
  /// setting's and its amplitude's carried to it, as reduce weighs the
  /// residuals and warns about them.
  std::vector<double> effective_uncertainties;
  std::vector<double> periods_model;        ///< the fitted model's T at each (s)
  std::vector<FitParameterText> parameters;
  double chi2 = 0.0;
  int dof = 0;
  std::optional<double> probability;
  /// (m/s^2); empty when the lengths determine no line (all equal, with
  /// the offset fitted).
  std::optional<double> textbook_g;
  double textbook_length_offset = 0.0;  ///< (m), 0 unless fitted
  /// At one length and three amplitudes or more: the amplitudes (rad) and
  /// the sweep's T0 and law test, plotted as T against the amplitude.
  std::vector<double> amplitudes;
  std::optional<AmplitudeSweep> sweep;
};

/// A physical pendulum's observations as a pivot scan (docs/report.md): the
/// fitted model and the textbook curve sampled on each side of the centre of
/// mass, never across it (the period is infinite at h = 0), up to the top
/// of the plotted period range, and the marks of the analysis's PivotScan.
/// Settings x (m) are the observations' own: pivot positions from the
/// body's mark, or pivot distances from the centre of mass.
struct PivotScanRecord {
  /// A curve on one side of its centre: x (m) uniform in h, from where the
  /// period comes down to period_high near the centre to the plotted range's
  /// end (or where the period rises to period_high again), and the value
  /// there (s).
  struct Branch {
    std::vector<double> x, period;
  };
  Setting setting = Setting::pivot_position;
  double center = 0.0;  ///< x of the model's centre of mass (m); 0 for pivot distances
  double radius_of_gyration = 0.0;  ///< k of the model (m)
  /// One branch per side of the centre that reaches into the plotted range.
  std::vector<Branch> model, textbook;
  /// The textbook curve minus the model on the model's grid, where both are
  /// in the plotted range on the same side of their centres (s).
  std::vector<Branch> textbook_minus_model;
  /// The curve is the model's for an observation at `amplitude` (rad, the
  /// median of the observations'), timed like the first, with the working
  /// period its ideal period at each x, and the amplitude method the
  /// analysis chose for the observation nearest that amplitude.
  double amplitude = 0.0;
  double amplitude_min = 0.0, amplitude_max = 0.0;  ///< of the observations (rad)
  int oscillations_per_trial = 1;
  AmplitudeChoice amplitude_method{AmplitudeMethod::agm, 0, 0.0};
  /// Each observation's error bar: the fit's effective uncertainty, u(T)
  /// with its pivot's and amplitude's uncertainties carried to T (s). Near
  /// the centre, where T is steep, the pivot's dominates.
  std::vector<double> uncertainties;
  double period_low = 0.0, period_high = 0.0;  ///< the plotted period range (s)
  /// The textbook curve T = 2 pi sqrt((k^2 + h^2)/(g h)) without corrections,
  /// from the straight line T^2 h = (4 pi^2/g)(k^2 + h^2) in h^2 fitted to
  /// the measured periods (analysis.hpp, physical_start).
  double textbook_g = 0.0, textbook_k = 0.0, textbook_center = 0.0;  ///< (m/s^2, m, m)
  std::optional<double> textbook_g_uncertainty;  ///< (m/s^2), from the textbook line's fit
  /// The analysis's minimum (ideal period, h = k) and where it lies, with
  /// the model's period there (on the plotted curve).
  Estimate minimum_period{0.0, std::nullopt}, minimum_pivot_distance{0.0, std::nullopt};
  std::vector<Estimate> minimum_x;
  double minimum_model_period = 0.0;  ///< (s)
  /// The first observation's conjugate pivot of equal period, when the
  /// analysis gives it: x' (m) and l = h + h' (m).
  std::optional<Estimate> conjugate_x, equivalent_length;
  double conjugate_period = 0.0;  ///< the model's period at the first observation's x (s)
  std::optional<double> bessel_g;  ///< Kater's reversible pendulum (m/s^2)
};

struct SceneReport {
  std::string input;  ///< the file as the user named it
  std::string title, source;
  /// The verdict (status.hpp): "ok" or "suspect", each reason naming the
  /// likely slip and the input to fix; the page shows it first.
  std::string status = "ok";
  std::vector<std::string> status_reasons;
  /// An uncertainty is empty when unknown (a singular fit): the report draws
  /// no error bar and says "uncertainty unknown".
  Estimate g;                 ///< (m/s^2)
  /// "9.8034 ± 0.0031 m/s² (k = 2.07, 95 %, ν_eff = 31)" (expanded_result);
  /// empty without an uncertainty.
  std::string g_expanded;
  /// g of Eq. 5, or of the textbook line of a series (m/s^2); empty when
  /// the lengths determine no line.
  std::optional<Estimate> g_uncorrected;
  /// Where the fit's chi2 was improbably large: the Birge ratio applied to
  /// g's uncertainty, and g's uncertainty from the stated ones alone.
  std::optional<double> birge_ratio, g_uncertainty_unscaled;
  Measured period_measured;   ///< (s)
  Estimate period_ideal;      ///< (s)
  int trials = 0;
  int oscillations_per_trial = 1;
  /// A series: the corrections above are its first observation's.
  std::optional<SeriesRecord> series;
  /// A physical pendulum's series, plotted as a pivot scan.
  std::optional<PivotScanRecord> pivot_scan;
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

/// The pivot-scan record of an analysed physical pendulum's series; empty
/// for any other scene.
std::optional<PivotScanRecord> pivot_scan_record(const ParsedScene& scene, const Analysis& analysis);

/// The report data of an analysed scene; `input` names its file.
/// `samples[i]`, where given, is the recording scene.recordings[i] names, for
/// its signal plot (the reduction does not keep the samples; the caller
/// reads them again, read_recording).
SceneReport make_scene_report(const std::string& input, const ParsedScene& scene, const Analysis& analysis,
                              const std::vector<Recording>& samples = {});

}  // namespace pendulum::report
