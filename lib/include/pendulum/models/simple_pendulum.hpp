#pragma once
/// \file models/simple_pendulum.hpp
/// \brief The period model of a ball on a wire (Nelson & Olsson 1986): the
/// ideal pendulum's 2 pi sqrt(l/g) times every correction the apparatus
/// needs, with g and a common length offset as its parameters.

#include <array>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "pendulum/corrections.hpp"
#include "pendulum/estimate.hpp"
#include "pendulum/period_model.hpp"
#include "pendulum/reduction.hpp"

namespace pendulum {

/// The textbook answer beside the fit: T^2 against L as a straight line,
/// with no corrections (through the origin unless the length offset is fitted).
struct TextbookFit {
  Estimate g;                            ///< 4 pi^2 / slope (m/s^2)
  std::optional<Estimate> length_offset; ///< intercept / slope (m)
};

struct SimplePendulum {
  static constexpr const char* kName = "simple_pendulum";
  /// A bob of any shape on a string (docs/phone.md) is set by its length.
  static constexpr std::array<Setting, 1> kSettings{{Setting::length}};
  /// Every row as visit_corrections computes it.
  static constexpr std::array<CorrectionUse, kCorrectionCount> kCorrectionUse = [] {
    std::array<CorrectionUse, kCorrectionCount> use{};
    for (auto& u : use) u = CorrectionUse::applies;
    return use;
  }();
  static constexpr int kParameters = 2;
  enum Parameter { g, length_offset };
  static constexpr std::array<ParameterInfo, kParameters> kParameterInfo{{
      {"g", "m/s^2", "local acceleration of gravity"},
      {"length_offset", "m",
       "length to add to every measured length: from the mark measured to, to the bob's centre"},
  }};
  /// Starting values where the data give none (SI).
  static constexpr std::array<double, kParameters> kDefaults{{kStandardGravity, 0.0}};

  /// The fitted parameters in their reported form (already unique here).
  static void canonicalise(double*) {}

  /// Where the fit of several observations starts: g from the textbook line
  /// T^2 = (4 pi^2/g) L through the origin, the offset at 0 (models/simple_pendulum.cpp).
  static std::array<double, kParameters> start(const ParsedScene& scene, const std::array<bool, kParameters>& fitted);
  /// Its results beside the fit's: the textbook line, none where the
  /// lengths determine none (all equal, with the offset fitted).
  using Results = TextbookFit;
  /// Sets them (FitReport::set_results) and warns of lengths too close to
  /// separate the offset, a chi2 too small.
  static void report(const FitState<kParameters>& fit, Analysis& out);
  /// Its results in the output (models/simple_pendulum.cpp): "fit.textbook"
  /// (null without a line), an observation's "g_uncorrected" (Eq. 5), and
  /// the table's lines of both. `textbook` is null where report() gave none.
  static void put_fit_results(const Results* textbook, JsonOut& fit);
  static void put_observation_results(const Results* textbook, JsonOut& observation);
  static void fit_results_lines(const Results* textbook, std::ostream& os);
  static void observation_results_lines(const Results* textbook, std::ostream& os);

  /// Its keys are the shared ones (length, bob, ring, cap, wire, air, ...).
  static void read_keys(json_reader::Object&, ParsedScene&) {}
  /// The unknowns besides g a scene of observations alone (a table's) fits:
  /// none, the lengths being to the bob's centre.
  static constexpr std::array<bool, kParameters> unknowns_of_observations_alone(Setting) { return {}; }
  /// The bob, ring and cap fit above every observation's length
  /// (json/scene_json.cpp).
  static void check_scene(const ParsedScene& scene);
  /// At standard gravity: 2 pi sqrt(l/g) (Eq. 3) times every row's T/T0;
  /// a slip is judged with the finite amplitude alone, before it drives
  /// another row out of its range (models/simple_pendulum.cpp).
  static std::optional<Expectation> expectation(const ParsedScene& scene, const Observation<double>& o);
  /// Each first-order row within its range (plausibility.hpp, check_first_order).
  static void check_rows(const ParsedScene& scene, const Observation<double>& o);
  /// The air's and a bob mass's share where the scene lacks them
  /// (plausibility.hpp, warn_about_skipped_ball_parts).
  static std::vector<std::string> skipped_part_warnings(const ParsedScene& scene, double negligible_fraction);
  static constexpr SuspectCauses kSuspectCauses{
      "the length (pivot to the bob's centre)", "the length (pivot to the bob's centre)",
      "a miscounted oscillation, a length misread or taken to another point",
      "the length's reference point (pivot to the bob's centre)",
      "the length's reference point, pivot to the bob's centre; the amplitude; a miscounted oscillation", true};

  /// The period of one observation at parameters p = (g (m/s^2), length
  /// offset (m)): T0 = 2 pi sqrt(l/g) (Eq. 3) with l = length + offset, times
  /// T/T0 of the corrections (corrections.hpp, compose).
  template <class T>
  static PeriodPrediction<T> predict(const T* p, const Observation<T>& o, const Apparatus<T>& app,
                                     const AmplitudeChoice& amplitude) {
    return prediction_of<SimplePendulum>(p, o, app, amplitude);  // T0: Eq. (3)
  }

  /// It owns no row: every one applies (kCorrectionUse).
  template <class T, class Sink>
  static void own_corrections(const Apparatus<T>&, const Swing<T>&, Sink&) {}

  /// The part of an observation's swing that no parameter changes (the
  /// length as measured): a fit computes it once per observation.
  template <class T>
  static Swing<T> swing(const Observation<T>& o) {
    return Swing<T>::of(o, T(0.0));
  }

  /// The swing the corrections act on at p: the measured one with the
  /// offset added to its length.
  template <class T>
  static Swing<T> swing_at(const T* p, Swing<T> measured, const Apparatus<T>&) {
    measured.length += p[length_offset];
    return measured;
  }

  /// predict()'s composition without the rows (corrections.hpp, compose).
  template <class T>
  static Composition<T> composition(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude) {
    return model_composition<SimplePendulum>(app, s, amplitude);
  }

  /// The closed form for one observation with g the only unknown (the
  /// other parameters held at p): the g at which predict() returns the
  /// measured period (reduction.hpp).
  template <class T>
  static T solve_g(const T* p, const Observation<T>& o, const Apparatus<T>& app,
                   const AmplitudeChoice& amplitude) {
    return reduce_g(app, o, amplitude, p[length_offset]);
  }
};

}  // namespace pendulum
