// The report of a recording (lib/include/pendulum/report/recording_report.hpp)
// and how the report draws an unknown uncertainty (a singular fit).
//
// The recordings are the seeded simulations of tests/recording_simulation.hpp
// (RK4 of Nelson & Olsson Eqs. 1, 30, 35): their exact turning times, where
// the gyroscope's signal crosses zero, come from the integration, not from
// the code under test.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pendulum/amplitude.hpp"
#include "pendulum/recordings/swings.hpp"
#include "pendulum/report/html_report.hpp"
#include "pendulum/report/plots.hpp"
#include "pendulum/report/recording_report.hpp"
#include "recording_simulation.hpp"

using namespace pendulum;
using namespace pendulum::report;
using Catch::Matchers::Contains;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A phyphox gyroscope recording as the reader would return it.
Recording gyroscope(const test::RecordingSimulation& s, test::SimulatedRecording& truth) {
  truth = test::simulate_recording(s);
  Recording r;
  r.format = RecordingFormat::phyphox;
  r.kind = SignalKind::angular_rate;
  r.time = truth.t;
  r.channels = {truth.rate[0], truth.rate[1], truth.rate[2]};
  r.rows = truth.t.size();
  return r;
}

constexpr std::size_t kColumns = 720;

// What a drawn trace of (time, value) must keep, checked against the whole
// record by brute force. Each returns what is missing first, or "".
// Only samples, in time order, the first and the last among them.
std::string not_samples(const SignalTrace& trace, const std::vector<double>& time, const std::vector<double>& value) {
  std::size_t at = 0;
  for (std::size_t k = 0; k < trace.time.size(); ++k) {
    while (at < time.size() && time[at] < trace.time[k]) ++at;
    if (at == time.size() || time[at] != trace.time[k] || value[at] != trace.value[k]) {
      return "trace point " + std::to_string(k) + " is not a sample in time order";
    }
  }
  if (trace.time.front() != time.front() || trace.time.back() != time.back()) return "the first or last sample";
  return "";
}

// The least and the greatest sample of each of the `kColumns` equal time slices.
std::string missing_extremes(const SignalTrace& trace, const std::vector<double>& time,
                             const std::vector<double>& value) {
  const double t0 = time.front(), span = time.back() - t0, width = span / kColumns;
  std::vector<double> lo(kColumns, INFINITY), hi(kColumns, -INFINITY);
  for (std::size_t k = 0; k < time.size(); ++k) {
    const std::size_t c = std::min(kColumns - 1, static_cast<std::size_t>((time[k] - t0) / span * kColumns));
    lo[c] = std::min(lo[c], value[k]);
    hi[c] = std::max(hi[c], value[k]);
  }
  for (std::size_t c = 0; c < kColumns; ++c) {
    const double a = t0 + c * width, b = a + width;
    bool has_lo = false, has_hi = false;
    for (std::size_t k = 0; k < trace.time.size(); ++k) {
      if (trace.time[k] < a - 1e-9 || trace.time[k] > b + 1e-9) continue;
      has_lo = has_lo || trace.value[k] == lo[c];
      has_hi = has_hi || trace.value[k] == hi[c];
    }
    if (!has_lo || !has_hi) return "the extremes of slice " + std::to_string(c);
  }
  return "";
}

// For each crossing time, a segment of the drawn line that changes sign
// within one slice of it.
std::string missing_crossing(const SignalTrace& trace, const std::vector<double>& time,
                             const std::vector<double>& crossings) {
  const double width = (time.back() - time.front()) / kColumns;
  for (double c : crossings) {
    bool found = false;
    for (std::size_t k = 0; k + 1 < trace.time.size() && !found; ++k) {
      found = trace.time[k + 1] >= c - width && trace.time[k] <= c + width &&
              (trace.value[k] < 0.0) != (trace.value[k + 1] < 0.0);
    }
    if (!found) return "the crossing at " + std::to_string(c) + " s";
  }
  return "";
}

}  // namespace

TEST_CASE("Decimation keeps every slice's extremes and a sign change at every crossing", "[report][recording]") {
  // One hour at 50 Hz (180 000 samples, 2.8 periods per slice of 5 s):
  // alpha and beta of the benchmark's one-hour recording, seed 3.
  test::RecordingSimulation s;
  s.duration = 3600.0, s.rate_hz = 50.0, s.alpha = 2e-4, s.beta = 4e-4, s.seed = 3;
  test::SimulatedRecording truth;
  const Recording rec = gyroscope(s, truth);
  const std::vector<double> signal = swing_signal(rec);
  REQUIRE(signal.size() == rec.time.size());
  // The true crossings of the signal, omega = 0, within the record.
  std::vector<double> crossings;
  for (double t : truth.turning_times) {
    if (t > rec.time.front() && t < rec.time.back()) crossings.push_back(t);
  }
  INFO(crossings.size() << " crossings");
  REQUIRE(crossings.size() > 3900);

  const SignalTrace trace = decimate_signal(rec.time, signal, kColumns);
  CHECK(trace.time.size() <= 2 * kColumns + 2);
  CHECK(not_samples(trace, rec.time, signal) == "");
  CHECK(missing_extremes(trace, rec.time, signal) == "");
  CHECK(missing_crossing(trace, rec.time, crossings) == "");
  const auto [lo, hi] = std::minmax_element(signal.begin(), signal.end());
  CHECK(std::count(trace.value.begin(), trace.value.end(), *lo) >= 1);
  CHECK(std::count(trace.value.begin(), trace.value.end(), *hi) >= 1);

  // The check can fail: every k-th sample to as many points loses the
  // extremes, and the greatest sample per slice alone loses the crossings.
  SignalTrace stride, upper;
  const std::size_t step = rec.time.size() / trace.time.size();
  for (std::size_t k = 0; k < rec.time.size(); k += step) stride.time.push_back(rec.time[k]), stride.value.push_back(signal[k]);
  stride.time.push_back(rec.time.back()), stride.value.push_back(signal.back());
  CHECK(not_samples(stride, rec.time, signal) == "");
  CHECK_THAT(missing_extremes(stride, rec.time, signal), Contains("the extremes of slice"));
  for (std::size_t k = 0; k < trace.time.size(); ++k) {
    if (trace.value[k] > 0.0 || k == 0 || k + 1 == trace.time.size()) {
      upper.time.push_back(trace.time[k]), upper.value.push_back(trace.value[k]);
    }
  }
  CHECK_THAT(missing_crossing(upper, rec.time, crossings), Contains("the crossing at"));

  // A short record is drawn whole.
  const std::vector<double> t = {0.0, 1.0, 2.0}, v = {1.0, -1.0, 1.0};
  CHECK(decimate_signal(t, v, 2).time == t);
  CHECK_THROWS_AS(decimate_signal(t, {1.0}, 2), std::invalid_argument);
}

TEST_CASE("A one-hour recording's report: every crossing marked, the period on Eq. (8), a small page",
          "[report][recording]") {
  test::RecordingSimulation s;
  s.duration = 3600.0, s.rate_hz = 50.0, s.alpha = 2e-4, s.beta = 4e-4, s.seed = 3;
  test::SimulatedRecording truth;
  const Recording rec = gyroscope(s, truth);
  const RecordingSummary summary{"hour.csv", rec.format, rec.kind, rec.rows, 0, analyse_swings(rec, "hour.csv")};
  const RecordingRecord r = make_recording_record(summary, &rec);
  REQUIRE(r.trace);
  CHECK(r.samples == rec.time.size());

  // The crossings the analysis found are marked, at zero: an hour's (over
  // 3000) one tick per n, n the fewest that keeps them to kMaxCrossingTicks
  // (beyond about 250, 2.5 px apart, they merged into a band), said so.
  const auto signal = signal_figure(r, "s");
  REQUIRE(signal);
  const Points& ticks = signal->panels[0].points[0];
  const std::size_t n = summary.swings.crossings.size();
  const std::size_t every = (n + kMaxCrossingTicks - 1) / kMaxCrossingTicks;
  REQUIRE(every > 1);
  CHECK(ticks.x.size() <= kMaxCrossingTicks);
  REQUIRE(ticks.x.size() == (n + every - 1) / every);
  for (std::size_t i = 0; i < ticks.x.size(); ++i) CHECK(ticks.x[i] == summary.swings.crossings[i * every].time);
  CHECK_THAT(signal->description, Contains("one tick per " + std::to_string(every) + " crossings"));
  CHECK(std::all_of(ticks.y.begin(), ticks.y.end(), [](double y) { return y == 0.0; }));

  // Period against amplitude: the measured periods follow the exact period
  // T0 (1 + DeltaT/T0), whose change over the record (theta0 from 0.25 to
  // 0.13 rad: 3.9 ms to 1.1 ms of T0) is many error bars; a period that did
  // not depend on the amplitude (T0 times the record's mean factor) does not.
  const auto pa = period_amplitude_figure(r, "p");
  REQUIRE(pa);
  const Points& obs = pa->panels[0].points[0];
  const Points& residuals = pa->panels[1].points[0];
  REQUIRE(obs.x.size() >= 150);
  REQUIRE(obs.x.size() <= 200);
  // T0 by the stated least squares, sum T f / sum f^2.
  double tf = 0.0, ff = 0.0, chi2 = 0.0, chi2_flat = 0.0, mean = 0.0;
  for (std::size_t i = 0; i < obs.x.size(); ++i) {
    const double f = 1.0 + finite_amplitude_agm(obs.x[i] * kPi / 180.0);
    tf += obs.y[i] * f, ff += f * f, mean += obs.y[i] / obs.y.size();
  }
  // T0 against the true 2 pi sqrt(l/g) = 1.7945870 s (docs/recordings.md),
  // to 1e-5 of itself (the damping terms and the amplitudes' noise).
  CHECK(tf / ff == Approx(2.0 * kPi * std::sqrt(0.80 / 9.80665)).epsilon(1e-5));
  for (std::size_t i = 0; i < obs.x.size(); ++i) {
    const double theta = obs.x[i] * kPi / 180.0;
    const double theory = tf / ff * (1.0 + finite_amplitude_agm(theta));
    CHECK(residuals.y[i] == Approx(obs.y[i] - theory).margin(1e-15));
    chi2 += std::pow(residuals.y[i] / obs.y_error[i], 2);
    chi2_flat += std::pow((obs.y[i] - mean) / obs.y_error[i], 2);
  }
  const double dof = static_cast<double>(obs.x.size());
  INFO(obs.x.size() << " points, chi2/dof against Eq. (8) " << chi2 / dof << ", against a flat period " << chi2_flat / dof);
  // Error bars sqrt(sigma_a^2 + sigma_b^2) / m: chi2/dof is 1 within a few
  // sqrt(2/dof) = 0.1 when they are honest.
  CHECK(chi2 / dof > 0.6);
  CHECK(chi2 / dof < 1.4);
  // The amplitude's effect is seen: one parameter each, chi2 smaller by far
  // more than 25 (5 sigma).
  CHECK(chi2_flat - chi2 > 25.0);

  // The page's plots stay small: the signal is 2 points per slice, the
  // crossings and the 4000 amplitudes one path each.
  const auto amplitude = amplitude_figure(r, "a");
  REQUIRE(amplitude);
  const std::string svg = to_svg(*signal, false) + to_svg(*amplitude, false) + to_svg(*pa, false);
  INFO("SVG bytes: signal " << to_svg(*signal, false).size() << ", amplitude " << to_svg(*amplitude, false).size()
                            << ", period-amplitude " << to_svg(*pa, false).size());
  CHECK(svg.size() < 400000);
  CHECK(count(svg, "<circle") < 500);
}

TEST_CASE("An unknown uncertainty is drawn as unknown, never as +- 0", "[report][uncertainty]") {
  CHECK(estimate_text({9.80340, std::nullopt}, 5, "m/s\u00B2") == "9.80340 m/s\u00B2 (uncertainty unknown)");
  CHECK(estimate_text({9.80340, 0.00148}, 5, "m/s\u00B2") == "9.80340 \u00B1 0.00148 m/s\u00B2");

  // The class chart: no error bar for the unknown one, and its row says so.
  ClassPoint known{"a.json", "#scene-1", 9.80, 0.01, Measured{9.81, 0.0}, -1.0};
  ClassPoint unknown{"b.json", "#scene-2", 9.813, std::nullopt, Measured{9.81, 0.0}, std::nullopt};
  ClassPoint small = unknown;  // an error bar within the same axis
  small.uncertainty = 0.001;
  small.z = 5.0;
  const CategoryChart both = class_chart({known, unknown}, "c");
  CHECK(both.notes[1] == "uncertainty unknown");
  const std::string with_unknown = to_svg(both, false), all_known = to_svg(class_chart({known, small}, "c"), false);
  // An error bar is three lines (the bar and two caps).
  CHECK(count(all_known, "<line") - count(with_unknown, "<line") == 3);
  CHECK_THAT(with_unknown, Contains("uncertainty unknown"));

  // A decay fit whose covariance is singular: the fit, no band, and the legend says why.
  DecayRecord d;
  d.times = {0.0, 10.0, 20.0, 30.0};
  d.amplitudes = {0.10, 0.09, 0.081, 0.073};
  d.fitted = d.amplitudes;
  d.grid = d.times;
  d.grid_fit = d.amplitudes;
  d.model = "Eq. (25)";
  const std::string no_band = to_svg(decay_figure(d, "d"), false);
  CHECK(count(no_band, "<polygon") == 0);
  CHECK_THAT(no_band, Contains("uncertainty unknown (singular covariance): no band"));
  d.grid_uncertainty = {0.001, 0.001, 0.001, 0.001};
  CHECK(count(to_svg(decay_figure(d, "d"), false), "<polygon") == 1);

  // A correction whose uncertainty is unknown: no error bar, and its note says so.
  SceneReport r;
  r.corrections = {{"finite_amplitude", "Finite amplitude", "applied", "", "", "", 596e-6, std::nullopt, 0.0},
                   {"air_buoyancy", "Buoyancy", "applied", "", "", "", 120e-6, 10e-6, 0.0}};
  const auto chart = corrections_chart(r, "k");
  REQUIRE(chart);
  CHECK(chart->notes[0] == "+596 \u00B5s, uncertainty unknown");
  CHECK(chart->notes[1] == "+120 \u00B5s");
}

TEST_CASE("A pixel track's signal is drawn in the track's own unit and values", "[report][recording]") {
  // A 0.80 m pendulum released at 0.25 rad, filmed at 30 frames/s and 1000
  // px/m (tests/recording_simulation.hpp's pixel_track layout): the bob's x
  // swings by 1000 L sin(theta) px about the middle, 198 px at the release.
  // Before, the axis said "(track unit)" and drew the angle in rad (+-0.25).
  test::RecordingSimulation s;
  s.duration = 20.0, s.drop = 0.0, s.noise = 0.0, s.rate_hz = 30.0;
  const auto sim = test::simulate_recording(s);
  const Recording rec = parse_recording(test::published_csv(sim, s.length, test::PublishedLayout::pixel_track, 0.0, 1),
                                        "track.csv", RecordingFormat::automatic, {}, {});
  REQUIRE(rec.kind == SignalKind::position);
  const RecordingSummary summary{"track.csv", rec.format, rec.kind, rec.rows, 0, analyse_swings(rec, "track.csv"),
                                 "", rec.columns};
  const RecordingRecord r = make_recording_record(summary, &rec);
  REQUIRE(r.trace);
  CHECK(r.trace_label == "position on the principal axis (px)");
  double swing = 0.0, drawn = 0.0;
  for (double th : sim.theta) swing = std::max(swing, 1000.0 * s.length * std::abs(std::sin(th)));
  for (double v : r.trace->value) drawn = std::max(drawn, std::abs(v));
  // The mean removed is the track's over 20 s of a damped swing: within 1%.
  CHECK(drawn == Approx(swing).epsilon(0.01));
  CHECK_THAT(to_svg(*signal_figure(r, "s"), false), Contains("(px)"));
}

TEST_CASE("A report says what the clean stretch cut and bridged, and shades it on the signal", "[report][recording]") {
  // A 60 s gyroscope recording (the simulation's defaults, seed 31) with 2 s
  // of rows missing at 24-26 s, bridged by default, and a +1 s clock jump at
  // 45 s, whose shorter side is cut (tests/test_swing_stamps.cpp, the same cases).
  test::SimulatedRecording sim;
  test::RecordingSimulation s;
  s.seed = 31;
  const Recording whole = gyroscope(s, sim);
  Recording r = whole;
  r.time.clear();
  for (auto& c : r.channels) c.clear();
  for (std::size_t k = 0; k < whole.time.size(); ++k) {
    if (whole.time[k] > 24.0 && whole.time[k] < 26.0) continue;
    r.time.push_back(whole.time[k] + (whole.time[k] > 45.0 ? 1.0 : 0.0));
    for (int j = 0; j < 3; ++j) r.channels[j].push_back(whole.channels[j][k]);
  }
  const SwingAnalysis a = analyse_swings(r, "cut.csv");
  REQUIRE(a.cuts.size() == 2);
  const RecordingSummary summary{"cut.csv", r.format, r.kind, r.time.size(), 0, a, "", {}};
  const RecordingRecord record = make_recording_record(summary, &r);
  CHECK(record.cuts.size() == 2);
  const std::string html = recording_report_html(record);
  CHECK_THAT(html, Contains(">stretch analysed<") && Contains(">bridged<") && Contains(">cut<") &&
                       Contains("a glitch inside, its count carried across") &&
                       Contains("the shorter side of a glitch") && Contains(">whole record&#39;s period<"));
  const std::string svg = to_svg(*signal_figure(record, "s"), false);
  CHECK_THAT(svg, Contains("cut by default (the clean stretch), or bridged with its count carried"));
}

TEST_CASE("A page prints the period to the crossing fit's own clock floor, as the JSON does", "[report][recording]") {
  // A 60 s gyroscope recording (the simulation's defaults, seed 7) whose
  // stamps are printed to 10 ms: the crossing fit floors its uncertainty at
  // the clock's (q^2/12 a crossing through the slope), which the JSON
  // states. The page used sqrt(2) q / N instead (4e-4 s over 33 periods,
  // many times the fit's), rounding the period coarser than the JSON says:
  // a held-frames track read 0.8600 +- 0.0059 s on its page, +- 0.0011 s in
  // its JSON.
  test::SimulatedRecording sim;
  test::RecordingSimulation s;
  s.seed = 7;
  Recording rec = gyroscope(s, sim);
  for (double& t : rec.time) t = std::round(t / 0.01) * 0.01;
  rec.time_quantum = 0.01;
  const RecordingSummary summary{"stamps.csv", rec.format, rec.kind, rec.rows, 0, analyse_swings(rec, "stamps.csv")};
  REQUIRE(summary.swings.period.resolution_floor > 0.0);
  const RecordingRecord r = make_recording_record(summary, &rec);
  CHECK(r.period_resolution == summary.swings.period.resolution_floor);
  const std::string html = recording_report_html(r);
  CHECK_THAT(html, Contains("T = " + value_with_uncertainty(r.period.value, r.period.uncertainty, false) + " s") &&
                       !Contains("below the clock's resolution"));
}
