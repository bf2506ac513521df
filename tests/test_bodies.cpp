// Bodies from parts (bodies.hpp) against Kelley (1993) Sec. V c, Eqs. (45)-(64)
// and Fig. 9, and against Nelson & Olsson's (1986) first-order mass rows
// (mass.hpp) on their own apparatus.
#include <catch2/catch.hpp>
#include <ceres/jet.h>

#include <cmath>
#include <vector>

#include "pendulum/bodies.hpp"
#include "pendulum/mass.hpp"
#include "reference.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kDay = 86400.0;  // s

/// A point bob of mass M at x = l on a thin rod of mass m from the pivot (x = 0).
std::vector<Part<double>> rod_and_bob(double m, double M, double l) {
  return {make_part(thin_rod(l), m, 0.5 * l), make_part(point_mass_shape<double>(), M, l)};
}

/// l_t = I/(M h) about a pivot at x = 0 (Kelley Eq. 55).
template <class T>
T true_length_from_top(const std::vector<Part<T>>& parts) {
  const BodyProperties<T> b = body_properties(parts);
  return equivalent_length(b.radius_of_gyration, b.center);
}

}  // namespace

TEST_CASE("Fig. 9: each shape's moment of inertia and volume", "[bodies]") {
  const double r = 0.03, b = 0.02, L = 0.5;
  // Each limit of the general shapes is one of Fig. 9's rows.
  CHECK_THAT(spherical_shell(r, 0.0).gyration_squared, WithinRel(solid_sphere(r).gyration_squared, 1e-15));
  CHECK_THAT(spherical_shell(r, r).gyration_squared, WithinRel(2.0 / 3.0 * r * r, 1e-15));  // thin shell
  CHECK(spherical_shell(r, r).volume == 0.0);
  // (2/5)(a^5 - b^5)/(a^3 - b^3) directly, where it has no cancellation.
  CHECK_THAT(spherical_shell(r, b).gyration_squared,
             WithinRel(0.4 * (std::pow(r, 5) - std::pow(b, 5)) / (std::pow(r, 3) - std::pow(b, 3)), 1e-14));
  CHECK_THAT(spherical_shell(r, b).volume, WithinRel(solid_sphere(r).volume - solid_sphere(b).volume, 1e-14));
  // Hoop (b = a) about its axis: I = M R^2; about a diameter: M R^2/2.
  CHECK_THAT(cylinder(r, r, 0.0, CylinderAxis::swing_axis).gyration_squared, WithinRel(r * r, 1e-15));
  CHECK_THAT(cylinder(r, r, 0.0, CylinderAxis::swing_direction).gyration_squared, WithinRel(r * r / 2, 1e-15));
  // Solid cylinder about its axis M R^2/2, about a central diameter M R^2/4 + M L^2/12.
  CHECK_THAT(cylinder(r, 0.0, L, CylinderAxis::swing_axis).gyration_squared, WithinRel(r * r / 2, 1e-15));
  CHECK_THAT(cylinder(r, 0.0, L, CylinderAxis::body_axis).gyration_squared,
             WithinRel(r * r / 4 + L * L / 12, 1e-15));
  CHECK(cylinder(r, 0.0, L, CylinderAxis::body_axis).half_length == L / 2);
  CHECK(cylinder(r, 0.0, L, CylinderAxis::swing_direction).half_length == r);
  // A thin rod is the cylinder of radius 0 across its axis.
  CHECK_THAT(thin_rod(L).gyration_squared,
             WithinRel(cylinder(0.0, 0.0, L, CylinderAxis::body_axis).gyration_squared, 1e-15));
  // Nelson & Olsson's ring (an annulus edge on) about the pivot, mass.hpp.
  const double mr = 0.065, ri = 0.0175, ro = 0.024, dr = 0.0065;
  const BodyProperties<double> ring_body =
      body_properties(std::vector<Part<double>>{make_part(cylinder(ro, ri, 0.0, CylinderAxis::swing_direction), mr, dr)});
  CHECK_THAT(inertia_about_pivot(ring_body, dr), WithinRel(ring_moment_of_inertia(mr, dr, ri, ro), 1e-15));
  // A square box is the plate's perpendicular axis: (a^2 + b^2)/12.
  CHECK_THAT(box(1.0, 0.028, 0.006).gyration_squared, WithinRel((1.0 + 0.028 * 0.028) / 12, 1e-15));
}

TEST_CASE("Holes: negative mass restores the body without them", "[bodies]") {
  // A uniform bar with a hole at x, and the same hole filled back in: the
  // body of the bar alone, to rounding.
  const double rho = 700.0;  // kg/m^3, wood
  const Shape<double> bar = box(1.0, 0.028, 0.006);
  const Shape<double> hole = cylinder(0.003, 0.0, 0.006, CylinderAxis::swing_axis);
  const double hole_mass = rho * hole.volume;
  const std::vector<Part<double>> with_hole{make_part(bar, rho * bar.volume, 0.5),
                                            make_part(hole, -hole_mass, 0.05)};
  std::vector<Part<double>> filled = with_hole;
  filled.push_back(make_part(hole, hole_mass, 0.05));
  const auto b = body_properties(filled);
  CHECK_THAT(b.center, WithinAbs(0.5, 1e-15));
  CHECK_THAT(b.radius_of_gyration, WithinRel(std::sqrt(bar.gyration_squared), 1e-14));
  // The hole moves the centre away from it: x_c = (M/2 - m_h x_h)/(M - m_h).
  const double M = rho * bar.volume;
  CHECK_THAT(body_properties(with_hole).center, WithinRel((M * 0.5 - hole_mass * 0.05) / (M - hole_mass), 1e-14));
}

TEST_CASE("Kelley Eqs. (45)-(52): a rod and a bob", "[bodies][kelley]") {
  const double l = 1.0, M = 5.0;
  // "a steel pendulum rod of 4 mm diameter and 1 m length with a mass of
  // about 100 gm (the density of steel is about 7.8 gm/cc)": 98 g.
  const double m = 7800.0 * cylinder(0.002, 0.0, l, CylinderAxis::body_axis).volume;
  CHECK_THAT(m, WithinAbs(0.100, 0.005));
  for (const double rod : {m, 0.1, 1.0, 5.0}) {
    const auto parts = rod_and_bob(rod, M, l);
    const auto b = body_properties(parts);
    CHECK_THAT(b.center, WithinRel(l * (M + rod / 2) / (M + rod), 1e-15));                       // Eq. (46)
    CHECK_THAT(inertia_about_pivot(b, b.center), WithinRel(M * l * l + rod * l * l / 3, 1e-14));  // Eq. (45)
    CHECK_THAT(true_length_from_top(parts), WithinRel(l * (M + rod / 3) / (M + rod / 2), 1e-14)); // Eq. (48)
  }
  // Eq. (49) at A = 20 deg against 4 sqrt(l/g) K(sin^2(A/2)) [(1 + m/3M)/(1 + m/2M)]^(1/2),
  // K from std::comp_ellint_1 (which takes the modulus k = sin(A/2)).
  const double g = 9.80665, A = 20.0 * test::kDegree;
  const auto b = body_properties(rod_and_bob(0.1, M, l));
  const double eq49 =
      4.0 * std::sqrt(l / g) * std::comp_ellint_1(std::sin(A / 2)) * std::sqrt((1 + 0.1 / (3 * M)) / (1 + 0.1 / (2 * M)));
  CHECK_THAT(physical_pendulum_period(g, b.radius_of_gyration, b.center, A), WithinRel(eq49, 1e-14));
  // "the fractional error ... is about 2e-3, representing a gain of about
  // 2 1/3 minutes per day" (one digit; a third of a minute).
  const double fraction = 1.0 - std::sqrt(true_length_from_top(rod_and_bob(0.1, M, l)) / l);
  CHECK_THAT(fraction, WithinAbs(2e-3, 0.5e-3));
  CHECK_THAT(fraction * kDay / 60.0, WithinAbs(7.0 / 3.0, 1.0 / 6.0));
  // Eq. (52): l (1 - m/6M), to second order in m/M.
  const double mu = 0.1 / M;
  CHECK_THAT(true_length_from_top(rod_and_bob(0.1, M, l)), WithinAbs(l * (1 - mu / 6), mu * mu * l));
}

TEST_CASE("Kelley Eqs. (57)-(61): a 5 kg steel bob on a 1 m rod", "[bodies][kelley]") {
  // "A 5-kg steel pendulum bob (of density 7.8 gm/cc) ... a period of about
  // 5.7e-4 [of itself] longer ... a loss of 49 seconds [a day]"; osmium
  // (22.5 gm/cc): 24 seconds. The radius of 5 kg of steel is 5.35 cm, not the
  // printed 4.67 cm, and 5.7e-4 is the fraction, not seconds (docs/deviations.md).
  const double l = 1.0;
  auto loss_per_day = [&](double density) {
    const double radius = std::cbrt(3.0 * 5.0 / (4.0 * kPi * density));
    const std::vector<Part<double>> bob{make_part(solid_sphere(radius), 5.0, l)};
    const auto b = body_properties(bob);
    const double ratio = std::sqrt(equivalent_length(b.radius_of_gyration, b.center) / l);  // Eq. (60)
    CHECK_THAT(ratio, WithinRel(std::sqrt(1 + 0.4 * radius * radius / (l * l)), 1e-15));
    CHECK_THAT(ratio - 1, WithinRel(bob_radius(radius, l), 0.4 * radius * radius));      // Eq. (61), Eq. (10)
    return (ratio - 1) * kDay;
  };
  const double steel = loss_per_day(7800.0);
  CHECK_THAT(steel / kDay, WithinAbs(5.7e-4, 0.05e-4));
  CHECK_THAT(steel, WithinAbs(49.0, 0.5));
  CHECK_THAT(loss_per_day(22500.0), WithinAbs(24.0, 0.5));
  CHECK_THAT(std::cbrt(3.0 * 5.0 / (4.0 * kPi * 7800.0)), WithinAbs(0.0535, 0.00005));
  // The printed radius would make 3.33 kg of steel, and lose 37.7 s a day.
  CHECK_THAT(7800.0 * solid_sphere(0.0467).volume, WithinAbs(3.33, 0.005));
}

TEST_CASE("Kelley Eqs. (62)-(64): the mercury pendulum", "[bodies][kelley]") {
  // A thin steel rod of mass m and length l with a mercury column (radius R,
  // height h) standing on its end, the vial neglected as in the text.
  const double l = 0.9936, m = 0.1, R = 0.025, h = 0.18;
  const double M = 13546.0 * cylinder(R, 0.0, h, CylinderAxis::body_axis).volume;
  const std::vector<Part<double>> parts{make_part(thin_rod(l), m, l / 2),
                                        make_part(cylinder(R, 0.0, h, CylinderAxis::body_axis), M, l - h / 2)};
  const auto b = body_properties(parts);
  const double eq62 = m * l * l / 3 + M * R * R / 4 + M * h * h / 12 + M * (l - h / 2) * (l - h / 2);
  CHECK_THAT(inertia_about_pivot(b, b.center), WithinRel(eq62, 1e-14));                  // Eq. (62)
  CHECK_THAT(b.center, WithinRel((m * l / 2 + M * (l - h / 2)) / (m + M), 1e-15));       // Eq. (63)
  // Eq. (64) is the true length I/((m + M) l_c), printed as "l_c".
  const double eq64 =
      l - h / 2 + (h * h / 6 + R * R / 2 + m * l * (h / 2 - l / 3) / M) / (l * (2 + m / M) - h);
  CHECK_THAT(equivalent_length(b.radius_of_gyration, b.center), WithinRel(eq64, 1e-14));
}

TEST_CASE("Kelley Eq. (41)-(42): temperature", "[bodies][kelley]") {
  // "a temperature increase of 10 degrees Centigrade produces an increase in
  // length of one tenth of a millimeter per meter" (w ~ 1e-5 /degC).
  CHECK_THAT(thermal_length(1.0, 1e-5, 10.0) - 1.0, WithinAbs(1e-4, 1e-15));
  // Steel (1.1e-5) warmed 1 degC: dT/T = w/2 (Eq. 40) "about 5e-6, or a gain
  // [loss] of about three seconds per week".
  const double rate = std::sqrt(thermal_length(1.0, 1.1e-5, 1.0)) - 1.0;
  CHECK_THAT(rate, WithinAbs(5e-6, 0.5e-6));
  CHECK_THAT(rate * 7 * kDay, WithinAbs(3.0, 0.5));

  // Eq. (42) compensates the centre of mass: a massless steel rod of length
  // l_s and a mercury column of height h_m = 2 l_s w_s / w_m (its bottom on
  // the rod's end, rising at w_m) keep x_c = l_s - h_m/2 fixed. Derivative by
  // a dual number in the temperature, through the body's centre.
  using Dual = ceres::Jet<double, 1>;
  const double ls = 0.9936, ws = 1.1e-5, wm = 6e-5, hm = 2 * ls * ws / wm;
  const Dual C(20.0, 0);
  const Dual l = thermal_length(Dual(ls), Dual(ws), C), h = thermal_length(Dual(hm), Dual(wm), C);
  const std::vector<Part<Dual>> column{
      make_part(cylinder(Dual(0.0), Dual(0.0), h, CylinderAxis::body_axis), Dual(1.0), l - h / 2.0)};
  CHECK(std::abs(body_properties(column).center.v[0]) < 1e-18);
  // For the seconds pendulum Eq. (42) gives 0.364 m = 14.3 in; the text's
  // "about 7.2 inches" is half of it (docs/deviations.md).
  CHECK_THAT(hm / 0.0254, WithinAbs(14.3, 0.05));
  // The period's length l_t (Eq. 64), not x_c, is what must stay fixed. For
  // the slender column l_t = x_c + (h^2/12)/x_c, so at Eq. (42)'s height
  // l_t still drifts by d l_t/dC = h h_m w_m/(6 x_c) (h, x_c at C): 1.6e-6 m/degC,
  // 15% of the bare rod's l_s w_s.
  const BodyProperties<Dual> bc = body_properties(column);
  const Dual lt = equivalent_length(bc.radius_of_gyration, bc.center);
  CHECK_THAT(lt.v[0], WithinRel(h.a * hm * wm / (6 * bc.center.a), 1e-12));
}

TEST_CASE("Nelson & Olsson's mass rows are the rigid body to second order", "[bodies][nelson_olsson]") {
  // Their apparatus as a rigid body, pivot at x = 0: bob, ring (an annulus
  // edge on, Sec. III.B.2), cap and screw (point masses above the bob's
  // centre), wire (a thin rod from the pivot to the bob's centre, the span
  // of Eq. 13). Not rigid-body effects, and not here: the double pendulum,
  // the wire's flexibility and the bob's rotation (Sec. III.B.3).
  // With every mass ratio and every length ratio scaled by s, the rows are
  // exact to first order, and the rest is second order:
  //   sqrt(l_t/l) - 1 - (sum of the rows) = c2 s^2 + O(s^3), with
  //   c2 = (11/288) mu^2 + mu D/12,
  // mu = m_w/m and D = (m_c + m_s)/m, from expanding
  // sqrt((1 + mu/3 + D)/(1 + mu/2 + D)) (Kelley Eq. 49 with the cap and the
  // screw added to the bob). 11/288 = 55/1440 is the rigid rod's second-order
  // term that Nelson & Olsson quote.
  using Real = long double;  // s^2 c2 is 1e-13 at s = 1e-3: 1e-6 of it in long double
  const Real l = 3.0044L, m = 0.8567L;
  auto residual = [&](Real s) {
    const Real a = 0.0305L * s, mr = 0.065L * s, ri = 0.0175L * s, ro = 0.024L * s, dr = 0.0065L * s;
    const Real mc = 4.4e-3L * s, dc = 0.039L * s, ms = -6.1e-3L * s, ds = 0.023L * s, mw = 1.367e-3L * s;
    const std::vector<Part<Real>> parts{
        make_part(solid_sphere(a), m, l),
        make_part(cylinder(ro, ri, Real(0), CylinderAxis::swing_direction), mr, dr),
        make_part(point_mass_shape<Real>(), mc, l - dc),
        make_part(point_mass_shape<Real>(), ms, l - ds),
        make_part(thin_rod(l), mw, l / 2),
    };
    const Real exact = std::sqrt(true_length_from_top(parts) / l) - 1;
    const Real rows = bob_radius(a, l) + ring(mr, ring_moment_of_inertia(mr, dr, ri, ro), dr, m, l) +
                      point_mass_on_bob(mc, dc, m, l) + point_mass_on_bob(ms, ds, m, l) + wire_mass(mw, m);
    return exact - rows;
  };
  const Real mu = 1.367e-3L / m, D = (4.4e-3L - 6.1e-3L) / m;
  const Real c2 = 11.0L / 288 * mu * mu + mu * D / 12;  // -1.666e-7
  // The third-order tail is 1% of c2 at s = 0.01, 0.1% at s = 1e-3.
  CHECK_THAT(double(residual(1e-3L) / 1e-6L), WithinRel(double(c2), 2e-3));
  CHECK_THAT(double(residual(1e-2L) / 1e-4L), WithinRel(double(c2), 2e-2));
  // At the apparatus itself (s = 1) second- and third-order terms of 1e-7
  // nearly cancel: the rows are exact to -2.1e-9 of T0, -0.0073 us, below
  // Table II's last digit (0.01 us).
  CHECK(std::abs(double(residual(1.0L)) * test::kIdealPeriod) < 0.01e-6);
  // The wire alone: the rigid rod's (55/1440)(m_w/m)^2 (Sec. III.B.3), third order left.
  const Real mw = 1.367e-3L;
  const std::vector<Part<Real>> wire_and_bob{make_part(point_mass_shape<Real>(), m, l),
                                             make_part(thin_rod(l), mw, l / 2)};
  const Real wire_residual = std::sqrt(true_length_from_top(wire_and_bob) / l) - 1 - wire_mass(mw, m);
  CHECK_THAT(double(wire_residual), WithinRel(double(55.0L / 1440 * mu * mu), 3 * double(mu)));
}
