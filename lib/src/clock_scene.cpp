#include "pendulum/clock_scene.hpp"

#include <cmath>

#include <ceres/jet.h>

#include "pendulum/input_error.hpp"
#include "text.hpp"

namespace pendulum {

std::string impulse_over_top(double theta0, double q, ClockPath path) {
  const bool cycloid = path == ClockPath::cycloidal;
  const double k_i = std::sqrt(1.0 + kPi / q) * (cycloid ? std::sin(theta0) : std::sin(theta0 / 2.0));  // Eq. (F-1)
  if (k_i < 1.0) return "";
  return "got " + format_number(q) + "; expected a Q large enough that the impulse (pi/Q of the energy, Eq. F-1) "
         "keeps the swing below " + (cycloid ? "90 deg" : "180 deg");
}

ClockAnalysis analyse_clock(const ClockScene& s, std::optional<ClockRoute> route) try {
  ClockAnalysis a{};
  const bool circular = s.path == ClockPath::circular;
  const double theta0 = s.semi_amplitude.value, q = s.q.value;
  a.location = s.relative_location ? s.location.value * theta0 : s.location.value;
  a.small_amplitude_period = s.nominal_period ? *s.nominal_period : ideal_period(s.length.value, s.g.value);
  a.circular_error_rate = circular ? circular_error_rate(theta0) : 0.0;
  a.circular_error = {circular ? circular_error(theta0) : 0.0, a.circular_error_rate * s.semi_amplitude.sigma};
  a.impulsed_amplitude = circular ? impulsed_amplitude(theta0, q)
                                  : std::asin(std::sqrt(1.0 + kPi / q) * std::sin(theta0));  // App. F

  if (route) {
    if (!route_fits(*route, s.path)) {
      throw InputError("--route", std::string("got ") + route_name(*route) +
                                      "; a circular route cannot model a cycloidal path");
    }
    const bool stand_in = circular && (*route == ClockRoute::cycloid || *route == ClockRoute::cycloid_damped);
    if (stand_in && !(a.impulsed_amplitude <= kPi / 3.0)) {
      throw InputError("--route", std::string("got ") + route_name(*route) +
                                      "; a cycloid of equal energy exists for a circular swing up to 60 deg");
    }
    a.choice = run_clock_route(*route, s.path, s.damped, theta0, a.location, q, s.accuracy);
  } else {
    a.choice = cheapest_clock_route(s.path, s.damped, theta0, a.location, q, s.accuracy);
  }
  const double sign = direction_sign(s.direction);
  a.impulse_error = sign * a.choice.effect.error;
  a.impulse_error_rate = sign * a.choice.effect.rate;
  if (s.accuracy > 0.0 && a.choice.error_bound > s.accuracy) {
    a.warnings.push_back("the accuracy asked (" + format_number(s.accuracy) + " s/day) was not reached: the bound of " +
                         route_name(a.choice.route) + " is " + format_number(a.choice.error_bound) + " s/day");
  }

  // First-order uncertainty from the amplitude, the location and Q, with
  // the derivatives of the path's closed-form route.
  using Jet = ceres::Jet<double, 3>;
  const Jet t0(theta0, 0), loc(s.location.value, 1), qq(q, 2);
  const Jet theta = s.relative_location ? loc * t0 : loc;
  const Jet e = circular ? impulse_error_elliptic(t0, theta, qq).error : impulse_error_cycloid(t0, theta, qq).error;
  const double sigmas[3] = {s.semi_amplitude.sigma, s.location.sigma, s.q.sigma};
  double variance = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (sigmas[i] > 0.0) variance += std::pow(e.v[i] * sigmas[i], 2);
  }
  if (std::isfinite(variance)) a.impulse_error_sigma = std::sqrt(variance);
  {
    using Jet1 = ceres::Jet<double, 1>;
    const Jet1 t(theta0, 0), fixed(a.location), qd(q);
    a.impulse_error_amplitude_rate =
        sign * (circular ? impulse_error_elliptic(t, fixed, qd).error : impulse_error_cycloid(t, fixed, qd).error).v[0];
  }

  const double ratio = circular ? finite_amplitude_agm(theta0) : 0.0;
  a.free_period = a.small_amplitude_period * (1.0 + ratio);
  a.impulsed_period = a.free_period * (1.0 + a.impulse_error / kSecondsPerDay);
  const double relative = s.nominal_period ? 0.0 : 0.5 * std::hypot(s.length.sigma / s.length.value, s.g.sigma / s.g.value);
  a.period_sigma = std::hypot(a.free_period * relative,
                              a.small_amplitude_period * a.circular_error.sigma / kSecondsPerDay);

  if (circular) a.insensitive_semi_amplitude = amplitude_insensitive_semi_amplitude(s.direction, a.location, q);
  if (!circular) {
    a.cancelling_note = "a cycloid has no circular error to cancel";
  } else if (s.direction == ImpulseDirection::away) {
    a.cancelling_note = "an impulse away from equilibrium adds its rate to the circular error's";
  } else {
    a.cancelling_semi_amplitude = cancelling_semi_amplitude(s.direction, s.location.value, s.relative_location, q);
    a.cancelling_note = a.cancelling_semi_amplitude
                            ? (s.relative_location ? "relative impulse location held fixed"
                                                   : "impulse location held fixed")
                            : "no semi-amplitude below 170 deg cancels";
  }
  return a;
} catch (const std::domain_error& e) {
  // A scene the validation let through but a route cannot model.
  throw InputError("", std::string("the clock cannot be modelled: ") + e.what());
}

}  // namespace pendulum
