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

#include "simulations/decay_simulation.hpp"

namespace pendulum::test {

struct RecordingSimulation {
  double g = 9.80665;        // m/s^2
  double length = 0.80;      // m
  double theta0 = 0.25;      // rad, release amplitude
  double alpha = 2e-3;       // 1/s
  double beta = 4e-3;        // 1/(s rad)
  double friction = 0.0;     // rad/s^2, a dry (Coulomb) friction's constant deceleration, a bearing's
  double rate_hz = 100.0;    // nominal sampling rate
  double duration = 60.0;    // s
  double noise = 0.01;       // sensor noise sigma per axis (signal unit)
  std::array<double, 3> bias{0.003, -0.002, 0.001};  // per axis (signal unit)
  double jitter = 2e-4;      // s, sigma of the sample-time jitter
  double phase = 0.0;        // the first sample's time after the release, in sample intervals [0, 1)
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
  std::vector<double> zero_times;           // exact theta = 0 (s): an angle's or a track's crossings
  double omega0 = 0.0;                      // sqrt(g/l)
};

/// A seed's sampling phase in [0, 1): the golden ratio's steps spread
/// seeds 1, 2, ... evenly, so that an error that depends on the phase is
/// drawn anew for each record, not once for all.
inline double seeded_phase(std::uint64_t seed) { return std::fmod(seed * 0.6180339887498949, 1.0); }

/// The share of normal errors within one standard deviation, and three
/// binomial sigmas of it over `runs` records: a coverage test's tolerance.
constexpr double kOneSigmaCoverage = 0.6826894921370859;
inline double coverage_tolerance(int runs) {
  return 3.0 * std::sqrt(kOneSigmaCoverage * (1.0 - kOneSigmaCoverage) / runs);
}

inline SimulatedRecording simulate_recording(const RecordingSimulation& s) {
  SimulatedRecording out;
  const double w0 = std::sqrt(s.g / s.length);
  out.omega0 = w0;
  const double eps = 3.0 * M_PI / 4.0 * s.beta / w0;
  auto f = [&](double th, double om, double& dth, double& dom) {
    dth = om;
    dom = -w0 * w0 * std::sin(th) - 2.0 * s.alpha * om - eps * om * std::fabs(om) - s.friction * ((om > 0.0) - (om < 0.0));
  };
  const double norm = std::sqrt(s.axis[0] * s.axis[0] + s.axis[1] * s.axis[1] + s.axis[2] * s.axis[2]);
  NormalDeviates normal(s.seed);
  std::mt19937_64 uniform(s.seed ^ 0x9e3779b97f4a7c15ULL);
  double th = s.theta0, om = 0.0, now = 0.0;
  const double dt = 1.0 / s.rate_hz;
  const std::size_t n = static_cast<std::size_t>(s.duration * s.rate_hz);
  for (std::size_t k = 0; k < n; ++k) {
    const double target = std::max(now, (k + s.phase) * dt + s.jitter * normal.next());
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
      // Linear within a 1 ms sub-step: theta'' = -w0^2 sin(theta) vanishes at the zero.
      if (now > 0.0 && ((th < 0.0) != (th_next < 0.0))) out.zero_times.push_back(now + th / (th - th_next) * h);
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

namespace pendulum::test {

/// The layouts students published (issue 19), each with its quirk, written
/// from a simulated swing: `theta` (rad, noise-free, at `t`) plus `noise`
/// (rad for an angle; m of the bob for a track, at 1000 px/m) drawn from
/// `seed`. Times as the simulation sampled them unless the layout says.
enum class PublishedLayout {
  rotary_degrees,      ///< "Time (s),Angle (Degrees)": a rotary-motion sensor's log in degrees
  opencv_angle,        ///< "time,angle": an OpenCV script's angle in degrees, no unit
  pixel_track,         ///< "frame,time (s),x (px),y (px)": a phone video's pixels, y down, a frame counter
  tracker_degrees,     ///< "mass A" / "t<TAB>θ": Tracker's angle in degrees, no unit
  logger_pro_video,    ///< "VideoAnalysis: Time (s)<TAB>VideoAnalysis: X (m)<TAB>VideoAnalysis: Y (m)"
  headerless_txy,      ///< "t x y" by tabs, no header (Tracker's data copied)
  headerless_timer,    ///< "n<TAB>t", no header: one stamp per period (theta up through 0)
  spaces,              ///< "   t      theta (rad)" and columns aligned by runs of spaces
  repeated_stamps,     ///< "Time (s),Angle (rad)": stamps of a 100 Hz clock printed with 3 decimals at 500 Hz
  // Issue 38's quirks:
  headerless_degrees,  ///< "t theta" by a space, no header: an OpenCV angle track in degrees
  headerless_radians,  ///< the same in radians
  microbit_ms,         ///< "ms, mg", no header: a micro:bit's millisecond clock and its tangential
                       ///< acceleration g sin(theta) in whole milli-g
  microbit_two_axes,   ///< "ms<TAB>along<TAB>across", no header: a micro:bit's axis along the string,
                       ///< -g(3 cos(theta) - 2) (at twice the swing's frequency), then g sin(theta), whole milli-g
  timer_ms,            ///< "n<TAB>ms", no header: a microcontroller's stamps, one a period, in whole ms
  slash_units,         ///< "Time/s,Angle/rad": the unit after a slash
  header_mismatch,     ///< "x y dx dy" over rows of two columns (time, angle in degrees): a header of other columns
  portuguese,          ///< "frame,tempo,x,y": a frame counter, the time in Portuguese, pixels
  tilted_camera,       ///< "t x y" by tabs, no header, metres: Tracker's track from a camera pitched
                       ///< 50 deg off square to the swing, whose heights show cos 50 deg of themselves
                       ///< (the track's circle then has 1.56 times the pendulum's radius)
  held_frames,         ///< "t, theta" by ", ", no header, printf's %g: an OpenCV loop writing, at every
                       ///< third sample, the angle in degrees of the camera's latest frame, one every
                       ///< ninth sample (each frame's noise drawn once): a staircase of held frames
  t_theta_extra,       ///< "t theta extra" by spaces, no header: the angle in degrees, then a third
                       ///< signal at the swing's frequency, half the angle a fifth of a period
                       ///< earlier (a second sensor's lagging reading): no track's y
  generic_names,       ///< "X,Y,X',Y'": a fitting program's generic names over the time, the angle
                       ///< in degrees, the time's uncertainty (half a frame) and the angle's
                       ///< (0.5 deg and 2 % of it)
};

inline std::string published_csv(const SimulatedRecording& r, double length, PublishedLayout layout, double noise,
                                 std::uint64_t seed) {
  NormalDeviates normal(seed);
  std::string out;
  char line[200];
  auto put = [&](const char* fmt, auto... args) { out.append(line, std::snprintf(line, sizeof line, fmt, args...)); };
  constexpr double kDeg = 180.0 / M_PI;
  switch (layout) {
    case PublishedLayout::rotary_degrees: put("Time (s),Angle (Degrees)\n"); break;
    case PublishedLayout::opencv_angle: put("time,angle\n"); break;
    case PublishedLayout::pixel_track: put("frame,time (s),x (px),y (px)\n"); break;
    case PublishedLayout::tracker_degrees: put("mass A\nt\t\xce\xb8\n"); break;
    case PublishedLayout::logger_pro_video:
      put("VideoAnalysis: Time (s)\tVideoAnalysis: X (m)\tVideoAnalysis: Y (m)\n");
      break;
    case PublishedLayout::spaces: put("%10s %14s\n", "t", "theta (rad)"); break;
    case PublishedLayout::repeated_stamps: put("Time (s),Angle (rad)\n"); break;
    case PublishedLayout::slash_units: put("Time/s,Angle/rad\n"); break;
    case PublishedLayout::header_mismatch: put("x y dx dy\n"); break;
    case PublishedLayout::portuguese: put("frame,tempo,x,y\n"); break;
    case PublishedLayout::generic_names: put("X,Y,X',Y'\n"); break;
    case PublishedLayout::headerless_txy:
    case PublishedLayout::held_frames:
    case PublishedLayout::tilted_camera:
    case PublishedLayout::headerless_timer:
    case PublishedLayout::headerless_degrees:
    case PublishedLayout::headerless_radians:
    case PublishedLayout::microbit_ms:
    case PublishedLayout::microbit_two_axes:
    case PublishedLayout::t_theta_extra:
    case PublishedLayout::timer_ms: break;
  }
  if (layout == PublishedLayout::headerless_timer || layout == PublishedLayout::timer_ms) {
    for (std::size_t k = 0, n = 1; k < r.zero_times.size(); ++k) {
      // Up through zero: the release is at +theta0, so the odd zeros.
      const double t = r.zero_times[k] + noise * normal.next();
      if (k % 2 == 1) {
        layout == PublishedLayout::timer_ms ? put("%zu\t%.0f\n", n++, 1000.0 * t) : put("%zu\t%.4f\n", n++, t);
      }
    }
    return out;
  }
  if (layout == PublishedLayout::held_frames) {
    double frame = 0.0;
    for (std::size_t k = 0; k < r.t.size(); k += 3) {
      if (k % 9 == 0) frame = (r.theta[k] + noise * normal.next()) * kDeg;
      put("%g, %g\n", r.t[k], frame);
    }
    return out;
  }
  // The lag of t_theta_extra's third column: a fifth of the first period.
  const std::size_t lag = r.zero_times.size() > 2
                              ? static_cast<std::size_t>((r.zero_times[2] - r.zero_times[0]) / 5.0 / (r.t[1] - r.t[0]))
                              : 0;
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const double t = r.t[k], th = r.theta[k];
    const double e1 = noise * normal.next(), e2 = noise * normal.next();
    const double x = length * std::sin(th) + e1, y = -length * std::cos(th) + e2;
    switch (layout) {
      case PublishedLayout::rotary_degrees: put("%.3f,%.3f\n", t, (th + e1) * kDeg); break;
      case PublishedLayout::opencv_angle: put("%.4f,%.4f\n", t, (th + e1) * kDeg); break;
      case PublishedLayout::pixel_track: put("%zu,%.5f,%.1f,%.1f\n", k, t, 640.0 + 1000.0 * x, 200.0 - 1000.0 * y); break;
      case PublishedLayout::tracker_degrees: put("%.4f\t%.3f\n", t, (th + e1) * kDeg); break;
      case PublishedLayout::logger_pro_video: put("%.4f\t%.5f\t%.5f\n", t, x, y); break;
      case PublishedLayout::headerless_txy: put("%.4f\t%.5f\t%.5f\n", t, x, y); break;
      case PublishedLayout::tilted_camera: put("%.4f\t%.5f\t%.5f\n", t, x, std::cos(50.0 / kDeg) * y); break;
      case PublishedLayout::spaces: put("%10.4f %14.6f\n", t, th + e1); break;
      case PublishedLayout::repeated_stamps: put("%.3f,%.6f\n", std::floor(t * 100.0) / 100.0, th + e1); break;
      case PublishedLayout::headerless_degrees: put("%.4f %.4f\n", t, (th + e1) * kDeg); break;
      case PublishedLayout::headerless_radians: put("%.4f %.6f\n", t, th + e1); break;
      case PublishedLayout::microbit_ms: put("%.0f, %.0f\n", 1000.0 * t, 1000.0 * std::sin(th + e1)); break;
      case PublishedLayout::microbit_two_axes:
        put("%.0f\t%.0f\t%.0f\n", 1000.0 * t, -1000.0 * (3.0 * std::cos(th + e2) - 2.0), 1000.0 * std::sin(th + e1));
        break;
      case PublishedLayout::slash_units: put("%.3f,%.6f\n", t, th + e1); break;
      case PublishedLayout::header_mismatch: put("%.6E %.6E\n", t, (th + e1) * kDeg); break;
      case PublishedLayout::portuguese: put("%zu,%.9f,%.0f,%.0f\n", k + 1, t, 640.0 + 1000.0 * x, 200.0 - 1000.0 * y); break;
      case PublishedLayout::t_theta_extra:
        put("%.4f %.4f %.4f\n", t, (th + e1) * kDeg, (0.5 * r.theta[k < lag ? 0 : k - lag] + e2) * kDeg);
        break;
      case PublishedLayout::generic_names:
        put("%.5f,%.4f,%.5f,%.4f\n", t, (th + e1) * kDeg, 0.5 / 12.0, 0.5 + 0.02 * std::fabs(th * kDeg));
        break;
      case PublishedLayout::headerless_timer:
      case PublishedLayout::held_frames:
      case PublishedLayout::timer_ms: break;
    }
  }
  return out;
}

/// A phyphox gyroscope export with a phone's glitches: `repeats` samples
/// written twice and `swaps` pairs of neighbours written in the wrong order,
/// at seeded random rows (never the first or last ten).
inline std::string glitchy_phyphox_csv(const SimulatedRecording& r, int repeats, int swaps, std::uint64_t seed) {
  std::string clean = phyphox_gyroscope_csv(r, false);
  std::vector<std::string> rows;
  for (std::size_t at = clean.find('\n') + 1; at < clean.size();) {
    const std::size_t nl = clean.find('\n', at);
    rows.push_back(clean.substr(at, nl + 1 - at));
    at = nl + 1;
  }
  std::mt19937_64 random(seed);
  for (int k = 0; k < swaps; ++k) {
    const std::size_t i = 10 + random() % (rows.size() - 21);
    std::swap(rows[i], rows[i + 1]);
  }
  for (int k = 0; k < repeats; ++k) {
    const std::size_t i = 10 + random() % (rows.size() - 21);
    rows.insert(rows.begin() + static_cast<std::ptrdiff_t>(i), rows[i]);
  }
  std::string out = clean.substr(0, clean.find('\n') + 1);
  for (const auto& row : rows) out += row;
  return out;
}

/// phyphox's experiment file saved with its data (".phyphox", issue 38): the
/// gyroscope's buffers as <container init="v1,v2,...">, in Java's float
/// notation, and an <export> whose sets name them: "Raw Data" (time and the
/// three rates) after "Autocorrelation" (a buffer of the app's analysis,
/// which reads as no recording), as the Pendulum experiment saves them.
inline std::string phyphox_experiment_xml(const SimulatedRecording& r) {
  std::string out = "<phyphox version=\"1.14\" locale=\"en\">\n<title>Pendulum</title>\n<data-containers>\n";
  char value[40];
  const auto buffer = [&](const std::string& name, const std::vector<double>& v) {
    out += "  <container size=\"" + std::to_string(v.size()) + "\" init=\"";
    for (std::size_t k = 0; k < v.size(); ++k) {
      out += (k ? "," : "") + std::string(value, std::snprintf(value, sizeof value, "%.9E", v[k]));
    }
    out += "\">" + name + "</container>\n";
  };
  buffer("gyr_time", r.t);
  buffer("gyrX", r.rate[0]), buffer("gyrY", r.rate[1]), buffer("gyrZ", r.rate[2]);
  buffer("autocorrelation_t", {0.0, 0.02, 0.04});
  buffer("autocorrelation", {1.0, 0.9, 0.7});
  out += "  <container init=\"1.3\">periodEstimate</container>\n</data-containers>\n<export>\n"
         "  <set name=\"Autocorrelation\">\n    <data name=\"Time shift (s)\">autocorrelation_t</data>\n"
         "    <data name=\"Autocorrelation of sum\">autocorrelation</data>\n  </set>\n"
         "  <set name=\"Raw Data\">\n    <data name=\"Time (s)\">gyr_time</data>\n"
         "    <data name=\"Rotation x (rad/s)\">gyrX</data>\n    <data name=\"Rotation y (rad/s)\">gyrY</data>\n"
         "    <data name=\"Rotation z (rad/s)\">gyrZ</data>\n  </set>\n</export>\n</phyphox>\n";
  return out;
}

}  // namespace pendulum::test
