// Finite-amplitude correction: the exact method against quad precision and
// the seeds' tables (Kelley 1993 Appendices A and B, Feinstein 2005 Table 1),
// the hard cases, the error bounds of every method, the trajectory, and the
// Eq. (8) series and theta0^2/16.
#include <catch2/catch.hpp>
#include <ceres/jet.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pendulum/amplitude.hpp"
#include "quad_reference.hpp"
#include "reference.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using test::Quad;

namespace {

// A printed table entry ("1.57079 63267 94897") as a quad number, so that
// comparing it costs no rounding.
Quad printed_quad(const std::string& text) {
  std::string digits;
  for (char ch : text) {
    if (ch != ' ') digits += ch;
  }
  return strtoflt128(digits.c_str(), nullptr);
}

double printed(const std::string& text) { return static_cast<double>(printed_quad(text)); }

// Digits after the decimal point of a printed entry.
int decimals(const std::string& text) {
  return static_cast<int>(text.size() - text.find('.') - 1) -
         static_cast<int>(std::count(text.begin() + static_cast<long>(text.find('.')), text.end(), ' '));
}

double relative_error(double value, Quad reference) {
  return static_cast<double>(fabsq((Quad(value) - reference) / reference));
}

// The amplitudes (deg) of the accuracy sweep: 10^4 evenly spaced over
// (0, 180), 100 a decade from 1e-8 to 1 deg and deficits from 1 to 1e-7 deg,
// and the hard cases.
std::vector<double> sweep_amplitudes() {
  std::vector<double> deg;
  for (int i = 0; i < 10000; ++i) deg.push_back(180.0 * (i + 0.5) / 10000.0);
  for (int i = 0; i <= 800; ++i) deg.push_back(std::pow(10.0, -8.0 + i / 100.0));
  for (int i = 0; i <= 700; ++i) deg.push_back(180.0 - std::pow(10.0, -7.0 + i / 100.0));
  for (double d : {1e-8, 1e-4, 0.18, 179.99999, 179.999999, 179.9999999}) deg.push_back(d);
  for (double d = 134.0; d <= 143.0; d += 0.25) deg.push_back(d);  // m in [0.85, 0.9)
  return deg;
}

}  // namespace

TEST_CASE("The exact method is within 1e-15 of quad precision from 1e-8 to 179.9999999 deg",
          "[amplitude][quad]") {
  double worst = 0.0, worst_at = 0.0;
  for (double deg : sweep_amplitudes()) {
    const double e = relative_error(finite_amplitude_agm_deg(deg), test::delta_ratio_quad(deg));
    if (e > worst) {
      worst = e;
      worst_at = deg;
    }
  }
  INFO("worst relative error " << worst << " at " << worst_at << " deg");
  CHECK(worst <= kExactRelativeErrorBound);
}

TEST_CASE("The radian entry agrees with the degree entry", "[amplitude]") {
  // theta0 (rad) = deg * pi/180 is rounded by up to 1 ulp, which moves
  // DeltaT/T0 by up to 2 ulp (r ~ theta0^2 at small amplitude, flatter
  // above); each entry is within 1e-15 of its own input: 3e-15 in all.
  for (double deg : {1e-6, 0.5, 3.0, 45.0, 89.0, 91.0, 120.0, 159.0, 161.0, 170.0}) {
    INFO(deg << " deg");
    CHECK_THAT(finite_amplitude_agm(deg * test::kDegree),
               WithinRel(finite_amplitude_agm_deg(deg), 3e-15));
  }
}

TEST_CASE("The radian entry is exact for its own amplitude up to the last double below pi",
          "[amplitude][quad]") {
  // Deficits pi - theta0 from 1.6 rad to 1.6e-15 rad and the last double
  // below pi (deficit 5.7e-16 from the true pi, 4.4e-16 from the double),
  // against quad precision from the deficit to quad pi: with the deficit
  // from the double pi alone, the result at 179.9 deg was 1.0e-14 off.
  std::vector<double> theta{std::nextafter(kPi, 0.0)};
  for (int i = 0; i <= 1500; ++i) theta.push_back(kPi - std::pow(10.0, 0.2 - i / 100.0));
  double worst = 0.0, worst_at = 0.0;
  for (double t : theta) {
    const double e = relative_error(finite_amplitude_agm(t), test::delta_ratio_quad_rad(t));
    if (e > worst) worst = e, worst_at = t;
  }
  INFO("worst relative error " << worst << " at pi - " << static_cast<double>(M_PIq - worst_at) << " rad");
  CHECK(worst <= kExactRelativeErrorBound);
}

TEST_CASE("Hard cases: tiny amplitudes, m from 0.85 to 0.9, the last 1e-5 deg before 180",
          "[amplitude][quad]") {
  // Every library route that forms k = sin(theta0/2) rounds k to exactly 1
  // above 179.9999988 deg (K infinite, NaN after); the deficit never lets k
  // appear. The largest double below 180 is 180 - 2.8e-14.
  const double top = std::nextafter(180.0, 0.0);
  for (double deg : {1e-8, 1e-4, 0.18, 134.0, 138.5, 143.0, 179.99999, 179.999999, 179.9999999,
                     179.99999999999, top}) {
    INFO(deg << " deg");
    const double r = finite_amplitude_agm_deg(deg);
    REQUIRE(std::isfinite(r));
    CHECK(relative_error(r, test::delta_ratio_quad(deg)) <= kExactRelativeErrorBound);
  }
  // m = sin^2(theta0/2) in [0.85, 0.9) is theta0 from 134.43 to 143.13 deg
  // (the sweep has 134 to 143 deg in steps of 0.25).
  for (double m = 0.85; m < 0.9; m += 0.01) {
    const double deg = 2.0 * std::asin(std::sqrt(m)) / test::kDegree;
    INFO("m = " << m << ", " << deg << " deg");
    CHECK(relative_error(finite_amplitude_agm_deg(deg), test::delta_ratio_quad(deg)) <=
          kExactRelativeErrorBound);
  }
  CHECK(finite_amplitude_agm_deg(0.0) == 0.0);
}

TEST_CASE("No NaN anywhere: values and derivatives across the whole range", "[amplitude][jet]") {
  using Jet = ceres::Jet<double, 1>;
  double previous = -1.0;
  for (double deg = 0.0; deg < 180.0; deg += 0.5) {
    const Jet r = finite_amplitude_agm_deg(Jet(deg, 0));
    INFO(deg << " deg");
    REQUIRE(std::isfinite(r.a));
    REQUIRE(std::isfinite(r.v[0]));
    CHECK(r.a > previous);
    CHECK(r.v[0] >= 0.0);
    previous = r.a;
  }
  for (double deg : {1e-8, 179.9999999, std::nextafter(180.0, 0.0)}) {
    const Jet r = finite_amplitude_agm_deg(Jet(deg, 0));
    CHECK(std::isfinite(r.a));
    CHECK(std::isfinite(r.v[0]));
  }
}

TEST_CASE("Amplitudes of 180 deg and beyond, negative or NaN are errors", "[amplitude]") {
  for (double deg : {180.0, 181.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    INFO(deg);
    CHECK_THROWS_AS(finite_amplitude_agm_deg(deg), std::domain_error);
    CHECK_THROWS_AS(finite_amplitude_agm(deg * test::kDegree), std::domain_error);
  }
  // The range and message of the CLI and Python (ranges::amplitude): was "amplitude -0.000000 rad is outside ...".
  CHECK_THROWS_WITH(finite_amplitude_agm(-1e-300), "amplitude: got -1e-300 rad; expected an amplitude from 0 to below "
                                                   "pi rad (at 180 deg and beyond the pendulum goes over the top)");
}

TEST_CASE("Derivative through ceres::Jet matches a quad-precision central difference",
          "[amplitude][jet]") {
  // d(DeltaT/T0)/d(theta0 in deg) from a central difference of the quad
  // reference with a step of 1e-9 of the distance to 0 or 180 deg: the
  // truncation (step^2 times r'''/6) and the roundoff (1e-34/step) are both
  // below 1e-15 of the derivative. The Jet carries the rounding of every
  // step of the method: 1e-13 allows a few hundred ulp.
  for (double deg : {1e-4, 3.0, 60.0, 90.0, 120.0, 160.0, 170.0, 179.9999}) {
    const double h = 1e-9 * std::fmin(deg, 180.0 - deg);
    const Quad step = Quad(deg + h) - Quad(deg - h);
    const double numeric = static_cast<double>(
        (test::delta_ratio_quad(deg + h) - test::delta_ratio_quad(deg - h)) / step);
    const ceres::Jet<double, 1> x(deg, 0);
    INFO(deg << " deg");
    CHECK_THAT(finite_amplitude_agm_deg(x).v[0], WithinRel(numeric, 1e-13));
  }
}

TEST_CASE("Kelley (1993) Appendix B: every digit of K(m)", "[amplitude][kelley]") {
  // K(m) to 15 decimals (from Abramowitz & Stegun), compared in quad. The
  // entries are within 0.55 units of the last place of the quad value (A&S's
  // rounding leaves four entries 0.51-0.54 units away), so a tolerance of 0.6
  // units catches any wrong digit but a last digit off by one on the side of
  // that rounding. Two entries are corrected from the transcription
  // (docs/deviations.md).
  struct Row {
    double m;
    const char* k;
  };
  const Row table[] = {
      {0.00, "1.57079 63267 94897"},
      {0.01, "1.57474 55615 17356"},
      {0.02, "1.57873 99120 07773"},
      {0.03, "1.58278 03424 06373"},
      {0.04, "1.58686 78474 54166"},
      {0.05, "1.59100 34537 90792"},
      {0.06, "1.59518 82213 21610"},
      {0.07, "1.59942 32446 58510"},
      {0.08, "1.60370 96546 39253"},
      {0.09, "1.60804 86199 30513"},
      {0.10, "1.61244 13487 20219"},
      {0.11, "1.61688 90905 05203"},
      {0.12, "1.62139 31379 80658"},
      {0.13, "1.62595 48290 38433"},
      {0.14, "1.63057 55488 81754"},
      {0.15, "1.63525 67322 64580"},
      {0.16, "1.63999 98658 64511"},
      {0.17, "1.64480 64907 98881"},
      {0.18, "1.64967 82052 94514"},
      {0.19, "1.65461 66675 22527"},
      {0.20, "1.65962 35986 10528"},
      {0.21, "1.66470 07858 45692"},
      {0.22, "1.66985 00860 83368"},
      {0.23, "1.67507 34293 77219"},
      {0.24, "1.68037 28228 48361"},
      {0.25, "1.68575 03548 12596"},
      {0.26, "1.69120 81991 86631"},
      {0.27, "1.69674 86201 96168"},
      {0.28, "1.70237 39774 10990"},
      {0.29, "1.70808 67311 34606"},
      {0.30, "1.71388 94481 78791"},
      {0.31, "1.71978 48080 56405"},
      {0.32, "1.72577 56096 29320"},
      {0.33, "1.73186 47782 52098"},
      {0.34, "1.73805 53734 56358"},
      {0.35, "1.74435 05972 25613"},
      {0.36, "1.75075 38029 15753"},
      {0.37, "1.75726 85048 82456"},
      {0.38, "1.76389 83888 83731"},
      {0.39, "1.77064 73233 33534"},
      {0.40, "1.77751 93714 91253"},
      {0.41, "1.78451 88046 81873"},
      {0.42, "1.79165 01166 52966"},
      {0.43, "1.79891 80391 87685"},
      {0.44, "1.80632 75591 07699"},
      {0.45, "1.81388 39368 16983"},
      {0.46, "1.82159 27265 56821"},
      {0.47, "1.82945 97985 64730"},
      {0.48, "1.83749 13633 55796"},
      {0.49, "1.84569 39983 74724"},
      {0.50, "1.85407 46773 01372"},
      {0.99, "3.69563 73629 89875"},
      {0.98, "3.35414 14456 99160"},
      {0.97, "3.15587 49478 91841"},
      {0.96, "3.01611 24924 77648"},
      {0.95, "2.90833 72484 44552"},
      {0.94, "2.82075 24967 55872"},
      {0.93, "2.74707 30040 24667"},
      {0.92, "2.68355 14063 15229"},
      {0.91, "2.62777 33320 84344"},
      {0.90, "2.57809 21133 48173"},
      {0.89, "2.53333 45460 02200"},
      {0.88, "2.49263 53232 39716"},
      {0.87, "2.45533 80283 21380"},
      {0.86, "2.42093 29603 44303"},
      {0.85, "2.38901 64863 25580"},
      {0.84, "2.35926 35547 45007"},
      {0.83, "2.33140 85677 50251"},
      {0.82, "2.30523 17368 77189"},
      {0.81, "2.28054 91384 22770"},  // printed "9138 22770"
      {0.80, "2.25720 53268 20854"},  // printed 53258
      {0.79, "2.23506 77552 60349"},
      {0.78, "2.21402 24978 46332"},
      {0.77, "2.19397 09253 19189"},
      {0.76, "2.17482 70902 46414"},
      {0.75, "2.15651 56474 99643"},
      {0.74, "2.13897 01837 52114"},
      {0.73, "2.12213 18631 57396"},
      {0.72, "2.10594 83200 52758"},
      {0.71, "2.09037 27465 52360"},
      {0.70, "2.07536 31352 92469"},
      {0.69, "2.06088 16467 30131"},
      {0.68, "2.04689 40772 10577"},
      {0.67, "2.03336 94091 52233"},
      {0.66, "2.02027 94286 03592"},
      {0.65, "2.00759 83984 24376"},
      {0.64, "1.99530 27776 64729"},
      {0.63, "1.98337 09795 27821"},
      {0.62, "1.97178 31617 25656"},
      {0.61, "1.96052 10441 65830"},
      {0.60, "1.94956 77498 06026"},
      {0.59, "1.93890 76652 34220"},
      {0.58, "1.92852 63181 14418"},
      {0.57, "1.91841 02691 09912"},
      {0.56, "1.90854 70162 81211"},
      {0.55, "1.89892 49102 71554"},
      {0.54, "1.88953 30788 53096"},
      {0.53, "1.88036 13596 22178"},
      {0.52, "1.87140 02398 11034"},
      {0.51, "1.86264 08023 32739"},
      {0.50, "1.85407 46773 01372"},
  };
  for (const Row& row : table) {
    INFO("m = " << row.m << ", K = " << row.k);
    const Quad m = Quad(std::lround(row.m * 100)) / 100;  // the decimal m, not its double
    const double units = static_cast<double>(fabsq(printed_quad(row.k) - test::complete_k_quad(m)) *
                                             powq(10, decimals(row.k)));
    CHECK(units <= 0.6);
  }
  // The transcription's two entries are not K: m = 0.80 prints 53258 for
  // 53268 (exactly 1e-9 off), m = 0.81 drops a 4 (2e-10 off).
  const Quad k80 = test::complete_k_quad(0.8Q), k81 = test::complete_k_quad(0.81Q);
  CHECK(static_cast<double>(fabsq(printed_quad("2.25720 53258 20854") + 1e-9Q - k80)) <= 0.6e-15);
  CHECK(static_cast<double>(fabsq(printed_quad("2.28054 9138 22770") - k81)) > 1e-10);
}

TEST_CASE("Kelley (1993) Appendix B through the exact method", "[amplitude][kelley]") {
  // K = (pi/2)(1 + DeltaT/T0) at theta0 = 2 asin(sqrt(m)) in degrees: the
  // conversion moves m by a few ulp, so the check is against the quad value
  // at the converted theta0 (within the method's 1e-15 of DeltaT/T0 plus the
  // rounding of (pi/2)(1 + r)), and that value against the table within the
  // conversion's effect, 1e-14 relative (dK/dm m/K < 0.3 up to m = 0.99).
  for (double m : {0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    const double deg = 2.0 * std::asin(std::sqrt(m)) / test::kDegree;
    const double k = M_PI / 2.0 * (1.0 + finite_amplitude_agm_deg(deg));
    const Quad k_reference = M_PIq / 2 * (1 + test::delta_ratio_quad(deg));
    INFO("m = " << m);
    CHECK_THAT(k, WithinRel(static_cast<double>(k_reference), 2e-15));
    CHECK_THAT(k, WithinRel(static_cast<double>(test::complete_k_quad(Quad(m))), 1e-14));
  }
}

TEST_CASE("Kelley (1993) Appendix A: F(phi|alpha) and the trajectory", "[amplitude][kelley]") {
  // Five rows of the table, every column; 8 decimals. A&S's rounding leaves
  // entries up to 0.61 units from the quad value (alpha = 70, phi = 20 deg),
  // so 0.65 units catch a wrong digit but a last digit off by one on the
  // side of that rounding. The first entry is corrected from the
  // transcription (docs/deviations.md).
  struct Entry {
    int alpha, phi;  // deg
    const char* f;
  };
  const Entry table[] = {
      {10, 5, "0.08726 980"}, {10, 10, "0.17455 949"}, {10, 15, "0.26188 842"}, {10, 20, "0.34927 479"},
      {10, 25, "0.43673 518"}, {10, 30, "0.52428 402"}, {10, 35, "0.61193 318"}, {10, 40, "0.69969 159"},
      {10, 45, "0.78756 494"}, {10, 50, "0.87555 545"}, {10, 55, "0.96366 180"}, {10, 60, "1.05187 911"},
      {10, 65, "1.14019 906"}, {10, 70, "1.22861 010"}, {10, 75, "1.31709 778"}, {10, 80, "1.40564 522"},
      {10, 85, "1.49423 361"}, {10, 90, "1.58284 280"},
      {30, 5, "0.08729 413"}, {30, 10, "0.17475 386"}, {30, 15, "0.26254 249"}, {30, 20, "0.35081 868"},
      {30, 25, "0.43973 377"}, {30, 30, "0.52942 863"}, {30, 35, "0.62003 018"}, {30, 40, "0.71164 728"},
      {30, 45, "0.80436 610"}, {30, 50, "0.89824 524"}, {30, 55, "0.99331 059"}, {30, 60, "1.08955 067"},
      {30, 65, "1.18691 274"}, {30, 70, "1.28530 059"}, {30, 75, "1.38457 455"}, {30, 80, "1.48455 455"},
      {30, 85, "1.58502 624"}, {30, 90, "1.68575 035"},
      {50, 5, "0.08733 149"}, {50, 10, "0.17505 392"}, {50, 15, "0.26356 191"}, {50, 20, "0.35325 724"},
      {50, 25, "0.44455 151"}, {50, 30, "0.53786 765"}, {50, 35, "0.63363 947"}, {50, 40, "0.73230 789"},
      {50, 45, "0.83431 247"}, {50, 50, "0.94007 568"}, {50, 55, "1.04997 735"}, {50, 60, "1.16431 637"},
      {50, 65, "1.28325 798"}, {50, 70, "1.40676 855"}, {50, 75, "1.53454 619"}, {50, 80, "1.66596 542"},
      {50, 85, "1.80006 176"}, {50, 90, "1.93558 110"},
      {70, 5, "0.08736 442"}, {70, 10, "0.17532 010"}, {70, 15, "0.26447 634"}, {70, 20, "0.35547 959"},
      {70, 25, "0.44903 502"}, {70, 30, "0.54593 192"}, {70, 35, "0.64707 458"}, {70, 40, "0.75352 078"},
      {70, 45, "0.86652 996"}, {70, 50, "0.98762 253"}, {70, 55, "1.11864 920"}, {70, 60, "1.26185 988"},
      {70, 65, "1.41993 796"}, {70, 70, "1.59590 624"}, {70, 75, "1.79268 736"}, {70, 80, "2.01192 798"},
      {70, 85, "2.25177 995"}, {70, 90, "2.50455 008"},
      {88, 5, "0.08737 730"}, {88, 10, "0.17542 473"}, {88, 15, "0.26483 842"}, {88, 20, "0.35636 908"},
      {88, 25, "0.45085 596"}, {88, 30, "0.54927 042"}, {88, 35, "0.65277 510"}, {88, 40, "0.76280 846"},
      {88, 45, "0.88121 143"}, {88, 50, "1.01042 658"}, {88, 55, "1.15382 828"}, {88, 60, "1.31630 510"},
      {88, 65, "1.50537 033"}, {88, 70, "1.73350 464"}, {88, 75, "2.02384 126"}, {88, 80, "2.42718 003"},
      {88, 85, "3.09448 898"}, {88, 90, "4.74271 727"},
  };
  for (const Entry& e : table) {
    INFO("alpha = " << e.alpha << ", phi = " << e.phi << ", F = " << e.f);
    const Quad f = test::incomplete_f_quad(e.phi, e.alpha);
    CHECK(static_cast<double>(fabsq(printed_quad(e.f) - f)) <= 0.65e-8);
    // Kelley's Eq. (12) read backwards: at omega0 t = F(phi | theta0/2) the
    // pendulum of amplitude theta0 = 2 alpha is at sin(theta/2) =
    // sin(alpha) sin(phi). The table's F is within 0.65e-8 of the true one
    // and |d sn/du| <= 1.
    const double theta0 = 2.0 * e.alpha * test::kDegree;
    const double s_alpha = std::sin(e.alpha * test::kDegree);
    const double expected = s_alpha * std::sin(e.phi * test::kDegree);
    CHECK_THAT(std::sin(pendulum_angle(theta0, printed(e.f)) / 2.0),
               WithinAbs(expected, 0.65e-8 * s_alpha + 1e-15));
    // The quad F rounded to double (within 2.6e-16, F < 4.8) shows the
    // Landen scale's own rounding: a few ulp.
    CHECK_THAT(jacobi_sn(static_cast<double>(f), s_alpha, std::cos(e.alpha * test::kDegree)),
               WithinAbs(std::sin(e.phi * test::kDegree), 2e-15));
  }
}

TEST_CASE("The trajectory reaches theta0 after a quarter of the exact period", "[amplitude]") {
  // omega0 T/4 = (pi/2)(T/T0) = K: sn(K) = 1, so theta = theta0 there, and 0
  // at half a period. At the top the angle is flat in time, so theta0 is met
  // only to the square root of the roundoff: 1e-7 relative.
  for (double deg : {1.0, 30.0, 90.0, 150.0, 179.0}) {
    const double theta0 = deg * test::kDegree;
    const double quarter = M_PI / 2.0 * (1.0 + finite_amplitude_agm(theta0));
    INFO(deg << " deg");
    CHECK_THAT(pendulum_angle(theta0, quarter), WithinRel(theta0, 1e-7));
    CHECK_THAT(pendulum_angle(theta0, 2.0 * quarter), WithinAbs(0.0, 1e-12));
    CHECK_THAT(pendulum_angle(theta0, 3.0 * quarter), WithinRel(-theta0, 1e-7));
  }
  // Small amplitude: theta0 sin(omega0 t) (Kelley Eq. 24), to O(theta0^2).
  CHECK_THAT(pendulum_angle(1e-3, 0.7), WithinRel(1e-3 * std::sin(0.7), 1e-6));
}

TEST_CASE("Feinstein (2005) Table 1: period, circular error, its rate", "[amplitude][feinstein]") {
  // l = 99.3961 cm, g = 981 cm/s^2, nominal period 2.0000 s, 43200 cycles a
  // day. Column 3 is the nominal 2.0000 s times T/T0 (with 2 pi sqrt(l/g) =
  // 2.00000019 s six rows would round up: docs/deviations.md).
  // Circular error (s/day) = 43200 * 2 s * DeltaT/T0; its rate (s/day per
  // arc second) = 43200 * 2 s * d(DeltaT/T0)/d(theta0 in arc seconds), the
  // derivative by ceres::Jet. Tolerances: half a unit of the last printed
  // digit.
  struct Row {
    double minutes;
    double period_s;
    double circular_s_day;
    int circular_decimals;
    double rate_mantissa;
    int rate_exponent;
  };
  const Row table[] = {
      {1.0, 2.000000, 0.0005, 4, 1.5231, -5},   {15.0, 2.000002, 0.1028, 4, 2.2846, -4},
      {30.0, 2.000010, 0.4112, 4, 4.5693, -4},  {60.0, 2.000038, 1.6450, 4, 9.1388, -4},
      {120.0, 2.000152, 6.5802, 4, 1.8280, -3}, {180.0, 2.000343, 14.807, 3, 2.7424, -3},
      {240.0, 2.000609, 26.326, 3, 3.6575, -3}, {300.0, 2.000952, 41.141, 3, 4.5733, -3},
      {360.0, 2.001372, 59.255, 3, 5.4900, -3}, {420.0, 2.001867, 80.671, 3, 6.4079, -3},
      {480.0, 2.002440, 105.39, 2, 7.3272, -3}, {540.0, 2.003089, 133.43, 2, 8.2480, -3},
      {600.0, 2.003814, 164.78, 2, 9.1705, -3},
  };
  // 99.3961 cm is the length of a 2.0000 s pendulum at g = 981 cm/s^2.
  CHECK_THAT(2.0 * M_PI * std::sqrt(99.3961 / 981.0), WithinAbs(2.0, 0.5e-6));
  constexpr double kNominal = 2.0, kCycles = 43200.0;
  for (const Row& row : table) {
    INFO(row.minutes << " arc minutes");
    const ceres::Jet<double, 1> r = finite_amplitude_agm_deg(ceres::Jet<double, 1>(row.minutes / 60.0, 0));
    CHECK_THAT(kNominal * (1.0 + r.a), WithinAbs(row.period_s, 0.5e-6));
    CHECK_THAT(kCycles * kNominal * r.a,
               WithinAbs(row.circular_s_day, 0.5 * std::pow(10.0, -row.circular_decimals)));
    const double rate = kCycles * kNominal * r.v[0] / 3600.0;  // r.v[0] is per degree
    CHECK_THAT(rate / std::pow(10.0, row.rate_exponent), WithinAbs(row.rate_mantissa, 0.5e-4));
  }
}

TEST_CASE("Kelley (1993) Sec. II and IV: the numbers in the text", "[amplitude][kelley]") {
  // "within 1% of 2 pi (l/g)^{1/2} for A < 22.79 degrees": T/T0 = 1.01 is
  // crossed at 22.814 deg, so 22.79 deg is inside (docs/deviations.md).
  CHECK(finite_amplitude_agm_deg(22.79) < 0.01);
  CHECK(finite_amplitude_agm_deg(22.82) > 0.01);
  // Table after Eq. (37), to 4 decimals: exact and 1 + A^2/16.
  const struct {
    double deg, exact, eq37;
  } table[] = {{10, 1.0019, 1.0019}, {20, 1.0077, 1.0076}, {30, 1.0174, 1.0171}};
  for (const auto& row : table) {
    INFO(row.deg << " deg");
    CHECK_THAT(1.0 + finite_amplitude_agm_deg(row.deg), WithinAbs(row.exact, 0.5e-4));
    CHECK_THAT(1.0 + finite_amplitude_small_angle(row.deg * test::kDegree),
               WithinAbs(row.eq37, 0.5e-4));
  }
  // Effective length E/l = (T/T0)^2 = 1.3932 at 90 deg (Eq. 34); a 1 s
  // pendulum swung at 60 deg has T = 1.0732 s.
  CHECK_THAT(std::pow(1.0 + finite_amplitude_agm_deg(90.0), 2), WithinAbs(1.3932, 0.5e-4));
  CHECK_THAT(1.0 + finite_amplitude_agm_deg(60.0), WithinAbs(1.0732, 0.5e-4));
}

TEST_CASE("AGM at 90 deg matches the lemniscate constant", "[amplitude]") {
  // K(k = sin 45 deg) = Gamma(1/4)^2 / (4 sqrt(pi)) (Whittaker & Watson,
  // 22.8), so T/T0 = 2K/pi = Gamma(1/4)^2 / (2 pi^{3/2}); tgamma is
  // accurate to a few ulp.
  const double pi = std::acos(-1.0);
  const double expected = std::pow(std::tgamma(0.25), 2) / (2.0 * std::pow(pi, 1.5)) - 1.0;
  CHECK_THAT(finite_amplitude_agm(pi / 2.0), WithinRel(expected, 1e-14));
}

TEST_CASE("AGM agrees with std::comp_ellint_1 where no digits cancel", "[amplitude]") {
  // 2K(k)/pi - 1 from libstdc++ (k = sin(theta0/2)); above 30 deg the
  // subtraction loses under two digits.
  for (double deg : {30.0, 60.0, 90.0, 120.0, 150.0, 170.0, 179.0}) {
    const double theta0 = deg * test::kDegree;
    const double expected = 2.0 * std::comp_ellint_1(std::sin(theta0 / 2.0)) / M_PI - 1.0;
    INFO("theta0 = " << deg << " deg");
    CHECK_THAT(finite_amplitude_agm(theta0), WithinRel(expected, 1e-13));
  }
}

TEST_CASE("AGM keeps full relative accuracy at tiny amplitudes", "[amplitude]") {
  // Eq. (8) in powers of theta: theta^2/16 + 11 theta^4/3072 + 173 theta^6/737280
  // (Feinstein 2005, Appendix E, printed as 519/2211840); the next term is
  // 1.7e-5 theta^8.
  for (double theta0 : {1e-12, 1e-8, 1e-5, 1e-3}) {
    const double t2 = theta0 * theta0;
    const double expected = t2 / 16.0 + 11.0 * t2 * t2 / 3072.0 + 173.0 * t2 * t2 * t2 / 737280.0;
    INFO("theta0 = " << theta0 << " rad");
    CHECK_THAT(finite_amplitude_agm(theta0), WithinRel(expected, 1e-15));
  }
  CHECK(finite_amplitude_agm(0.0) == 0.0);
}

TEST_CASE("Finite amplitude reproduces Table II: +596 us at 3 deg", "[amplitude][table2]") {
  const double dt_us = finite_amplitude_agm(test::kAmplitude) * test::kIdealPeriod * 1e6;
  CHECK_THAT(dt_us, WithinAbs(596.0, test::table2_tolerance_us(596.0)));
  // theta^2/16 is what the paper used: the two differ by
  // (11 theta^4/3072 + 173 theta^6/737280) T0 = 0.0936 us.
  const double small_us = finite_amplitude_small_angle(test::kAmplitude) * test::kIdealPeriod * 1e6;
  const double t2 = test::kAmplitude * test::kAmplitude;
  CHECK_THAT(dt_us - small_us,
             WithinAbs((11.0 / 3072.0 * t2 * t2 + 173.0 / 737280.0 * t2 * t2 * t2) * test::kIdealPeriod * 1e6, 1e-8));
}

TEST_CASE("Series terms and the small-angle form", "[amplitude]") {
  const double theta0 = 0.3;
  const double k2 = std::pow(std::sin(theta0 / 2.0), 2);
  CHECK_THAT(finite_amplitude_series(theta0, 1), WithinRel(k2 / 4.0, 1e-15));
  CHECK_THAT(finite_amplitude_series(theta0, 2), WithinRel(k2 / 4.0 + 9.0 / 64.0 * k2 * k2, 1e-15));
  CHECK(finite_amplitude_small_angle(theta0) == theta0 * theta0 / 16.0);
}

TEST_CASE("Every method's error bound holds and is not loose", "[amplitude][quad]") {
  // Against quad precision from 0.01 to 170 deg. Up to 150 deg (m <= 0.93),
  // where the truncation dominates the roundoff (true error above 1e-12 of
  // the value), a bound is required to be within a factor 4 of the true
  // error; beyond, the 1/(1 - m) of the tail bounds makes them looser.
  for (double deg : {0.01, 0.5, 3.0, 10.0, 30.0, 60.0, 90.0, 120.0, 150.0, 170.0}) {
    const double theta0 = deg * test::kDegree;
    const Quad reference = test::delta_ratio_quad(deg);
    auto check = [&](AmplitudeMethod method, int terms) {
      const double value = finite_amplitude(method, theta0, terms);
      const double error = static_cast<double>(fabsq(Quad(value) - reference));
      const double bound = amplitude_error_bound(method, theta0, terms);
      INFO(deg << " deg, " << method_name(method) << ", " << terms << " terms: error " << error
               << ", bound " << bound);
      CHECK(error <= bound);
      if (deg <= 150.0 && error > 1e-12 * static_cast<double>(reference)) {
        CHECK(bound <= 4.0 * error);
      }
    };
    check(AmplitudeMethod::small_angle, 0);
    for (int terms : {1, 2, 4, 8}) check(AmplitudeMethod::series, terms);
    check(AmplitudeMethod::agm, 0);
  }
}

TEST_CASE("Every method's error bound is finite and holds up to the last amplitude below 180 deg",
          "[amplitude][quad]") {
  // fuzz_arguments (docs/robustness.md): from 179.9999999 deg on sin^2(theta0/2) rounds to 1, and the
  // bounds of the series and the small-angle form, over 1 - m, were infinite (`pendulum-g amplitude
  // --theta0-deg 179.99999999 --method series` printed a bound of null).
  for (double deg : {179.9999999, 179.99999999, std::nextafter(180.0, 0.0)}) {
    const double theta0 = radians(deg);  // as the amplitude command takes it
    const double reference = static_cast<double>(test::delta_ratio_quad_rad(theta0));
    auto check = [&](AmplitudeMethod method, int terms) {
      const double bound = amplitude_error_bound(method, theta0, terms);
      INFO(deg << " deg, " << method_name(method) << ", " << terms << " terms: bound " << bound);
      CHECK(std::isfinite(bound));
      CHECK(std::fabs(finite_amplitude(method, theta0, terms) - reference) <= bound);
    };
    check(AmplitudeMethod::small_angle, 0);
    for (int terms : {1, 4, 1000}) check(AmplitudeMethod::series, terms);
  }
}

TEST_CASE("The automatic choice takes the cheapest method within the tolerance", "[amplitude]") {
  const double theta0 = 3.0 * test::kDegree;
  CHECK(cheapest_amplitude_method(theta0, 1e-6).method == AmplitudeMethod::small_angle);
  const AmplitudeChoice series = cheapest_amplitude_method(theta0, 1e-9);
  CHECK(series.method == AmplitudeMethod::series);
  CHECK(series.terms == 2);
  CHECK(series.bound < 1e-9);
  CHECK(amplitude_error_bound(AmplitudeMethod::series, theta0, 1) >= 1e-9);
  CHECK(cheapest_amplitude_method(theta0, 0.0).method == AmplitudeMethod::agm);
  CHECK(cheapest_amplitude_method(170.0 * test::kDegree, 1e-6).method == AmplitudeMethod::agm);
}

TEST_CASE("finite_amplitude_agm_many: the scalar function's values, bit for bit", "[amplitude]") {
  // Amplitudes in every case and on both sides of each case's limit, in a
  // count that is no multiple of the kernel's block, mixed so that a block
  // holds all three cases.
  std::vector<double> theta;
  for (double edge : {0.0, detail::kOneAgmStepLimit, detail::kTwoAgmStepsLimit}) {
    theta.push_back(edge);
    theta.push_back(std::nextafter(edge, 4.0));
    if (edge > 0.0) theta.push_back(std::nextafter(edge, 0.0));
  }
  theta.push_back(std::nextafter(kPi, 0.0));
  for (int i = 0; theta.size() < 1001; ++i) theta.push_back(std::fmod(i * 0.7548776662466927, 1.0) * kPi);
  std::vector<double> many(theta.size(), -1.0);
  REQUIRE(finite_amplitude_agm_many(theta.data(), many.data(), theta.size()) == theta.size());
  for (std::size_t i = 0; i < theta.size(); ++i) {
    INFO("theta0 = " << theta[i] << " rad");
    CHECK(many[i] == finite_amplitude_agm(theta[i]));
  }

  // The first amplitude out of range is named; nothing from it on is written.
  for (double bad : {kPi, -0.5, std::numeric_limits<double>::quiet_NaN()}) {
    std::vector<double> some = theta, out(theta.size(), -1.0);
    some[700] = bad;
    CHECK(finite_amplitude_agm_many(some.data(), out.data(), some.size()) == 700);
    CHECK(out[699] == finite_amplitude_agm(some[699]));
    CHECK(std::all_of(out.begin() + 768, out.end(), [](double v) { return v == -1.0; }));
  }

  // Blocks wholly in the first case (not sorted), its limit included, and a
  // bad amplitude among them still named.
  std::vector<double> low;
  for (int i = 0; low.size() < 1000; ++i) low.push_back(std::fmod(i * 0.7548776662466927, 1.0) * detail::kOneAgmStepLimit);
  low[3] = detail::kOneAgmStepLimit;
  std::vector<double> out(low.size(), -1.0);
  REQUIRE(finite_amplitude_agm_many(low.data(), out.data(), low.size()) == low.size());
  for (std::size_t i = 0; i < low.size(); ++i) CHECK(out[i] == finite_amplitude_agm(low[i]));
  for (double bad : {-0.5, std::numeric_limits<double>::quiet_NaN()}) {
    low[600] = bad;
    CHECK(finite_amplitude_agm_many(low.data(), out.data(), low.size()) == 600);
  }
}
