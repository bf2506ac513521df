#pragma once
/// \file fields.hpp
/// \brief Visiting the scalar fields of the experiment's data in one place:
/// each field comes with its JSON path and SI unit, so that conversions
/// (double -> Jet, values -> uncertainties) and the uncertainty budget list
/// no field twice.

#include <optional>
#include <type_traits>

namespace pendulum {

/// What a field is to the fit: the observation's period and length are the
/// inputs of Nelson & Olsson's Eq. (91), whose share of g's uncertainty the
/// output also gives alone.
enum class FieldRole { other, period, length };

/// A scalar field's name in the scene file and its SI unit.
struct Field {
  const char* path;  ///< JSON path below the part's owner ("bob.mass", "length")
  const char* unit;  ///< SI unit of the value ("kg", "1/(s rad)")
  FieldRole role = FieldRole::other;
};

namespace detail {

template <class P>
P& ensure(std::optional<P>& o) {
  if (!o) o.emplace();
  return *o;
}
template <class P>
const P& ensure(const std::optional<P>& o) {
  return *o;
}

/// Calls f(field, x, y) on a field pair; an optional field is visited only
/// where `a` has it, and is created in `b` first.
template <class F>
struct FieldZipper {
  F& f;
  template <class X, class Y>
  void operator()(const Field& field, X& x, Y& y) {
    f(field, x, y);
  }
  template <class X, class Y>
  void operator()(const Field& field, std::optional<X>& x, std::optional<Y>& y) {
    if (x) f(field, *x, ensure(y));
  }
  template <class X, class Y>
  void operator()(const Field& field, const std::optional<X>& x, std::optional<Y>& y) {
    if (x) f(field, *x, ensure(y));
  }
  template <class X, class Y>
  void operator()(const Field& field, std::optional<X>& x, const std::optional<Y>& y) {
    if (x) f(field, *x, *y);
  }
  template <class X, class Y>
  void operator()(const Field& field, const std::optional<X>& x, const std::optional<Y>& y) {
    if (x) f(field, *x, *y);
  }
};

/// Zips a part (an optional struct with a static zip) when `a` has it.
template <class P, class Q, class Z>
void zip_part(P& a, Q& b, Z& z) {
  if (a) {
    auto& pb = ensure(b);
    std::decay_t<decltype(*a)>::zip(*a, pb, z);
  }
}

}  // namespace detail

}  // namespace pendulum
