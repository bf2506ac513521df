#pragma once
// The inner loop of the decay fit: Eq. (25), its Jacobian and the sums the
// Gauss-Newton model needs, in one pass over the record. Compiled on its own
// with -ffast-math -fopenmp-simd (lib/CMakeLists.txt) so that GCC vectorises
// exp through glibc's libmvec, in versions for AVX2 and SSE2 chosen
// at run time (not AVX-512: decay_kernel.cpp). Nothing here may rely on NaN or infinity: callers check
// the sums with std::isfinite.

#include <cstddef>

namespace pendulum::kernel {

/// Sums over the points of r_i = (theta0(t_i) - theta_i) w_i and of the
/// Jacobian rows J_i = d r_i / d(alpha, beta, theta0m).
struct DecaySums {
  double rr = 0.0;         ///< sum r_i^2
  double dd = 0.0;         ///< sum (r_i / w_i)^2, the unweighted squares
  double jtr[3] = {};      ///< sum J_i r_i
  double jtj[3][3] = {};   ///< sum J_i^T J_i
};

/// Sums at p = (alpha, beta, theta0m); the Jacobian parts only when
/// `with_jacobian`. Times must be sorted ascending and >= 0.
DecaySums decay_sums(std::size_t n, const double* t, const double* theta, const double* w,
                     const double* p, bool with_jacobian);

/// Per-point residuals and, when `jacobian` is not null, the Jacobian,
/// column-major n x 3 (tests compare it with automatic differentiation).
void decay_points(std::size_t n, const double* t, const double* theta, const double* w,
                  const double* p, double* residuals, double* jacobian);

}  // namespace pendulum::kernel
