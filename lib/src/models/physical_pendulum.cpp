/// \file models/physical_pendulum.cpp
/// \brief The rigid body's start (a straight line in h^2) and its results
/// beside the fit: the pivot scan (docs/physical.md, docs/core.md).
#include "pendulum/models/physical_pendulum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pendulum/analysis.hpp"
#include "../fit_state.hpp"
#include "../json/writer.hpp"
#include "../text.hpp"
#include "pendulum/straight_line.hpp"

namespace pendulum {

static_assert(PhysicalPendulum::kParameters == 3, "physical_start (analysis.hpp) takes three parameters");

namespace {

/// Whether each observation hangs its own rod (Setting::rod_length), whose
/// k is known, rather than one body at its pivots.
bool rods(const ParsedScene& scene) {
  return !scene.observations.empty() && scene.observations.front().setting == Setting::rod_length;
}

}  // namespace

std::array<double, 3> physical_start(const ParsedScene& scene, const std::array<bool, 3>& fitted) {
  using M = PhysicalPendulum;
  std::array<double, M::kParameters> p = M::kDefaults;
  const auto& obs = scene.observations;
  const auto& body = scene.apparatus.body;
  // A k the body (or each rod) gives is held: the line is then T^2 h = (4 pi^2/g)(k^2 + h^2), through the origin.
  const bool known_k = (body && body->radius_of_gyration) || rods(scene);
  auto line_through = [&](double center, double& ssr) {
    std::vector<double> x, y, zero(obs.size(), 0.0);
    const double at[M::kParameters] = {p[M::g], p[M::radius_of_gyration], center};
    for (const auto& o : obs) {
      const double h = M::pivot_distance(at, o, scene.apparatus), k = M::gyration_at(at, o, scene.apparatus);
      x.push_back(h * h + (known_k ? k * k : 0.0));
      y.push_back(o.period * o.period * h);
    }
    const StraightLine line =
        fit_straight_line(x, y, zero, zero, !known_k && obs.size() > 1 && fitted[M::radius_of_gyration]);
    ssr = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double r = (line.slope * x[i] + line.intercept - y[i]) / y[i];
      ssr += r * r;
    }
    return line;
  };
  double center = body && body->center_of_mass_position ? *body->center_of_mass_position : 0.0;
  const bool positions = std::any_of(obs.begin(), obs.end(), [](const auto& o) { return o.setting == Setting::pivot_position; });
  if (positions && fitted[M::center_of_mass_position]) {
    const auto [lo, hi] = std::minmax_element(obs.begin(), obs.end(), [](const auto& a, const auto& b) { return a.length < b.length; });
    const double span = std::max(hi->length - lo->length, 1e-3);
    double best = HUGE_VAL;
    constexpr int kGrid = 600;
    for (int i = 0; i <= kGrid; ++i) {
      const double c = lo->length - span + 3.0 * span * i / kGrid;
      if (std::any_of(obs.begin(), obs.end(), [&](const auto& o) { return std::abs(o.length - c) < 1e-6 * span; })) continue;
      double ssr;
      line_through(c, ssr);
      if (ssr < best) best = ssr, center = c;
    }
    // Then golden-section search within a grid step either side, to 1e-9 of
    // the span: Levenberg-Marquardt then starts next to the optimum.
    const double step = 3.0 * span / kGrid, ratio = (std::sqrt(5.0) - 1.0) / 2.0;
    double a = center - step, b = center + step;
    auto cost = [&](double c) {
      double ssr;
      line_through(c, ssr);
      return ssr;
    };
    double c1 = b - ratio * (b - a), c2 = a + ratio * (b - a), f1 = cost(c1), f2 = cost(c2);
    while (b - a > 1e-9 * span) {
      if (f1 < f2) {
        b = c2, c2 = c1, f2 = f1, c1 = b - ratio * (b - a), f1 = cost(c1);
      } else {
        a = c1, c1 = c2, f1 = f2, c2 = a + ratio * (b - a), f2 = cost(c2);
      }
    }
    if (std::min(f1, f2) < best) center = f1 < f2 ? c1 : c2;
  }
  double ssr;
  const StraightLine line = line_through(center, ssr);
  p[M::g] = gravity_for_slope(line.slope);
  if (known_k && !rods(scene)) {
    p[M::radius_of_gyration] = *body->radius_of_gyration;  // held: what the model takes (PhysicalPendulum::gyration)
  } else if (!known_k && line.intercept > 0.0) {
    p[M::radius_of_gyration] = std::sqrt(line.intercept / line.slope);
  }
  p[M::center_of_mass_position] = center;
  return p;
}

namespace {

/// The pivot scan's textbook curve (PivotScan::Textbook) on the scene's
/// measured periods.
PivotScan::Textbook pivot_textbook(const ParsedScene& scene, const std::array<bool, 3>& fitted) {
  using M = PhysicalPendulum;
  const std::array<double, 3> t = physical_start(scene, fitted);
  const auto& obs = scene.observations;
  const auto& body = scene.apparatus.body;
  const bool known_k = (body && body->radius_of_gyration) || rods(scene);
  const bool positions = std::any_of(obs.begin(), obs.end(), [](const auto& o) { return o.setting == Setting::pivot_position; });
  const bool intercept = !known_k && obs.size() > 1 && fitted[M::radius_of_gyration];
  // physical_start's unweighted line T^2 h = a (h^2 + k^2) + b: its slope is
  // sum c_i y_i, c_i = (x_i - mean x)/Sxx (x_i/sum x^2 through the origin),
  // and y_i - a x_i moves by 2 T h dT + (T^2 dh/ds - a dx/ds) ds, s the
  // setting (a Jet: a rod's h = L/2 and k^2 = L^2/12 both move with L).
  std::vector<double> h(obs.size()), x(obs.size());
  double mean = 0.0;
  for (std::size_t i = 0; i < obs.size(); ++i) {
    h[i] = M::pivot_distance(t.data(), obs[i], scene.apparatus);
    const double k = M::gyration_at(t.data(), obs[i], scene.apparatus);
    x[i] = h[i] * h[i] + (known_k ? k * k : 0.0);
    if (intercept) mean += x[i] / obs.size();
  }
  double sxx = 0.0;
  for (double xi : x) sxx += (xi - mean) * (xi - mean);
  const double a = gravity_for_slope(t[M::g]);  // the slope of T^2 h against h^2 at g
  using J = ceres::Jet<double, 1>;
  const J at[M::kParameters] = {J(t[M::g]), J(t[M::radius_of_gyration]), J(t[M::center_of_mass_position])};
  const Apparatus<J> app = convert_apparatus<J>(scene.apparatus, [](const Field&, double v) { return J(v); });
  double variance = 0.0;
  for (std::size_t i = 0; i < obs.size(); ++i) {
    const double c = (x[i] - mean) / sxx, T = obs[i].period;
    const auto& u = scene.observation_uncertainties[i];
    Observation<J> o = convert_observation<J>(obs[i], [](const Field&, double v) { return J(v); });
    o.length.v[0] = 1.0;
    const J hj = M::pivot_distance(at, o, app), kj = M::gyration_at(at, o, app);
    const J xj = hj * hj + (known_k ? kj * kj : J(0.0));
    const double dt = 2.0 * T * h[i] * u.period, ds = (T * T * hj.v[0] - a * xj.v[0]) * u.length;
    variance += c * c * (dt * dt + ds * ds);
  }
  const double sigma = t[M::g] * std::sqrt(variance) / a;
  return {{t[M::g], std::isfinite(sigma) ? std::optional<double>(sigma) : std::nullopt},
          rods(scene) ? std::nullopt : std::optional<double>(t[M::radius_of_gyration]),
          positions ? std::optional<double>(t[M::center_of_mass_position]) : std::nullopt};
}

/// Air given but not the body's mass and volume: buoyancy is skipped; say
/// what a steel body's would be (g rises by rho_air/rho, Eq. 16 twice).
void warn_about_buoyancy(const FitState<PhysicalPendulum::kParameters>& fit, Analysis& out) {
  const Apparatus<double>& app = fit.scene.apparatus;
  if (!app.air || (app.body && app.body->mass && app.body->volume)) return;
  constexpr double kSteel = 7850.0;  // kg/m^3, a carbon steel
  const double shift = fit.p[0] * air_density(app.air->pressure, app.air->temperature, app.air->molar_mass) / kSteel;
  if (out.g.uncertainty && shift < fit.options.negligible_fraction * *out.g.uncertainty) return;
  out.warnings.push_back(rods(fit.scene) ? "air: the rods' densities are not known (a rod of rod_length has none), so "
                                           "buoyancy is skipped; steel rods' would raise g by " +
                                               format_number(shift, 3) + " m/s^2"
                                         : "air: the body's mass and volume are not known (give the body in parts with "
                                           "their densities), so buoyancy is skipped; a steel body's would raise g by " +
                                               format_number(shift, 3) + " m/s^2");
}

/// A fitted k or centre against what the body's parts give.
void check_against_parts(const FitState<PhysicalPendulum::kParameters>& fit, Analysis& out, PivotScan& scan) {
  if (!fit.scene.body_from_parts) return;
  const RigidBody<double>& parts = *fit.scene.body_from_parts;
  const std::pair<int, std::optional<double>*> checks[] = {
      {PhysicalPendulum::radius_of_gyration, &scan.parts_radius_of_gyration},
      {PhysicalPendulum::center_of_mass_position, &scan.parts_center_of_mass_position}};
  for (const auto& [i, field] : checks) {
    if (!fit.fitted[i]) continue;
    const double from_parts = i == PhysicalPendulum::radius_of_gyration ? *parts.radius_of_gyration
                                                                        : *parts.center_of_mass_position;
    *field = from_parts;
    const std::optional<double> sigma = fit.deviation(fit.covariance(i, i));
    if (!sigma || std::abs(fit.p[i] - from_parts) <= 3.0 * *sigma) continue;
    out.warnings.push_back(std::string("fit: ") + PhysicalPendulum::kParameterInfo[i].name + " = " +
                            format_number(fit.p[i], 6) + " +- " + format_number(*sigma, 2) + " m, but the body's parts give " +
                            format_number(from_parts, 6) + " m (" + format_number(std::abs(fit.p[i] - from_parts) / *sigma, 3) +
                            " standard uncertainties away): a part missing, misplaced or of the wrong mass?");
  }
}

/// Kater's reversible pendulum: two pivot positions on opposite sides of
/// a measured centre, at different distances from it (two pivots on one
/// side are an ordinary scan of two; at equal distances the periods are
/// equal by symmetry and Bessel's (T1^2 - T2^2)/(h1 - h2) is 0/0).
/// Bessel's formula on the ideal periods checks the fit; the rough centre
/// enters g only through T1^2 - T2^2, and a warning says when the periods
/// are too far apart for that.
void review_kater(const FitState<PhysicalPendulum::kParameters>& fit, Analysis& out, PivotScan& scan) {
  const auto& body = fit.scene.apparatus.body;
  if (fit.scene.observations.size() != 2 || !body || !body->center_of_mass_position) return;
  const auto& o1 = fit.scene.observations[0];
  const auto& o2 = fit.scene.observations[1];
  if (o1.setting != Setting::pivot_position || o2.setting != Setting::pivot_position) return;
  const double center = *body->center_of_mass_position;
  if ((o1.length - center) * (o2.length - center) >= 0.0) return;
  const double scale = PhysicalPendulum::thermal_scale(fit.scene.apparatus);
  const double h1 = scale * std::abs(o1.length - center), h2 = scale * std::abs(o2.length - center);
  if (std::abs(h1 - h2) <= 1e-6 * (h1 + h2)) return;
  auto ideal = [&](std::size_t k) {
    const ObservationResult& r = out.observations[k];
    return r.period_ideal.value / r.period_model * fit.scene.observations[k].period;
  };
  scan.bessel_g = bessel_g(ideal(0), ideal(1), h1, h2);
  double center_share = 0.0, others = 0.0;
  for (const auto& b : out.budget) {
    if (b.input == "center_of_mass_position") {
      center_share = b.contribution;
    } else {
      others = std::max(others, b.contribution);
    }
  }
  if (center_share > others && center_share > 0.0) {
    const double apart = std::abs(o1.period - o2.period);
    out.warnings.push_back(
        "kater: the periods differ by " + format_number(apart, 3) + " s, so the roughly located centre of mass "
        "(center_of_mass_position) contributes " + format_number(center_share, 3) + " m/s^2 to g's uncertainty, more "
        "than any other input (" + format_number(others, 3) + " m/s^2); Bessel's method needs T1 and T2 close, since the "
        "centre enters only through T1^2 - T2^2: move the adjustable mass until they agree within " +
        format_number(apart * others / center_share, 2) + " s, or locate the centre better");
  }
}

}  // namespace

std::array<double, PhysicalPendulum::kParameters> PhysicalPendulum::start(const ParsedScene& scene,
                                                                          const std::array<bool, kParameters>& fitted) {
  return physical_start(scene, fitted);
}

void PhysicalPendulum::report(const FitState<kParameters>& fit, Analysis& out) {
  using M = PhysicalPendulum;
  using JetP = ceres::Jet<double, kParameters>;
  const Apparatus<JetP> app = convert_apparatus<JetP>(fit.scene.apparatus, [](const Field&, double x) { return JetP(x); });
  PivotScan scan;
  // Only k^2 enters the period: the fit may land on either sign of k.
  auto k_of = [&](const JetP* p) {
    using std::abs;
    return M::thermal_scale(app) * abs(M::gyration(p, app));
  };
  if (!rods(fit.scene)) {
    scan.minimum_period = fit.derived_estimate([&](const JetP* p) { return minimum_period(p[M::g], k_of(p)); });
    scan.minimum_pivot_distance = fit.derived_estimate(k_of);
  }
  const auto& body = fit.scene.apparatus.body;
  const bool held_center = body && body->center_of_mass_position;
  const bool positions = std::any_of(fit.scene.observations.begin(), fit.scene.observations.end(),
                                     [](const auto& o) { return o.setting == Setting::pivot_position; });
  auto center_of = [&](const JetP* p) {
    return held_center ? JetP(*body->center_of_mass_position) : p[M::center_of_mass_position];
  };
  if (positions) {
    for (const double side : {-1.0, 1.0}) {
      scan.minimum_pivot_positions.push_back(
          fit.derived_estimate([&](const JetP* p) {
            using std::abs;
            return center_of(p) + side * abs(M::gyration(p, app));
          }));
    }
  }
  for (std::size_t k = 0; k < fit.scene.observations.size(); ++k) {
    const Observation<JetP> o =
        convert_observation<JetP>(fit.scene.observations[k], [](const Field&, double x) { return JetP(x); });
    PivotScan::Conjugate c;
    c.equivalent_length = fit.derived_estimate([&](const JetP* p) { return M::equivalent(p, o, app); });
    c.pivot_distance = fit.derived_estimate([&](const JetP* p) {
      return conjugate_pivot_distance(M::gyration_at(p, o, app), M::pivot_distance(p, o, app));
    });
    if (o.setting == Setting::pivot_position) {
      c.pivot_position = fit.derived_estimate([&](const JetP* p) {
        const JetP center = center_of(p);
        const JetP h = conjugate_pivot_distance(M::gyration_at(p, o, app), M::pivot_distance(p, o, app));
        return o.length < center ? center + h : center - h;
      });
    }
    scan.conjugates.push_back(c);
  }
  scan.textbook = pivot_textbook(fit.scene, fit.fitted);
  review_kater(fit, out, scan);
  check_against_parts(fit, out, scan);
  warn_about_buoyancy(fit, out);
  out.fit.set_results<PhysicalPendulum>(std::move(scan));
}

std::optional<Expectation> PhysicalPendulum::expectation(const ParsedScene& scene, const Observation<double>& o) {
  Apparatus<double> app = scene.apparatus;
  if (!app.body) return std::nullopt;
  RigidBody<double>& body = *app.body;
  if (scene.body_from_parts) {
    if (!body.radius_of_gyration) body.radius_of_gyration = scene.body_from_parts->radius_of_gyration;
    if (!body.center_of_mass_position) body.center_of_mass_position = scene.body_from_parts->center_of_mass_position;
  }
  if (o.setting != Setting::rod_length &&
      (!body.radius_of_gyration || (o.setting == Setting::pivot_position && !body.center_of_mass_position))) {
    return std::nullopt;
  }
  const double p[kParameters] = {kStandardGravity, 0.0, 0.0};  // k and the centre: the body's
  const double period =
      predicted_period<PhysicalPendulum>(p, swing(o), app, cheapest_amplitude_method(o.amplitude, 0.0));
  return Expectation{period, period};
}

namespace {

/// report() sets the scan on every fit: a null one is a fault of the code.
const PivotScan& require_scan(const PivotScan* scan) {
  if (!scan) throw std::logic_error("a physical pendulum's fit without its pivot scan");
  return *scan;
}

/// The textbook curve of a pivot scan (PivotScan::Textbook); null without one.
nlohmann::ordered_json pivot_textbook_json(const PivotScan& scan) {
  if (!scan.textbook) return nullptr;
  const PivotScan::Textbook& t = *scan.textbook;
  const char* equation =
      scan.bessel_g ? "T^2 h = (4 pi^2 / g)(k^2 + h^2) through the two pivots: Bessel's formula 8 pi^2/g = (T1^2 + "
                      "T2^2)/(h1 + h2) + (T1^2 - T2^2)/(h1 - h2) on the measured periods, no corrections"
      : !t.radius_of_gyration ? "T = 2 pi sqrt(2L/(3g)) of each rod pivoted at its end (h = L/2, k^2 = L^2/12): the "
                                "straight line T^2 h = (4 pi^2 / g)(k^2 + h^2) through the origin on the measured "
                                "periods, no corrections"
                              : "T = 2 pi sqrt((k^2 + h^2)/(g h)): the straight line T^2 h = (4 pi^2 / g)(k^2 + h^2) "
                                "on the measured periods, no corrections";
  return {{"equation", equation},
          {"g", writer::measured(t.g, "m/s^2")},
          {"radius_of_gyration_m", writer::optional_number(t.radius_of_gyration)},
          {"center_of_mass_position_m", writer::optional_number(t.center_of_mass_position)}};
}

}  // namespace

void PhysicalPendulum::put_fit_results(const Results* results, JsonOut& fit) {
  using writer::measured;
  using writer::optional_number;
  const PivotScan& scan = require_scan(results);
  for (std::size_t k = 0; k < scan.conjugates.size(); ++k) {
    const PivotScan::Conjugate& c = scan.conjugates[k];
    nlohmann::ordered_json conjugate = {{"equivalent_length", measured(c.equivalent_length, "m")},
                                        {"pivot_distance", measured(c.pivot_distance, "m")}};
    if (c.pivot_position) conjugate["pivot_position"] = measured(*c.pivot_position, "m");
    fit.json["observations"][k]["conjugate_pivot"] = conjugate;
  }
  auto positions = nlohmann::ordered_json::array();
  for (const auto& x : scan.minimum_pivot_positions) positions.push_back(measured(x, "m"));
  fit.json["pivot_scan"] = {
      {"equation", "T0 = 2 pi sqrt((k^2 + h^2)/(g h)), Kelley (1993) Eqs. (55)-(56)"},
      {"minimum", scan.minimum_period ? nlohmann::ordered_json{{"period", measured(*scan.minimum_period, "s")},
                                                               {"pivot_distance", measured(*scan.minimum_pivot_distance, "m")},
                                                               {"pivot_positions", positions}}
                                      : nlohmann::ordered_json(nullptr)},
      {"bessel_g_m_s2", optional_number(scan.bessel_g)},
      {"textbook", pivot_textbook_json(scan)},
      {"from_parts", {{"radius_of_gyration_m", optional_number(scan.parts_radius_of_gyration)},
                      {"center_of_mass_position_m", optional_number(scan.parts_center_of_mass_position)}}}};
}

void PhysicalPendulum::fit_results_lines(const Results* results, std::ostream& os) {
  const PivotScan& scan = require_scan(results);
  char line[160];
  if (scan.minimum_period) {
    std::snprintf(line, sizeof line, "Minimum period T0   = %.6f %s s at h = k = %.5f m\n", scan.minimum_period->value,
                  writer::plus_minus(scan.minimum_period->uncertainty, "%.6f").c_str(),
                  scan.minimum_pivot_distance->value);
    os << line;
  }
  if (scan.bessel_g) {
    std::snprintf(line, sizeof line, "Bessel's formula    : g = %.8f m/s^2\n", *scan.bessel_g);
    os << line;
  }
  if (const auto& t = scan.textbook) {
    os << (scan.bessel_g                ? "Textbook: Bessel's formula on the measured periods, no corrections: g = "
           : !t->radius_of_gyration ? "Textbook curve T = 2 pi sqrt(2L/(3g)) of each rod, no corrections: g = "
                                    : "Textbook curve T = 2 pi sqrt((k^2 + h^2)/(g h)), no corrections: g = ")
       << writer::rounded(t->g.value, t->g.uncertainty)
       << " m/s^2";
    if (t->radius_of_gyration) os << ", k = " << writer::format_fixed(*t->radius_of_gyration, 5) << " m";
    if (t->center_of_mass_position) os << ", centre at " << writer::format_fixed(*t->center_of_mass_position, 5) << " m";
    os << "\n";
  }
}

}  // namespace pendulum
