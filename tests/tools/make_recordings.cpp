// Writes the recordings of data/recordings/, one per family, from the seeded
// simulation of tests/recording_simulation.hpp (no real file of these
// exports can be shipped). Usage: make_recordings OUTPUT_DIR.
// Every file: l = 0.80 m, g = 9.80665 m/s^2, theta0 = 0.25 rad released at
// rest, alpha = 2e-3 1/s, beta = 4e-3 1/(s rad); the family's own sensor
// noise, written in the exporter's layout (docs/recordings.md, Formats).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "recording_simulation.hpp"

using pendulum::test::RecordingSimulation;
using pendulum::test::SimulatedRecording;
using pendulum::test::simulate_recording;

namespace {

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  std::printf("%s: %zu bytes\n", path.c_str(), text.size());
}

std::string comma_decimals(std::string s) {
  for (char& c : s) {
    if (c == '.') c = ',';
  }
  return s;
}

std::string number(const char* fmt, double x) {
  char b[40];
  std::snprintf(b, sizeof b, fmt, x);
  return b;
}

/// theta'' of the simulated pendulum at (theta, omega).
double angular_acceleration(const RecordingSimulation& s, double th, double om) {
  const double w0 = std::sqrt(s.g / s.length);
  return -w0 * w0 * std::sin(th) - 2.0 * s.alpha * om - 3.0 * M_PI / 4.0 * s.beta / w0 * om * std::fabs(om);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_recordings OUTPUT_DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  RecordingSimulation base;
  base.duration = 20.0;
  base.rate_hz = 50.0;

  {  // phyphox Gyroscope, comma-separated, seed 11
    RecordingSimulation s = base;
    s.seed = 11;
    write(dir + "/phyphox_gyroscope.csv", pendulum::test::phyphox_gyroscope_csv(simulate_recording(s), false));
  }
  {  // phyphox Pendulum experiment raw data: tab-separated, decimal comma, seed 12
    RecordingSimulation s = base;
    s.seed = 12;
    const SimulatedRecording r = simulate_recording(s);
    std::string out = "\"Time (s)\"\t\"Rotation x (rad/s)\"\t\"Rotation y (rad/s)\"\t\"Rotation z (rad/s)\"\n";
    for (std::size_t k = 0; k < r.t.size(); ++k) {
      out += comma_decimals(number("%.9E", r.t[k]) + "\t" + number("%.9E", r.rate[0][k]) + "\t" +
                            number("%.9E", r.rate[1][k]) + "\t" + number("%.9E", r.rate[2][k])) + "\n";
    }
    write(dir + "/phyphox_pendulum_raw.tsv", out);
  }
  // Accelerometers: the phone at the bob, its frame tilted; tangential axis
  // (0.30, 0.95, 0.09), radial (0.95, -0.30, 0.0) (orthogonal, normalised
  // below), noise 0.05 m/s^2 per axis.
  const double ta[3] = {0.30, 0.95, 0.09}, ra[3] = {0.95, -0.30, 0.0};
  const double tn = std::sqrt(0.30 * 0.30 + 0.95 * 0.95 + 0.09 * 0.09), rn = std::sqrt(0.95 * 0.95 + 0.30 * 0.30);
  for (const bool linear : {true, false}) {  // seeds 13 (linear), 14 (with g)
    RecordingSimulation s = base;
    s.seed = linear ? 13 : 14;
    s.noise = 0.0;
    const SimulatedRecording r = simulate_recording(s);
    pendulum::NormalDeviates noise(s.seed + 100);
    const char d = linear ? ';' : ',';
    const std::string stem = linear ? "Linear Acceleration" : "Acceleration";
    std::string out = "\"Time (s)\"" + std::string(1, d) + "\"" + stem + " x (m/s^2)\"" + d + "\"" + stem +
                      " y (m/s^2)\"" + d + "\"" + stem + " z (m/s^2)\"\n";
    for (std::size_t k = 0; k < r.t.size(); ++k) {
      const double th = r.theta[k], om = r.omega[k];
      const double tangential = s.length * angular_acceleration(s, th, om) + (linear ? 0.0 : s.g * std::sin(th));
      const double radial = s.length * om * om + (linear ? 0.0 : s.g * std::cos(th));
      std::string row = number("%.9E", r.t[k]);
      for (int j = 0; j < 3; ++j) {
        const double a = tangential * ta[j] / tn + radial * ra[j] / rn + 0.05 * noise.next();
        row += d + number("%.9E", a);
      }
      out += (linear ? comma_decimals(row) : row) + "\n";
    }
    write(dir + (linear ? "/phyphox_linear_acceleration.csv" : "/phyphox_acceleration.csv"), out);
  }
  // Photogates: the beam at the lowest point, a bob 25.0 mm wide; the gate is
  // blocked while |l sin theta| < w/2. Sampled at 20 kHz without noise, events
  // located by linear interpolation and rounded to 10 us (seed 15).
  RecordingSimulation gate = base;
  gate.rate_hz = 20000.0;
  gate.noise = 0.0, gate.jitter = 0.0, gate.drop = 0.0;
  gate.seed = 15;
  const SimulatedRecording g = simulate_recording(gate);
  const double half = 0.0125;
  std::vector<std::pair<double, int>> events;
  for (std::size_t k = 1; k < g.t.size(); ++k) {
    const double a = std::fabs(gate.length * std::sin(g.theta[k - 1])) - half;
    const double b = std::fabs(gate.length * std::sin(g.theta[k])) - half;
    if ((a < 0.0) != (b < 0.0)) {
      const double t = g.t[k - 1] + a / (a - b) * (g.t[k] - g.t[k - 1]);
      events.push_back({std::round(t * 1e5) / 1e5, b < 0.0 ? 1 : 0});
    }
  }
  {  // Vernier Graphical Analysis, Pendulum Timing: period at every third blocking
    std::string out = "\"Latest: Time (s)\",\"Latest: GateState\",\"Latest: Period (s)\"\n";
    int blockings = 0;
    double period_start = 0.0;
    for (const auto& [t, state] : events) {
      std::string period;
      if (state == 1) {
        if (blockings % 2 == 0) {
          if (blockings > 0) period = number("%.5f", t - period_start);
          period_start = t;
        }
        ++blockings;
      }
      out += number("%.5f", t) + "," + std::to_string(state) + "," + period + "\n";
    }
    write(dir + "/vernier_photogate.csv", out);
  }
  {  // a plain column of blocking times from a microcontroller, in ms
    std::string out = "t (ms)\n";
    for (const auto& [t, state] : events) {
      if (state == 1) out += number("%.2f", t * 1e3) + "\n";
    }
    write(dir + "/plain_blocking_times.txt", out);
  }
  {  // PASCO Capstone, rotary motion sensor at the pivot: angle at 50 Hz, 0.00153 rad steps (seed 16)
    RecordingSimulation s = base;
    s.seed = 16, s.noise = 0.0, s.jitter = 0.0, s.drop = 0.0;
    const SimulatedRecording r = simulate_recording(s);
    std::string out = "\"Time (s) Run #1\",\"Angle (rad) Run #1\"\n";
    for (std::size_t k = 0; k < r.t.size(); ++k) {
      const double a = std::round(r.theta[k] / 0.00153) * 0.00153;
      out += number("%.2f", std::round(r.t[k] * 50.0) / 50.0) + "," + number("%.5f", a) + "\n";
    }
    write(dir + "/pasco_rotary.csv", out);
  }
  // Tracker at 30 frames/s, the bob marked by hand: 1.5 mm noise per
  // coordinate; origin at the pivot, y up (seed 17).
  RecordingSimulation video = base;
  video.rate_hz = 30.0, video.noise = 0.0, video.jitter = 0.0, video.drop = 0.0, video.seed = 17;
  const SimulatedRecording v = simulate_recording(video);
  pendulum::NormalDeviates marks(17);
  {  // x, y: tab-separated, decimal comma (a German locale)
    std::string out = "mass A\nt\tx\ty\n";
    for (std::size_t k = 0; k < v.t.size(); ++k) {
      const double x = video.length * std::sin(v.theta[k]) + 0.0015 * marks.next();
      const double y = -video.length * std::cos(v.theta[k]) + 0.0015 * marks.next();
      out += comma_decimals(number("%.4f", k / 30.0) + "\t" + number("%.5f", x) + "\t" + number("%.5f", y)) + "\n";
    }
    write(dir + "/tracker_xy.txt", out);
  }
  {  // theta of the track in degrees about the pivot (x axis horizontal), semicolon
    std::string out = "mass A\nt;\xce\xb8\n";
    for (std::size_t k = 0; k < v.t.size(); ++k) {
      const double th = v.theta[k] + 0.0015 / video.length * marks.next();
      out += number("%.4f", k / 30.0) + ";" + number("%.3f", (th - M_PI / 2.0) * 180.0 / M_PI) + "\n";
    }
    write(dir + "/tracker_theta.csv", out);
  }
  {  // two tracks, Tracker's "#multi:" export: a mark on the support (mass A,
     // still), then the bob (mass B), one time column; tab-separated
    pendulum::NormalDeviates two(18);
    std::string out = "#multi:\n\tmass A\t\tmass B\t\nt\tx\ty\tx\ty\n";
    for (std::size_t k = 0; k < v.t.size(); ++k) {
      const double xa = 0.0015 * two.next(), ya = 0.0015 * two.next();
      const double xb = video.length * std::sin(v.theta[k]) + 0.0015 * two.next();
      const double yb = -video.length * std::cos(v.theta[k]) + 0.0015 * two.next();
      out += number("%.4f", k / 30.0) + "\t" + number("%.5f", xa) + "\t" + number("%.5f", ya) + "\t" +
             number("%.5f", xb) + "\t" + number("%.5f", yb) + "\n";
    }
    write(dir + "/tracker_two_tracks.txt", out);
  }
  // The same track copied out of Tracker's table without its header: t, x,
  // y by tabs, 1.5 mm per coordinate (seed 19); the reader finds the roles
  // from the numbers (docs/recordings.md, Columns).
  write(dir + "/tracker_headerless_xy.txt",
        pendulum::test::published_csv(v, video.length, pendulum::test::PublishedLayout::headerless_txy, 0.0015, 19));
  {  // A hand-triggered timer's log, headerless "n<TAB>t": one press a period
     // at the same extreme, l = 2.72 m (T = 3.31 s), theta0 = 0.15 rad, 41
     // presses, 40 ms of reaction scatter, printed to 10 ms (seed 19). The
     // 18th press was missed: the timer's count n runs on without it.
    RecordingSimulation s = base;
    s.length = 2.72, s.theta0 = 0.15, s.duration = 140.0, s.rate_hz = 10.0, s.seed = 19;
    const std::vector<double> stamps = pendulum::test::timer_stamps(simulate_recording(s), 0.040, 0.010, 19);
    std::string out;
    int n = 0;
    for (std::size_t k = 0; k < 41 && k < stamps.size(); ++k) {
      if (k == 17) continue;
      out += std::to_string(++n) + "\t" + number("%.2f", stamps[k]) + "\n";
    }
    write(dir + "/timer_missed_stamp.txt", out);
  }
  {  // Tracker, clicked by hand at 15 frames/s for 300 s (seed 20): 1.5 mm of
     // scatter, then from 130 s on (the last 170 s) 3 cm of scatter and one
     // click in ten on the wrong spot, 20 cm to the side; a glitchy end.
    RecordingSimulation s = base;
    s.duration = 300.0, s.rate_hz = 15.0, s.noise = 0.0, s.jitter = 0.0, s.drop = 0.0, s.seed = 20;
    const SimulatedRecording r = simulate_recording(s);
    auto xy = pendulum::test::track_xy(r, s.length, 0.0015, 20);
    pendulum::NormalDeviates sloppy(21);
    std::string out = "mass A\nt\tx\ty\n";
    for (std::size_t k = 0; k < r.t.size(); ++k) {
      const double t = k / 15.0;
      if (t >= 130.0) {
        xy[0][k] += 0.03 * sloppy.next() + (k % 10 == 3 ? 0.2 : 0.0);
        xy[1][k] += 0.03 * sloppy.next();
      }
      out += number("%.4f", t) + "\t" + number("%.5f", xy[0][k]) + "\t" + number("%.5f", xy[1][k]) + "\n";
    }
    write(dir + "/tracker_glitchy_end.txt", out);
  }
  return 0;
}
