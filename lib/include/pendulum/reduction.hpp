#pragma once
/// \file reduction.hpp
/// \brief One observation -> period corrections -> ideal period -> g, in
/// closed form, generic in the scalar type (double, ceres::Jet): the fast
/// path of the simple pendulum's model (models/simple_pendulum.hpp) when g
/// is its only unknown.
///
/// T = T0 (T/T0) with T/T0 = (1 + r_amplitude)(1 + sum of the other r_i)
/// (corrections.hpp, compose), so T0 = T / (T/T0), DeltaT_i = r_i T0 and
/// g = 4 pi^2 l / T0^2 (Nelson & Olsson 1986, Eqs. 3, 6-7).

#include "pendulum/amplitude.hpp"
#include "pendulum/apparatus.hpp"
#include "pendulum/corrections.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/observation.hpp"

namespace pendulum {

/// Choices the user may make about the reduction.
struct ReductionOptions {
  /// `automatic` takes the cheapest method whose error bound is below
  /// amplitude_tolerance; the others are forced.
  AmplitudeMethod amplitude_method = AmplitudeMethod::automatic;
  int series_terms = 4;  ///< for AmplitudeMethod::series
  /// Largest error of DeltaT/T0 (dimensionless) the automatic choice may
  /// make; 0 takes the exact method.
  double amplitude_tolerance = 0.0;
};

/// The finite-amplitude method the options ask for at theta0 (rad).
inline AmplitudeChoice choose_amplitude_method(const ReductionOptions& options, double theta0) {
  if (options.amplitude_method == AmplitudeMethod::automatic) {
    return cheapest_amplitude_method(theta0, options.amplitude_tolerance);
  }
  return {options.amplitude_method, options.series_terms,
          amplitude_error_bound(options.amplitude_method, theta0, options.series_terms)};
}

/// Everything the closed form computes, in SI units.
template <class T>
struct Reduction {
  Terms<T> terms;
  Composition<T> composition;
  T total_ratio;    ///< T/T0 - 1
  T period_ideal;   ///< T0 (s)
  T g;              ///< 4 pi^2 l / T0^2 (m/s^2)
  T g_uncorrected;  ///< 4 pi^2 l / T^2 (m/s^2), Eq. (5)
};

/// The g at which the corrected pendulum of `app` with this observation's
/// length (plus `length_offset`, m) swings in the measured period. Pure.
template <class T>
Reduction<T> reduce(const Apparatus<T>& app, const Observation<T>& obs, const AmplitudeChoice& amplitude,
                    const T& length_offset) {
  const Swing<T> swing = Swing<T>::of(obs, length_offset);
  Reduction<T> out;
  out.terms = correction_terms(app, swing, amplitude);
  out.composition = compose(out.terms);
  out.total_ratio = out.composition.total;
  out.period_ideal = obs.period / (1.0 + out.total_ratio);                             // Eqs. (6)-(7)
  out.g = gravity_for_period(swing.length, out.period_ideal);                         // Eq. (3)
  out.g_uncorrected = gravity_for_period(swing.length, obs.period);                   // Eq. (5)
  return out;
}

/// reduce()'s g alone, bit for bit, without its rows (a Monte Carlo draw's).
template <class T>
T reduce_g(const Apparatus<T>& app, const Observation<T>& obs, const AmplitudeChoice& amplitude,
           const T& length_offset) {
  const Swing<T> swing = Swing<T>::of(obs, length_offset);
  const T total_ratio = compose_in_table_order(app, swing, amplitude).total;
  return gravity_for_period(swing.length, T(obs.period / (1.0 + total_ratio)));  // Eqs. (3), (6)-(7)
}

/// The same with the options' amplitude method and no length offset.
template <class T>
Reduction<T> reduce(const Apparatus<T>& app, const Observation<T>& obs, const ReductionOptions& options = {}) {
  return reduce(app, obs, choose_amplitude_method(options, value_of(obs.amplitude)), T(0.0));
}

}  // namespace pendulum
