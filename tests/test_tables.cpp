// Tables of settings and periods (docs/series.md, "Tables"): the layouts of
// tests/tables/ (tests/tools/make_tables.py, seeded), the grouping of repeats
// against a computation of its own, the table route against the same series
// written as JSON, and an amplitude not recorded.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pendulum/analysis.hpp"
#include "pendulum/recordings/table.hpp"
#include "pendulum/scene_json.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using nlohmann::json;

namespace {

const std::string kData = PENDULUM_DATA_DIR;
const std::string kTables = PENDULUM_TABLES_DIR;

/// The rows of a comma-separated file of two numeric columns after a header, read here by hand.
std::vector<std::pair<double, double>> rows_of(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // the header
  std::vector<std::pair<double, double>> rows;
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    rows.emplace_back(std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1)));
  }
  return rows;
}

struct Group {
  double length;
  std::vector<double> times;
};

/// The same series as JSON, built from the rows by this test's own grouping:
/// consecutive rows at one length, a trial each; the pooled standard
/// deviation (sum of squares over sum of n - 1) as every length's one-trial
/// uncertainty (the floor of its own scatter).
json series_by_hand(const std::vector<std::pair<double, double>>& rows, double& pooled) {
  std::vector<Group> groups;
  for (const auto& [l, t] : rows) {
    if (groups.empty() || groups.back().length != l) groups.push_back({l, {}});
    groups.back().times.push_back(t);
  }
  double ss = 0.0, dof = 0.0;
  for (const Group& g : groups) {
    double mean = 0.0;
    for (double t : g.times) mean += t;
    mean /= static_cast<double>(g.times.size());
    for (double t : g.times) ss += (t - mean) * (t - mean);
    dof += static_cast<double>(g.times.size()) - 1.0;
  }
  pooled = std::sqrt(ss / dof);
  json observations = json::array();
  for (const Group& g : groups) {
    json timing = {{"oscillations_per_trial", 10}, {"unit", "s"}, {"trials", g.times}};
    timing["uncertainty"] = pooled;
    observations.push_back({{"length", {{"value", g.length}, {"unit", "cm"}}}, {"timing", timing}});
  }
  return {{"amplitude", "not recorded"}, {"observations", observations}};
}

}  // namespace

TEST_CASE("Tables: a T-against-L table with repeats equals the same series as JSON", "[tables]") {
  const std::string file = kData + "/pendulum_lengths_table.csv";
  double pooled = 0.0;
  const json by_hand = series_by_hand(rows_of(file), pooled);
  REQUIRE(by_hand["observations"].size() == 10);  // make_tables.py: 39 rows at 10 lengths

  const SettingsTable table = read_settings_table(file);
  REQUIRE(table.rows == 39);
  REQUIRE(table.observations.size() == 10);
  REQUIRE(table.pooled_sigma);
  CHECK(*table.pooled_sigma == Approx(pooled).epsilon(1e-12));
  CHECK(table.pooled_dof == 29);

  // Each observation's period and its uncertainty, against Eq. (4) on the groups computed here.
  const ParsedScene imported = parse_scene(table_scene(table, "pendulum_lengths_table.csv"));
  const ParsedScene hand = parse_scene(by_hand.dump());
  REQUIRE(imported.observations.size() == 10);
  for (std::size_t k = 0; k < 10; ++k) {
    const auto& times = by_hand["observations"][k]["timing"]["trials"];
    const double n = static_cast<double>(times.size());
    double mean = 0.0, ss = 0.0;
    for (const auto& t : times) mean += t.get<double>() / n;
    for (const auto& t : times) ss += (t.get<double>() - mean) * (t.get<double>() - mean);
    const double own = n > 1 ? std::sqrt(ss / (n - 1.0)) : 0.0;
    const double one = std::max(own, pooled);
    INFO(k);
    CHECK(imported.observations[k].period == Approx(mean / 10.0).epsilon(1e-13));
    CHECK(imported.observation_uncertainties[k].period == Approx(one / std::sqrt(n) / 10.0).epsilon(1e-12));
    CHECK(imported.observations[k].length == Approx(by_hand["observations"][k]["length"]["value"].get<double>() / 100.0));
  }
  const Analysis a = analyse(imported), b = analyse(hand);
  CHECK(a.g.value == Approx(b.g.value).epsilon(1e-12));
  CHECK(*a.g.uncertainty == Approx(*b.g.uncertainty).epsilon(1e-10));

  // The scene naming the table reads the same observations.
  const json named = {{"amplitude", "not recorded"}, {"observations", {{"table", "pendulum_lengths_table.csv"}}}};
  SceneFiles files;
  files.directory = kData;
  const ParsedScene referenced = parse_scene(named.dump(), files);
  CHECK(analyse(referenced).g.value == Approx(b.g.value).epsilon(1e-12));
  // Counted row by row, the same length read once would weigh up to seven times.
  json rows = json::array();
  for (const auto& [l, t] : rows_of(file)) {
    rows.push_back({{"length", {{"value", l}, {"unit", "cm"}}},
                    {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"trials", {t}}, {"uncertainty", pooled}}}});
  }
  const Analysis ungrouped = analyse(parse_scene(json{{"amplitude", "not recorded"}, {"observations", rows}}.dump()));
  CHECK(ungrouped.g.value != Approx(a.g.value).epsilon(1e-6));
}

TEST_CASE("Tables: the layouts of one series read to one result", "[tables]") {
  // make_tables.py writes the same rows (seed 7) as semicolons with decimal
  // commas behind a byte-order mark, a quoted header in metres, and a
  // tab-separated file without units (lengths 55-135: centimetres, with a warning).
  const SettingsTable comma = read_settings_table(kTables + "/semicolon_decimal_comma_bom.csv");
  const SettingsTable quoted = read_settings_table(kTables + "/quoted_header.csv");
  const SettingsTable bare = read_settings_table(kTables + "/unitless_cm.txt");
  CHECK(comma.setting_unit == "cm");
  CHECK(quoted.setting_unit == "m");
  CHECK(bare.setting_unit == "cm");
  CHECK(bare.warnings.size() == 2);  // the length's unit and the time's, from the numbers
  CHECK(comma.oscillations == 10);
  CHECK(quoted.oscillations == 10);
  CHECK(bare.oscillations == 10);
  const double g = analyse(parse_scene(table_scene(comma, "a"))).g.value;
  CHECK(analyse(parse_scene(table_scene(quoted, "b"))).g.value == Approx(g).epsilon(1e-12));
  CHECK(analyse(parse_scene(table_scene(bare, "c"))).g.value == Approx(g).epsilon(1e-12));
}

TEST_CASE("Tables: a headerless h, sigma_h, T, sigma_T pivot scan", "[tables]") {
  const std::string text = test::read_text(kTables + "/headerless_pivot_scan.txt");
  CHECK(looks_like_settings_table(text));
  const SettingsTable scan = parse_settings_table(text, "scan");
  CHECK(scan.setting == Setting::pivot_distance);
  REQUIRE(scan.columns.size() == 4);
  CHECK(scan.columns[1].role == "uncertainty of the pivot distance");
  CHECK(scan.columns[3].role == "uncertainty of the period");
  for (const auto& c : scan.columns) CHECK(c.decided_by == "content");
  // make_tables.py: a metre stick, k = 1/sqrt(12) m, g = 9.81 m/s^2.
  const Analysis a = analyse(parse_scene(table_scene(scan, "scan")));
  CHECK(std::abs(a.g.value - 9.81) < 3.0 * *a.g.uncertainty);
  // A recording is no table: phyphox's header names no setting.
  CHECK_FALSE(looks_like_settings_table("Time (s),Gyroscope x (rad/s)\n0,0.1\n0.01,0.2\n"));
}

// docs/series.md lists x as a pivot position's header word, and a track's x
// is a recording's: the times tell them apart, since a recording's increase.
TEST_CASE("Tables: x and T are a pivot scan where the periods do not increase, a track's x where they do",
          "[tables]") {
  const std::string table = "x (cm),T (s),u\n5,1.60,0.01\n10,1.55,0.01\n20,1.53,0.01\n60,1.60,0.01\n";
  CHECK(looks_like_settings_table(table));
  CHECK(parse_settings_table(table, "scan").setting == Setting::pivot_position);
  CHECK(looks_like_settings_table("x;T\n5;1,60\n10;1,55\n"));  // a decimal comma
  CHECK_FALSE(looks_like_settings_table("t,x\n0,0.1\n0.033,0.098\n0.067,0.093\n"));
  CHECK_FALSE(looks_like_settings_table("t (s),x (m),y (m)\n0,0.1,0\n0.033,0.098,0.001\n"));
}

TEST_CASE("Amplitude not recorded: a uniform distribution over its range", "[tables][amplitude]") {
  // The smallest scene (docs/scene.md): only the amplitude's own correction
  // runs, so its row is the first-order theta0 sigma/4 of g (a decay record
  // would lower it: the amplitude decays through each trial).
  const json base = {{"length", {{"value", 1.0}, {"uncertainty", 0.001}, {"unit", "m"}}},
                     {"amplitude", {{"value", 3.0}, {"unit", "deg"}}},
                     {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"resolution", 0.01}, {"trials", {20.07, 20.08, 20.06}}}}};
  auto with = [&](const json& amplitude) {
    json s = base;
    s["amplitude"] = amplitude;
    return analyse(parse_scene(s.dump()));
  };
  // GUM 4.3.7: uniform over [a, b] is (a + b)/2 +- (b - a)/sqrt(12).
  const Analysis range = with({{"range", {3, 15}}, {"unit", "deg"}});
  const Analysis stated = with({{"value", 9.0}, {"uncertainty", 12.0 / std::sqrt(12.0)}, {"unit", "deg"}});
  const Analysis unrecorded = with("not recorded");
  CHECK(range.g.value == Approx(stated.g.value).epsilon(1e-14));
  CHECK(*range.g.uncertainty == Approx(*stated.g.uncertainty).epsilon(1e-12));
  CHECK(unrecorded.g.value == Approx(range.g.value).epsilon(1e-14));
  const auto row = std::find_if(range.budget.begin(), range.budget.end(), [](const BudgetEntry& e) { return e.input == "amplitude"; });
  REQUIRE(row != range.budget.end());
  // Its size, theta0 sigma/4 of g to first order (the warning's figure).
  // To first order: the next term, 11 theta0^2/96, is 0.3 % at 9 deg.
  const double theta = 9.0 * kPi / 180.0, sigma = 12.0 / std::sqrt(12.0) * kPi / 180.0;
  CHECK(row->contribution == Approx(range.g.value * theta * sigma / 4.0).epsilon(0.005));

  json zero = base, wide = base;
  zero["amplitude"]["value"] = 0;
  wide["amplitude"] = {{"value", 5}, {"uncertainty", 5}, {"unit", "deg"}};
  CHECK_THROWS_WITH(parse_scene(zero.dump()), Catch::Contains("expected a positive angle: if the amplitude was not recorded, write \"amplitude\": \"not recorded\""));
  CHECK_THROWS_WITH(parse_scene(wide.dump()), Catch::Contains("is written \"amplitude\": {\"range\": [0, 10], \"unit\": \"deg\"}"));
}
