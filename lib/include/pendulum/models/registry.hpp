#pragma once
/// \file models/registry.hpp
/// \brief The experiment kinds pendulum-g reduces: one registry of period
/// models, each checked at compile time for every piece of the interface
/// (is_period_model, period_model.hpp), that the reader, the fit and the
/// output consult instead of switching on a kind (docs/core.md).

#include <algorithm>
#include <iosfwd>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "pendulum/models/physical_pendulum.hpp"
#include "pendulum/models/simple_pendulum.hpp"

namespace pendulum {

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
