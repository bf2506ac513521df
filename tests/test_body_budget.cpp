// A body's parts in g's uncertainty budget (docs/physical.md, "Uncertainty
// of a body in parts"): each part's mass, density, dimensions and position
// is a budget row named by its JSON path, and each row's sensitivity equals
// the finite difference of g computed independently: the scene file with
// that one value moved by +-h, read and reduced again.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "pendulum/air.hpp"
#include "pendulum/reduce_scene.hpp"
#include "pendulum/json/scene_json.hpp"
#include "reference.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using json = nlohmann::json;

namespace {

AnalysisOptions exact() {
  AnalysisOptions options;
  options.reduction.amplitude_method = AmplitudeMethod::agm;
  return options;
}

double g_of(const json& scene) { return reduce_scene(parse_scene(scene.dump()), exact()).g.value; }

/// The quantity object {"value", "uncertainty", "unit"} at a budget path
/// ("body.parts[1].mass", "observations[0].amplitude"), or null when the
/// path names a derived input (timing.period, from the trials).
json* node_at(json& scene, const std::string& path) {
  json* at = &scene;
  std::size_t from = 0;
  while (from < path.size()) {
    const std::size_t dot = path.find('.', from);
    std::string key = path.substr(from, dot == std::string::npos ? std::string::npos : dot - from);
    const std::size_t bracket = key.find('[');
    const std::string name = key.substr(0, bracket);
    if (!at->is_object() || !at->contains(name)) return nullptr;
    at = &(*at)[name];
    if (bracket != std::string::npos) at = &(*at)[std::stoul(key.substr(bracket + 1))];
    from = dot == std::string::npos ? path.size() : dot + 1;
  }
  return at->is_object() && at->contains("value") ? at : nullptr;
}

/// SI per unit of the file, for the steps: a temperature's step is the same
/// in degC and K.
double si_per_unit(const std::string& unit) {
  static const std::map<std::string, double> units{{"m", 1.0},   {"kg", 1.0},         {"kg/m^3", 1.0},
                                                   {"degC", 1.0}, {"K", 1.0},          {"kPa", 1e3},
                                                   {"Pa", 1.0},   {"deg", test::kDegree}, {"1/K", 1.0}};
  const auto it = units.find(unit);
  if (it == units.end()) throw std::logic_error("no step for the unit " + unit);
  return it->second;
}

struct Checked {
  int rows = 0, parts = 0;
};

/// Every budget row whose input the file states as a quantity: its
/// sensitivity against (g(x + h) - g(x - h))/(2h), h = step x its
/// uncertainty; rows agree within `tolerance` of the budget's largest
/// contribution (m/s^2 per standard uncertainty).
Checked check_budget(const json& scene, double step, double tolerance) {
  const Analysis a = reduce_scene(parse_scene(scene.dump()), exact());
  REQUIRE(!a.budget.empty());
  const double largest = a.budget.front().contribution;
  Checked checked;
  for (const BudgetEntry& row : a.budget) {
    json moved = scene;
    json* node = node_at(moved, row.input);
    if (!node) continue;
    const double h_file = step * row.uncertainty / si_per_unit((*node)["unit"].get<std::string>());
    const double x = (*node)["value"].get<double>();
    (*node)["value"] = x + h_file;
    const double up = g_of(moved);
    (*node)["value"] = x - h_file;
    const double down = g_of(moved);
    const double difference = (up - down) / (2.0 * step);  // dg per standard uncertainty
    INFO(row.input << ": budget " << row.sensitivity * row.uncertainty << " m/s^2, finite difference " << difference);
    CHECK_THAT(row.sensitivity * row.uncertainty, WithinAbs(difference, tolerance * largest));
    ++checked.rows;
    if (row.input.rfind("body.parts[", 0) == 0) ++checked.parts;
  }
  return checked;
}

json quantity(double value, double uncertainty, const char* unit) {
  return {{"value", value}, {"uncertainty", uncertainty}, {"unit", unit}};
}

/// A steel rod (density given) with a brass weight (mass given) and a hole
/// drilled across it, hung at one pivot in room air: k, the centre, the
/// mass and the volume all from the parts, every part's value uncertain.
json weighted_rod() {
  return {
      {"pivot_position", quantity(0.05, 2e-4, "m")},
      {"amplitude", quantity(3.0, 0.5, "deg")},
      {"timing", {{"oscillations_per_trial", 20}, {"unit", "s"}, {"resolution", 0.01}, {"trials", {37.58, 37.6, 37.59}}}},
      {"air", {{"pressure", quantity(101.3, 0.3, "kPa")}, {"temperature", quantity(21.0, 0.5, "degC")}}},
      {"body",
       {{"parts",
         {{{"shape", "cylinder"}, {"radius", quantity(0.006, 2e-5, "m")}, {"length", quantity(1.2, 5e-4, "m")},
           {"axis", "body"}, {"density", quantity(7850, 30, "kg/m^3")}, {"position", quantity(0.6, 5e-4, "m")}},
          {{"shape", "cylinder"}, {"radius", quantity(0.03, 5e-5, "m")}, {"inner_radius", quantity(0.006, 5e-5, "m")},
           {"length", quantity(0.04, 5e-5, "m")}, {"axis", "body"}, {"mass", quantity(0.95, 0.002, "kg")},
           {"position", quantity(1.0, 5e-4, "m")}},
          {{"shape", "cylinder"}, {"radius", quantity(0.002, 2e-5, "m")}, {"length", quantity(0.012, 2e-5, "m")},
           {"axis", "swing"}, {"density", quantity(7850, 30, "kg/m^3")}, {"position", quantity(0.3, 5e-4, "m")},
           {"hole", true}}}}}}};
}

/// The bundled Kater pendulum (centre balanced to 1 mm, k fitted) with its
/// body given in parts, masses weighed: a steel bar (0 to 1.2 m) and a brass
/// weight clamped below its end, placed so that the parts give the file's
/// centre (0.800 m) and k (0.413 m, sqrt(0.220 m x 0.774 m)). The measured
/// centre is held; the parts give the mass and volume (buoyancy).
json kater_in_parts() {
  json scene = json::parse(test::read_text(std::string(PENDULUM_DATA_DIR) + "/kater_reversible_pendulum.json"));
  scene["body"] = {
      {"parts",
       {{{"shape", "box"}, {"length", quantity(1.2, 2e-4, "m")}, {"width", quantity(0.03, 2e-5, "m")},
         {"thickness", quantity(0.01, 2e-5, "m")}, {"mass", quantity(2.826, 0.002, "kg")},
         {"position", quantity(0.6, 5e-4, "m")}},
        {{"shape", "cylinder"}, {"radius", quantity(0.04, 5e-5, "m")}, {"length", quantity(0.03, 5e-5, "m")},
         {"axis", "body"}, {"mass", quantity(1.2845, 0.002, "kg")}, {"position", quantity(1.24, 5e-4, "m")}}}}};
  return scene;
}

}  // namespace

TEST_CASE("A body in parts: each part's row in g's budget is the finite difference of g", "[physical][budget]") {
  // One pivot, g alone unknown: the closed form, exact in every input. The
  // step is 1e-2 of each uncertainty: the truncation (h^2 g'''/6) and the
  // rounding (1e-16 g / h) each stay below 1e-9 of the largest row.
  const json scene = weighted_rod();
  const Analysis a = reduce_scene(parse_scene(scene.dump()), exact());
  REQUIRE(a.fit.method == std::string("closed_form"));
  // Every part's every value is an input: 4 + 5 + 4 fields.
  int rows = 0;
  for (const auto& b : a.budget) rows += b.input.rfind("body.parts[", 0) == 0;
  CHECK(rows == 13);
  const Checked checked = check_budget(scene, 1e-2, 1e-7);
  CHECK(checked.parts == 13);
  // The uncertainty is the budget's sum in quadrature (no correlated inputs).
  double sum = 0.0;
  for (const auto& b : a.budget) sum += b.contribution * b.contribution;
  CHECK_THAT(*a.g.uncertainty, WithinRel(std::sqrt(sum), 1e-12));
}

TEST_CASE("Kater in parts: the parts and the rough centre in g's budget, against finite differences",
          "[physical][kater][budget]") {
  // k fitted to two periods: zero degrees of freedom, so the residuals
  // vanish at the optimum and the propagation's Gauss-Newton derivative is
  // exact. The fit converges to about 1e-12 of g: steps of a whole standard
  // uncertainty keep that noise below 1e-5 of the smallest row checked.
  const json scene = kater_in_parts();
  const Analysis a = reduce_scene(parse_scene(scene.dump()), exact());
  REQUIRE(a.fit.converged);
  const Checked checked = check_budget(scene, 1.0, 1e-5);
  CHECK(checked.parts == 9);  // 5 of the bar, 4 of the weight
  // Why Kater's method works: the centre, known to 1 mm, enters through
  // T1^2 - T2^2 only and contributes less than either knife edge's 21 um.
  double centre = 0.0, edge = 0.0, parts = 0.0;
  for (const auto& b : a.budget) {
    if (b.input == "center_of_mass_position") centre = b.contribution;
    if (b.input == "observations[0].pivot_position") edge = b.contribution;
    if (b.input.rfind("body.parts[", 0) == 0) parts = std::max(parts, b.contribution);
  }
  INFO("centre " << centre << " m/s^2, a knife edge " << edge << " m/s^2, the largest part " << parts << " m/s^2");
  CHECK(centre > 0.0);
  CHECK(centre < 0.25 * edge);
  // The parts enter through the buoyancy m_air/(2M) alone (k is fitted,
  // the centre measured; their positions' rows are 0): the bar's 10 mm
  // thickness to 20 um moves its volume, and m_air/(2M) = 7e-5, by 2e-3.
  CHECK(parts < 0.1 * centre);
}

TEST_CASE("Kelley's expansion coefficient carries its uncertainty into g's budget", "[physical][budget]") {
  // Steel at 35 degC, measured at 20 degC: l and so g scale by
  // (1 + w C)/(1 + w C_ref) (Kelley Eq. 41), so dg/dw = g [C/(1 + w C) -
  // C_ref/(1 + w C_ref)]; w's uncertainty is Kelley's range for typical
  // steels, 9.07e-6 to 1.21e-5 /K (beside his table), as a uniform interval.
  json scene = weighted_rod();
  scene.erase("air");
  scene["temperature"] = quantity(35.0, 0.0, "degC");
  scene["reference_temperature"] = quantity(20.0, 0.0, "degC");
  scene["material"] = "steel";
  const Analysis a = reduce_scene(parse_scene(scene.dump()), exact());
  const double w = 1.1e-5, g = a.g.value;
  bool found = false;
  for (const auto& b : a.budget) {
    if (b.input != "expansion_coefficient") continue;
    found = true;
    CHECK_THAT(b.uncertainty, WithinRel((1.21e-5 - 9.07e-6) / std::sqrt(12.0), 1e-15));
    CHECK_THAT(b.sensitivity, WithinRel(g * (35 / (1 + w * 35) - 20 / (1 + w * 20)), 1e-9));
  }
  CHECK(found);
}

TEST_CASE("A bar's added mass in potential flow: its limits", "[physical][air]") {
  const double rho = 1.2, a = 0.006, d = 0.8, L = 0.04;
  // No air, no added mass.
  CHECK(strip_added_inertia(0.0, a, d - L / 2, d + L / 2) == 0.0);
  // A short rod at distance d: its strips' s^2 integrate exactly to
  // m_a (d^2 + L^2/12), m_a = rho pi a^2 L the air it displaces (Lamb Sec. 68:
  // kappa = 1).
  const double m_a = rho * kPi * a * a * L;
  CHECK_THAT(strip_added_inertia(rho, a, d - L / 2, d + L / 2), WithinRel(m_a * (d * d + L * L / 12), 1e-14));
  // So the rod as a point bob of mass m on a massless rod of length d is
  // Nelson & Olsson's Eq. (54) with kappa = 1, twice the potential-flow
  // sphere's 1/2 of Eq. (58) (kappa = 1/2 as added_mass_factor(1, 1, 0, a)).
  const double m = 5.0;
  const double rod = 0.5 * strip_added_inertia(rho, a, d - 1e-7, d + 1e-7) / (m * d * d);
  CHECK_THAT(rod, WithinRel(added_mass(1.0, rho * kPi * a * a * 2e-7, m), 1e-9));
  const double sphere_m_a = rho * 4.0 / 3.0 * kPi * a * a * a;
  CHECK_THAT(added_mass(added_mass_factor(1.0, 1.0, 0.0, a), sphere_m_a, m), WithinRel(0.25 * sphere_m_a / m, 1e-15));
  // A pivot at the rod's middle: the halves add (s1 = -s2).
  CHECK_THAT(strip_added_inertia(rho, a, -0.5, 0.5), WithinRel(2 * strip_added_inertia(rho, a, 0.0, 0.5), 1e-15));
}
