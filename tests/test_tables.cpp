// Tables of settings and periods (docs/series.md, "Tables"): the layouts of
// tests/tables/ (tests/tools/make_tables.py, seeded), the grouping of repeats
// against a computation of its own, the table route against the same series
// written as JSON, and an amplitude not recorded.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include <boost/math/distributions/students_t.hpp>
#include <iomanip>
#include <random>

#include "pendulum/reduce_scene.hpp"
#include "pendulum/recordings/table.hpp"
#include "pendulum/json/scene_json.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using nlohmann::json;

namespace {

const std::string kData = PENDULUM_DATA_DIR;
using Catch::Matchers::Contains;

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
  // import fits the offset of a table of three lengths or more (docs/series.md, "The offset").
  return {{"amplitude", "not recorded"}, {"fit", {"length_offset"}}, {"observations", observations}};
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
    double mean = 0.0;
    for (const auto& t : times) mean += t.get<double>() / n;
    // The table's floor and the scene reader's rule for a series agree: the
    // trials' scatter pooled over the lengths (docs/uncertainty.md).
    const double one = pooled;
    INFO(k);
    if (n > 1) CHECK(evaluation_of(imported.evaluations, imported.sources[k].path + "timing.period").shared == SharedVariance::pooled_trials);
    CHECK(imported.observations[k].period == Approx(mean / 10.0).epsilon(1e-13));
    CHECK(imported.observation_uncertainties[k].period == Approx(one / std::sqrt(n) / 10.0).epsilon(1e-12));
    CHECK(imported.observations[k].length == Approx(by_hand["observations"][k]["length"]["value"].get<double>() / 100.0));
  }
  const Analysis a = reduce_scene(imported), b = reduce_scene(hand);
  CHECK(a.g.value == Approx(b.g.value).epsilon(1e-12));
  CHECK(*a.g.uncertainty == Approx(*b.g.uncertainty).epsilon(1e-10));

  // The scene naming the table reads the same observations.
  const json named = {{"amplitude", "not recorded"},
                      {"fit", {"length_offset"}},
                      {"observations", {{"table", "pendulum_lengths_table.csv"}}}};
  SceneFiles files;
  files.directory = kData;
  const ParsedScene referenced = parse_scene(named.dump(), files);
  CHECK(reduce_scene(referenced).g.value == Approx(b.g.value).epsilon(1e-12));
  // Counted row by row, the same length read once would weigh up to seven times.
  json rows = json::array();
  for (const auto& [l, t] : rows_of(file)) {
    rows.push_back({{"length", {{"value", l}, {"unit", "cm"}}},
                    {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"trials", {t}}, {"uncertainty", pooled}}}});
  }
  const Analysis ungrouped =
      reduce_scene(parse_scene(json{{"amplitude", "not recorded"}, {"fit", {"length_offset"}}, {"observations", rows}}.dump()));
  // With the trials' scatter pooled over the lengths (docs/uncertainty.md), a
  // length's mean of n trials weighs what its n rows weigh (the normal
  // equations hold the same sums), and the shared amplitude weighs none:
  // row by row or grouped, one g and one u(g).
  CHECK(ungrouped.g.value == Approx(a.g.value).epsilon(1e-12));
  CHECK(*ungrouped.g.uncertainty == Approx(*a.g.uncertainty).epsilon(1e-9));
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
  const double g = reduce_scene(parse_scene(table_scene(comma, "a"))).g.value;
  CHECK(reduce_scene(parse_scene(table_scene(quoted, "b"))).g.value == Approx(g).epsilon(1e-12));
  CHECK(reduce_scene(parse_scene(table_scene(bare, "c"))).g.value == Approx(g).epsilon(1e-12));
}

TEST_CASE("Tables: a quoted header cell holding a line break is one cell (RFC 4180)", "[tables]") {
  // quoted_header.csv with each header cell broken before its unit, as a spreadsheet writes a cell of two lines.
  const std::string text = test::read_text(kTables + "/quoted_header.csv");
  const std::string rows = text.substr(text.find('\n') + 1);
  const double g = reduce_scene(parse_scene(table_scene(parse_settings_table(text, "a"), "a"))).g.value;
  for (const std::string line_break : {"\n", "\r\n"}) {
    const SettingsTable broken =
        parse_settings_table("\"l" + line_break + "(m)\",\"t_{10}" + line_break + "(s)\"\n" + rows, "b");
    CHECK(broken.setting_unit == "m");
    CHECK(broken.oscillations == 10);
    CHECK(reduce_scene(parse_scene(table_scene(broken, "b"))).g.value == g);
  }
  // A row's line and column are the file's: the header fills lines 1 to 3, the bad cell is on line 5.
  CHECK_THROWS_WITH(parse_settings_table("\"l\n(m)\",\"t_{10}\n(s)\"\n0.550,14.90\n0.550,x\n", "c"),
                    Catch::Matchers::Contains("c:5:7"));
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
  const Analysis a = reduce_scene(parse_scene(table_scene(scan, "scan")));
  CHECK(std::abs(a.g.value - 9.81) < 3.0 * *a.g.uncertainty);
  // A recording is no table: phyphox's header names no setting.
  CHECK_FALSE(looks_like_settings_table("Time (s),Gyroscope x (rad/s)\n0,0.1\n0.01,0.2\n"));
}

TEST_CASE("Tables: rows and columns past the limit are refused at the first one past it", "[tables]") {
  TableOptions options;
  options.limits = {1 << 20, 3, 2, "a table"};
  const std::string rows = "L (cm),t10 (s)\n55,14.91\n75,17.38\n95,19.55\n";
  CHECK(parse_settings_table(rows, "t", options).rows == 3);
  // Line 5 is the fourth row.
  CHECK_THROWS_WITH(parse_settings_table(rows + "115,21.53\n", "t", options),
                    "t:5:1: got more than 3 rows; expected at most 3 in a table (--max-rows raises the limit)");
  CHECK_THROWS_WITH(parse_settings_table("L (cm),t10 (s),theta (deg)\n55,14.91,5\n75,17.38,5\n", "t", options),
                    "t:1:16: got more than 2 columns; expected at most 2 in a table (--max-columns raises the limit)");
  // Empty cells to the end of a line are no columns (issue 42: a header followed by 10^5 of them was
  // "unrecognised header", then over the limit).
  CHECK(parse_settings_table("L (cm),t10 (s),,\n55,14.91\n75,17.38\n95,19.55\n", "t", options).rows == 3);
  const std::string wide = "L (cm),t10 (s)" + std::string(100000, ',') + "\n55,14.91\n75,17.38\n95,19.55\n";
  CHECK(parse_settings_table(wide, "t", TableOptions{}).rows == 3);
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
    return reduce_scene(parse_scene(s.dump()));
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

// The layouts students type (tests/tools/make_tables.py): each read with the
// roles its numbers and words give, and g within three of its standard
// uncertainties of the generator's 9.81 m/s^2.
namespace {

Analysis reduced(const SettingsTable& t) { return reduce_scene(parse_scene(table_scene(t, "t"))); }

std::vector<std::string> roles(const SettingsTable& t) {
  std::vector<std::string> out;
  for (const auto& c : t.columns) out.push_back(c.role);
  return out;
}

void check_g(const SettingsTable& t) {
  const Analysis a = reduced(t);
  REQUIRE(a.g.uncertainty);
  CHECK(std::abs(a.g.value - 9.81) < 3.0 * *a.g.uncertainty);
}

}  // namespace

TEST_CASE("Tables: a units row, trials side by side and a count of swings from the numbers", "[tables]") {
  const SettingsTable t = read_settings_table(kTables + "/units_row_trials.csv");
  CHECK(t.setting_unit == "m");  // the units row's "(m)"
  CHECK(t.oscillations == 10);   // times of 10 swings, nowhere written
  CHECK(t.observations.size() == 5);
  CHECK(t.observations[0].times.size() == 3);  // a row's trials are its repeats; an empty cell is none
  CHECK(t.columns[2].role == "time of 10 oscillations");
  check_g(t);
  // The same rows in one column each, headerless, in centimetres: the same observations.
  const SettingsTable bare = read_settings_table(kTables + "/headerless_times_of_swings.txt");
  CHECK(bare.setting_unit == "cm");
  CHECK(bare.oscillations == 10);
  REQUIRE(bare.observations.size() == t.observations.size());
  for (std::size_t k = 0; k < t.observations.size(); ++k) CHECK(bare.observations[k].times == t.observations[k].times);
}

TEST_CASE("Tables: Dutch headers with error columns", "[tables]") {
  const SettingsTable t = read_settings_table(kTables + "/dutch_errors.csv");
  CHECK(t.setting_unit == "cm");
  CHECK(t.oscillations == 10);
  CHECK(roles(t) == std::vector<std::string>{"length", "time of 10 oscillations", "uncertainty of the length",
                                             "uncertainty of the time of 10 oscillations"});
  REQUIRE(t.observations[0].setting_sigma);
  CHECK(*t.observations[0].setting_sigma == 0.2);
  check_g(t);
}

TEST_CASE("Tables: sigma columns by place and by matplotlib's names, the periods first", "[tables]") {
  const SettingsTable xy = read_settings_table(kTables + "/x_y_sx_sy.txt");
  const std::vector<std::string> x_y_sx_sy = {"length", "period", "uncertainty of the length", "uncertainty of the period"};
  CHECK(roles(xy) == x_y_sx_sy);
  CHECK(*xy.observations[0].time_sigma == 0.01);
  const SettingsTable named = read_settings_table(kTables + "/xerr_yerr.csv");
  CHECK(roles(named) == x_y_sx_sy);
  check_g(xy);
  check_g(named);
  const SettingsTable swapped = read_settings_table(kTables + "/period_first.txt");
  CHECK(roles(swapped) == std::vector<std::string>{"period", "length"});
  CHECK(swapped.setting_unit == "cm");
  CHECK(swapped.sigma_from_scatter);
}

TEST_CASE("Tables: two period columns named by their timing method are compared, the first read", "[tables]") {
  // Issue 39: Tracker's and phyphox's periods side by side gave "no period
  // column". Four lengths, the second column within 2 ms of the first (1.4
  // standard errors: they agree), or 2.3 % longer (11: they do not, which a
  // warning says); either way the first is read and g is the same.
  const std::string lengths[] = {"0.40", "0.60", "0.80", "1.00"};
  const std::string tracker[] = {"1.270", "1.555", "1.795", "2.007"}, near[] = {"1.272", "1.556", "1.797", "2.006"},
                    far[] = {"1.302", "1.596", "1.840", "2.057"};
  std::string agree = "L (m),T Tracker (s),T_phyphox (s)\n", disagree = "L (m),period (tracker) (s),phyphox T (s)\n",
              alone = "L (m),T (s)\n";
  for (int i = 0; i < 4; ++i) {
    agree += lengths[i] + "," + tracker[i] + "," + near[i] + "\n";
    disagree += lengths[i] + "," + tracker[i] + "," + far[i] + "\n";
    alone += lengths[i] + "," + tracker[i] + "\n";
  }
  const SettingsTable a = parse_settings_table(agree, "t"), d = parse_settings_table(disagree, "t");
  for (const SettingsTable* t : {&a, &d}) CHECK(roles(*t) == std::vector<std::string>{"length", "period", "unused"});
  CHECK_THAT(a.columns[2].why, Contains("its periods agree with it: they differ by 0.001 s on average (1.41 standard errors;"));
  for (const auto& w : a.warnings) CHECK_THAT(w.text, !Contains("two timings that disagree"));
  REQUIRE(d.warnings.size() == 1);
  CHECK_THAT(d.warnings[0].text, Contains("\"phyphox T (s)\" times the same rows 2.34 % longer than \"period (tracker) (s)\"") &&
                                     Contains("11 standard errors"));
  const double g = reduced(parse_settings_table(alone, "t")).g.value;
  CHECK(reduced(a).g.value == g);
  CHECK(reduced(d).g.value == g);
  // The g the other column gives, as the warning says it (two figures):
  // independently, least squares in T of T = c sqrt(L + delta) for each
  // column (c = sum T s / sum s^2 at each delta, s = sqrt(L + delta), delta
  // by a fine scan), g = (2 pi / c)^2. A reduction weights each row by its
  // length's last digit too, which moves the offset: not this figure's oracle.
  auto least_squares_g = [&](const std::string* periods) {
    double best = HUGE_VAL, g_best = 0.0;
    int k_best = 0;
    for (int k = -20000; k <= 20000; ++k) {
      const double delta = k * 1e-6;
      double ts = 0.0, ss = 0.0, tt = 0.0;
      for (int i = 0; i < 4; ++i) {
        const double t = std::stod(periods[i]), sq = std::sqrt(std::stod(lengths[i]) + delta);
        ts += t * sq, ss += sq * sq, tt += t * t;
      }
      const double c = ts / ss, rss = tt - c * ts;
      if (rss < best) best = rss, g_best = std::pow(2.0 * kPi / c, 2), k_best = k;
    }
    CHECK(std::abs(k_best) < 20000);  // the optimum inside the scan, not at its edge
    return g_best;
  };
  const double lower = 100.0 * (1.0 - least_squares_g(far) / least_squares_g(tracker));
  const std::string& text = d.warnings[0].text;
  const std::string lead = "read instead, g from the fit of T against L is ";
  REQUIRE(text.find(lead) != std::string::npos);
  CHECK_THAT(text, Contains(" % lower"));
  // The figure has two significant digits (4.8 for 4.76): half a unit of the last.
  CHECK(std::stod(text.substr(text.find(lead) + lead.size())) == Approx(lower).margin(0.05));
  // A timing method alone, or beside another word, names no period.
  CHECK_THROWS_WITH(parse_settings_table("L (m),tracker (s)\n0.4,1.27\n0.6,1.555\n", "t"), Contains("no period column"));
  CHECK_THROWS_WITH(parse_settings_table("L (m),T initial (s)\n0.4,1.27\n0.6,1.555\n", "t"), Contains("no period column"));
}

TEST_CASE("Tables: error columns by the spellings students use, each after its value", "[tables]") {
  // Issue 39's list: dL/dT, u(L), sigma L, a bare +-, delta, unc, err, and
  // Delta L; each the uncertainty of its value, by its own name or as the
  // uncertainty of the column before it.
  const std::string rows = "20,0.5,0.90,0.02\n40,0.5,1.27,0.02\n60,0.5,1.55,0.02\n80,0.5,1.80,0.02\n";
  const std::vector<std::string> expected = {"length", "uncertainty of the length", "period", "uncertainty of the period"};
  for (const std::string header :
       {"L (cm),dL (cm),T (s),dT (s)", "L (cm),u(L) (cm),T (s),u(T) (s)", "L (cm),\xcf\x83L (cm),T (s),\xcf\x83T (s)",
        "L (cm),\xc2\xb1 (cm),T (s),\xc2\xb1 (s)", "L (cm),delta L (cm),T (s),delta T (s)", "L (cm),unc (cm),T (s),unc (s)",
        "L (cm),err (cm),T (s),err (s)", "L (cm),\xce\x94L (cm),T (s),\xce\x94T (s)"}) {
    INFO(header);
    const SettingsTable t = parse_settings_table(header + "\n" + rows, "t");
    CHECK(roles(t) == expected);
    REQUIRE(t.observations[0].time_sigma);
    CHECK(*t.observations[0].time_sigma == 0.02);
  }
}

TEST_CASE("Tables: a fitting program's generic header (x y dx dy) is read by place, as without a header",
          "[tables]") {
  // PHY180's fitting program names its columns x, y, dx, dy (or X', Y' for
  // the uncertainties): where a value goes in the fit, not what it is. The
  // rows of x_y_sx_sy.txt (exact for g = 9.81) under such headers read as
  // that headerless file does: a table (not a recording of 6 samples), each
  // value column with its uncertainty, in either order.
  std::string rows = test::read_text(kTables + "/x_y_sx_sy.txt");
  std::replace(rows.begin(), rows.end(), '\t', ' ');  // one delimiter, as the header's
  const std::vector<std::string> x_y_sx_sy = {"length", "period", "uncertainty of the length", "uncertainty of the period"};
  for (const std::string header : {"x y dx dy\n", "X Y X' Y'\n"}) {
    INFO(header);
    CHECK(looks_like_settings_table(header + rows));
    const SettingsTable t = parse_settings_table(header + rows, "t");
    CHECK(roles(t) == x_y_sx_sy);
    check_g(t);
  }
  // Values and uncertainties alternating: each uncertainty after its value.
  std::string alternating = "x,dx,y,dy\n";
  for (const std::string& line : {std::string("0.35,0.002,1.181,0.01"), std::string("0.50,0.002,1.422,0.01"),
                                  std::string("0.65,0.002,1.627,0.01"), std::string("0.80,0.002,1.795,0.01")}) {
    alternating += line + "\n";
  }
  CHECK(looks_like_settings_table(alternating));
  CHECK(roles(parse_settings_table(alternating, "t")) ==
        std::vector<std::string>{"length", "uncertainty of the length", "period", "uncertainty of the period"});
}

TEST_CASE("Tables: an uncertainty named in a phrase, \"uncertainty in period\", \"error in the length\"", "[tables]") {
  // A class's published table (issue 39's real files): "length (cm),period
  // (seconds),uncertainty in period (seconds)"; its third column was unused,
  // "a word the reader does not know", and the repeats' scatter took its place.
  const std::string rows = "20,0.90,0.02\n40,1.27,0.02\n60,1.55,0.02\n80,1.80,0.02\n";
  const SettingsTable in = parse_settings_table("length (cm),period (seconds),uncertainty in period (seconds)\n" + rows, "t");
  CHECK(roles(in) == std::vector<std::string>{"length", "period", "uncertainty of the period"});
  REQUIRE(in.observations[0].time_sigma);
  CHECK(*in.observations[0].time_sigma == 0.02);
  const SettingsTable phrases =
      parse_settings_table("length (cm),error in the length (cm),period (s),error of T (s)\n"
                           "20,0.5,0.90,0.02\n40,0.5,1.27,0.02\n60,0.5,1.55,0.02\n80,0.5,1.80,0.02\n", "t");
  CHECK(roles(phrases) == std::vector<std::string>{"length", "uncertainty of the length", "period",
                                                   "uncertainty of the period"});
  const SettingsTable german =
      parse_settings_table("L\xc3\xa4nge (cm),Fehler der L\xc3\xa4nge (cm),Periode (s),Unsicherheit der Periode (s)\n"
                           "20,0.5,0.90,0.02\n40,0.5,1.27,0.02\n60,0.5,1.55,0.02\n80,0.5,1.80,0.02\n", "t");
  CHECK(roles(german) == roles(phrases));
}

TEST_CASE("Tables: a time of N swings beside its period, and a per-row g, are not inputs", "[tables]") {
  // make_tables.py: L (no unit; 35-110: centimetres), t = 10 T, T, and each row's 4 pi^2 L/T^2.
  const SettingsTable t = read_settings_table(kTables + "/l_t_T_g.csv");
  CHECK(t.setting_unit == "cm");
  CHECK(t.oscillations == 1);
  REQUIRE(roles(t) == std::vector<std::string>{"length", "unused", "period", "unused"});
  CHECK(t.columns[1].why.find("the time of 10 oscillations beside the periods of column 3") != std::string::npos);
  CHECK_THAT(t.columns[3].why, Contains("each row's g (a student's working): not read; compared with each row's "
                                        "4 pi^2 L/T^2: within 0.01 % at every row"));
  for (const auto& w : t.warnings) CHECK_THAT(w.text, !Contains("a slip in the working"));
  check_g(t);
  // T^2 and g beside L and T (issue 39): compared, never read; a g slipped
  // in one row's working (9.52 where 0.60 m and 1.555 s give 9.796) is named
  // at its line, and the fit is the same as without the two columns.
  const std::string rows[] = {"0.40,1.270,1.6129,9.79\n", "0.60,1.555,2.4180,9.52\n", "0.80,1.795,3.2220,9.80\n",
                              "1.00,2.007,4.0280,9.80\n"};
  std::string derived = "L (m),T (s),T^2 (s^2),g (m/s^2)\n", plain = "L (m),T (s)\n";
  for (const std::string& row : rows) derived += row, plain += row.substr(0, row.find(',', 5)) + "\n";
  const SettingsTable d = parse_settings_table(derived, "t");
  CHECK(roles(d) == std::vector<std::string>{"length", "period", "unused", "unused"});
  CHECK_THAT(d.columns[2].why, Contains("the periods squared (a student's working): not read; compared with each "
                                        "row's T^2: within 0.01 % at every row"));
  REQUIRE(d.warnings.size() == 1);
  CHECK(d.warnings[0].line == 3);
  CHECK_THAT(d.warnings[0].text, Contains("\"g (m/s^2)\" at line 3: 9.52 m/s^2 where its row's 4 pi^2 L/T^2 is "
                                          "9.79603 m/s^2 (2.8 % off"));
  CHECK(reduced(d).g.value == reduced(parse_settings_table(plain, "t")).g.value);
  // A row of trials is compared by their mean, as its working took them:
  // trials 3 % either side of 1.270 s give the row's g exactly, no warning.
  const SettingsTable trials = parse_settings_table(
      "L (m),trial 1 (s),trial 2 (s),trial 3 (s),g (m/s^2)\n0.40,1.2319,1.270,1.3081,9.790\n"
      "0.60,1.508,1.555,1.602,9.796\n0.80,1.741,1.795,1.849,9.802\n", "t");
  for (const auto& w : trials.warnings) CHECK_THAT(w.text, !Contains("a slip in the working"));
  // An uncertainty after a working is the working's: not the period's.
  const SettingsTable sigma = parse_settings_table(
      "L (m),T (s),g (m/s^2),\xc2\xb1 (m/s^2)\n0.40,1.270,9.79,0.2\n0.60,1.555,9.80,0.2\n0.80,1.795,9.80,0.2\n", "t");
  CHECK(roles(sigma) == std::vector<std::string>{"length", "period", "unused", "unused"});
  CHECK_THAT(sigma.columns[3].why, Contains("the uncertainty of a student's working before it: not read"));
  // In other units a working is not compared, and says so.
  CHECK_THAT(parse_settings_table("L (m),T (s),g (cm/s^2)\n0.40,1.270,979\n0.60,1.555,980\n", "t").columns[2].why,
             Contains("not compared (its unit cm/s^2)"));
}

TEST_CASE("Tables: single timings take their uncertainty from the scatter about the fit", "[tables]") {
  const SettingsTable t = read_settings_table(kTables + "/single_timings.csv");
  CHECK(t.sigma_from_scatter);
  CHECK(t.resolution == Approx(0.001).epsilon(1e-9));  // "1.181": three decimals
  const ParsedScene scene = parse_scene(table_scene(t, "t"));
  CHECK(scene.period_uncertainty_from_scatter);
  CHECK(scene.fit == std::vector<std::string>{"length_offset"});
  const Analysis a = reduce_scene(scene);
  check_g(t);
  // chi2 gives no verdict: no status reason from it, whatever its size.
  for (const auto& r : a.status_reasons) CHECK(r.find("scatter about the fit") == std::string::npos);
  // Each period's uncertainty is the scatter (S = 27 times the floor of 0.001 s/sqrt(12)):
  // no period is called a miscount against the floor alone (six such warnings before).
  for (const auto& w : a.warnings) CHECK(w.find("a miscounted oscillation") == std::string::npos);
  // With a sigma column nothing changes: the same rows with one stated.
  const SettingsTable stated = read_settings_table(kTables + "/xerr_yerr.csv");
  CHECK_FALSE(stated.sigma_from_scatter);
  CHECK_FALSE(parse_scene(table_scene(stated, "t")).period_uncertainty_from_scatter);
}

namespace {

constexpr double kTrueG = 9.81;

/// A seeded table without sigma (std::mt19937_64): six lengths 0.4-1.4 m taped to the top of a
/// ball 12.7 mm above its centre, one period each from T = 2 pi sqrt(L/g) 2K(sin(theta0/2))/pi at
/// g = 9.81 m/s^2 and theta0 = 2 deg (the closed form the reduction inverts), plus N(0, noise s),
/// written with `decimals` decimals.
SettingsTable swung_table(int seed, double noise, int decimals) {
  const double offset = 0.0127, theta = 2.0 * kPi / 180.0;
  const double factor = 2.0 / kPi * std::comp_ellint_1(std::sin(theta / 2.0));
  std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
  std::normal_distribution<double> error(0.0, noise);
  std::ostringstream text;
  text << "L (m),T (s),theta (deg)\n";
  for (int i = 0; i < 6; ++i) {
    const double l = 0.4 + 0.2 * i;
    const double t = 2.0 * kPi * std::sqrt((l + offset) / kTrueG) * factor + error(rng);
    text << l << "," << std::fixed << std::setprecision(decimals) << t << std::defaultfloat << ",2\n";
  }
  return parse_settings_table(text.str(), "seed " + std::to_string(seed));
}

}  // namespace

TEST_CASE("Tables: the scatter's sigma covers the truth at Student's t rate", "[tables][coverage]") {
  // 400 seeded tables (seeds 1-400), 2 ms of noise written to 0.1 ms. The offset and g are fitted
  // (n - p = 4 degrees of freedom), so g +- its sigma from the scatter holds the truth with
  // probability P(|t_4| < 1) = 0.626 (Boost.Math's Student's t), 400 p (1 - p) its binomial variance.
  const int runs = 400;
  int covered = 0;
  for (int seed = 1; seed <= runs; ++seed) {
    const SettingsTable table = swung_table(seed, 0.002, 4);
    REQUIRE(table.sigma_from_scatter);
    const Analysis a = reduced(table);
    covered += std::abs(a.g.value - kTrueG) < *a.g.uncertainty;
  }
  const boost::math::students_t t4(4.0);
  const double p = 2.0 * boost::math::cdf(t4, 1.0) - 1.0;
  const double sd = std::sqrt(runs * p * (1.0 - p));
  INFO("covered " << covered << " of " << runs << ", expected " << runs * p << " +- " << sd);
  CHECK(std::abs(covered - runs * p) < 3.5 * sd);

  // S is applied wherever it is above 1, not only where chi2 is improbable: tables written to
  // 0.01 s (a floor of 2.9 ms) whose 3 ms of noise scatter just above it.
  int probable = 0;
  for (int seed = 1; seed <= 100; ++seed) {
    const Analysis a = reduced(swung_table(seed, 0.003, 2));
    if (!(*a.fit.birge_ratio > 1.0)) continue;
    probable += *a.fit.probability > 0.01;
    INFO("seed " << seed << ": S = " << *a.fit.birge_ratio);
    // Nothing but the periods has an uncertainty: g's is the unscaled one times S.
    CHECK(*a.g.uncertainty == Approx(*a.fit.birge_ratio * *a.g_uncertainty_unscaled).epsilon(1e-9));
  }
  CHECK(probable > 10);
}

namespace {

/// A class's pooled table (std::mt19937_64 `seed`): five lengths 0.2-3.2 m,
/// doubling (a class's run from a short string to the stairwell),
/// four groups' rows at each, "length (cm),period (s),uncertainty in period
/// (s)", each row's period at g = 9.81 from T = 2 pi sqrt(L/g) 2K/pi at 5 deg
/// plus N(0, 0.02 s) of timing, the 0.02 s stated; and `length_error` (m):
/// each group's tape off by N(0, it) from the nominal length (a length's
/// error, (T/2L) of it in the period), or, where negative, a stopwatch's
/// further N(0, |it|) s, the same at every length.
SettingsTable class_table(int seed, double length_error) {
  const double theta = 5.0 * kPi / 180.0, factor = 2.0 / kPi * std::comp_ellint_1(std::sin(theta / 2.0));
  std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
  std::normal_distribution<double> normal(0.0, 1.0);
  std::ostringstream text;
  text << "length (cm),period (s),uncertainty in period (s)\n";
  for (int i = 0; i < 5; ++i) {
    const double l = 0.2 * std::pow(2.0, i);
    for (int group = 0; group < 4; ++group) {
      const double taped = length_error > 0.0 ? l + length_error * normal(rng) : l;
      const double t = 2.0 * kPi * std::sqrt(taped / kTrueG) * factor + 0.02 * normal(rng) +
                       (length_error < 0.0 ? -length_error * normal(rng) : 0.0);
      text << 100.0 * l << "," << std::fixed << std::setprecision(3) << t << std::defaultfloat << ",0.02\n";
    }
  }
  return parse_settings_table(text.str(), "class " + std::to_string(seed));
}

}  // namespace

TEST_CASE("Tables: rows at one length that scatter as lengths do are readings of their own", "[tables][coverage]") {
  // 100 seeded class tables (class_table) whose groups' tapes are each off by
  // 30 mm: their rows scatter as the lengths' error does, (T/2L) 30 mm, 0.08 s
  // at 20 cm and 0.02 s at 3.2 m, beyond the stated 0.02 s. Each row then is
  // its own observation, and g (its offset fitted, the lengths' scatter too)
  // within 3 of its uncertainties of the truth. The same tables with a
  // stopwatch's further 0.05 s instead, the same at every length, keep their
  // rows at one length as repeats of one reading. Four rows a length say
  // little about how their scatter changes with it: at the factor e the rates
  // measured at this commit were 69 split of 100 and 88 kept of 100; the
  // checks hold each within 3 binomial sigmas below that (4.6 and 3.2), a
  // regression test of the rule's power, not a derived rate.
  int split = 0, kept = 0, outside = 0;
  for (int seed = 1; seed <= 100; ++seed) {
    const SettingsTable lengths = class_table(seed, 0.03);
    if (lengths.observations.size() == 20) {
      ++split;
      const Analysis a = reduced(lengths);
      outside += !(std::abs(a.g.value - kTrueG) < 3.0 * *a.g.uncertainty);
    }
    kept += class_table(seed, -0.05).observations.size() == 5;
  }
  WARN("split " << split << " of 100 length-like tables, kept " << kept << " of 100 stopwatch-like; " << outside
                << " of the split beyond 3 sigmas");
  CHECK(split >= 69 - 14);
  CHECK(kept >= 88 - 10);
  // 3 sigmas leave 0.27 % out: 0.2 of the split; 2 or more has a Poisson probability of 1.7 %.
  CHECK(outside <= 1);
}
