#pragma once
/// \file period_model.hpp
/// \brief What every period model shares: its parameters' names and units,
/// and what it predicts for one observation.
///
/// A period model is a struct with
///   kParameters, kParameterInfo, kDefaults,
///   canonicalise(double* p): the fitted parameters in their reported form
///       (a sign only the square of which matters),
///   template <class T> PeriodPrediction<T> predict(const T* p,
///       const Observation<T>&, const Apparatus<T>&, const AmplitudeChoice&),
///   template <class T> Swing<T> swing(const Observation<T>&): what of the
///       swing no parameter changes, computed once per observation by a fit,
///   template <class T> T period(const T* p, Swing<T>, apparatus, amplitude):
///       predict()'s period alone, from swing(),
///   template <class T> T solve_g(const T* p, observation, apparatus, amplitude):
///       the closed form for one observation with g the only unknown,
/// generic in the scalar so that the fit (period_fit.hpp) and the
/// propagation of uncertainties (analysis.hpp) run it on ceres::Jet.

#include "pendulum/corrections.hpp"

namespace pendulum {

struct ParameterInfo {
  const char* name;  ///< as in the scene's "fit" and the output
  const char* unit;  ///< SI
  const char* description;
};

/// A model's period for one observation, with the corrections behind it.
template <class T>
struct PeriodPrediction {
  T period;  ///< T (s)
  T ideal;   ///< T0 (s), the small-amplitude period of the ideal pendulum
  Terms<T> terms;
  Composition<T> composition;
};

}  // namespace pendulum
