#pragma once
// Reference values shared by the tests, each with its source.

namespace pendulum::test {

// Nelson & Olsson (1986), the experiment of Sec. II and Fig. 1 (SI units).
constexpr double kLength = 3.0044;       // m, Sec. II
constexpr double kBobRadius = 0.0305;    // m, half of 6.10 cm, Sec. II
constexpr double kBobMass = 0.8567;      // kg, Sec. II
constexpr double kAmplitudeDeg = 3.0;    // deg, Sec. III.A
constexpr double kDegree = 3.14159265358979323846 / 180.0;  // one degree in radians
constexpr double kAmplitude = kAmplitudeDeg * kDegree;  // rad
constexpr double kPeriod = 3.47880;      // s, Eq. (4)
constexpr double kIdealPeriod = 3.47833; // s, Eq. (90): converts Table II's ratios to us
constexpr double kAlpha = 2.49e-4;       // 1/s, Eq. (28)
constexpr double kBeta = 3.17e-3;        // 1/(s rad), Eq. (29)
constexpr double kTiming = 347.880;      // s, t_f of Eq. (50b), text after it
constexpr double kOmega0 = 2.0 * 3.14159265358979323846 / kPeriod;  // rad/s

// Table II's tolerance rule (issue 2): rows of 10 us or more within 1 us,
// rows below 1 us within 0.01 us, the others within 0.1 us.
inline double table2_tolerance_us(double printed_us) {
  const double size = printed_us < 0 ? -printed_us : printed_us;
  if (size >= 10.0) return 1.0;
  if (size < 1.0) return 0.01;
  return 0.1;
}

}  // namespace pendulum::test
