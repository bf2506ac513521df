#include "decay_kernel.hpp"

#include <cmath>

#include "pendulum/damping.hpp"

namespace pendulum::kernel {
namespace {

/// Below this alpha t the factors E(y) = (1 - e^{-y})/y and E'(y) = (u - E)/y
/// come from their Taylor series (11 terms: 0.1^11/12! < 1e-19); above it
/// the closed forms lose at most a factor 1/(1 - e^{-0.1}) < 11 to
/// cancellation.
constexpr double kSeriesBelow = 0.1;

struct Point {
  double d;     ///< residual theta0(t) - theta
  double r;     ///< weighted residual
  double j[3];  ///< d r / d(alpha, beta, theta0m)
};

/// Eq. (25) at one time (pendulum::decayed_amplitude_from_factors, which has
/// no 0/0 at alpha = 0 (Eq. 46) or beta = 0 (Eq. 33)) and its derivatives.
/// The derivatives are written out here rather than taken by ceres::Jet: they
/// reuse u, E, E' (from the same series pass) and the denominator, and Jets
/// would bring Eigen into this -ffast-math file and out of the simd loop.
template <bool kSeries>
inline Point point(double t, double theta, double w, double alpha, double beta,
                   double theta0) {
  const double y = alpha * t;
  const double u = std::exp(-y);
  double e, e_prime;
  if (kSeries) {
    e = 0.0;
    e_prime = 0.0;
    double term = 1.0;  // (-y)^k / (k+1)!
    for (int k = 0; k < 11; ++k) {
      e += term;
      e_prime -= (k + 1) * term / (k + 2);  // derivative of the term after this one
      term *= -y / (k + 2);
    }
  } else {
    const double inv_y = 1.0 / y;
    e = (1.0 - u) * inv_y;
    e_prime = (u - e) * inv_y;
  }
  const double inv_d = 1.0 / (1.0 + beta * theta0 * t * e);
  const double model = decayed_amplitude_from_factors(theta0, beta, t, u, e);
  return {model - theta, (model - theta) * w,
          {-t * model * (1.0 + beta * theta0 * t * e_prime * inv_d) * w,
           -model * theta0 * t * e * inv_d * w, u * inv_d * inv_d * w}};
}

/// The first index whose alpha t reaches kSeriesBelow (times are sorted).
std::size_t series_end(std::size_t n, const double* t, double alpha) {
  std::size_t k = 0;
  while (k < n && alpha * t[k] < kSeriesBelow) ++k;
  return k;
}

template <bool kSeries>
__attribute__((always_inline)) inline void accumulate(std::size_t begin, std::size_t end,
                                                      const double* t, const double* theta,
                                                      const double* w, double alpha, double beta,
                                                      double theta0, bool with_jacobian,
                                                      DecaySums& s) {
  double rr = 0, dd = 0, r0 = 0, r1 = 0, r2 = 0, a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0;
  if (!with_jacobian) {
#pragma omp simd reduction(+ : rr, dd)
    for (std::size_t i = begin; i < end; ++i) {
      const Point q = point<kSeries>(t[i], theta[i], w[i], alpha, beta, theta0);
      rr += q.r * q.r;
      dd += q.d * q.d;
    }
  } else {
#pragma omp simd reduction(+ : rr, dd, r0, r1, r2, a00, a01, a02, a11, a12, a22)
    for (std::size_t i = begin; i < end; ++i) {
      const Point q = point<kSeries>(t[i], theta[i], w[i], alpha, beta, theta0);
      rr += q.r * q.r;
      dd += q.d * q.d;
      r0 += q.j[0] * q.r;
      r1 += q.j[1] * q.r;
      r2 += q.j[2] * q.r;
      a00 += q.j[0] * q.j[0];
      a01 += q.j[0] * q.j[1];
      a02 += q.j[0] * q.j[2];
      a11 += q.j[1] * q.j[1];
      a12 += q.j[1] * q.j[2];
      a22 += q.j[2] * q.j[2];
    }
  }
  s.rr += rr;
  s.dd += dd;
  s.jtr[0] += r0;
  s.jtr[1] += r1;
  s.jtr[2] += r2;
  const double gram[3][3] = {{a00, a01, a02}, {a01, a11, a12}, {a02, a12, a22}};
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) s.jtj[a][b] += gram[a][b];
  }
}

// One copy per instruction set, chosen at run time (target_clones takes no
// templates, hence one function per variant). No AVX-512 copy: its eight
// lanes sum in another order than AVX2's four, and libmvec's exp differs,
// so the fit's last digits, which the JSON prints, depended on the machine
// (tests/outputs were an AVX-512 machine's, failing on an AVX2 one).
#define PENDULUM_ACCUMULATE(name, series)                                                    \
  __attribute__((target_clones("avx2", "default"))) void name(                    \
      std::size_t begin, std::size_t end, const double* t, const double* theta,              \
      const double* w, double alpha, double beta, double theta0, bool with_jacobian,         \
      DecaySums& s) {                                                                         \
    accumulate<series>(begin, end, t, theta, w, alpha, beta, theta0, with_jacobian, s);       \
  }
PENDULUM_ACCUMULATE(accumulate_series, true)
PENDULUM_ACCUMULATE(accumulate_closed_form, false)
#undef PENDULUM_ACCUMULATE

}  // namespace

DecaySums decay_sums(std::size_t n, const double* t, const double* theta, const double* w,
                     const double* p, bool with_jacobian) {
  DecaySums s;
  const std::size_t k = series_end(n, t, p[0]);
  accumulate_series(0, k, t, theta, w, p[0], p[1], p[2], with_jacobian, s);
  accumulate_closed_form(k, n, t, theta, w, p[0], p[1], p[2], with_jacobian, s);
  return s;
}

void decay_points(std::size_t n, const double* t, const double* theta, const double* w,
                  const double* p, double* residuals, double* jacobian) {
  const std::size_t k = series_end(n, t, p[0]);
  for (std::size_t i = 0; i < n; ++i) {
    const Point q = i < k ? point<true>(t[i], theta[i], w[i], p[0], p[1], p[2])
                          : point<false>(t[i], theta[i], w[i], p[0], p[1], p[2]);
    residuals[i] = q.r;
    if (jacobian) {
      for (int c = 0; c < 3; ++c) jacobian[c * n + i] = q.j[c];
    }
  }
}

}  // namespace pendulum::kernel
