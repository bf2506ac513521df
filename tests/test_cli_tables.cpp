// pendulum-g import TABLE and the scenes that name a table (docs/series.md,
// "Tables"; docs/physical.md, "A pivot scan typed as a table").
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;
using nlohmann::json;

namespace {
const std::string kData = PENDULUM_DATA_DIR;
const std::string kTests = PENDULUM_TESTS_DIR;

double g_of(const Run& r) { return json::parse(r.out).at("g").at("value").get<double>(); }

/// A command that must succeed.
Run succeeded(const std::string& command) {
  const Run r = run(command);
  INFO(command << ": " << r.err);
  REQUIRE(r.status == 0);
  return r;
}
}  // namespace

TEST_CASE("import TABLE prints a scene that reduces to the scene naming the table", "[cli][tables]") {
  for (const std::string name : {"pendulum_lengths_table", "pivot_scan_table"}) {
    INFO(name);
    const Run imported = run("import " + kData + "/" + name + ".csv");
    REQUIRE(imported.status == 0);
    const json scene = json::parse(imported.out);
    CHECK(scene.at("amplitude") == "not recorded");  // the table has no amplitude column
    CHECK(scene.at("import").at("columns").size() == (name == "pivot_scan_table" ? 4 : 2));
    const std::string file = temporary_file();
    std::ofstream(file) << imported.out;
    const Run from_import = run("reduce " + file);
    std::remove(file.c_str());
    const Run named = run("reduce " + kData + "/" + name + "_scene.json");
    REQUIRE(from_import.status == 0);
    REQUIRE(named.status == 0);
    CHECK(g_of(from_import) == Approx(g_of(named)).epsilon(1e-12));
    CHECK_THAT(named.out, Contains("\"input\": \"amplitude\""));  // the amplitude's row in the budget
  }
}

TEST_CASE("a correct 170 deg row is no mixed unit: the check compares g with each row's amplitude applied",
          "[cli][tables]") {
  // Periods exact for g = 9.81 m/s^2 (tests/tools/make_tables.py, exact_period: 4 sqrt(L/g) K(sin^2(theta0/2)));
  // the 170 deg row's is 2.44 times its small-amplitude one, and 4 pi^2 L/T^2 0.17 times the others' g.
  const Run imported = succeeded("import " + kTests + "/tables/amplitude_170.csv");
  const std::string file = temporary_file();
  std::ofstream(file) << imported.out;
  const Run reduced = succeeded("reduce " + file);
  std::remove(file.c_str());
  const json result = json::parse(reduced.out);
  const double u = result.at("g").at("uncertainty").get<double>();
  CHECK(std::fabs(g_of(reduced) - 9.81) < 2.0 * u);
}

TEST_CASE("import of a headerless pivot scan reads a table, not blocking times", "[cli][tables]") {
  const Run r = run("import " + kTests + "/tables/headerless_pivot_scan.txt");
  REQUIRE(r.status == 0);
  const json scene = json::parse(r.out);
  CHECK(scene.at("fit") == json{"radius_of_gyration"});
  CHECK(scene.at("observations").size() == 9);
  CHECK(scene.at("import").at("columns")[0].at("decided_by") == "content");
  // A warning as every command prints one (print_warnings).
  CHECK_THAT(r.err, Contains("pendulum-g: warning: " + kTests + "/tables/headerless_pivot_scan.txt: \"column 1\": no "
                             "unit; read as m"));
}

// The message names the column's own symbol and letter (kSettingInfo): a
// position's was a distance's "h (cm)" before.
TEST_CASE("import of a unitless pivot-position column that fits two units names its symbol", "[cli][tables]") {
  const std::string file = temporary_file();
  std::ofstream(file) << "x,T\n5,1.60\n10,1.55\n20,1.53\n60,1.60\n";
  const Run r = run("import --columns x,T " + file);
  std::remove(file.c_str());
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Contains("fit the periods in cm or mm; expected its unit in the header (\"x (cm)\") or declared: "
                             "--columns \"x:cm,...\" (a scene's \"columns\": {\"pivot_position\": {\"column\": 1"));
}

// import --help and the message for a column it cannot read list the same roles
// (table_column_roles), the settings' letters among them.
TEST_CASE("import --help names a table's column roles, as the message for a wrong one does", "[cli][tables]") {
  const std::string roles = "l (length), h (pivot distance), x (pivot position), r (rod length), T (period), tN "
                            "(time of N oscillations: t10), theta (amplitude), u (the uncertainty of the column before)";
  CHECK_THAT(run("import --help").out, Contains(roles));
  const Run wrong = run("import --columns l,T,q " + kData + "/pendulum_lengths_table.csv");
  CHECK(wrong.status == 1);
  CHECK_THAT(wrong.err, Contains("got the column \"q\"; expected " + roles + ", or - for a column not used"));
}

TEST_CASE("reduce and report TABLE say what to do instead of 'not valid JSON' or 'unrecognised header'",
          "[cli][tables]") {
  // A pivot scan's "x (cm)" beside a time is a track's header too: its
  // periods, which do not increase, make it a table.
  const std::string scan = temporary_file() + ".csv", page = temporary_file() + ".html";
  std::ofstream(scan) << "x (cm),T (s)\n5,1.62\n10,1.55\n20,1.52\n30,1.58\n";
  for (const std::string& command : {std::string("reduce"), "report -o " + page}) {
    for (const std::string& table : {kData + "/pendulum_lengths_table.csv", kData + "/pivot_scan_table.csv", scan}) {
      INFO(command << " " << table);
      const Run r = run(command + " " + table);
      CHECK(r.status == 1);
      CHECK(r.out.empty());
      CHECK_THAT(r.err, Contains("a table of settings and periods, not a scene (JSON); expected a scene: make one with "
                                 "pendulum-g import TABLE > scene.json"));
      CHECK_THAT(r.err, !Contains("not valid JSON") && !Contains("unrecognised header"));
      CHECK_FALSE(std::ifstream(page).good());
    }
  }
  std::remove(scan.c_str());
}

TEST_CASE("a scene's table is confined to its folder like a recording", "[cli][tables]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(temporary_file() + ".d");
  fs::create_directories(dir / "inner");
  fs::copy_file(kData + "/pendulum_lengths_table.csv", dir / "lengths.csv");
  std::ofstream(dir / "inner" / "scene.json")
      << R"({"amplitude": "not recorded", "observations": {"table": "../lengths.csv"}})";
  const Run refused = run("reduce " + (dir / "inner" / "scene.json").string());
  CHECK(refused.status == 1);
  CHECK_THAT(refused.err, Contains("observations.table: got \"../lengths.csv\"; expected a file in the scene's folder or "
                                   "below (\"..\" leads out of it): a scene's tables are read from elsewhere only with "
                                   "--allow-outside"));
  const Run allowed = run("reduce --allow-outside " + (dir / "inner" / "scene.json").string());
  CHECK(allowed.status == 0);
  // Declared columns replace the header's reading: column 2 as single periods is refused by the physics.
  std::ofstream(dir / "declared.json")
      << R"({"amplitude": "not recorded", "observations": {"table": "lengths.csv", "columns": {"length": {"column": 1, "unit": "cm"}, "time": {"column": 2, "oscillations": 10, "unit": "s"}}}})";
  const Run declared = run("reduce " + (dir / "declared.json").string());
  CHECK(declared.status == 0);
  CHECK(g_of(declared) == Approx(g_of(allowed)).epsilon(1e-12));
  fs::remove_all(dir);
}

TEST_CASE("import --format table shows a table's columns and each observation the scene gets", "[cli][tables]") {
  const std::string file = kData + "/pendulum_lengths_table.csv";
  const Run text = succeeded("import --format table " + file), scene = succeeded("import " + file);
  CHECK_THAT(text.out, Contains("column 1               length (cm) \"L (cm)\", by the header"));
  CHECK_THAT(text.out, Contains("(39 rows, 10 observations)"));
  // One line per observation of the scene: its length, rows and mean time.
  const json observations = json::parse(scene.out).at("observations");
  REQUIRE(observations.size() == 10);
  for (const json& o : observations) {
    const json& trials = o.at("timing").at("trials");
    double mean = 0.0;
    for (const json& t : trials) mean += t.get<double>() / static_cast<double>(trials.size());
    char line[100];
    std::snprintf(line, sizeof line, "\n%-22.6g %5zu %-18.7g ", o.at("length").at("value").get<double>(),
                  trials.size(), mean);
    CHECK_THAT(text.out, Contains(line));
  }
  CHECK(text.out.find('{') == std::string::npos);  // no JSON
}

TEST_CASE("The tables in data/ are tests/tools/make_tables.py's output", "[cli][tables]") {
  // The script writes every table of tests/tables/ and data/ from its seeds,
  // here under a folder of its own.
  const std::string dir = temporary_file() + ".d";
  std::filesystem::create_directories(dir);
  const std::string command = "/usr/bin/python3 " + kTests + "/tools/make_tables.py " + dir + " > /dev/null";
  REQUIRE(std::system(command.c_str()) == 0);
  for (const std::string name : {"pendulum_lengths_table.csv", "pivot_scan_table.csv", "amplitude_sweep.csv"}) {
    REQUIRE(std::filesystem::exists(dir + "/data/" + name));
  }
  // And every other file it writes (tests/tables/, the bad tables).
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = std::filesystem::relative(entry.path(), dir).string();
    INFO(name);
    CHECK(pendulum::test::read_text(entry.path().string()) == pendulum::test::read_text(kData + "/../" + name));
    ++files;
  }
  CHECK(files == 35);
  std::filesystem::remove_all(dir);
}

TEST_CASE("The pivot scan's HTML report gives the textbook g with its uncertainty, as the JSON does", "[cli][tables]") {
  const std::string scene = kData + "/pivot_scan_table_scene.json";
  const Run result = succeeded("reduce " + scene), page = succeeded("report " + scene);
  const json g = json::parse(result.out).at("fit").at("pivot_scan").at("textbook").at("g");
  const std::string head = "g of the textbook curve (no corrections)</th><td>";
  const auto at = page.out.find(head);
  REQUIRE(at != std::string::npos);
  const std::string cell = page.out.substr(at + head.size(), page.out.find("</td>", at) - at - head.size());
  INFO(cell);
  const std::string plus_minus = " \u00B1 ";
  const auto pm = cell.find(plus_minus);
  REQUIRE(pm != std::string::npos);
  const double value = std::stod(cell.substr(0, pm)), sigma = std::stod(cell.substr(pm + plus_minus.size()));
  // Rounded to the uncertainty's first digits (value_with_uncertainty).
  CHECK(std::abs(value - g.at("value").get<double>()) <= sigma);
  CHECK(sigma == Approx(g.at("uncertainty").get<double>()).epsilon(0.5));
}

TEST_CASE("an amplitude sweep's table reduces to its small-amplitude period, and to g once its length is given",
          "[cli][tables][sweep]") {
  // tests/tools/make_tables.py draws each on the exact law (mpmath's K) at g = 9.81 m/s^2 and this length (m).
  struct Case {
    std::string file;
    double length;
    const char* unit;
  };
  const Case cases[] = {{kData + "/amplitude_sweep.csv", 0.80, "deg"},
                        {kTests + "/tables/sweep_signed_radians.txt", 0.47, "rad"},
                        {kTests + "/tables/sweep_winkel.txt", 1.20, "deg"},
                        {kTests + "/tables/sweep_degrees_headerless.txt", 0.35, "deg"}};
  for (const Case& c : cases) {
    INFO(c.file);
    json scene = json::parse(succeeded("import " + c.file).out);
    CHECK(scene.at("length") == "not measured");
    CHECK(scene.at("title").get<std::string>().find("an amplitude sweep") != std::string::npos);
    CHECK(scene.at("import").at("columns")[0].at("role") == "amplitude");
    CHECK(scene.at("import").at("columns")[0].at("unit") == c.unit);
    CHECK_FALSE(scene.at("observations")[0].contains("length"));
    const std::string file = temporary_file();
    std::ofstream(file) << scene.dump();
    const json sweep = json::parse(succeeded("reduce " + file).out);
    CHECK(sweep.at("kind") == "amplitude_sweep");
    CHECK(sweep.at("g").is_null());
    const json& t0 = sweep.at("amplitude_sweep").at("small_amplitude_period");
    const double truth = 2.0 * M_PI * std::sqrt(c.length / 9.81);
    CHECK(std::abs(t0.at("value").get<double>() - truth) < 3.0 * t0.at("uncertainty").get<double>());
    CHECK(sweep.at("amplitude_sweep").at("quadratic").at("agrees_with_law") == true);
    CHECK(sweep.at("status") == "ok");
    CHECK_THAT(succeeded("reduce --format table " + file).out,
               Contains("small-amplitude period T0 = ") && Contains("g                   = none: the length was not measured"));
    // Nothing else computes g without a length: each command says so (batch in its line for the file).
    for (const std::string& command : {std::string("batch ") + file, "report -o " + file + ".html " + file}) {
      const Run refused = run(command);
      CHECK(refused.status == 1);
      CHECK_THAT(refused.err + refused.out, Contains("an amplitude sweep without its length gives its small-amplitude period"));
    }
    // With its length, a series: g from the corrected fit, and T0 beside it.
    scene["length"] = {{"value", c.length}, {"uncertainty", 0.001}, {"unit", "m"}};
    std::ofstream(file) << scene.dump();
    const json series = json::parse(succeeded("reduce " + file).out);
    std::remove(file.c_str());
    CHECK(series.at("kind") == "series");
    const json& g = series.at("g");
    CHECK(std::abs(g.at("value").get<double>() - 9.81) < 3.0 * g.at("uncertainty").get<double>());
    CHECK(series.at("fit").at("textbook").is_null());  // no line through one length
    CHECK(series.at("amplitude_sweep").at("small_amplitude_period").at("value").get<double>() ==
          Approx(t0.at("value").get<double>()).epsilon(1e-12));
  }
  // The page plots T against the amplitude with the law and the quadratic, and says the test's verdict.
  const std::string page = temporary_file() + ".html";
  succeeded("report -o " + page + " " + kData + "/amplitude_sweep_scene.json");
  const std::string html = pendulum::test::read_text(page);
  std::remove(page.c_str());
  // docs/series.md shows the plot alone as this command writes it.
  const std::string svg = temporary_file() + ".svg";
  succeeded("report " + kData + "/amplitude_sweep_scene.json --plot series -o " + svg);
  CHECK(pendulum::test::read_text(svg) == pendulum::test::read_text(kData + "/../docs/amplitude-sweep.svg"));
  std::remove(svg.c_str());
  CHECK_THAT(html, Contains("<h3>Amplitude sweep</h3>") && Contains("exact law T = T\u2080 2K/\u03C0") &&
                       Contains("at these amplitudes (1/16 at small ones): agrees"));
}

TEST_CASE("a spreadsheet's sheet is read as the table it holds: stamps beside their difference, a length written once",
          "[cli][tables][xlsx]") {
  // tests/tools/make_tables.py writes it: sheet 1, single periods (N(0, 0.06 s)) at six lengths in cm
  // between the stamps read off a trace; sheet 2, a sweep of 0.351 m on the exact law; sheet 3 empty.
  const std::string book = kTests + "/tables/lab_sheet.xlsx";
  const json lengths = json::parse(succeeded("import " + book).out);
  const json& columns = lengths.at("import").at("columns");
  CHECK(columns[0].at("role") == "unused");
  CHECK_THAT(columns[0].at("why").get<std::string>(), Contains("a time stamp: column 3 is column 2 minus column 1"));
  CHECK(columns[2].at("role") == "period");
  CHECK(columns[3].at("unit") == "cm");
  const std::string file = temporary_file();
  std::ofstream(file) << lengths.dump();
  const json g = json::parse(succeeded("reduce " + file).out).at("g");
  CHECK(std::abs(g.at("value").get<double>() - 9.81) < 3.0 * g.at("uncertainty").get<double>());
  // By name or number; the length in its first row is every row's, a sweep at one known length.
  for (const std::string sheet : {"Angles", "angles", "2"}) {
    const json sweep = json::parse(succeeded("import --sheet " + sheet + " " + book).out);
    CHECK(sweep.at("length").at("value") == 35.1);
    CHECK(sweep.at("observations").size() == 6);
  }
  std::ofstream(file) << succeeded("import --set 2 " + book).out;
  const json series = json::parse(succeeded("reduce " + file).out);
  std::remove(file.c_str());
  const json& t0 = series.at("amplitude_sweep").at("small_amplitude_period");
  CHECK(std::abs(t0.at("value").get<double>() - 2.0 * M_PI * std::sqrt(0.351 / 9.81)) <
        3.0 * t0.at("uncertainty").get<double>());
  // A sheet not there or empty: refused, naming the sheets.
  for (const std::string sheet : {"Notes", "4", "Foo"}) {
    const Run r = run("import --sheet " + sheet + " " + book);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Contains("\"Lengths\", \"Angles\", \"Notes\""));
  }
}

TEST_CASE("a sweep's table is told from a pivot scan, a recording that starts late, and a length table's slip",
          "[cli][tables][sweep]") {
  const std::string dir = temporary_directory();
  auto import = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + "/" + name) << text;
    return run("import " + dir + "/" + name);
  };
  // A metre stick (k^2 = 1/12 m^2) at 15 to 50 cm, exact periods 2 pi sqrt((k^2 + h^2)/(g h)), no
  // header: flat within 25 % like a sweep's, but U-shaped, so a pivot scan.
  std::string scan;
  for (int h = 15; h <= 50; h += 5) {
    const double m = h / 100.0;
    scan += std::to_string(h) + "\t" + std::to_string(2.0 * M_PI * std::sqrt((1.0 / 12.0 + m * m) / (9.81 * m))) + "\n";
  }
  const Run pivots = import("scan.txt", scan);
  REQUIRE(pivots.status == 0);
  CHECK(json::parse(pivots.out).at("import").at("columns")[0].at("role") == "pivot distance");
  // "amplitude (deg)" names a sweep as "theta (deg)" does.
  const Run named = import("amp.csv", "amplitude (deg),T (s)\n10,1.797\n20,1.808\n30,1.825\n40,1.852\n");
  REQUIRE(named.status == 0);
  CHECK(json::parse(named.out).at("length") == "not measured");
  // An angle track whose clock starts at 40 s: its times are within 25 % of each other but step as
  // a clock's, so it is a recording, not a sweep with periods of 40 s.
  std::string track = "t (s),theta (deg)\n";
  for (int k = 0; k < 40; ++k) track += std::to_string(40.0 + 0.1 * k) + "," + std::to_string(15.0 * std::cos(2.0 * M_PI * 0.1 * k / 1.8)) + "\n";
  const Run late = import("late.csv", track);
  CHECK_THAT(late.out, !Contains("amplitude sweep"));
  CHECK_THAT(late.out + late.err, !Contains("not measured"));
  // A negative amplitude beside lengths that change is a slip, refused; a sweep's are releases either side.
  const Run slip = import("slip.csv", "L (m),T (s),theta (deg)\n0.4,1.27,5\n0.6,1.55,-5\n0.8,1.80,5\n");
  CHECK(slip.status == 1);
  CHECK_THAT(slip.err, Contains("got -5 in column \"theta (deg)\" (amplitude); expected a non-negative number"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("a spreadsheet's cells as other programs write them, and stamps told from their period by name",
          "[cli][tables][xlsx]") {
  // tests/tables/quirks_sheet.xlsx (make_tables.py): "Length " and "(cm)" in two runs beside a phonetic
  // run "XX", "t10&#10;(&#x73;)" (a line break and a character reference), cells without their
  // reference, an inline string "note" over no numbers.
  const json scene = json::parse(succeeded("import " + kTests + "/tables/quirks_sheet.xlsx").out);
  const json& columns = scene.at("import").at("columns");
  CHECK(columns[0].at("name") == "Length (cm)");
  CHECK(columns[1].at("name") == "t10 (s)");
  CHECK(columns[1].at("role") == "time of 10 oscillations");
  CHECK(scene.at("observations").size() == 3);
  const std::string dir = temporary_directory();
  auto import = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + "/" + name) << text;
    return run("import " + dir + "/" + name);
  };
  // A first stamp smaller than the period, or negative: the unnumbered "time" is the period.
  for (const std::string& first : {std::string("0.41"), std::string("-0.41")}) {
    const double a = std::stod(first);
    std::string text = "length (cm),time1 (s),time2 (s),time (s)\n";
    for (const auto& [l, t] : std::vector<std::pair<int, double>>{{40, 1.269}, {60, 1.554}, {80, 1.794}}) {
      text += std::to_string(l) + "," + first + "," + std::to_string(a + t) + "," + std::to_string(t) + "\n";
    }
    const Run r = import("stamps.csv", text);
    REQUIRE(r.status == 0);
    const json parsed = json::parse(r.out);
    const json& c = parsed.at("import").at("columns");
    CHECK(c[3].at("role") == "period");
    CHECK(c[1].at("role") == "unused");
    // Declared, the columns are as the option says: its first period column, the stamp of 0.41 s,
    // is the period (and makes no pendulum beside these lengths), not the difference.
    const Run declared = run("import --columns \"l:cm,T:s,T:s,T:s\" " + dir + "/stamps.csv");
    if (a > 0.0) {
      CHECK(declared.status == 1);
      CHECK_THAT(declared.err, Contains("the lengths in cm and the periods in s give 4 pi^2 L/T^2 = 141 m/s^2"));
    }
  }
  // A length left empty beside no amplitudes is a cell left empty, not the first row's length.
  const Run empty = import("empty.csv", "L (cm),t10 (s)\n50.0,14.19\n,17.95\n");
  CHECK(empty.status == 1);
  CHECK_THAT(empty.err, Contains("an empty cell in column \"L (cm)\""));
  std::filesystem::remove_all(dir);
}

namespace {

// Coramik & Inanc 2023 (Phys. Educ. 58 055014): a Lego beam at five total
// lengths, 48.00 to 67.20 cm in steps of 6 studs (4.80 cm), pivoted at its
// end, Tracker's periods 1.139 to 1.349 s.
const std::string kLegoRows = "48.00,1.139\n52.80,1.199\n57.60,1.249\n62.40,1.300\n67.20,1.349\n";

/// `table` imported (with `options`) and the scene given to `command`
/// (reduce, report), as a user runs them.
Run imported_and_reduced(const std::string& table, const std::string& options, const std::string& command = "reduce") {
  const std::string file = temporary_file() + ".csv", scene = temporary_file();
  std::ofstream(file) << table;
  std::ofstream(scene) << succeeded("import " + file + options).out;
  const Run reduced = succeeded(command + " " + scene);
  std::remove(scene.c_str());
  std::remove(file.c_str());
  return reduced;
}

}  // namespace

TEST_CASE("Lego beams pivoted at an end, typed as a table of lengths, are named as such", "[cli][tables]") {
  // As a simple pendulum's lengths the beams give g x 1.5 (a rod swings as
  // one of 2L/3): the reason names it.
  const Run reduced = imported_and_reduced("L (cm),T (s)\n" + kLegoRows, "");
  const json result = json::parse(reduced.out);
  CHECK(g_of(reduced) / 9.80665 == Approx(1.5).epsilon(0.02));
  CHECK(result.at("status") == "suspect");
  CHECK_THAT(result.at("status_reasons").dump(), Contains("a uniform rod or beam pivoted at its end"));
  CHECK_THAT(result.at("status_reasons").dump(), Contains("rod_length"));
}

TEST_CASE("Lego beams typed as rods pivoted at an end give g within 1% of 9.80 (issue 39)", "[cli][tables]") {
  // The rows above under a rod's header, and headerless with the column
  // declared: each beam swings as a simple pendulum of 2L/3 (Kelley Eq. 45).
  for (const auto& [header, columns] : {std::pair<std::string, std::string>{"rod length (cm),T (s)\n", ""},
                                        {"beam length (cm),T (s)\n", ""},
                                        {"", " --columns \"r,T\""}}) {
    INFO(header << columns);
    const Run reduced = imported_and_reduced(header + kLegoRows, columns);
    const json result = json::parse(reduced.out);
    CHECK(result.at("fit").at("model") == "physical_pendulum");
    CHECK(std::abs(g_of(reduced) / 9.80 - 1.0) < 0.01);
    CHECK(result.at("status") == "ok");
    const json& scan = result.at("fit").at("pivot_scan");
    CHECK(scan.at("minimum").is_null());
    CHECK(scan.at("textbook").at("radius_of_gyration_m").is_null());
    CHECK_THAT(result.at("fit").at("observations")[0].at("conjugate_pivot").at("equivalent_length").at("value")
                   .get<double>(),
               WithinRel(2 * 0.48 / 3, 1e-12));
  }
  // The page gives the rods' textbook g as the JSON does, and plots T^2
  // against each rod's 2L/3.
  const json result = json::parse(imported_and_reduced("rod length (cm),T (s)\n" + kLegoRows, "").out);
  const double textbook = result.at("fit").at("pivot_scan").at("textbook").at("g").at("value");
  const std::string page = imported_and_reduced("rod length (cm),T (s)\n" + kLegoRows, "", "report").out;
  CHECK_THAT(page, Contains("g of the textbook line (no corrections)") && !Contains("undefined: the lengths"));
  char shown[16];
  std::snprintf(shown, sizeof shown, "%.3f", textbook);
  CHECK_THAT(page, Contains(shown));
  CHECK_THAT(page, Contains("equivalent length 2L/3 of each rod (m)"));
}
