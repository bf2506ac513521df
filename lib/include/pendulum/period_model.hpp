#pragma once
/// \file period_model.hpp
/// \brief What every period model shares: its parameters' names and units,
/// and what it predicts for one observation.
///
/// A period model is a struct with (is_period_model, at the end, checks every
/// piece at compile time; docs/core.md):
///   kName: its name in the output ("fit.model"),
///   kSettings: the observation keys it reads (Setting), by which the reader
///       knows a scene's kind,
///   kCorrectionUse: per row of kCorrections, whether it applies, is
///       replaced by the model's own, or does not apply (a test checks
///       predict() against it),
///   template <class T, class Sink> own_corrections(const Apparatus<T>&,
///       const Swing<T>&, Sink&): the rows it replaces, and why the rows
///       that do not apply are skipped, as visit_corrections hands rows over
///       (visit_model_corrections),
///   kParameters, kParameterInfo, kDefaults (g is parameter 0),
///   canonicalise(double* p): the fitted parameters in their reported form
///       (a sign only the square of which matters),
///   template <class T> PeriodPrediction<T> predict(const T* p,
///       const Observation<T>&, const Apparatus<T>&, const AmplitudeChoice&),
///   template <class T> Swing<T> swing(const Observation<T>&): what of the
///       swing no parameter changes, computed once per observation by a fit,
///   template <class T> Swing<T> swing_at(const T* p, Swing<T> measured,
///       const Apparatus<T>&): the swing the corrections act on, its length
///       the pendulum's (equivalent) length at p; the parameters change
///       nothing else of the swing, and g not even that,
///   template <class T> Composition<T> composition(apparatus, swing_at(...),
///       amplitude): T/T0 - 1 and its parts, predict()'s without the rows,
///   template <class T> T solve_g(const T* p, observation, apparatus, amplitude):
///       the closed form for one observation with g the only unknown,
///   start(scene, fitted) and report(const FitState&, Analysis&): where its
///       fit starts, and its results beside the fit's, of its type Results
///       (FitReport::set_results, results_of),
///   put_fit_results, put_observation_results(const Results*, JsonOut&)
///       and fit_results_lines, observation_results_lines(const Results*,
///       std::ostream&): those results in the JSON and in the table,
///   read_keys(json_reader::Object&, ParsedScene&): the scene's keys it
///       reads beyond the shared ones, and check_scene(const ParsedScene&):
///       its parts against its observations (the scene reader),
///   expectation(scene, observation) -> std::optional<Expectation>,
///       check_rows(scene, observation) and skipped_part_warnings(scene,
///       negligible_fraction): its plausibility checks (plausibility.cpp),
///   kSuspectCauses: the verdict's words for what goes wrong with it;
/// the non-templated functions in lib/src/models/<kind>.cpp, the templates
/// generic in the scalar so that the fit (period_fit.hpp) and the
/// propagation of uncertainties (analysis.hpp) run it on ceres::Jet. Its
/// period is then ideal_period(swing_at(...).length, g) (1 + composition):
/// g^-1/2 times a function of the other parameters, which the fit uses to
/// project g out.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iosfwd>
#include <optional>
#include <type_traits>
#include <utility>

#include "pendulum/corrections.hpp"
#include "pendulum/observation.hpp"

namespace pendulum {

struct ParsedScene;
struct Analysis;
namespace json_reader {
class Object;  // a JSON object as the scene reader reads it (lib/src/json/reader.hpp)
}
/// What a model's own results read of its fit (lib/src/fit_state.hpp).
template <int P>
struct FitState;
/// Where a model writes its results into the JSON (lib/src/json/writer.hpp),
/// so that no public header includes the JSON library.
struct JsonOut;

/// The period model a scene is reduced with: its model's place in the
/// registry (PeriodModels, models/registry.hpp), which kind_of<Model>()
/// gives. The default, 0, is the registry's first: the ball on a string.
struct PeriodModelKind {
  std::size_t index = 0;
  friend constexpr bool operator==(PeriodModelKind a, PeriodModelKind b) { return a.index == b.index; }
  friend constexpr bool operator!=(PeriodModelKind a, PeriodModelKind b) { return !(a == b); }
};

/// How a model treats one row of kCorrections (its kCorrectionUse, one per
/// CorrectionId): the row as visit_corrections computes it, its own formula
/// in its place, or a row that does not describe it (skipped with a reason).
enum class CorrectionUse { applies, replaced, not_applicable };

struct ParameterInfo {
  const char* name;  ///< as in the scene's "fit" and the output
  const char* unit;  ///< SI
  const char* description;
};

/// What a model expects of one observation before any fit, at standard
/// gravity (its expectation(); the plausibility checks, plausibility.cpp).
struct Expectation {
  double period;  ///< (s) with every correction the scene's parts give
  /// (s) the period against which one off by a factor (a unit typed wrong,
  /// a miscount) is refused and its slip named: where such a slip could
  /// drive another row out of its range first, the one with the finite
  /// amplitude alone.
  double slip_check;
};

/// The words the verdict uses for a model's observations (its
/// kSuspectCauses; status.cpp).
struct SuspectCauses {
  const char* settings;             ///< what to check when g is far from the expected
  const char* settings_from_parts;  ///< the same for a body given by its parts
  const char* scatter;              ///< what scatters the observations about a fit
  const char* reference;            ///< the point the lengths are measured from, to check when g is off
  const char* systematic;           ///< the systematic errors that move g, where no slip explains it
  /// Lengths measured to a point of the bob: its top misread as its centre,
  /// and the length_offset that a series fits for it, are named.
  bool lengths_to_bob;
};

/// Every row of kCorrections as `Model` declares it (kCorrectionUse), handed
/// to `sink` as visit_corrections hands them: a row that applies as
/// visit_corrections computes it; a row replaced or not applicable as
/// Model::own_corrections gives it, after the rows that apply (the sums'
/// order), or, where it gives none, skipped with visit_corrections's reason
/// (a part the scene lacks). Each row is handed over once; a replaced row's
/// shared formula never.
template <class Model, class T, class Sink>
void visit_owned_corrections(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude,
                             Sink& sink) {
  // Bit i of a mask is row i. Only the bits are cleared per call: the rows'
  // values are read where a bit says they were given.
  static_assert(kCorrectionCount <= 32, "one bit per row");
  constexpr std::uint32_t owned = [] {
    std::uint32_t mask = 0;
    for (int i = 0; i < kCorrectionCount; ++i) {
      if (Model::kCorrectionUse[i] != CorrectionUse::applies) mask |= 1u << i;
    }
    return mask;
  }();
  struct Own {
    std::uint32_t given = 0, valued = 0;  // rows own_corrections gave; those with a ratio
    std::array<T, kCorrectionCount> ratio;
    std::array<const char*, kCorrectionCount> text;  // the method, or the reason it is skipped
    void set(CorrectionId id, const T& r, const char* method) {
      const int i = static_cast<int>(id);
      given |= 1u << i;
      valued |= 1u << i;
      ratio[i] = r;
      text[i] = method;
    }
    void skip(std::initializer_list<CorrectionId> ids, const char* reason) {
      for (CorrectionId id : ids) {
        const int i = static_cast<int>(id);
        given |= 1u << i;
        valued &= ~(1u << i);
        text[i] = reason;
      }
    }
  } own;
  Model::own_corrections(app, s, own);
  struct Shared {
    const Own& own;
    Sink& sink;
    void set(CorrectionId id, const T& ratio, const char* method) {
      if (!(owned >> static_cast<int>(id) & 1u)) sink.set(id, ratio, method);
    }
    void skip(std::initializer_list<CorrectionId> ids, const char* reason) {
      for (CorrectionId id : ids) {
        if (!((owned & own.given) >> static_cast<int>(id) & 1u)) sink.skip({id}, reason);
      }
    }
  } shared{own, sink};
  visit_corrections(app, s, amplitude, shared);
  for (int i = 0; i < kCorrectionCount; ++i) {
    if (!((owned & own.given) >> i & 1u)) continue;
    const auto id = static_cast<CorrectionId>(i);
    if (own.valued >> i & 1u) {
      sink.set(id, own.ratio[i], own.text[i]);
    } else {
      sink.skip({id}, own.text[i]);
    }
  }
}

/// visit_owned_corrections, or for a model that owns no row (every
/// kCorrectionUse `applies`) visit_corrections itself: a fit composes every
/// observation's rows, and the bookkeeping of owned rows would double that cost.
template <class Model, class T, class Sink>
void visit_model_corrections(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude,
                             Sink& sink) {
  constexpr bool owns_none = [] {
    for (CorrectionUse use : Model::kCorrectionUse) {
      if (use != CorrectionUse::applies) return false;
    }
    return true;
  }();
  if constexpr (owns_none) {
    visit_corrections(app, s, amplitude, sink);
  } else {
    visit_owned_corrections<Model>(app, s, amplitude, sink);
  }
}

/// `Model`'s rows (visit_model_corrections): what its predict() reports.
template <class Model, class T>
Terms<T> model_terms(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude) {
  return rows_of<T>([&](auto& sink) { visit_model_corrections<Model>(app, s, amplitude, sink); }, amplitude);
}

/// `Model`'s composition without the rows: what its composition() returns.
template <class Model, class T>
Composition<T> model_composition(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude) {
  return composition_of<T>([&](auto& sink) { visit_model_corrections<Model>(app, s, amplitude, sink); });
}

/// The period (s) `Model` predicts at parameters p (SI, g first) from a
/// measured swing (Model::swing): predict()'s period without the rows.
template <class Model, class T>
T predicted_period(const T* p, const Swing<T>& measured, const Apparatus<T>& app, const AmplitudeChoice& amplitude) {
  const Swing<T> s = Model::swing_at(p, measured, app);
  return ideal_period(s.length, p[0]) * (1.0 + Model::composition(app, s, amplitude).total);
}

/// A model's period for one observation, with the corrections behind it.
template <class T>
struct PeriodPrediction {
  T period;  ///< T (s)
  T ideal;   ///< T0 (s), the small-amplitude period of the ideal pendulum
  Terms<T> terms;
  Composition<T> composition;
};

/// predict() as a model computes it from its swing_at and its rows: T0 =
/// 2 pi sqrt(l/g) at swing_at's length l, times T/T0 of model_terms.
template <class Model, class T>
PeriodPrediction<T> prediction_of(const T* p, const Observation<T>& o, const Apparatus<T>& app,
                                  const AmplitudeChoice& amplitude) {
  const Swing<T> s = Model::swing_at(p, Model::swing(o), app);
  PeriodPrediction<T> out;
  out.terms = model_terms<Model>(app, s, amplitude);
  out.composition = compose(out.terms);
  out.ideal = ideal_period(s.length, p[0]);
  out.period = out.ideal * (1.0 + out.composition.total);
  return out;
}

/// prediction_of()'s period bit for bit, without its rows: a Monte Carlo
/// draw's refit evaluates it at every step.
template <class Model, class T>
T prediction_period(const T* p, const Observation<T>& o, const Apparatus<T>& app, const AmplitudeChoice& amplitude) {
  const Swing<T> s = Model::swing_at(p, Model::swing(o), app);
  const Composition<T> composition =
      composition_in_table_order_of<T>([&](auto& sink) { visit_model_corrections<Model>(app, s, amplitude, sink); });
  return ideal_period(s.length, p[0]) * (1.0 + composition.total);
}

namespace detail {

/// A sink for the rows a model owns (own_corrections), to check it exists.
struct RowSink {
  void set(CorrectionId, const double&, const char*) {}
  void skip(std::initializer_list<CorrectionId>, const char*) {}
};

template <class M, class = void>
struct HasModelPieces : std::false_type {};

// Every piece a period model declares (the list above); a kind that lacks
// one does not compile as a registered model.
template <class M>
struct HasModelPieces<
    M, std::void_t<decltype(M::kName), decltype(M::kSettings), decltype(M::kParameters),
                   decltype(M::kParameterInfo), decltype(M::kDefaults), decltype(M::kCorrectionUse),
                   decltype(M::canonicalise(std::declval<double*>())),
                   decltype(M::start(std::declval<const ParsedScene&>(),
                                     std::declval<const std::array<bool, M::kParameters>&>())),
                   decltype(M::report(std::declval<const FitState<M::kParameters>&>(), std::declval<Analysis&>())),
                   typename M::Results,
                   decltype(M::put_fit_results(std::declval<const typename M::Results*>(), std::declval<JsonOut&>())),
                   decltype(M::put_observation_results(std::declval<const typename M::Results*>(),
                                                       std::declval<JsonOut&>())),
                   decltype(M::fit_results_lines(std::declval<const typename M::Results*>(),
                                                 std::declval<std::ostream&>())),
                   decltype(M::observation_results_lines(std::declval<const typename M::Results*>(),
                                                         std::declval<std::ostream&>())),
                   decltype(M::predict(std::declval<const double*>(), std::declval<const Observation<double>&>(),
                                       std::declval<const Apparatus<double>&>(),
                                       std::declval<const AmplitudeChoice&>())),
                   decltype(M::own_corrections(std::declval<const Apparatus<double>&>(),
                                               std::declval<const Swing<double>&>(), std::declval<RowSink&>())),
                   decltype(M::swing(std::declval<const Observation<double>&>())),
                   decltype(M::swing_at(std::declval<const double*>(), std::declval<Swing<double>>(),
                                        std::declval<const Apparatus<double>&>())),
                   decltype(M::composition(std::declval<const Apparatus<double>&>(),
                                           std::declval<const Swing<double>&>(),
                                           std::declval<const AmplitudeChoice&>())),
                   decltype(M::solve_g(std::declval<const double*>(), std::declval<const Observation<double>&>(),
                                       std::declval<const Apparatus<double>&>(),
                                       std::declval<const AmplitudeChoice&>())),
                   decltype(M::read_keys(std::declval<json_reader::Object&>(), std::declval<ParsedScene&>())),
                   decltype(M::unknowns_of_observations_alone(Setting::length)),
                   decltype(M::check_scene(std::declval<const ParsedScene&>())),
                   decltype(M::expectation(std::declval<const ParsedScene&>(),
                                           std::declval<const Observation<double>&>())),
                   decltype(M::check_rows(std::declval<const ParsedScene&>(),
                                          std::declval<const Observation<double>&>())),
                   decltype(M::skipped_part_warnings(std::declval<const ParsedScene&>(), 0.0)),
                   decltype(M::kSuspectCauses)>> : std::true_type {};

}  // namespace detail

/// Whether M is a period model: every piece of the interface, with g its
/// first parameter and one table row per correction.
template <class M>
constexpr bool is_period_model() {
  if constexpr (!detail::HasModelPieces<M>::value) {
    return false;
  } else {
    return std::is_same_v<decltype(M::expectation(std::declval<const ParsedScene&>(),
                                                  std::declval<const Observation<double>&>())),
                          std::optional<Expectation>> &&
           std::is_same_v<std::remove_cv_t<decltype(M::kSuspectCauses)>, SuspectCauses> &&
           std::is_same_v<decltype(M::unknowns_of_observations_alone(Setting::length)),
                          std::array<bool, M::kParameters>> &&
           M::kParameters >= 1 && M::kParameterInfo.size() == std::size_t(M::kParameters) &&
           M::kDefaults.size() == std::size_t(M::kParameters) && M::kCorrectionUse.size() == kCorrectionCount &&
           !M::kSettings.empty();
  }
}

}  // namespace pendulum
