#pragma once
/// \file fields.hpp
/// \brief Visiting the scalar fields of the experiment's data in one place:
/// each field comes with its JSON path and SI unit, so that conversions
/// (double -> Jet, values -> uncertainties) and the uncertainty budget list
/// no field twice.

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace pendulum {

/// What a field is to the fit: the observation's period and length are the
/// inputs of Nelson & Olsson's Eq. (91), whose share of g's uncertainty the
/// output also gives alone.
enum class FieldRole { other, period, length };

/// A scalar field's name in the scene file and its SI unit.
struct Field {
  const char* path;  ///< JSON path below the part's owner ("bob.mass", "length"; "body.parts[].mass" in a list)
  const char* unit;  ///< SI unit of the value ("kg", "1/(s rad)")
  FieldRole role = FieldRole::other;
  int index = -1;  ///< a field of a list's element: its place, written into the path's "[]"
};

/// The field's JSON path with its list index: "body.parts[1].mass".
inline std::string field_path(const Field& f) {
  std::string path = f.path;
  const std::size_t at = path.find("[]");
  if (f.index >= 0 && at != std::string::npos) path.insert(at + 1, std::to_string(f.index));
  return path;
}

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
/// where `a` has it, and is created in `b` first. Inside a list (zip_list)
/// each field carries its element's index.
template <class F>
struct FieldZipper {
  F& f;
  int index = -1;
  template <class X, class Y>
  void operator()(const Field& field, X& x, Y& y) {
    visit(field, x, y);
  }
  template <class X, class Y>
  void operator()(const Field& field, std::optional<X>& x, std::optional<Y>& y) {
    if (x) visit(field, *x, ensure(y));
  }
  template <class X, class Y>
  void operator()(const Field& field, const std::optional<X>& x, std::optional<Y>& y) {
    if (x) visit(field, *x, ensure(y));
  }
  template <class X, class Y>
  void operator()(const Field& field, std::optional<X>& x, const std::optional<Y>& y) {
    if (x) visit(field, *x, *y);
  }
  template <class X, class Y>
  void operator()(const Field& field, const std::optional<X>& x, const std::optional<Y>& y) {
    if (x) visit(field, *x, *y);
  }

 private:
  template <class X, class Y>
  void visit(const Field& field, X& x, Y& y) {
    if (index < 0) return f(field, x, y);
    Field indexed = field;
    indexed.index = index;
    f(indexed, x, y);
  }
};

/// Zips each element of a list (a struct with a static zip) with the same
/// element of `b`, which a writable `b` is resized to hold.
template <class A, class B, class Z>
void zip_list(A& a, B& b, Z& z) {
  if constexpr (!std::is_const_v<B>) b.resize(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    z.index = static_cast<int>(i);
    std::decay_t<decltype(a[i])>::zip(a[i], b[i], z);
  }
  z.index = -1;
}

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
