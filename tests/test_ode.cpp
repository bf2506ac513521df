// Full physics: the equation of motion with linear and quadratic damping,
// theta'' = -omega0^2 sin(theta) - 2 alpha theta' - eps theta' |theta'|,
// integrated numerically (Boost.Odeint's Dormand-Prince 5(4) with dense
// output; classic RK4 in Feinstein's Sec. G form as a cross-check), 100
// oscillations counted from the release, against
// T0 (1 + amplitude + decay + damping corrections): Nelson & Olsson's
// assumption that the corrections add (Eqs. 6-7). docs/amplitude.md reports
// the difference.
#include <catch2/catch.hpp>

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "pendulum/amplitude.hpp"
#include "pendulum/damping.hpp"
#include "reference.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

using State = std::array<double, 2>;  // theta (rad), theta' (rad/s)

// The pendulum of Nelson & Olsson's Eqs. (1), (30), (35): eps = c l/m, and
// Eq. (27), beta = (4/3)(omega0/pi) eps, gives eps = (3 pi/4) beta/omega0.
// `linear` replaces sin(theta) by theta, leaving only the damping effects.
struct Pendulum {
  double omega0;  // rad/s
  double alpha;   // 1/s
  double beta;    // 1/(s rad)
  bool linear = false;
  void operator()(const State& x, State& dxdt, double /*t*/) const {
    const double eps = 3.0 * M_PI / 4.0 * beta / omega0;
    const double restoring = linear ? x[0] : std::sin(x[0]);
    dxdt[0] = x[1];
    dxdt[1] = -omega0 * omega0 * restoring - 2.0 * alpha * x[1] - eps * x[1] * std::abs(x[1]);
  }
};

// The turning points after the release from theta0 at rest at t = 0, up to
// the end of n oscillations (the n-th maximum): their times (s) and
// |theta| (rad), the release included. Dormand-Prince 5(4) at 1e-13
// relative and absolute tolerance; each turning point is located by
// bisection on the dense output.
struct Extremes {
  std::vector<double> t, amplitude;
};
Extremes extremes_dopri(const Pendulum& p, double theta0, int n) {
  namespace odeint = boost::numeric::odeint;
  auto stepper = odeint::make_dense_output(1e-13, 1e-13, odeint::runge_kutta_dopri5<State>());
  stepper.initialize(State{theta0, 0.0}, 0.0, 1e-3);
  Extremes e{{0.0}, {theta0}};
  int maxima = 0;
  while (maxima < n) {
    const auto [t0, t1] = stepper.do_step(p);
    const double before = stepper.previous_state()[1], after = stepper.current_state()[1];
    if ((before > 0.0) == (after > 0.0)) continue;
    double lo = t0, hi = t1;
    State x;
    for (int i = 0; i < 60; ++i) {
      const double mid = (lo + hi) / 2.0;
      stepper.calc_state(mid, x);
      ((x[1] > 0.0) == (before > 0.0) ? lo : hi) = mid;
    }
    stepper.calc_state((lo + hi) / 2.0, x);
    e.t.push_back((lo + hi) / 2.0);
    e.amplitude.push_back(std::abs(x[0]));
    if (before > 0.0) ++maxima;
  }
  return e;
}

// One step of classic RK4 as Feinstein (2005) Sec. G prints it for
// theta' = a, a' = f(t, theta, a): n_i = z f(...), with the theta stages
// theta + (z/2) a, theta + (z/2) a + (z/4) n1, theta + z a + (z/2) n2.
State rk4_step(const Pendulum& p, const State& x, double z) {
  auto f = [&](double theta, double a) {
    State dx;
    p(State{theta, a}, dx, 0.0);
    return dx[1];
  };
  const double n1 = z * f(x[0], x[1]);
  const double n2 = z * f(x[0] + z / 2.0 * x[1], x[1] + n1 / 2.0);
  const double n3 = z * f(x[0] + z / 2.0 * x[1] + z / 4.0 * n1, x[1] + n2 / 2.0);
  const double n4 = z * f(x[0] + z * x[1] + z / 2.0 * n2, x[1] + n3);
  return {x[0] + z * x[1] + z / 6.0 * (n1 + n2 + n3), x[1] + (n1 + 2.0 * n2 + 2.0 * n3 + n4) / 6.0};
}

// The time (s) of the n-th maximum after the release by fixed-step RK4,
// `steps` a small-amplitude period; a maximum inside a step is located by
// bisection on the length of one RK4 step from the step's start.
double nth_maximum_rk4(const Pendulum& p, double theta0, int n, int steps) {
  const double z = 2.0 * M_PI / p.omega0 / steps;
  State x{theta0, 0.0};
  for (long i = 0, found = 0;; ++i) {
    const State next = rk4_step(p, x, z);
    if (x[1] > 0.0 && next[1] <= 0.0 && ++found == n) {
      double lo = 0.0, hi = z;
      for (int j = 0; j < 60; ++j) {
        const double mid = (lo + hi) / 2.0;
        (rk4_step(p, x, mid)[1] > 0.0 ? lo : hi) = mid;
      }
      return i * z + (lo + hi) / 2.0;
    }
    x = next;
  }
}

// Nelson & Olsson: T0 of Eq. (90), theta0 = 3 deg, alpha and beta of
// Eqs. (28)-(29).
const double kOmega0 = 2.0 * M_PI / test::kIdealPeriod;

// The cross term of linear and quadratic damping, which Nelson & Olsson's
// independent perturbations leave out: DeltaT/T0 = (16/(9 pi)) (alpha/omega0)
// eps theta0 = (4/3) alpha beta theta0 / omega0^2. The coefficient 16/(9 pi)
// = 0.56588 is the limit of half-periods of theta'' + theta = -2a theta' +
// eps theta'^2 integrated to 35 digits (mpmath): 0.565683 at a = 1e-4,
// eps = 2e-3, theta0 = 0.05, falling linearly in a and eps
// (docs/deviations.md).
double damping_cross_term(double alpha, double beta, double omega0, double theta0) {
  return 4.0 / 3.0 * alpha * beta * theta0 / (omega0 * omega0);
}

// Sum over the half-cycles between turning points of (T0/2) (1 + the
// corrections at the half-cycle's mean amplitude): the prediction with the
// amplitude each half-cycle really has.
double summed_half_cycles(const Extremes& e, const Pendulum& p,
                          const std::function<double(double)>& ratio) {
  double t = 0.0;
  for (std::size_t j = 0; j + 1 < e.amplitude.size(); ++j) {
    t += M_PI / p.omega0 * (1.0 + ratio((e.amplitude[j] + e.amplitude[j + 1]) / 2.0));
  }
  return t;
}

}  // namespace

TEST_CASE("Undamped: the integrated period is the exact T0 (1 + DeltaT/T0)", "[ode][amplitude]") {
  // RK4 at 4000 steps a small-amplitude period: its period error falls
  // 16-fold when the steps double and is below 1e-12 relative here (8e-13
  // at 170 deg, where the turning points are slow); the exact method's
  // 1e-15 is far below.
  for (double deg : {3.0, 90.0, 170.0}) {
    const Pendulum p{kOmega0, 0.0, 0.0};
    const double t100 = nth_maximum_rk4(p, deg * test::kDegree, 100, 4000);
    const double predicted = test::kIdealPeriod * (1.0 + finite_amplitude_agm_deg(deg));
    INFO(deg << " deg");
    CHECK_THAT(t100 / 100.0, WithinRel(predicted, 2e-12));
  }
}

TEST_CASE("Damping alone (sin theta -> theta): Eq. (34), Eq. (48) and the cross term",
          "[ode][damping]") {
  // With a linear restoring force the period depends on damping only. Each
  // half-cycle's amplitude comes from the integration; the integrators'
  // 1e-11 relative error is 4e-5 us on T0.
  const double theta0 = test::kAmplitude;
  auto effect_us = [&](double alpha, double beta, const std::function<double(double)>& ratio) {
    const Pendulum p{kOmega0, alpha, beta, true};
    const Extremes e = extremes_dopri(p, theta0, 100);
    return (e.t.back() - summed_half_cycles(e, p, ratio)) / 100.0 * 1e6;
  };
  const double lin = linear_damping(test::kAlpha, kOmega0);
  auto quad = [&](double a) { return quadratic_damping(test::kBeta, kOmega0, a); };
  // Linear damping: omega = sqrt(omega0^2 - alpha^2) exactly; Eq. (34) is
  // its first term, the next, (3/8)(alpha/omega0)^4, is 1e-16.
  CHECK_THAT(effect_us(test::kAlpha, 0.0, [&](double) { return lin; }), WithinAbs(0.0, 1e-4));
  // Quadratic damping: (3/32)(pi beta/omega0)^2 theta0^2 = eps^2 theta0^2/6.
  // The next order is eps theta0 = 2e-4 of it: 5e-6 us.
  CHECK_THAT(effect_us(0.0, test::kBeta, quad), WithinAbs(0.0, 1e-4));
  // Eq. (47)'s printed omega_2 = -(1/8) theta0^2 omega0 would leave 6.6e-3 us.
  CHECK(std::abs(effect_us(0.0, test::kBeta, [&](double a) { return 0.75 * quad(a); })) > 5e-3);
  // Both: the two add only with the cross term (+0.055 us here); its next
  // orders are eps theta0 and alpha/omega0 of it, 1e-5 us.
  auto both = [&](double a) { return lin + quad(a) + damping_cross_term(test::kAlpha, test::kBeta, kOmega0, a); };
  CHECK_THAT(effect_us(test::kAlpha, test::kBeta, both), WithinAbs(0.0, 1e-4));
}

TEST_CASE("Nelson-Olsson with damping: 100 integrated oscillations against the summed corrections",
          "[ode][damping]") {
  const Pendulum p{kOmega0, test::kAlpha, test::kBeta};
  const double theta0 = test::kAmplitude;
  const Extremes e = extremes_dopri(p, theta0, 100);
  const double t_f = e.t.back();  // s, the duration of the 100 oscillations
  // RK4 agrees: its error at 2000 steps a period is about 1e-10 s over the run.
  CHECK_THAT(nth_maximum_rk4(p, theta0, 100, 2000), WithinAbs(t_f, 1e-8));

  // Every correction at each half-cycle's integrated amplitude, with the
  // cross term. Left out: third order in the damping ratios, (alpha/omega0 +
  // eps theta0)^3 = (3.5e-4)^3 = 4e-11 of T0 (1.5e-4 us), and the
  // integration's 4e-5 us.
  const double lin = linear_damping(test::kAlpha, kOmega0);
  const double full = summed_half_cycles(e, p, [&](double a) {
    return finite_amplitude_agm(a) + lin + quadratic_damping(test::kBeta, kOmega0, a) +
           damping_cross_term(test::kAlpha, test::kBeta, kOmega0, a);
  });
  CHECK_THAT((t_f - full) / 100.0 * 1e6, WithinAbs(0.0, 5e-4));

  // The paper's sum: the corrections at the starting amplitude, the decay
  // of theta0^2/16 along Eq. (25), no cross term (docs/amplitude.md).
  const double paper =
      test::kIdealPeriod * (1.0 + finite_amplitude_agm(theta0) +
                            amplitude_decay(theta0, test::kAlpha, test::kBeta, t_f) + lin +
                            quadratic_damping(test::kBeta, kOmega0, theta0));
  WARN("simulated mean period " << t_f / 100.0 << " s; T0 (1 + sum of the paper's corrections) "
       << paper << " s; difference " << (t_f / 100.0 - paper) * 1e6 << " us");
}
