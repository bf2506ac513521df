#include "parts.hpp"

#include <algorithm>
#include <cmath>

#include "pendulum/air.hpp"
#include "pendulum/argument_ranges.hpp"
#include "pendulum/numeric.hpp"
#include "recording_reader.hpp"

namespace pendulum::json_reader {

namespace {

/// air: "vacuum", or pressure and temperature (molar mass and viscosity
/// default to dry air's).
void read_air(const json& air, ParsedScene& out) {
  if (air.is_string()) {
    PENDULUM_FAIL_IF(air.get<std::string>() != "vacuum", "air",
                     "got " + shown(air) + "; expected \"vacuum\" or an object with pressure and temperature");
    out.apparatus.vacuum = true;
    return;
  }
  Object o(air, "air", "\"vacuum\" or an object with pressure and temperature");
  auto& pv = out.apparatus.air.emplace();
  auto& pu = out.apparatus_uncertainty.air.emplace();
  put(o, "pressure", Dimension::pressure, Range::positive, pv.pressure, pu.pressure);
  put(o, "temperature", Dimension::temperature, Range::positive, pv.temperature, pu.temperature);
  // A laboratory's gas: 25 "K" meant degC, 296 "degC" meant K, 28.96 "kg/mol" meant g/mol.
  const double as_kelvin = pv.temperature - 273.15;  // the value typed, were it in K
  const bool kelvin = as_kelvin - 273.15 >= 5.0 && as_kelvin - 273.15 <= 40.0;
  within(pv.temperature, 150.0, 500.0, "air.temperature.value", "K",
         "the temperature of a laboratory's air, 150 K to 500 K (-123 degC to 227 degC)" +
             (kelvin ? "; " + format_number(as_kelvin, 5) + " K is " + format_number(as_kelvin - 273.15, 3) +
                           " degC: kelvin written as degC? fix air.temperature.unit (\"K\")"
                     : std::string()));
  // Thinner air is a vacuum; and its density would near a double's underflow.
  within(pv.pressure, 1e-12, HUGE_VAL, "air.pressure.value", "Pa",
         "at least 1e-12 Pa, an ultra-high vacuum (for less, \"air\": \"vacuum\")");
  if (o.has("molar_mass")) {
    put(o, "molar_mass", Dimension::molar_mass, Range::positive, pv.molar_mass, pu.molar_mass);
    within(pv.molar_mass, 1e-3, 1.0, "air.molar_mass.value", "kg/mol",
           "the molar mass of a gas, 0.001 to 1 kg/mol (air 0.02896)");
  } else {
    pv.molar_mass = kDryAirMolarMass;
    pu.molar_mass = 0.0;
    out.assumptions.push_back("air.molar_mass: not given; dry air, 0.02896 kg/mol");
  }
  if (o.has("viscosity")) {
    put(o, "viscosity", Dimension::viscosity, Range::positive, pv.viscosity, pu.viscosity);
    within(pv.viscosity, 1e-6, 1e-4, "air.viscosity.value", "Pa s",
           "the viscosity of a gas, 1e-6 to 1e-4 Pa s (air 1.8e-5)");
  } else {
    pv.viscosity = air_viscosity(pv.temperature);
    pu.viscosity = 0.0;
    out.assumptions.push_back("air.viscosity: not given; Sutherland's law gives " + format_number(pv.viscosity) +
                              " Pa s");
  }
  o.finish();
  const double rho = air_density(pv.pressure, pv.temperature, pv.molar_mass);
  PENDULUM_FAIL_IF(rho > 100.0, "air",
                   "density " + format_number(rho) +
                       " kg/m^3 from this pressure, temperature and molar mass; expected a gas (below 100 kg/m^3)");
  if (out.apparatus.cap && !out.apparatus.cap->volume) {
    out.warnings.push_back("cap.volume: not given; buoyancy and added mass count the bob's volume only");
  }
}

/// A person starting and stopping a stopwatch scatters a trial by about this
/// much (s, standard deviation; reaction times of about 0.07 s at each end)...
constexpr double kReactionTime = 0.1;
/// ...on a timer read to this resolution (s) or coarser, or of no stated
/// resolution: a phone's or a stopwatch's 0.01 s. A finer one is a gate's.
constexpr double kHandTimerResolution = 0.01;

/// Warns about trials (in `unit`, of `seconds` s, each of `oscillations`)
/// that disagree more than they should: one far from the others (off by
/// whole periods: a miscounted oscillation; by a fraction of one: a
/// stopwatch started or stopped off; or a typo), or a scatter far beyond
/// the stated one-trial uncertainty. A scatter beyond
/// the resolution alone is normal: a hand on a stopwatch scatters more than
/// its last digit, and with five trials the median deviation alone is no
/// measure of it (issue 14: 33 of 300 clean hand-timed scenes drew this
/// warning), so a hand-read timer's trials may stray by 5 reaction times.
void warn_about_trials(const std::string& path, const std::vector<double>& times, int oscillations, double spread,
                       std::optional<double> resolution, std::optional<double> trial_sigma, const std::string& unit,
                       double seconds, std::vector<std::string>& warnings, std::vector<std::string>& suspicions) {
  auto in_unit = [&](double x) { return format_number(x, 4) + " " + unit; };
  if (trial_sigma && spread > 3.0 * *trial_sigma) {
    warnings.push_back(path + ".uncertainty: the trials scatter by " + in_unit(spread) +
                       " (standard deviation), over 3 times the stated one-trial uncertainty " +
                       in_unit(*trial_sigma) + "; the period's uncertainty uses the scatter");
  }
  if (times.size() < 3) return;  // two trials: no telling which one is off
  // The median and the median absolute deviation (MAD), which one bad trial
  // cannot drag; 1.4826 MAD estimates the standard deviation of the others.
  auto median = [](std::vector<double> x) {
    const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
    std::nth_element(x.begin(), mid, x.end());
    const double upper = *mid;
    if (x.size() % 2) return upper;
    return (*std::max_element(x.begin(), mid) + upper) / 2.0;
  };
  const double centre = median(times);
  std::vector<double> deviation(times.size());
  for (std::size_t i = 0; i < times.size(); ++i) deviation[i] = std::abs(times[i] - centre);
  const double scatter = 1.4826 * median(deviation);
  const bool by_hand = !resolution || *resolution * seconds >= kHandTimerResolution * (1.0 - 1e-9);
  const double reaction = by_hand ? kReactionTime / seconds : 0.0;
  const double allowed =
      5.0 * std::max({scatter, resolution.value_or(0.0), trial_sigma.value_or(0.0), reaction});
  const auto worst = std::max_element(deviation.begin(), deviation.end());
  if (allowed == 0.0 || *worst <= allowed) return;
  std::vector<std::string> allowance{"the trials' scatter (" + in_unit(scatter) + ")"};
  if (resolution) allowance.push_back("the resolution (" + in_unit(*resolution) + ")");
  if (trial_sigma) allowance.push_back("the stated uncertainty (" + in_unit(*trial_sigma) + ")");
  if (by_hand) allowance.push_back("a hand's reaction time (" + in_unit(reaction) + ")");
  std::string largest = allowance.size() > 1 ? "the largest of " : "";
  for (std::size_t k = 0; k < allowance.size(); ++k) {
    largest += (k == 0 ? "" : k + 1 == allowance.size() ? " and " : ", ") + allowance[k];
  }
  const auto i = static_cast<std::size_t>(worst - deviation.begin());
  // In periods of the median trial: whole ones (within a tenth) are a
  // count; under 0.9 of one, the hand on the stopwatch (and about half of
  // one, a pass counted as a swing); more and not whole, neither.
  const double periods = *worst / (centre / oscillations);
  const bool counted = std::abs(periods - std::round(periods)) <= 0.1 && periods >= 0.9;
  const bool hand = periods < 0.9;
  const std::string late = times[i] < centre ? "started late or stopped early" : "started early or stopped late";
  const bool half = std::abs(periods - 0.5) <= 0.1;
  const std::string trial = path + ".trials[" + std::to_string(i) + "]: " + format_number(times[i]) + " " + unit;
  suspicions.push_back(trial + ", far from the other trials (warnings): " +
                       (counted ? std::string("a miscounted oscillation? Count again, or drop the trial")
                        : hand  ? "a stopwatch " + late + " by " + in_unit(*worst) + " (" + format_number(periods, 2) +
                                     " of a period)" +
                                     (half ? ", or a pass counted as a swing" : ", too little for a miscounted oscillation") +
                                     "? Time it again, or drop the trial"
                                : "a typo (" + format_number(periods, 2) + " periods off: neither whole periods nor "
                                  "a stopwatch's fraction of one)? Check it, or drop the trial"));
  warnings.push_back(trial + " is " + in_unit(*worst) + " from the median trial " + format_number(centre) + " " + unit +
                     ", over 5 times " + largest +
                     (counted ? std::string("; a miscounted oscillation or a typo?")
                      : hand  ? "; " + format_number(periods, 2) + " of a period: a stopwatch " + late +
                                   (half ? ", a pass counted as a swing" : "") + ", or a typo?"
                              : "; " + format_number(periods, 2) + " periods: a typo?"));
}

/// Trials that are a stopwatch's lap totals, each the sum of the laps
/// before it: increasing, and their differences (the first trial the first
/// difference) within 15% of their median. Refused, as no mean of them
/// means anything, with the differences to give instead.
void refuse_lap_totals(const std::string& path, const std::vector<double>& times, const std::string& unit) {
  constexpr double kLapTolerance = 0.15;
  if (times.size() < 2) return;
  std::vector<double> laps{times.front()};
  for (std::size_t i = 1; i < times.size(); ++i) laps.push_back(times[i] - times[i - 1]);
  std::vector<double> sorted = laps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double lap = sorted[sorted.size() / 2];
  for (double d : laps) {
    if (!(std::abs(d / lap - 1.0) <= kLapTolerance)) return;
  }
  std::string differences;
  for (double d : laps) differences += (differences.empty() ? "" : ", ") + format_number(d, 6);
  throw InputError(path, "these look like a stopwatch's lap totals: give differences, the time of each trial: [" +
                             differences + "] (got " + format_number(times.front()) + ", " + format_number(times[1]) +
                             (times.size() > 2 ? ", ..." : "") + " " + unit + ", each about " + format_number(lap, 4) +
                             " " + unit + " more than the one before: the time since the start, not since the last "
                             "lap)");
}

/// Trials pasted rather than timed, on a hand's timer, whose reaction-time
/// scatter (kReactionTime) spans many of its digits: every one of 4 or more
/// trials the same to the last digit, or, among 6 or more, a run of 4 equal
/// ones (a paste down a column) or two thirds of them equal, at least 4,
/// wherever they stand (a paste over a few cells). Four equal among five
/// anywhere is not enough: 3 of 300 clean hand-timed scenes
/// (tests/test_status.cpp's, 0.05 s scatter read to 0.01 s) hold that by
/// chance. Four of six hold it by chance with probability 0.0034 at that
/// scatter, 0.00045 at kReactionTime's (tests/test_status.cpp).
void suspect_pasted_trials(const std::string& path, const std::vector<double>& times, std::optional<double> resolution,
                           const std::string& unit, double seconds, std::vector<std::string>& suspicions) {
  const bool by_hand = !resolution || *resolution * seconds >= kHandTimerResolution * (1.0 - 1e-9);
  if (!by_hand || times.size() < 4) return;
  constexpr std::size_t kPastedRun = 4, kTrialsForRun = 6;
  std::size_t most = 0, run = 1, longest = 1;
  double value = times.front();
  for (double x : times) {
    const auto same = static_cast<std::size_t>(std::count(times.begin(), times.end(), x));
    if (same > most) most = same, value = x;
  }
  for (std::size_t i = 1; i < times.size(); ++i) {
    run = times[i] == times[i - 1] ? run + 1 : 1;
    longest = std::max(longest, run);
  }
  const std::size_t two_thirds = std::max(kPastedRun, (2 * times.size() + 2) / 3);
  const bool many = times.size() >= kTrialsForRun && (longest >= kPastedRun || most >= two_thirds);
  if (most != times.size() && !many) return;
  suspicions.push_back(path + ".trials: " + std::to_string(most) + " of " + std::to_string(times.size()) +
                       " trials are " + format_number(value) + " " + unit +
                       ", the same to the last digit, while a hand on a stopwatch scatters by about " +
                       format_number(kReactionTime) + " s: pasted? Give each trial as timed, else the period's "
                       "uncertainty is too small");
}

}  // namespace

void read_timing(Object& parent, const std::string& prefix, Observation<double>& value, Observation<double>& sigma,
                 ObservationSource& source, ParsedScene& out) {
  Object t(parent.at("timing"), prefix + "timing");
  const json& n_json = t.at("oscillations_per_trial");
  // 10.0 is the whole number 10, as a spreadsheet writes it.
  const double n_value = n_json.is_number() ? n_json.get<double>() : 0.0;
  if (!(n_value >= 1.0 && n_value <= 1e9 && n_value == std::floor(n_value))) {
    throw InputError(t.path("oscillations_per_trial"),
                     "got " + shown(n_json) + "; expected a positive whole number of oscillations (an "
                     "oscillation is a full swing, there and back)");
  }
  const int n_osc = static_cast<int>(n_value);
  // Trials written as quantities, each with its unit, are the usual slip.
  PENDULUM_FAIL_IF(!t.has("unit"), t.path("unit"),
                   "missing; expected the unit of the trial times, e.g. \"unit\": \"s\", with \"trials\" a list "
                   "of plain numbers in it");
  const std::string unit_name = t.text("unit");
  const auto unit = find_unit(unit_name, Dimension::time);
  if (!unit) {
    throw InputError(t.path("unit"), "got " + shown(t.at("unit")) + "; expected a unit of a time: " +
                                         unit_names(Dimension::time));
  }
  const json& trials = t.at("trials");
  if (!trials.is_array() || trials.empty()) {
    throw InputError(t.path("trials"), "got " + shown(trials) +
                                           "; expected a non-empty array of trial times");
  }
  std::vector<double> times;  // in `unit`
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const auto p = [&] { return t.path("trials") + "[" + std::to_string(i) + "]"; };
    const double x = finite_number(trials[i], p, "a time (number)");
    if (x <= 0.0) {
      throw InputError(p(), "got " + format_number(x) + " " + unit_name +
                                "; expected a positive time");
    }
    times.push_back(x);
  }
  // A bare number in the trials' unit, or a quantity like any other.
  auto optional_time = [&](const char* key) -> std::optional<double> {
    if (!t.has(key)) return std::nullopt;
    const double x = t.at(key).is_object()
                         ? quantity(t, key, Dimension::time, Range::any).value / unit->factor
                         : finite_number(t.at(key), [&] { return t.path(key); }, "a number or a quantity");
    if (x <= 0.0) {
      throw InputError(t.path(key), "got " + format_number(x) + " " + unit_name +
                                        "; expected a positive time");
    }
    const std::string why = out_of_range(ranges::timing_uncertainty, x * unit->factor);
    PENDULUM_FAIL_IF(!why.empty(), t.path(key), why);
    return x;
  };
  const std::optional<double> resolution = optional_time("resolution");
  const std::optional<double> trial_sigma = optional_time("uncertainty");
  if (t.has("source")) t.text("source");
  t.finish();

  // In the file's unit, and relative to the mean so that no sum overflows.
  auto in_unit = [&](double x) { return format_number(x) + " " + unit_name; };
  const double n = static_cast<double>(times.size());
  double mean = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) mean += (times[i] - mean) / (i + 1.0);
  // Beyond a third of the mean, a one-trial uncertainty leaves a mean +-
  // standard error (N&O Eq. 4) that means nothing: trials of different
  // oscillation counts or units, or a wrong resolution.
  PENDULUM_FAIL_IF(resolution && *resolution >= mean, t.path("resolution"),
          "got " + in_unit(resolution.value_or(0.0)) +
              "; expected a resolution finer than the mean trial (" + in_unit(mean) + ")");
  PENDULUM_FAIL_IF(trial_sigma && *trial_sigma > mean / 3.0, t.path("uncertainty"),
          "got " + in_unit(trial_sigma.value_or(0.0)) +
              "; expected a one-trial uncertainty below a third of the mean trial (" +
              in_unit(mean) + ")");
  refuse_lap_totals(t.path("trials"), times, unit_name);
  double sigma_trial = 0.0;
  const std::string period_path = prefix + "timing.period";
  InputEvaluation evaluation{period_path};
  if (times.size() >= 2) {
    double ss = 0.0;
    for (double x : times) ss += (x / mean - 1.0) * (x / mean - 1.0);
    const double spread = std::sqrt(ss / (n - 1.0)) * mean;
    const auto [lo, hi] = std::minmax_element(times.begin(), times.end());
    PENDULUM_FAIL_IF(spread > mean / 3.0, t.path("trials"),
            "got trials from " + format_number(*lo) + " to " + in_unit(*hi) +
                ", a standard deviation over a third of their mean " + in_unit(mean) +
                "; expected repeated timings of the same oscillations (a mean of these means nothing)");
    // The resolution and a stated uncertainty are floors: a scatter below
    // them is luck.
    const double floor = std::max(resolution.value_or(0.0) / std::sqrt(12.0), trial_sigma.value_or(0.0));
    sigma_trial = std::max(spread, floor);
    source.trial_scatter = ObservationSource::TrialScatter{spread * unit->factor, floor * unit->factor,
                                                          floor != trial_sigma.value_or(0.0)};
    // GUM 4.2: the scatter is a Type A evaluation (the mean of n readings, a
    // t with n - 1 degrees of freedom, S1 6.4.9); a floor that wins is Type B.
    evaluation = sigma_trial == spread ? InputEvaluation{period_path, 'A', Distribution::student_t, n - 1.0}
                 : sigma_trial == trial_sigma.value_or(0.0) ? InputEvaluation{period_path}
                                                            : InputEvaluation{period_path, 'B', Distribution::rectangular};
    if (sigma_trial == 0.0) {
      out.warnings.push_back(
          t.path("trials") + ": all trials are equal and no resolution is given, so "
          "the period's uncertainty is 0; state timing.resolution");
    }
    warn_about_trials(t.path(), times, n_osc, spread, resolution, trial_sigma, unit_name, unit->factor,
                      out.warnings, out.suspicions);
    suspect_pasted_trials(t.path(), times, resolution, unit_name, unit->factor, out.suspicions);
  } else if (trial_sigma) {
    sigma_trial = *trial_sigma;
    out.assumptions.push_back(
        t.path() + ": a single trial; its uncertainty is timing.uncertainty");
  } else if (resolution) {
    sigma_trial = *resolution / std::sqrt(12.0);
    evaluation.distribution = Distribution::rectangular;
    out.assumptions.push_back(
        t.path() + ": a single trial; its uncertainty is timing.resolution/sqrt(12)");
  } else {
    throw InputError(t.path("trials"),
                     "got a single trial; expected two or more, or a single one "
                     "with timing.uncertainty or timing.resolution");
  }
  source.trial_count = static_cast<int>(times.size());
  out.evaluations.push_back(evaluation);
  value.oscillations_per_trial = n_osc;
  sigma.oscillations_per_trial = n_osc;
  value.period = mean * unit->factor / n_osc;
  sigma.period = sigma_trial * unit->factor / std::sqrt(n) / n_osc;
}

void read_parts(Object& top, ParsedScene& out) {
  Apparatus<double>& v = out.apparatus;
  Apparatus<double>& u = out.apparatus_uncertainty;
  if (top.has("bob")) {
    Object bob(top.at("bob"), "bob");
    auto& bv = v.bob.emplace();
    auto& bu = u.bob.emplace();
    if (bob.has("shape")) {
      const std::string shape = bob.text("shape");
      PENDULUM_FAIL_IF(shape != "sphere" && shape != "box" && shape != "cylinder", "bob.shape",
                       "got " + shown(bob.at("shape")) + "; expected \"sphere\", \"box\" or \"cylinder\"");
      bv.shape = bu.shape = shape == "box" ? BobShape::box : shape == "cylinder" ? BobShape::cylinder : BobShape::sphere;
    }
    // A ball is measured across: its radius is a slip for the diameter, said as such.
    // (The raw object: Object::has would take "radius" for a known key.)
    const json& written = top.at("bob");
    if (bv.shape != BobShape::box && written.contains("radius") && !written.contains("diameter")) {
      json twice = written.at("radius");
      for (const char* key : {"value", "uncertainty"}) {
        if (twice.is_object() && twice.contains(key) && twice[key].is_number()) twice[key] = 2.0 * twice[key].get<double>();
      }
      throw InputError("bob.radius", "got a radius; expected the diameter, twice it: \"diameter\": " + shown(twice));
    }
    // A shape's own dimensions (apparatus.hpp, Bob), each required.
    if (bv.shape != BobShape::box) put(bob, "diameter", Dimension::length, Range::positive, bv.diameter, bu.diameter);
    if (bv.shape == BobShape::box) put(bob, "width", Dimension::length, Range::positive, bv.width, bu.width);
    if (bv.shape != BobShape::sphere) put(bob, "height", Dimension::length, Range::positive, bv.height, bu.height);
    if (bv.shape == BobShape::box) put(bob, "depth", Dimension::length, Range::positive, bv.depth, bu.depth);
    put(bob, "mass", Dimension::mass, Range::positive, bv.mass, bu.mass);
    bob.finish();
    if (bv.mass) {
      const double density = *bv.mass / bv.volume();
      // A thousandth of it a metal's (aluminium 2700 kg/m^3 and up): a mass in g written as kg.
      const bool grams = density / 1000.0 >= 2000.0 && density / 1000.0 <= kMaxDensity;
      PENDULUM_FAIL_IF(density > kMaxDensity, "bob.mass.value",
                       "got " + format_number(*bv.mass) + " kg, a density of " + format_number(density) +
                           " kg/m^3 for this " + (bv.shape == BobShape::sphere ? "diameter" : "size") +
                           "; expected at most " + format_number(kMaxDensity) +
                           " kg/m^3 (osmium, the densest element)" +
                           (grams ? "; a mass in g written as kg? It gives " + format_number(density / 1000.0, 4) +
                                        " kg/m^3 (brass: 8500, steel: 7850): fix bob.mass.unit (\"g\")"
                                  : std::string()));
    }
  }
  if (top.has("suspension")) {
    const std::string suspension = top.text("suspension");
    PENDULUM_FAIL_IF(suspension != "flexible" && suspension != "rigid", "suspension",
                     "got " + shown(top.at("suspension")) + "; expected \"flexible\" (a string or wire, the "
                     "default) or \"rigid\" (a rod clamped to the bob)");
    PENDULUM_FAIL_IF(!v.bob, "suspension", "got " + shown(top.at("suspension")) + " but no bob; expected a bob "
                     "that hangs from it");
    v.bob->suspension = u.bob->suspension = suspension == "rigid" ? Suspension::rigid : Suspension::flexible;
  }
  // A part's fields are read into `pv` (values) and `pu` (uncertainties); its
  // consistency is checked once no unknown key is left. Every part but the
  // air is a mass or a spring acting on the bob: its correction needs the
  // bob's mass.
  auto part = [&](const char* key, auto& value, auto& sigma, auto&& read, auto&& check) {
    if (!top.has(key)) return;
    Object o(top.at(key), key);
    read(o, value.emplace(), sigma.emplace());
    o.finish();
    PENDULUM_FAIL_IF(!v.bob || !v.bob->mass, key,
                     std::string("got a ") + key + " but no bob.mass; expected the bob's diameter and mass, " +
                         "since its correction is relative to the bob's mass");
    check(*value);
  };
  auto lighter_than_bob = [&](double mass, const std::string& path, const char* what) {
    PENDULUM_FAIL_IF(mass >= *v.bob->mass, path,
                     "got " + format_number(mass) + " kg; expected " + what + " lighter than the bob (" +
                         format_number(*v.bob->mass) +
                         " kg): the corrections are first order in its mass ratio");
  };
  part("ring", v.ring, u.ring, [&](Object& o, Ring<double>& pv, Ring<double>& pu) {
    put(o, "mass", Dimension::mass, Range::positive, pv.mass, pu.mass);
    put(o, "inner_radius", Dimension::length, Range::non_negative, pv.inner_radius, pu.inner_radius);
    put(o, "outer_radius", Dimension::length, Range::positive, pv.outer_radius, pu.outer_radius);
    put(o, "pivot_distance", Dimension::length, Range::non_negative, pv.pivot_distance, pu.pivot_distance);
  }, [&](const Ring<double>& pv) {
    PENDULUM_FAIL_IF(pv.inner_radius >= pv.outer_radius, "ring.inner_radius.value",
                     "got " + format_number(pv.inner_radius) + " m; expected less than ring.outer_radius (" +
                         format_number(pv.outer_radius) + " m)");
    lighter_than_bob(pv.mass, "ring.mass.value", "a ring");
  });
  part("cap", v.cap, u.cap, [&](Object& o, Cap<double>& pv, Cap<double>& pu) {
    put(o, "mass", Dimension::mass, Range::non_negative, pv.mass, pu.mass);
    put(o, "center_distance", Dimension::length, Range::non_negative, pv.center_distance, pu.center_distance);
    put(o, "volume", Dimension::volume, Range::non_negative, pv.volume, pu.volume);
  }, [&](const Cap<double>& pv) { lighter_than_bob(pv.mass, "cap.mass.value", "a cap"); });
  part("cap_screw", v.cap_screw, u.cap_screw,
       [&](Object& o, CapScrew<double>& pv, CapScrew<double>& pu) {
         put(o, "mass_deficit", Dimension::mass, Range::any, pv.mass_deficit, pu.mass_deficit);
         put(o, "center_distance", Dimension::length, Range::non_negative, pv.center_distance,
             pu.center_distance);
       },
       [&](const CapScrew<double>& pv) {
         lighter_than_bob(std::abs(pv.mass_deficit), "cap_screw.mass_deficit.value", "a mass deficit");
         PENDULUM_FAIL_IF(v.bob->shape != BobShape::sphere, "cap_screw",
                          "got a cap screw on a bob.shape other than \"sphere\"; expected it only in a sphere "
                          "(Nelson & Olsson's bob, Sec. III.B.2)");
         PENDULUM_FAIL_IF(pv.center_distance >= v.bob->diameter / 2.0, "cap_screw.center_distance.value",
                          "got " + format_number(pv.center_distance) +
                              " m; expected less than the bob radius (" + format_number(v.bob->diameter / 2.0) +
                              " m): the screw is inside the bob");
       });
  part("wire", v.wire, u.wire, [&](Object& o, Wire<double>& pv, Wire<double>& pu) {
    put(o, "mass", Dimension::mass, Range::positive, pv.mass, pu.mass);
    put(o, "diameter", Dimension::length, Range::positive, pv.diameter, pu.diameter);
    put(o, "youngs_modulus", Dimension::modulus, Range::positive, pv.youngs_modulus, pu.youngs_modulus);
  }, [&](const Wire<double>& pv) {
    lighter_than_bob(pv.mass, "wire.mass.value", "a wire");
    if (pv.diameter) {
      const double across = v.bob->shape == BobShape::box ? std::min(v.bob->width, v.bob->depth) : v.bob->diameter;
      PENDULUM_FAIL_IF(*pv.diameter >= across, "wire.diameter.value",
                       "got " + format_number(*pv.diameter) + " m; expected a wire thinner than the bob (" +
                           format_number(across) + " m)");
    }
    if (!pv.youngs_modulus) return;
    within(*pv.youngs_modulus, 0.0, kMaxYoungsModulus, "wire.youngs_modulus.value", "Pa",
           "at most " + format_number(kMaxYoungsModulus) + " Pa (diamond, the stiffest material)");
    if (!pv.diameter) return;
    // Eq. (79) is the stretch of a stiff wire; the bob's weight over E S is
    // the wire's static strain.
    const double strain =
        *v.bob->mass * kStandardGravity / (*pv.youngs_modulus * kPi * *pv.diameter * *pv.diameter / 4.0);
    PENDULUM_FAIL_IF(!(strain < 0.1), "wire",
                     "got a wire that the bob stretches by " + format_number(100.0 * strain, 3) +
                         "% (weight / (youngs_modulus x cross-section)); expected a stiff wire, "
                         "stretched by less than 10%");
  });
  if (top.has("air")) read_air(top.at("air"), out);
  part("support", v.support, u.support, [&](Object& o, Support<double>& pv, Support<double>& pu) {
    put(o, "stiffness", Dimension::stiffness, Range::positive, pv.stiffness, pu.stiffness);
    put(o, "mass", Dimension::mass, Range::positive, pv.mass, pu.mass);
  }, [&](const Support<double>& pv) {
    PENDULUM_FAIL_IF(!pv.stiffness && !pv.mass, "support", "got neither stiffness nor mass; expected at least one");
    // Bounds that keep Eq. (83)'s discriminant, (K/M)^2, a finite number.
    if (pv.stiffness) {
      within(*pv.stiffness, 0.0, kMaxYoungsModulus, "support.stiffness.value", "N/m",
             "at most " + format_number(kMaxYoungsModulus) + " N/m (a cubic metre of diamond)");
    }
    if (pv.mass) within(*pv.mass, 1e-6, HUGE_VAL, "support.mass.value", "kg", "at least 1 mg");
  });
}

/// decay: alpha and beta as measured, and/or a record to fit them from
/// (docs/scene.md); the record is validated here, fitted by the analysis.
void read_decay(Object& top, ParsedScene& out, RecordingReader& recordings) {
  Object o(top.at("decay"), "decay");
  const bool given = o.has("alpha") || o.has("beta");
  const bool has_data = o.has("data");
  PENDULUM_FAIL_IF(!given && !has_data, "decay", "got neither alpha and beta nor data; expected one of them");
  if (given) {
    auto& pv = out.apparatus.decay.emplace();
    auto& pu = out.apparatus_uncertainty.decay.emplace();
    put(o, "alpha", Dimension::rate, Range::non_negative, pv.alpha, pu.alpha);
    put(o, "beta", Dimension::rate_per_angle, Range::non_negative, pv.beta, pu.beta);
  }
  if (has_data && names_recording(o.at("data"))) {
    out.decay_data = read_recorded_decay(o, out, recordings);
  } else if (has_data) {
    Object d(o.at("data"), "decay.data");
    const Unit time_unit = unit_at(d, "time_unit", Dimension::time);
    const Unit angle_unit = unit_at(d, "amplitude_unit", Dimension::angle);
    DecayData data;
    data.times = number_array(d, "times", time_unit.factor);
    data.amplitudes = number_array(d, "amplitudes", angle_unit.factor);
    PENDULUM_FAIL_IF(d.has("sigma") && d.has("sigmas"), d.path("sigmas"),
            "got both sigma and sigmas; expected one of them");
    if (d.has("sigma")) {
      // A bare number in amplitude_unit, or a quantity like any other.
      const double sigma = d.at("sigma").is_object()
                               ? quantity(d, "sigma", Dimension::angle, Range::any).value / angle_unit.factor
                               : finite_number(d.at("sigma"), [&] { return d.path("sigma"); },
                                               "a number or a quantity");
      PENDULUM_FAIL_IF(!(sigma > 0.0), d.path("sigma"),
              "got " + format_number(sigma) + "; expected a positive uncertainty");
      data.sigmas.assign(data.times.size(), sigma * angle_unit.factor);
    } else if (d.has("sigmas")) {
      data.sigmas = number_array(d, "sigmas", angle_unit.factor);
    }
    if (d.has("initial_amplitude")) {
      data.initial_amplitude =
          quantity(d, "initial_amplitude", Dimension::angle, Range::positive).value;
    }
    if (d.has("of")) {
      // Whose angle the amplitudes are, as an amplitude's "of" (docs/phone.md).
      const std::string of = d.text("of");
      PENDULUM_FAIL_IF(of != "pendulum" && of != "body", d.path("of"),
                       "got \"" + one_line(of, 60, true) + "\"; expected \"pendulum\" (the default) or \"body\" (a sensor in the bob)");
      data.angle_of = of == "body" ? AngleOf::body : AngleOf::pendulum;
    }
    if (d.has("source")) d.text("source");
    if (d.has("generator")) d.at("generator");  // free-form metadata
    d.finish();
    validate_decay_data(data, "decay.data");
    out.decay_data = std::move(data);
  }
  o.finish();
}

/// site: a measured reference g, or latitude and height for normal gravity.
void read_site(Object& top, ParsedScene& out) {
  Object o(top.at("site"), "site");
  Site site;
  if (o.has("latitude")) {
    const Measured lat = quantity(o, "latitude", Dimension::angle, Range::any);
    const double deg = degrees(lat.value);
    const std::string why = out_of_range(ranges::latitude, deg);
    if (!why.empty()) throw InputError("site.latitude.value", why);
    site.latitude_deg = deg;
  }
  if (o.has("height")) {
    const double h = quantity(o, "height", Dimension::length, Range::any).value;
    const std::string why = out_of_range(ranges::height, h);
    if (!why.empty()) throw InputError("site.height.value", why);
    site.height = h;
    const std::string reference = o.text("height_reference");
    if (reference != "ellipsoid" && reference != "sea_level") {
      throw InputError(o.path("height_reference"),
                       "got \"" + one_line(reference, 60, true) + "\"; expected \"ellipsoid\" or \"sea_level\"");
    }
    site.height_above_ellipsoid = reference == "ellipsoid";
  }
  if (o.has("reference_g")) {
    const Measured g = quantity(o, "reference_g", Dimension::acceleration, Range::positive);
    // Any planet's surface, with room to spare; beyond, a unit slip or a typo.
    within(g.value, 0.1, 1000.0, "site.reference_g.value", "m/s^2", "a surface gravity from 0.1 to 1000 m/s^2");
    site.reference_g = g.value;
    site.reference_g_uncertainty = g.sigma;
    const json& q = o.at("reference_g");
    if (q.contains("source") && q.at("source").is_string()) site.reference_source = q.at("source").get<std::string>();
  }
  o.finish();
  if (!site.reference_g && (!site.latitude_deg || !site.height)) {
    throw InputError("site", "expected reference_g, or latitude and height");
  }
  out.site = site;
}

}  // namespace pendulum::json_reader
