#pragma once
// Quad-precision references (__float128 and libquadmath, 113-bit
// significand, unit roundoff 1e-34) for the amplitude tests and benchmark.
// They use other algorithms than the code under test where they can: Eq. (8)
// summed to convergence, the plain AGM with a final subtraction (harmless
// with 34 digits where DeltaT/T0 >= 0.025), and Carlson's R_F for F(phi|m).
#include <quadmath.h>

namespace pendulum::test {

using Quad = __float128;

/// AGM(a, b) by the plain iteration, to quad precision.
inline Quad agm_quad(Quad a, Quad b) {
  while (fabsq(a - b) > 1e-33Q * a) {
    const Quad next = (a + b) / 2;
    b = sqrtq(a * b);
    a = next;
  }
  return (a + b) / 2;
}

/// K(m) = pi / (2 AGM(1, sqrt(1 - m))), 0 <= m < 1.
inline Quad complete_k_quad(Quad m) { return M_PIq / (2 * agm_quad(1, sqrtq(1 - m))); }

/// DeltaT/T0 = 2K/pi - 1 from m = sin^2(theta0/2) and kc = cos(theta0/2).
/// For m < 0.1, Eq. (8) summed until a term is below 1e-40 of the sum
/// (convergence ratio < 0.1); otherwise 1/AGM(1, kc) - 1, which loses at most
/// 2 of its 34 digits to the subtraction.
inline Quad delta_ratio_quad_of(Quad m, Quad kc) {
  if (m >= 0.1Q) return 1 / agm_quad(1, kc) - 1;
  Quad sum = 0, coefficient = 1, power = 1;
  for (int n = 1;; ++n) {
    coefficient *= Quad(2 * n - 1) / (2 * n);
    power *= m;
    const Quad term = coefficient * coefficient * power;
    sum += term;
    if (term <= 1e-40Q * sum) return sum;
  }
}

/// DeltaT/T0 at the half amplitude (rad) or, above 45 deg, from the half
/// deficit (rad), each given in quad.
inline Quad delta_ratio_quad_half(Quad half, Quad half_deficit, bool from_deficit) {
  if (!from_deficit) return delta_ratio_quad_of(sinq(half) * sinq(half), cosq(half));
  return delta_ratio_quad_of(cosq(half_deficit) * cosq(half_deficit), sinq(half_deficit));
}

/// DeltaT/T0 at the amplitude theta0_deg (deg), taken exactly as the double
/// it is. m and kc come from theta0 up to 90 deg and from the deficit
/// 180 - theta0 (exact in quad) above.
inline Quad delta_ratio_quad(double theta0_deg) {
  const Quad deg = theta0_deg;
  return delta_ratio_quad_half(deg * M_PIq / 360, (180 - deg) * M_PIq / 360, theta0_deg > 90.0);
}

/// DeltaT/T0 at the amplitude theta0 (rad), taken exactly as the double it
/// is: above pi/2 from the deficit to quad pi (1e-34 absolute).
inline Quad delta_ratio_quad_rad(double theta0) {
  const Quad rad = theta0;
  return delta_ratio_quad_half(rad / 2, (M_PIq - rad) / 2, rad > M_PIq / 2);
}

/// Carlson's R_F(x, y, z) by duplication; stops when the arguments agree to
/// 1e-7, where the fifth-order closing series errs by 1e-40.
inline Quad carlson_rf_quad(Quad x, Quad y, Quad z) {
  for (;;) {
    const Quad mu = (x + y + z) / 3;
    const Quad dx = 1 - x / mu, dy = 1 - y / mu, dz = 1 - z / mu;
    if (fmaxq(fabsq(dx), fmaxq(fabsq(dy), fabsq(dz))) < 1e-7Q) {
      const Quad e2 = dx * dy - dz * dz, e3 = dx * dy * dz;
      return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / sqrtq(mu);
    }
    const Quad sx = sqrtq(x), sy = sqrtq(y), sz = sqrtq(z);
    const Quad lambda = sx * sy + sy * sz + sz * sx;
    x = (x + lambda) / 4;
    y = (y + lambda) / 4;
    z = (z + lambda) / 4;
  }
}

/// F(phi | alpha) = integral_0^phi (1 - sin^2(alpha) sin^2(t))^{-1/2} dt
/// (Kelley's Appendix A) = sin(phi) R_F(cos^2 phi, 1 - sin^2 alpha sin^2 phi, 1),
/// angles in degrees, 0 <= phi <= 90, 0 <= alpha <= 90 (phi < 90 at alpha = 90).
inline Quad incomplete_f_quad(Quad phi_deg, Quad alpha_deg) {
  const Quad s = sinq(phi_deg * M_PIq / 180), c = cosq(phi_deg * M_PIq / 180);
  const Quad k = sinq(alpha_deg * M_PIq / 180);
  return s * carlson_rf_quad(c * c, 1 - k * k * s * s, 1);
}

}  // namespace pendulum::test
