#pragma once
/// \file mass.hpp
/// \brief Mass-distribution corrections: bob, ring, cap, cap screw, wire.
///
/// Each function returns DeltaT/T0 (dimensionless), the relative change of
/// the period caused by one departure from a point bob on a massless cord.
/// They follow from the physical-pendulum period T = 2 pi sqrt(I / (M g h))
/// (Nelson & Olsson 1986, Eq. 9) to first order in the small ratio, unless
/// stated. Lengths in m, masses in kg, moments of inertia in kg m^2; any
/// consistent units give the same ratio.

#include <array>
#include <cmath>

namespace pendulum {

/// Uniform spherical bob of radius a: DeltaT/T0 = (1/5) (a/l)^2.
/// \param a bob radius (m), 0 <= a < l.
/// \param l pivot to bob centre (m), > 0.
/// Reference: Nelson & Olsson (1986) Eq. (10).
template <class T>
T bob_radius(const T& a, const T& l) {
  const T r = a / l;
  return r * r / 5.0;
}

/// Rotation of the bob about its point of contact with a flexible wire:
/// Eq. (10) multiplied by 1 + (2/5)(a/l), so the extra term is
/// DeltaT/T0 = (2/25) (a/l)^3.
/// \param a bob radius (m), 0 <= a < l.
/// \param l pivot to bob centre (m), > 0.
/// Reference: Nelson & Olsson (1986) Sec. III.B.3 (after Eq. 13), Ref. 14.
template <class T>
T bob_rotation(const T& a, const T& l) {
  const T r = a / l;
  return 2.0 / 25.0 * r * r * r;
}

/// A bob of any shape clamped to a rigid, massless rod: the physical
/// pendulum T = 2 pi sqrt((l^2 + k^2)/(g l)) (Nelson & Olsson Eq. 9), so
/// DeltaT/T0 = sqrt(1 + k^2/l^2) - 1, exactly (T0 = 2 pi sqrt(l/g)).
/// \param k2 the bob's k^2 about its centre (m^2), >= 0 (Bob::gyration_squared).
/// \param l pivot to the bob's centre (m), > 0.
/// Its first order is Eq. (10): (1/2) k^2/l^2 = (1/5)(a/l)^2 for a sphere.
template <class T>
T rigid_bob(const T& k2, const T& l) {
  using std::sqrt;
  const T u = k2 / (l * l);
  return u / (sqrt(1.0 + u) + 1.0);  // sqrt(1 + u) - 1 without cancellation
}

/// A bob of any shape on a flexible, massless string from the pivot to its
/// knot, the bob's centre d below the knot: the slow mode of the double
/// pendulum, exact for small oscillations (docs/phone.md). With s = l - d the
/// string's length, the string's angle phi and the bob's psi obey
///   M [[s^2, s d], [s d, d^2 + k^2]] (phi, psi)'' = -M g [[s, 0], [0, d]] (phi, psi),
/// whose eigenvalues lambda = omega^2/g solve s k^2 lambda^2 - (d l + k^2) lambda + d = 0;
/// the slow mode's, lambda = 2d/(B + R) with B = d l + k^2 and
/// R = sqrt(B^2 - 4 s d k^2), gives T/T0 = 1/sqrt(lambda l) = sqrt(1 + u), where
///   u = k^2 N / (2 d l (R + d l)),  N = 4 d^2 + k^2 + k^2 (k^2 + 4 d^2 - 2 d l)/(R + d l)
/// is 1/(lambda l) - 1 rearranged so that no step cancels. DeltaT/T0 = sqrt(1 + u) - 1.
/// In a/l for a sphere (k^2 = (2/5) a^2, d = a) it is
///   (1/5)(a/l)^2 + (2/25)(a/l)^3 - (17/250)(a/l)^4 + ...,
/// Eq. (10) times 1 + (2/5)(a/l): Nelson & Olsson's rows bob_radius and bob_rotation.
/// \param k2 the bob's k^2 about its centre (m^2), >= 0.
/// \param d knot to the bob's centre (m), > 0.
/// \param l pivot to the bob's centre (m), > d.
/// Reference: Nelson & Olsson (1986) Sec. III.B.3, Ref. 14; the eigenproblem of any
/// double pendulum (Landau & Lifshitz, Mechanics, Sec. 23).
template <class T>
T slow_mode(const T& k2, const T& d, const T& l) {
  using std::sqrt;
  const T dl = d * l, b = dl + k2, s = l - d;
  const T r = sqrt(b * b - 4.0 * s * d * k2);
  const T n = 4.0 * d * d + k2 + k2 * (k2 + 4.0 * d * d - 2.0 * dl) / (r + dl);
  const T u = k2 * n / (2.0 * dl * (r + dl));
  return u / (sqrt(1.0 + u) + 1.0);
}

/// The slow mode's angle of the line from the pivot to the bob's centre over
/// the bob's own angle (what a phone's gyroscope turns with): from the
/// eigenvector, phi/psi = lambda d/(1 - lambda s), so
///   theta/psi = (s phi + d psi)/(l psi) = d/(l (1 - lambda s)),
/// with lambda l = 1/(1 + u) (slow_mode). 1 for a point bob; below 1 for a
/// body, which turns more than the line to its centre. Same arguments.
template <class T>
T slow_mode_line_over_body(const T& k2, const T& d, const T& l) {
  const T r = slow_mode(k2, d, l);  // sqrt(1 + u) - 1
  const T lambda_l = 1.0 / ((1.0 + r) * (1.0 + r));
  return d / (l - lambda_l * (l - d));
}

/// The slow mode's period at finite amplitude as a series in the body's
/// amplitude psi0 (rad): T/T_slow = 1 + kappa2 psi0^2 + kappa4 psi0^4 +
/// O(psi0^6), for the body of slow_mode on a massless, taut string. From the
/// averaged Lagrangian of the nonlinear normal mode with its first and third
/// harmonics, (phi, psi) = A v cos tau + A^3 [(u, 0) cos tau + w cos 3 tau],
/// v = (a, 1), a = phi/psi = lambda d/(1 - lambda s), s = l - d, per unit
/// mass and g with Om = omega^2/g (derivation: tests/tools/phone_nonlinear_check.py,
/// kappas()):
///   P = a^2 s^2 + 2 a s d + d^2 + k^2,  M = [[s^2, s d], [s d, d^2 + k^2]],  K = diag(s, d),
///   L4 = (s a^4 + d)/64 - lambda s d a (a - 1)^2/16,
///   f = (s a^3/48 - lambda s d (a - 1)(a - 3)/16,  d/48 - lambda s d a (a - 1)(3a - 1)/16),
///   w = -H^-1 f,  H = (9 lambda M - K)/2,
///   L6 = lambda s d a (a - 1)^4/384 - (s a^6 + d)/2304 + f.w/2,
///   Om2 = -8 L4/P,  b = s a^3/16 - lambda s d (a - 1)(3a - 1)/16,  c' = lambda s^2 - s,
///   u = -(Om2 (s^2 a + s d) + 2 b)/c',  S = Om2 (s^2 a + s d) u + (3/4) c' u^2 + 3 b u,
///   Om4 = -(8 Om2 (-s d a (a - 1)^2/16) + 12 L6 + 4 S)/P,
///   x2 = Om2/lambda,  x4 = (Om4 - 2 w_2 Om2)/lambda  (psi0 = A + A^3 w_2),
///   kappa2 = -x2/2 = (s a^4 + d - 4 lambda s d a (a - 1)^2)/(16 (s a^2 + d)),
///   kappa4 = (3/8) x2^2 - x4/2.
/// A point bob (k = 0, a = 1) gives a simple pendulum's 1/16 and 11/3072.
/// Both match fits to the nonlinear mode's periods to 3-4 digits (docs/phone.md).
/// Same arguments as slow_mode. Returns {kappa2, kappa4}.
template <class T>
std::array<T, 2> slow_mode_amplitude_series(const T& k2, const T& d, const T& l) {
  using std::sqrt;
  const T s = l - d, b0 = d * l + k2;
  const T lambda = 2.0 * d / (b0 + sqrt(b0 * b0 - 4.0 * s * d * k2));
  const T a = lambda * d / (1.0 - lambda * s), am1 = a - 1.0;
  const T sd = s * d, p = a * a * s * s + 2.0 * a * sd + d * d + k2;
  const T l4 = (s * a * a * a * a + d) / 64.0 - lambda * sd * a * am1 * am1 / 16.0;
  const T f1 = s * a * a * a / 48.0 - lambda * sd * am1 * (a - 3.0) / 16.0;
  const T f2 = d / 48.0 - lambda * sd * a * am1 * (3.0 * a - 1.0) / 16.0;
  const T h11 = (9.0 * lambda * s * s - s) / 2.0, h12 = 9.0 * lambda * sd / 2.0;
  const T h22 = (9.0 * lambda * (d * d + k2) - d) / 2.0, det = h11 * h22 - h12 * h12;
  const T w1 = -(h22 * f1 - h12 * f2) / det, w2 = -(h11 * f2 - h12 * f1) / det;
  const T l6 = lambda * sd * a * am1 * am1 * am1 * am1 / 384.0 -
               (s * a * a * a * a * a * a + d) / 2304.0 + (f1 * w1 + f2 * w2) / 2.0;
  const T om2 = -8.0 * l4 / p, p1 = s * s * a + sd;
  const T b = s * a * a * a / 16.0 - lambda * sd * am1 * (3.0 * a - 1.0) / 16.0, cp = lambda * s * s - s;
  const T u = -(om2 * p1 + 2.0 * b) / cp;
  const T shape = om2 * p1 * u + 0.75 * cp * u * u + 3.0 * b * u;
  const T om4 = -(8.0 * om2 * (-sd * a * am1 * am1 / 16.0) + 12.0 * l6 + 4.0 * shape) / p;
  const T x2 = om2 / lambda, x4 = (om4 - 2.0 * w2 * om2) / lambda;
  return {-x2 / 2.0, 3.0 * x2 * x2 / 8.0 - x4 / 2.0};
}

/// Moment of inertia of the suspension ring about the pivot, the ring being
/// a flat annulus whose plane contains the swing axis:
/// I_r = m_r [d_r^2 + (r_i^2 + r_o^2)/4].
/// \param m_r ring mass (kg); \param d_r pivot to ring centre (m);
/// \param r_i, r_o inner and outer radius (m).
/// \return I_r (kg m^2). Reference: Nelson & Olsson (1986) text after Eq. (11).
template <class T>
T ring_moment_of_inertia(const T& m_r, const T& d_r, const T& r_i,
                         const T& r_o) {
  return m_r * (d_r * d_r + (r_i * r_i + r_o * r_o) / 4.0);
}

/// Suspension ring of mass m_r whose centre hangs d_r below the pivot:
/// DeltaT/T0 = -(1/2)(m_r/m)(d_r/l) + (1/2) I_r/(m l^2).
/// \param m_r ring mass (kg); \param i_r ring moment of inertia about the
/// pivot (kg m^2); \param d_r pivot to ring centre (m);
/// \param m bob mass (kg); \param l pivot to bob centre (m).
/// Validity: m_r << m, d_r << l. Reference: Nelson & Olsson (1986) Eq. (11).
template <class T>
T ring(const T& m_r, const T& i_r, const T& d_r, const T& m, const T& l) {
  return -0.5 * (m_r / m) * (d_r / l) + 0.5 * i_r / (m * l * l);
}

/// Double-pendulum term of the ring and bob:
/// DeltaT/T0 = (1/2)(m_r/m)^2 d_r^2 / (l_1 l), with l_1 = d_r + r_o the pivot
/// to the ring's lower edge.
/// \param m_r ring mass (kg); \param d_r pivot to ring centre (m);
/// \param r_o ring outer radius (m); \param m bob mass (kg);
/// \param l pivot to bob centre (m).
/// Reference: Nelson & Olsson (1986) Eq. (15), third term. The transcription
/// prints the denominator as l l; the paper's +4.6 us needs l_1 l
/// (docs/deviations.md).
template <class T>
T double_pendulum(const T& m_r, const T& d_r, const T& r_o, const T& m,
                  const T& l) {
  const T mass_ratio = m_r / m;
  return 0.5 * mass_ratio * mass_ratio * d_r * d_r / ((d_r + r_o) * l);
}

/// A small mass m_x fixed to the bob at distance d_x above its centre (toward
/// the pivot): DeltaT/T0 = -(1/2)(m_x/m)(d_x/l). Serves the cap (Eq. 12) and
/// the cap screw, whose "mass" is the (negative) deficit of a light screw in
/// a dense bob.
/// \param m_x added mass (kg), may be negative for a deficit;
/// \param d_x its distance above the bob centre (m); \param m bob mass (kg);
/// \param l pivot to bob centre (m).
/// Reference: Nelson & Olsson (1986) Eq. (12) and the text after it.
template <class T>
T point_mass_on_bob(const T& m_x, const T& d_x, const T& m, const T& l) {
  return -0.5 * (m_x / m) * (d_x / l);
}

/// Mass of a uniform wire, first order: DeltaT/T0 = -(1/12)(m_w/m).
/// \param m_w wire mass (kg); \param m bob mass (kg).
/// Reference: Nelson & Olsson (1986) Eq. (13).
template <class T>
T wire_mass(const T& m_w, const T& m) {
  return -(m_w / m) / 12.0;
}

/// Flexibility of the wire: the second-order mass term of a flexible wire,
/// (71/1440)(m_w/m)^2, minus that of a rigid rod, (55/1440)(m_w/m)^2:
/// DeltaT/T0 = (16/1440)(m_w/m)^2.
/// \param m_w wire mass (kg); \param m bob mass (kg).
/// Reference: Nelson & Olsson (1986) Sec. III.B.3 (after Eq. 13). The
/// transcription drops the square on the flexible term; the paper's +0.44 us
/// needs it (docs/deviations.md).
template <class T>
T wire_flexibility(const T& m_w, const T& m) {
  const T r = m_w / m;
  return (71.0 - 55.0) / 1440.0 * r * r;
}

}  // namespace pendulum
