#pragma once
/// \file period_model.hpp
/// \brief What every period model shares: its parameters' names and units,
/// and what it predicts for one observation.
///
/// A period model is a struct with (models/registry.hpp checks every piece
/// at compile time; docs/core.md):
///   kName: its name in the output ("fit.model"),
///   kKind: its PeriodModelKind, its place in the registry,
///   kSettings: the observation keys it reads (Setting), by which the reader
///       knows a scene's kind,
///   kCorrectionUse: per row of kCorrections, whether it applies, is
///       replaced by the model's own, or does not apply (a test checks
///       predict() against it),
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

struct ParsedScene;
struct Analysis;
/// What a model's own results read of its fit (lib/src/fit_state.hpp).
template <int P>
struct FitState;

/// The period model a scene is reduced with: one per registered kind, in
/// the registry's order (models/registry.hpp).
enum class PeriodModelKind { simple_pendulum, physical_pendulum };

/// How a model treats one row of kCorrections (its kCorrectionUse, one per
/// CorrectionId): the row as visit_corrections computes it, its own formula
/// in its place, or a row that does not describe it (skipped with a reason).
enum class CorrectionUse { applies, replaced, not_applicable };

struct ParameterInfo {
  const char* name;  ///< as in the scene's "fit" and the output
  const char* unit;  ///< SI
  const char* description;
};

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
