#pragma once
/// \file scene.hpp
/// \brief The experiment ("scene") as plain data in SI units, generic in its
/// scalar type so that the same reduction runs on `double` and on dual numbers.
///
/// A part that the experiment lacks is an empty std::optional, and the
/// corrections for it are skipped. Every scalar field has the name of its
/// JSON path (docs/scene.md); `zip_fields` visits them in one place so that
/// conversions (double -> Jet, values -> uncertainties) list no field twice.

#include <optional>

namespace pendulum {

/// Sphere of uniform density hanging at the end of the suspension.
template <class T>
struct Bob {
  T diameter;  ///< (m)
  T mass;      ///< (kg)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f("bob.diameter", a.diameter, b.diameter);
    f("bob.mass", a.mass, b.mass);
  }
};

/// Suspension ring (annulus) with the pivot inside it, above the wire.
template <class T>
struct Ring {
  T mass;            ///< (kg)
  T inner_radius;    ///< (m)
  T outer_radius;    ///< (m)
  T pivot_distance;  ///< pivot to ring centre (m)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f("ring.mass", a.mass, b.mass);
    f("ring.inner_radius", a.inner_radius, b.inner_radius);
    f("ring.outer_radius", a.outer_radius, b.outer_radius);
    f("ring.pivot_distance", a.pivot_distance, b.pivot_distance);
  }
};

/// Cap joining the wire to the bob.
template <class T>
struct Cap {
  T mass;             ///< without its screw (kg)
  T center_distance;  ///< cap centre of mass above the bob centre (m)
  std::optional<T> volume;  ///< (m^3), displaces air with the bob
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f("cap.mass", a.mass, b.mass);
    f("cap.center_distance", a.center_distance, b.center_distance);
    f("cap.volume", a.volume, b.volume);
  }
};

/// Screw of the cap, lighter than the bob material it replaces.
template <class T>
struct CapScrew {
  T mass_deficit;     ///< mass missing from the bob (kg); negative for a heavier screw
  T center_distance;  ///< deficit's centre above the bob centre (m)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f("cap_screw.mass_deficit", a.mass_deficit, b.mass_deficit);
    f("cap_screw.center_distance", a.center_distance, b.center_distance);
  }
};

/// Suspension wire from the ring (or pivot) to the cap (or bob).
template <class T>
struct Wire {
  T mass;                           ///< (kg)
  std::optional<T> diameter;        ///< (m)
  std::optional<T> youngs_modulus;  ///< (Pa)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f("wire.mass", a.mass, b.mass);
    f("wire.diameter", a.diameter, b.diameter);
    f("wire.youngs_modulus", a.youngs_modulus, b.youngs_modulus);
  }
};

/// Still air around the pendulum (absent for a vacuum).
template <class T>
struct Air {
  T pressure;     ///< (Pa)
  T temperature;  ///< (K)
  T molar_mass;   ///< (kg/mol)
  T viscosity;    ///< (Pa s)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f("air.pressure", a.pressure, b.pressure);
    f("air.temperature", a.temperature, b.temperature);
    f("air.molar_mass", a.molar_mass, b.molar_mass);
    f("air.viscosity", a.viscosity, b.viscosity);
  }
};

/// The support, as a mass on a spring (Nelson & Olsson Fig. 3); at least one
/// of the two is given.
template <class T>
struct Support {
  std::optional<T> stiffness;  ///< (N/m)
  std::optional<T> mass;       ///< (kg)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f("support.stiffness", a.stiffness, b.stiffness);
    f("support.mass", a.mass, b.mass);
  }
};

/// Amplitude decay d theta0/dt = -alpha theta0 - beta theta0^2 (Eq. 24).
template <class T>
struct Decay {
  T alpha;  ///< (1/s)
  T beta;   ///< (1/(s rad))
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f("decay.alpha", a.alpha, b.alpha);
    f("decay.beta", a.beta, b.beta);
  }
};

/// One pendulum experiment: the measured period and length, the amplitude,
/// and the parts it has.
template <class T>
struct Scene {
  T period;     ///< mean measured period (s)
  T length;     ///< pivot to bob centre, wire stretched by the bob (m)
  T amplitude;  ///< amplitude at the start of each timing (rad)
  int oscillations_per_trial = 1;  ///< oscillations in one timing
  Bob<T> bob;
  std::optional<Ring<T>> ring;
  std::optional<Cap<T>> cap;
  std::optional<CapScrew<T>> cap_screw;
  std::optional<Wire<T>> wire;
  std::optional<Air<T>> air;
  std::optional<Support<T>> support;
  std::optional<Decay<T>> decay;
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

/// Calls f(path, x, y) on a field pair; an optional field is visited only
/// where `a` has it, and is created in `b` first.
template <class F>
struct FieldZipper {
  F& f;
  template <class X, class Y>
  void operator()(const char* path, X& x, Y& y) {
    f(path, x, y);
  }
  template <class X, class Y>
  void operator()(const char* path, std::optional<X>& x, std::optional<Y>& y) {
    if (x) f(path, *x, ensure(y));
  }
  template <class X, class Y>
  void operator()(const char* path, const std::optional<X>& x,
                  std::optional<Y>& y) {
    if (x) f(path, *x, ensure(y));
  }
  template <class X, class Y>
  void operator()(const char* path, std::optional<X>& x, const std::optional<Y>& y) {
    if (x) f(path, *x, *y);
  }
  template <class X, class Y>
  void operator()(const char* path, const std::optional<X>& x,
                  const std::optional<Y>& y) {
    if (x) f(path, *x, *y);
  }
};

template <class P, class Q, class Z>
void zip_part(P& a, Q& b, Z& z) {
  if (a) {
    auto& pb = ensure(b);
    std::decay_t<decltype(*a)>::zip(*a, pb, z);
  }
}

}  // namespace detail

/// Visits every scalar field that `a` has, paired with the same field of
/// `b`: f(json_path, a_field, b_field). Parts and optional fields present in
/// `a` are created in `b` when `b` is writable; a read-only `b` must have the
/// shape of `a` (pass `a` twice to visit one scene).
template <class A, class B, class F>
void zip_fields(A& a, B& b, F&& f) {
  detail::FieldZipper<F> z{f};
  z("timing.trials", a.period, b.period);
  z("length", a.length, b.length);
  z("amplitude", a.amplitude, b.amplitude);
  decltype(a.bob)::zip(a.bob, b.bob, z);
  detail::zip_part(a.ring, b.ring, z);
  detail::zip_part(a.cap, b.cap, z);
  detail::zip_part(a.cap_screw, b.cap_screw, z);
  detail::zip_part(a.wire, b.wire, z);
  detail::zip_part(a.air, b.air, z);
  detail::zip_part(a.support, b.support, z);
  detail::zip_part(a.decay, b.decay, z);
}

/// The same scene with every scalar mapped by f(json_path, value) -> U.
template <class U, class T, class F>
Scene<U> convert_scene(const Scene<T>& s, F&& f) {
  Scene<U> out;
  out.oscillations_per_trial = s.oscillations_per_trial;
  zip_fields(s, out, [&](const char* path, const T& x, U& y) { y = f(path, x); });
  return out;
}

}  // namespace pendulum
