#pragma once
/// \file models/registry.hpp
/// \brief The experiment kinds pendulum-g reduces: one registry of period
/// models, each checked at compile time for every piece of the interface
/// (period_model.hpp), that the reader, the fit and the output consult
/// instead of switching on a kind (docs/core.md).

#include <algorithm>
#include <iosfwd>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "pendulum/models/physical_pendulum.hpp"
#include "pendulum/models/simple_pendulum.hpp"
#include "pendulum/parsed_scene.hpp"

namespace pendulum {

namespace detail {

/// A sink for the rows a model owns (own_corrections), to check it exists.
struct RowSink {
  void set(CorrectionId, const double&, const char*) {}
  void skip(std::initializer_list<CorrectionId>, const char*) {}
};

template <class M, class = void>
struct HasModelPieces : std::false_type {};

// Every piece a period model declares (period_model.hpp); a kind that lacks
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

/// The registered kinds; a kind is its place here (PeriodModelKind), the
/// first the default.
using PeriodModels = std::tuple<SimplePendulum, PhysicalPendulum>;

namespace detail {
template <class... M>
constexpr bool registry_is_complete(std::tuple<M...>*) {
  return (is_period_model<M>() && ...);
}
template <class M, class... Ms>
constexpr std::size_t index_in(std::tuple<Ms...>*) {
  std::size_t i = 0;
  const bool found = ((std::is_same_v<M, Ms> || (++i, false)) || ...);
  return found ? i : sizeof...(Ms);
}
}  // namespace detail
static_assert(detail::registry_is_complete(static_cast<PeriodModels*>(nullptr)),
              "every registered period model has every piece of the interface (period_model.hpp)");

namespace detail {
template <class... M>
std::variant<std::monostate, typename M::Results...> results_variant(std::tuple<M...>*);
}
/// One registered model's own results (its Results, at its kind's index + 1)
/// or none: FitReport::results.
using ModelResults = decltype(detail::results_variant(static_cast<PeriodModels*>(nullptr)));

/// The kind of a registered model M: its place in PeriodModels.
template <class M>
constexpr PeriodModelKind kind_of() {
  constexpr std::size_t index = detail::index_in<M>(static_cast<PeriodModels*>(nullptr));
  static_assert(index < std::tuple_size_v<PeriodModels>, "M is registered in PeriodModels");
  return {index};
}
// A scene's default kind (ParsedScene::model) is the ball's.
static_assert(kind_of<SimplePendulum>() == PeriodModelKind{}, "the ball on a string is the registry's first");

/// Calls f(Model{}) for each registered model.
template <class F>
void for_each_period_model(F&& f) {
  std::apply([&](auto... model) { (f(model), ...); }, PeriodModels{});
}

/// Calls f(Model{}) for the model of `kind` and returns its result.
template <class F>
decltype(auto) visit_period_model(PeriodModelKind kind, F&& f) {
  using R = decltype(f(SimplePendulum{}));
  if constexpr (std::is_void_v<R>) {
    for_each_period_model([&](auto model) {
      if (kind_of<decltype(model)>() == kind) f(model);
    });
  } else {
    R out{};
    for_each_period_model([&](auto model) {
      if (kind_of<decltype(model)>() == kind) out = f(model);
    });
    return out;
  }
}

/// The kind whose observations are set by `setting` (a model's kSettings):
/// the reader infers a scene's kind from its observations' keys this way.
inline PeriodModelKind kind_of_setting(Setting setting) {
  PeriodModelKind kind;
  for_each_period_model([&](auto model) {
    const auto& settings = decltype(model)::kSettings;
    if (std::find(settings.begin(), settings.end(), setting) != settings.end()) kind = kind_of<decltype(model)>();
  });
  return kind;
}

}  // namespace pendulum
