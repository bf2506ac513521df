// Damping and the decay of the amplitude: Nelson & Olsson (1986) Sec. III.C.2.
#include <catch2/catch.hpp>
#include <ceres/jet.h>

#include <cmath>

#include "pendulum/damping.hpp"
#include "reference.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
double us(double ratio) { return ratio * test::kIdealPeriod * 1e6; }

// Eq. (25) written as printed, in long double.
long double eq25(long double theta0m, long double alpha, long double beta, long double t) {
  if (alpha == 0.0L) return theta0m / (1.0L + beta * theta0m * t);  // Eq. (46)
  const long double e = std::exp(-alpha * t);
  return alpha * theta0m * e / (beta * theta0m * (1.0L - e) + alpha);
}

// Independent value of the decay correction: Eq. (49) by composite Simpson
// quadrature of Eq. (25) in long double, minus theta0m^2/16.
double decay_by_quadrature(double theta0m, double alpha, double beta, double t_f) {
  const int n = 20000;
  const long double h = static_cast<long double>(t_f) / n;
  long double sum = 0.0L;
  for (int i = 0; i <= n; ++i) {
    const long double th = eq25(theta0m, alpha, beta, i * h);
    const long double w = (i == 0 || i == n) ? 1.0L : (i % 2 ? 4.0L : 2.0L);
    sum += w * th * th;
  }
  const long double mean = sum * h / 3.0L / t_f;
  return static_cast<double>((mean - static_cast<long double>(theta0m) * theta0m) / 16.0L);
}
}  // namespace

TEST_CASE("Linear damping: Eq. (34), +0.033 us", "[damping][table2]") {
  CHECK_THAT(us(linear_damping(test::kAlpha, test::kOmega0)), WithinAbs(0.033, 0.01));
  CHECK(linear_damping(0.0, test::kOmega0) == 0.0);
  CHECK_THAT(linear_damping(2 * test::kAlpha, test::kOmega0),
             WithinRel(4 * linear_damping(test::kAlpha, test::kOmega0), 1e-15));
}

TEST_CASE("Quadratic damping: Eq. (48), +0.027 us", "[damping][table2]") {
  CHECK_THAT(us(quadratic_damping(test::kBeta, test::kOmega0, test::kAmplitude)), WithinAbs(0.027, 0.01));
  CHECK(quadratic_damping(0.0, test::kOmega0, test::kAmplitude) == 0.0);
  CHECK_THAT(quadratic_damping(test::kBeta, test::kOmega0, 2 * test::kAmplitude),
             WithinRel(4 * quadratic_damping(test::kBeta, test::kOmega0, test::kAmplitude), 1e-15));
}

TEST_CASE("Decayed amplitude after 100 oscillations: 0.869, 0.917, 0.945", "[damping]") {
  const double th = test::kAmplitude, t = test::kTiming;
  // Text after Eq. (50b), (51) and (52).
  CHECK_THAT(decayed_amplitude(th, test::kAlpha, test::kBeta, t) / th, WithinAbs(0.869, 0.0005));
  CHECK_THAT(decayed_amplitude(th, test::kAlpha, 0.0, t) / th, WithinAbs(0.917, 0.0005));
  CHECK_THAT(decayed_amplitude(th, 0.0, test::kBeta, t) / th, WithinAbs(0.945, 0.0005));
  // The limits are the closed forms Eq. (33) and Eq. (46).
  CHECK_THAT(decayed_amplitude(th, test::kAlpha, 0.0, t), WithinRel(th * std::exp(-test::kAlpha * t), 1e-15));
  CHECK_THAT(decayed_amplitude(th, 0.0, test::kBeta, t), WithinRel(th / (1 + test::kBeta * th * t), 1e-15));
  for (double t_i : {0.0, 1.0, 100.0, 1e4}) {
    CHECK_THAT(decayed_amplitude(th, test::kAlpha, test::kBeta, t_i),
               WithinRel(static_cast<double>(eq25(th, test::kAlpha, test::kBeta, t_i)), 1e-14));
  }
}

TEST_CASE("Decay of finite amplitude: Eq. (50), 519 us mean and -77 us", "[damping][table2]") {
  const double r = amplitude_decay(test::kAmplitude, test::kAlpha, test::kBeta, test::kTiming);
  CHECK_THAT(us(r), WithinAbs(-77.0, 1.0));
  CHECK_THAT(us(r + test::kAmplitude * test::kAmplitude / 16.0), WithinAbs(519.0, 1.0));
}

TEST_CASE("Decay limits: Eq. (51) for beta = 0, Eq. (52) for alpha = 0", "[damping]") {
  const double th = test::kAmplitude, t = test::kTiming;
  const double constant = th * th / 16.0;
  {  // beta = 0, Eq. (51): 547 us, an effect of -49 us
    const double thf = th * std::exp(-test::kAlpha * t);
    const double eq51 = (th * th - thf * thf) / (32.0 * std::log(th / thf));
    const double r = amplitude_decay(th, test::kAlpha, 0.0, t);
    CHECK_THAT(r + constant, WithinRel(eq51, 1e-13));
    CHECK_THAT(us(eq51), WithinAbs(547.0, 1.0));
    CHECK_THAT(us(r), WithinAbs(-49.0, 1.0));
    // beta -> 0 approaches the limit continuously.
    CHECK_THAT(amplitude_decay(th, test::kAlpha, 1e-15, t) + constant, WithinRel(eq51, 1e-11));
  }
  {  // alpha = 0, Eq. (52): 564 us, an effect of -32 us
    const double thf = th / (1.0 + test::kBeta * th * t);
    const double eq52 = th * thf / 16.0;
    const double r = amplitude_decay(th, 0.0, test::kBeta, t);
    CHECK_THAT(r + constant, WithinRel(eq52, 1e-13));
    CHECK_THAT(us(eq52), WithinAbs(564.0, 1.0));
    CHECK_THAT(us(r), WithinAbs(-32.0, 1.0));
    CHECK_THAT(amplitude_decay(th, 1e-15, test::kBeta, t) + constant, WithinRel(eq52, 1e-11));
  }
  CHECK(amplitude_decay(th, 0.0, 0.0, t) == 0.0);
}

TEST_CASE("A decay too slow to resolve: first order, continuous, finite at subnormal rates",
          "[damping][jet]") {
  const double th = test::kAmplitude, t = test::kTiming;
  // First order, theta0^2 (alpha + beta theta0) t_f / 16, below s = 1e-8 ...
  const double slow = 1e-10 / t;
  CHECK_THAT(amplitude_decay(th, slow, 0.0, t), WithinRel(-th * th * 1e-10 / 16.0, 1e-14));
  // ... and on both sides of it the same line, to the 1e-8 either form holds.
  const double below = amplitude_decay(th, 0.999e-8 / t, 0.0, t);
  const double above = amplitude_decay(th, 1.001e-8 / t, 0.0, t);
  CHECK_THAT(above / below, WithinRel(1.001 / 0.999, 1e-7));
  // alpha = 0 and a subnormal beta theta0: the exact form divided by it,
  // and the derivatives were NaN (found by fuzzing).
  using J = ceres::Jet<double, 2>;
  const J r = amplitude_decay(J(1e-5), J(0.0, 0), J(3e-308, 1), J(t));
  CHECK(std::isfinite(r.a));
  CHECK(std::isfinite(r.v[0]));
  CHECK(std::isfinite(r.v[1]));
}

TEST_CASE("Decay correction agrees with quadrature of Eq. (25) over decades of alpha and beta",
          "[damping]") {
  const double th = test::kAmplitude;
  for (double alpha : {0.0, 1e-9, 1e-5, 2.49e-4, 1e-2}) {
    for (double beta : {0.0, 1e-8, 1e-4, 3.17e-3, 0.3}) {
      if (alpha == 0.0 && beta == 0.0) continue;
      for (double t_f : {3.5, 347.88, 3000.0}) {
        const double expected = decay_by_quadrature(th, alpha, beta, t_f);
        INFO("alpha " << alpha << " beta " << beta << " t_f " << t_f);
        CHECK_THAT(amplitude_decay(th, alpha, beta, t_f),
                   WithinAbs(expected, 1e-12 * th * th + 1e-9 * std::abs(expected)));
      }
    }
  }
}

TEST_CASE("Decay correction has finite derivatives at alpha = 0 and beta = 0", "[damping][jet]") {
  using J = ceres::Jet<double, 2>;
  const J th(test::kAmplitude);
  const J t(test::kTiming);
  for (const auto& ab : {std::pair{0.0, test::kBeta}, std::pair{test::kAlpha, 0.0}}) {
    const J r = amplitude_decay(th, J(ab.first, 0), J(ab.second, 1), t);
    CHECK(std::isfinite(r.a));
    CHECK(std::isfinite(r.v[0]));
    CHECK(std::isfinite(r.v[1]));
    // More damping, faster decay, smaller mean amplitude.
    CHECK(r.v[0] < 0.0);
    CHECK(r.v[1] < 0.0);
  }
}
