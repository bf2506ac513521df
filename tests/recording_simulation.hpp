#pragma once
// Synthetic recordings of a damped pendulum, seeded and identical on every
// platform, for tests/test_recordings.cpp, tests/benchmarks/ and the files in
// data/recordings/ (tests/tools/make_recordings.cpp).
//
// The motion is the equation of tests/test_ode.cpp (Nelson & Olsson Eqs. 1,
// 30, 35): theta'' = -(g/l) sin theta - 2 alpha theta' - eps theta'|theta'|,
// eps = (3 pi/4) beta/omega0 (Eq. 27), released at rest from theta0 at t = 0,
// integrated by classic RK4 in sub-steps of at most 1 ms between sample
// times (the local error, (omega0 h)^5/120 ~ 1e-15, is far below any noise
// here). The sensors then add what real ones do: Gaussian noise per axis,
// a constant bias per axis, sampling jitter (Gaussian, on the sample times),
// dropped samples, and a tilt (the swing axis is an arbitrary unit vector in
// the phone's frame). The exact crossing times (theta' = 0: turning points)
// come from the same integration, refined by linear interpolation within a
// 1 ms sub-step (there theta''' = -omega0^2 cos(theta) theta' vanishes, so
// the interpolation error is of order h^3).
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "pendulum/decay_simulation.hpp"

namespace pendulum::test {

struct RecordingSimulation {
  double g = 9.80665;        // m/s^2
  double length = 0.80;      // m
  double theta0 = 0.25;      // rad, release amplitude
  double alpha = 2e-3;       // 1/s
  double beta = 4e-3;        // 1/(s rad)
  double rate_hz = 100.0;    // nominal sampling rate
  double duration = 60.0;    // s
  double noise = 0.01;       // sensor noise sigma per axis (signal unit)
  std::array<double, 3> bias{0.003, -0.002, 0.001};  // per axis (signal unit)
  double jitter = 2e-4;      // s, sigma of the sample-time jitter
  double drop = 0.01;        // probability that a sample is missing
  std::array<double, 3> axis{0.28, 0.15, 0.948};    // swing axis in the phone (normalised below)
  std::uint64_t seed = 1;
};

struct SimulatedRecording {
  std::vector<double> t;                    // s
  std::array<std::vector<double>, 3> rate;  // gyroscope (rad/s)
  std::vector<double> theta;                // noise-free angle at t (rad)
  std::vector<double> omega;                // noise-free theta' at t (rad/s)
  std::vector<double> turning_times;        // exact theta' = 0 (s), the release excluded
  std::vector<double> turning_amplitudes;   // |theta| there (rad)
  double omega0 = 0.0;                      // sqrt(g/l)
};

inline SimulatedRecording simulate_recording(const RecordingSimulation& s) {
  SimulatedRecording out;
  const double w0 = std::sqrt(s.g / s.length);
  out.omega0 = w0;
  const double eps = 3.0 * M_PI / 4.0 * s.beta / w0;
  auto f = [&](double th, double om, double& dth, double& dom) {
    dth = om;
    dom = -w0 * w0 * std::sin(th) - 2.0 * s.alpha * om - eps * om * std::fabs(om);
  };
  const double norm = std::sqrt(s.axis[0] * s.axis[0] + s.axis[1] * s.axis[1] + s.axis[2] * s.axis[2]);
  NormalDeviates normal(s.seed);
  std::mt19937_64 uniform(s.seed ^ 0x9e3779b97f4a7c15ULL);
  double th = s.theta0, om = 0.0, now = 0.0;
  const double dt = 1.0 / s.rate_hz;
  const std::size_t n = static_cast<std::size_t>(s.duration * s.rate_hz);
  for (std::size_t k = 0; k < n; ++k) {
    const double target = std::max(now, k * dt + s.jitter * normal.next());
    while (now < target) {  // RK4 sub-steps up to the sample time
      const double h = std::min(1e-3, target - now);
      double a1, b1, a2, b2, a3, b3, a4, b4;
      f(th, om, a1, b1);
      f(th + h / 2 * a1, om + h / 2 * b1, a2, b2);
      f(th + h / 2 * a2, om + h / 2 * b2, a3, b3);
      f(th + h * a3, om + h * b3, a4, b4);
      const double th_next = th + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
      const double om_next = om + h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
      if (now > 0.0 && ((om < 0.0) != (om_next < 0.0))) {
        const double u = om / (om - om_next);
        out.turning_times.push_back(now + u * h);
        out.turning_amplitudes.push_back(std::fabs(th + u * (th_next - th)));
      }
      th = th_next, om = om_next, now += h;
    }
    const double noise[3] = {normal.next(), normal.next(), normal.next()};
    if ((uniform() >> 11) * 0x1.0p-53 < s.drop) continue;
    out.t.push_back(now);
    out.theta.push_back(th);
    out.omega.push_back(om);
    for (int j = 0; j < 3; ++j) {
      out.rate[j].push_back(om * s.axis[j] / norm + s.bias[j] + s.noise * noise[j]);
    }
  }
  return out;
}

/// One stamp a period as a hand-triggered timer logs it: the turning times
/// at one extreme (every other one, the release's side), each plus a
/// Gaussian reaction error of sigma `jitter` (s), rounded to the timer's
/// `quantum` (s) when it is positive.
inline std::vector<double> timer_stamps(const SimulatedRecording& r, double jitter, double quantum,
                                        std::uint64_t seed) {
  NormalDeviates normal(seed);
  std::vector<double> out;
  for (std::size_t k = 1; k < r.turning_times.size(); k += 2) {
    const double t = r.turning_times[k] + jitter * normal.next();
    out.push_back(quantum > 0.0 ? std::round(t / quantum) * quantum : t);
  }
  return out;
}

/// A video track of the bob: x = l sin theta, y = -l cos theta (m, pivot at
/// the origin) at the sample times, each plus Gaussian click noise `noise` (m).
inline std::array<std::vector<double>, 2> track_xy(const SimulatedRecording& r, double length, double noise,
                                                   std::uint64_t seed) {
  NormalDeviates normal(seed);
  std::array<std::vector<double>, 2> out;
  for (double th : r.theta) {
    out[0].push_back(length * std::sin(th) + noise * normal.next());
    out[1].push_back(-length * std::cos(th) + noise * normal.next());
  }
  return out;
}

/// A phyphox Gyroscope export ("Time (s)","Gyroscope x (rad/s)",...) with
/// phyphox's number format 1.234567890E-1; `decimal_comma` writes the
/// semicolon-separated variant with decimal commas.
inline std::string phyphox_gyroscope_csv(const SimulatedRecording& r, bool decimal_comma) {
  const char d = decimal_comma ? ';' : ',';
  std::string out;
  out.reserve(r.t.size() * 70 + 100);
  char line[160];
  std::snprintf(line, sizeof line, "\"Time (s)\"%c\"Gyroscope x (rad/s)\"%c\"Gyroscope y (rad/s)\"%c\"Gyroscope z (rad/s)\"\n",
                d, d, d);
  out += line;
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const int n = std::snprintf(line, sizeof line, "%.9E%c%.9E%c%.9E%c%.9E\n", r.t[k], d, r.rate[0][k], d,
                                r.rate[1][k], d, r.rate[2][k]);
    if (decimal_comma) {
      for (int i = 0; i < n; ++i) {
        if (line[i] == '.') line[i] = ',';
      }
    }
    out.append(line, n);
  }
  return out;
}

}  // namespace pendulum::test
