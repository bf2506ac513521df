#pragma once
/// \file period_model.hpp
/// \brief What every period model shares: its parameters' names and units,
/// and what it predicts for one observation.
///
/// A period model is a struct with
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
/// generic in the scalar so that the fit (period_fit.hpp) and the
/// propagation of uncertainties (analysis.hpp) run it on ceres::Jet. Its
/// period is then ideal_period(swing_at(...).length, g) (1 + composition):
/// g^-1/2 times a function of the other parameters, which the fit uses to
/// project g out.

#include <cmath>

#include "pendulum/corrections.hpp"

namespace pendulum {

struct ParameterInfo {
  const char* name;  ///< as in the scene's "fit" and the output
  const char* unit;  ///< SI
  const char* description;
};

/// T0 = 2 pi sqrt(l/g) (s): the small-amplitude period of the ideal
/// pendulum of length l (m; a rigid body's equivalent length) in gravity g
/// (m/s^2). Nelson & Olsson (1986) Eq. (3); Kelley (1993) Eq. (56) without
/// K. g may be a plain number where the scalar T is a dual number (the fit
/// evaluates at g = 1).
template <class T, class G>
T ideal_period(const T& l, const G& g) {
  using std::sqrt;
  return 2.0 * kPi * sqrt(l / g);  // Eq. (3)
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

}  // namespace pendulum
