// The pendulum-g command's reduce: Table II of Nelson & Olsson (1986) from
// the bundled data, the table format, the catalogue of bad scenes
// (tests/bad_scenes.json), each of which must fail with its message, a
// non-zero exit and nothing on stdout, the catalogue of valid scenes
// (tests/valid_scenes.json), extreme or suspicious, each of which must work
// and warn as listed, and the students' slips. The other commands: one file
// each (test_cli_*.cpp).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>
#include <string>

#include "catalogue.hpp"
#include "cli_run.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

namespace {

// Every number of a result is finite and no uncertainty is -0. The JSON
// library writes NaN and inf as null, so a null may stand only where
// docs/output.md says a value may be absent: a skipped correction's values,
// a correction's error bound, a parameter a fit held fixed, the wire parts of
// the drag theory, and a z-score without uncertainties.
void check_numbers(const json& result) {
  const json flat = result.flatten();
  for (const auto& [pointer, value] : flat.items()) {
    INFO(pointer);
    const json& original = result.at(json::json_pointer(pointer));  // flatten() nulls {} and []
    if (original.is_null()) {
      const std::string parent = pointer.substr(0, pointer.rfind('/'));
      const std::string key = pointer.substr(pointer.rfind('/') + 1);
      if (key == "error_bound_delta_T_s" || pointer == "/comparison/z" || parent.rfind("/drag_theory", 0) == 0) {
        continue;
      }
      // Degrees of freedom: null is infinite (a Type B row; GUM G.4.2), and
      // there is no expanded uncertainty without an uncertainty (docs/output.md).
      if (key == "degrees_of_freedom" || key == "effective_degrees_of_freedom" ||
          (pointer == "/g/expanded" && result.at("g").at("uncertainty").is_null())) {
        continue;
      }
      // A physical pendulum's pivot scan: Bessel's g without Kater's pair, the
      // parts' k and centre without parts (docs/output.md).
      if (pointer == "/fit/pivot_scan/bessel_g_m_s2" || parent == "/fit/pivot_scan/from_parts") continue;
      // As many observations as unknowns: no chi2 to judge (docs/output.md).
      if ((pointer == "/fit/probability" || pointer == "/fit/reduced_chi2" || pointer == "/fit/birge_ratio") &&
          result.at("fit").at("dof") == 0) {
        continue;
      }
      // A decay record without sigmas, or without a degree of freedom: no chi2 to judge.
      if ((pointer == "/decay_fit/probability" || pointer == "/decay_fit/birge_ratio") &&
          (result.at("decay_fit").at("uncertainty_scaling") != "sigma" || result.at("decay_fit").at("dof") == 0)) {
        continue;
      }
      // The lengths' scatter and chi2 against the stated uncertainties: both
      // or neither, where tau was fitted (docs/series.md, "Lengths that scatter").
      if (pointer == "/fit/length_scatter_m" || pointer == "/fit/chi2_stated") {
        CHECK(result.at("fit").at("length_scatter_m").is_null());
        CHECK(result.at("fit").at("chi2_stated").is_null());
        continue;
      }
      // The textbook curve of a scan of pivot distances has no centre.
      if (pointer == "/fit/pivot_scan/textbook/center_of_mass_position_m") continue;
      // A singular fit: no uncertainty, no correlation, and with every length
      // equal no textbook line (docs/output.md).
      if (result.at("g").at("uncertainty").is_null() &&
          (key.find("uncertainty") != std::string::npos || pointer == "/fit/correlation/matrix" ||
           pointer == "/fit/textbook")) {
        continue;
      }
      // Through one length no textbook line; an amplitude sweep's chi2 has no
      // verdict where the periods' sigma is its scatter (docs/series.md).
      if (pointer == "/fit/textbook") {
        const json& obs = result.at("fit").at("observations");
        CHECK(std::all_of(obs.begin(), obs.end(), [&](const json& o) { return o.at("length") == obs[0].at("length"); }));
        continue;
      }
      if (pointer == "/amplitude_sweep/probability") {
        CHECK(result.at("amplitude_sweep").at("period_uncertainty") == "scatter_about_fit");
        continue;
      }
      // A recording that is not a zip export has no set (docs/recordings.md).
      if (parent.rfind("/recordings/", 0) == 0 && key == "set") continue;
      if (parent.rfind("/decay_fit/", 0) == 0 || parent.rfind("/fit/parameters/", 0) == 0) {
        CHECK(result.at(json::json_pointer(parent + "/fitted")) == false);
        continue;
      }
      // A series: a correction row in an observation's table.
      CHECK(parent.find("/corrections/") != std::string::npos);
      CHECK(result.value(json::json_pointer(parent + "/status"), "") == "skipped");
    } else if (value.is_number()) {
      CHECK(std::isfinite(value.get<double>()));
      if (pointer.size() >= 11 && pointer.substr(pointer.size() - 11) == "uncertainty") {
        CHECK_FALSE(std::signbit(value.get<double>()));
      }
    }
  }
}

}  // namespace

TEST_CASE("Table II of Nelson & Olsson (1986) from the CLI", "[cli][table2]") {
  const Run r = run("reduce " + kNelsonOlsson);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const json result = json::parse(r.out);

  // Table II as printed: Delta T (us) and Delta g, whose printed unit
  // 10^-3 m/s^2 is a slip for 10^-5 m/s^2 (docs/deviations.md).
  struct Row {
    const char* id;
    double delta_t_us;
    double delta_g_1e5;
  };
  const Row table2[] = {
      {"finite_amplitude", 596, 336},  {"bob_radius", 72, 41},
      {"ring", -282, -159},            {"cap", -116, -65},
      {"cap_screw", 95, 54},           {"wire_mass", -463, -261},
      {"wire_flexibility", 0.10, 0.06}, {"bob_rotation", 0.29, 0.16},
      {"double_pendulum", 4.6, 2.6},   {"buoyancy", 292, 165},
      {"linear_damping", 0.033, 0.019}, {"quadratic_damping", 0.027, 0.015},
      {"amplitude_decay", -77, -43},   {"added_mass", 346, 195},
      {"wire_stretch", 3.4, 1.9},      {"support_motion", 1, 0.6},
  };
  REQUIRE(result.at("corrections").size() == 16);
  for (const Row& row : table2) {
    const json& c = correction(result, row.id);
    INFO(row.id);
    REQUIRE(c.at("status") != "skipped");
    // Issue 2's rule: >= 10 us within 1 us, < 1 us within 0.01 us, else
    // 0.1 us; the support's "+1" is rounded to the unit, so 0.5 us there.
    // Delta g follows the same rule in units of 1e-5 m/s^2.
    const bool support = std::string(row.id) == "support_motion";
    const double dt = c.at("delta_T_s").get<double>() * 1e6;
    const double dg = c.at("delta_g_m_s2").get<double>() * 1e5;
    const double tol_t = support ? 0.5 : (std::abs(row.delta_t_us) >= 10 ? 1.0 : std::abs(row.delta_t_us) < 1 ? 0.01 : 0.1);
    const double tol_g = support ? 0.5 : (std::abs(row.delta_g_1e5) >= 10 ? 1.0 : std::abs(row.delta_g_1e5) < 1 ? 0.01 : 0.1);
    CHECK_THAT(dt, WithinAbs(row.delta_t_us, tol_t));
    CHECK_THAT(dg, WithinAbs(row.delta_g_1e5, tol_g));
    CHECK(c.at("equation").get<std::string>().find("Nelson & Olsson (1986)") == 0);
    CHECK_FALSE(c.at("method").get<std::string>().empty());
  }
  CHECK_THAT(result.at("total_delta_T_s").get<double>() * 1e6, WithinAbs(472.0, 2.0));
  // Eq. (91): g = 9.8034 +- 0.0014 m/s^2, from the trials' spread and +-0.3 mm.
  CHECK_THAT(result.at("g").at("value").get<double>(), WithinAbs(9.8034, 0.00005));
  CHECK_THAT(result.at("g").at("uncertainty_period_and_length").get<double>(), WithinAbs(0.0014, 0.00005));
  // The full uncertainty adds the other inputs' (tests/test_reduction.cpp checks
  // it against finite differences and Monte Carlo): here, its budget's sum.
  double quadrature = 0.0;
  for (const auto& b : result.at("g").at("budget")) quadrature += std::pow(b.at("contribution_m_s2").get<double>(), 2);
  CHECK_THAT(result.at("g").at("uncertainty").get<double>(), WithinAbs(std::sqrt(quadrature), 1e-15));
  CHECK(result.at("g").at("uncertainty").get<double>() > 0.0014);
  CHECK(result.at("g").at("unit") == "m/s^2");
  // Eq. (4) and Eq. (90).
  CHECK_THAT(result.at("period").at("measured").at("value").get<double>(), WithinAbs(3.47880, 0.000005));
  CHECK_THAT(result.at("period").at("ideal").at("value").get<double>(), WithinAbs(3.47833, 0.000005));
  CHECK(result.at("schema") == "pendulum-g/result/1");
}

TEST_CASE("The table format prints every row and g", "[cli]") {
  const Run r = run("reduce --format table " + kNelsonOlsson);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Contains("Decay of finite amplitude"));
  // g rounded to its uncertainty's two significant digits (0.00148 m/s^2).
  CHECK_THAT(r.out, Contains("g                   = 9.8034 +- 0.0015 m/s^2 (period and length alone: +- 0.0014)"));
  CHECK_THAT(r.out, Contains("dg (mGal)"));
  CHECK_THAT(r.out, Contains("status              = ok"));
  CHECK_THAT(r.out, Contains("Inputs without an uncertainty (they add nothing to the budget): ring.mass"));
  // The warnings and the status are in the table, not repeated on stderr.
  CHECK(r.err.empty());
  // Without any uncertainty there is no z, but the difference is printed.
  const std::string file = temporary_file();
  std::ofstream(file) << R"({"length": {"value": 1, "unit": "m"}, "amplitude": {"value": 5, "unit": "deg"},
    "timing": {"oscillations_per_trial": 10, "unit": "s", "trials": [20.08, 20.08]},
    "site": {"reference_g": {"value": 9.81, "unit": "m/s^2"}}})";
  const Run exact = run("reduce --format table " + file);
  std::remove(file.c_str());
  CHECK_THAT(exact.out, Contains("difference          = -0.0"));
  CHECK_THAT(exact.out, Contains("(no z: neither g nor the expected g has an uncertainty)"));
}

TEST_CASE("The scene may come on standard input", "[cli]") {
  const Run r = run("reduce - < " + kNelsonOlsson);
  REQUIRE(r.status == 0);
  CHECK(json::parse(r.out).at("input") == "-");
}

TEST_CASE("A file name that is not UTF-8 is echoed, not an internal error", "[cli]") {
  // Found by hand: the JSON writer threw on the name's byte 0xff (exit 3);
  // then printed it as U+FFFD, which made two such names one (issue 22).
  const std::string base = temporary_file();
  const std::string file = base + "-\xff.json";
  std::ofstream(file, std::ios::binary) << pendulum::test::read_text(kNelsonOlsson);
  const Run r = run("reduce '" + file + "'");
  std::remove(file.c_str());
  std::remove(base.c_str());
  REQUIRE(r.status == 0);
  CHECK_THAT(json::parse(r.out).at("input").get<std::string>(), Contains("-\\xff.json"));
}

TEST_CASE("Catalogue of bad scenes", "[cli][errors]") {
  const json catalogue = json::parse(pendulum::test::read_text(std::string(PENDULUM_TESTS_DIR) + "/bad_scenes.json"));
  const json base = json::parse(pendulum::test::read_text(kNelsonOlsson));
  const std::string file = temporary_file();
  for (const json& entry : catalogue.at("cases")) {
    const std::string name = entry.at("name");
    std::ofstream(file, std::ios::binary) << pendulum::test::catalogue_text(entry, base);
    // The cases name recordings by absolute paths: the catalogue tests the
    // reader, tests/cli_safety.sh the confinement to the scene's folder.
    const Run r = run("reduce --allow-outside " + file);
    INFO(name << "\nstderr: " << r.err);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Contains(entry.at("error").get<std::string>()));
    // One line (docs/output.md), so no raw newline from the input, and no
    // sanitizer report after it.
    CHECK(r.err.rfind("pendulum-g: error: ", 0) == 0);
    CHECK(r.err.find('\n') == r.err.size() - 1);
    CHECK_FALSE(pendulum::test::says_nan(r.err));
    // report fails with the same message and writes nothing (docs/report.md).
    const Run report = run("report --allow-outside " + file + " -o " + file + ".html");
    CHECK(report.status == 1);
    CHECK(report.err == r.err);
    CHECK_FALSE(std::filesystem::exists(file + ".html"));
  }
  std::remove(file.c_str());
}

TEST_CASE("Catalogue of valid scenes, extreme or suspicious", "[cli]") {
  const json catalogue =
      json::parse(pendulum::test::read_text(std::string(PENDULUM_TESTS_DIR) + "/valid_scenes.json"));
  const json base = json::parse(pendulum::test::read_text(kNelsonOlsson));
  const std::string file = temporary_file();
  for (const json& entry : catalogue.at("cases")) {
    std::ofstream(file, std::ios::binary) << pendulum::test::catalogue_text(entry, base);
    const Run r = run("reduce --allow-outside " + file);
    INFO(entry.at("name").get<std::string>() << "\nstderr: " << r.err);
    REQUIRE(r.status == 0);
    const json result = json::parse(r.out);
    check_numbers(result);
    CHECK(result.at("g").at("value").get<double>() > 0.0);
    if (entry.contains("g")) {
      CHECK_THAT(result.at("g").at("value").get<double>(),
                 WithinAbs(entry.at("g").at("value"), entry.at("g").at("tolerance")));
    }
    // Each expected warning, in order, in the JSON and on stderr; no other.
    const json expected = entry.value("warnings", json::array());
    const json& warnings = result.at("warnings");
    REQUIRE(warnings.size() == expected.size());
    std::string err;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      CHECK(warnings[i].get<std::string>().rfind(expected[i].get<std::string>(), 0) == 0);
      err += "pendulum-g: warning: " + warnings[i].get<std::string>() + "\n";
    }
    // The status, "ok" unless the case says otherwise; a suspect one's
    // reasons follow the warnings on stderr.
    CHECK(result.at("status") == entry.value("status", "ok"));
    for (const auto& reason : result.at("status_reasons")) {
      err += "pendulum-g: suspect: " + reason.get<std::string>() + "\n";
    }
    CHECK(r.err == err);
    const Run table = run("reduce --allow-outside --format table " + file);
    CHECK(table.status == 0);
    for (const char* bad : {"nan", "inf", "NaN", "INF"}) CHECK_THAT(table.out, !Contains(bad));
  }
  std::remove(file.c_str());
}

TEST_CASE("Usage errors exit with status 2, a missing file with 1", "[cli][errors]") {
  CHECK(run("").status == 2);
  CHECK(run("reduce").status == 2);
  CHECK(run("reduce --format yaml " + kNelsonOlsson).status == 2);
  CHECK(run("reduce --amplitude-method magic " + kNelsonOlsson).status == 2);
  const Run missing = run("reduce /nonexistent/scene.json");
  CHECK(missing.status == 1);
  CHECK(missing.out.empty());
  CHECK_THAT(missing.err, Contains("cannot open the file"));
  CHECK(run("--help").status == 0);
  // Two scenes for reduce: batch is the command for several (issue 14).
  const Run two = run("reduce " + kNelsonOlsson + " " + kNelsonOlsson);
  CHECK(two.status == 2);
  CHECK(two.out.empty());
  CHECK_THAT(two.err, Contains("pendulum-g: reduce takes one scene; for several, run: pendulum-g batch " + kNelsonOlsson +
                               " " + kNelsonOlsson));
}

TEST_CASE("reduce names the amplitude method and its error bound", "[cli][amplitude]") {
  // auto: theta0^2/16 is within 1% of the period's 169 us uncertainty at 3 deg,
  // its bound (9/64) m^2 T0 = 0.23 us with m = sin^2 1.5 deg.
  const json automatic = json::parse(run("reduce " + kNelsonOlsson).out);
  const json& a = correction(automatic, "finite_amplitude");
  CHECK(a.at("method") == "small_angle");
  CHECK_THAT(a.at("error_bound_delta_T_s").get<double>() * 1e6, WithinAbs(0.2297, 0.0001));
  CHECK(correction(automatic, "bob_radius").at("error_bound_delta_T_s").is_null());
  const json exact = json::parse(run("reduce --amplitude-method agm " + kNelsonOlsson).out);
  const json& e = correction(exact, "finite_amplitude");
  CHECK(e.at("method") == "agm");
  // 596.0954 us (Table II: +596) and 1e-15 of it.
  CHECK_THAT(e.at("delta_T_s").get<double>() * 1e6, WithinAbs(596.0954, 0.0001));
  CHECK(e.at("error_bound_delta_T_s").get<double>() < 1e-18);
  const json series = json::parse(run("reduce --amplitude-method series --series-terms 3 " + kNelsonOlsson).out);
  CHECK(correction(series, "finite_amplitude").at("series_terms") == 3);
}

TEST_CASE("Catalogue of student slips: each gets its status and message", "[cli][status]") {
  const json catalogue =
      json::parse(pendulum::test::read_text(std::string(PENDULUM_TESTS_DIR) + "/student_slips.json"));
  const json& base = catalogue.at("base");
  char dir_template[] = "/tmp/pendulum-g-slips-XXXXXX";
  REQUIRE(mkdtemp(dir_template));
  const std::string dir = dir_template;
  std::vector<std::string> files;
  for (const json& entry : catalogue.at("cases")) {
    const std::string name = entry.at("name");
    const std::string status = entry.at("status");
    const std::string message = entry.value("message", "");
    char file_name[32];
    std::snprintf(file_name, sizeof file_name, "/case%03zu.json", files.size());
    files.push_back(dir + file_name);
    std::ofstream(files.back(), std::ios::binary) << pendulum::test::catalogue_text(entry, base);
    const Run r = run("reduce --strict " + files.back());
    INFO(name << "\nstdout: " << r.out.substr(0, 400) << "\nstderr: " << r.err);
    if (status == "failed") {
      CHECK(r.status == 1);
      CHECK(r.out.empty());
      CHECK_THAT(r.err, Contains(message));
      continue;
    }
    REQUIRE(r.status == (status == "ok" ? 0 : 4));
    const json result = json::parse(r.out);
    CHECK(result.at("status") == status);
    const json& reasons = result.at("status_reasons");
    CHECK(reasons.empty() == (status == "ok"));
    const json& warnings = result.at("warnings");
    if (status == "suspect") {
      bool found = false;
      for (const auto& reason : reasons) {
        found = found || reason.get<std::string>().find(message) != std::string::npos;
        CHECK_THAT(r.err, Contains("pendulum-g: suspect: " + reason.get<std::string>()));
      }
      CHECK(found);
    } else if (message.empty()) {
      CHECK(warnings.empty());
    } else {
      REQUIRE(warnings.size() == 1);
      CHECK_THAT(warnings[0].get<std::string>(), Contains(message));
    }
  }
  // batch gives each scene the same status, and counts them on its last line.
  std::string args;
  for (const auto& f : files) args += " " + f;
  const Run batch = run("batch --jobs 2" + args);
  std::istringstream lines(batch.out);
  std::vector<json> rows;
  for (std::string line; std::getline(lines, line);) rows.push_back(json::parse(line));
  REQUIRE(rows.size() == files.size() + 1);
  int counts[3] = {0, 0, 0};
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string status = catalogue.at("cases")[i].at("status");
    INFO(catalogue.at("cases")[i].at("name").get<std::string>());
    CHECK(rows[i].at("status") == status);
    ++counts[status == "ok" ? 0 : status == "suspect" ? 1 : 2];
  }
  const json& last = rows.back();
  CHECK(last.at("class") == true);
  CHECK(last.at("counts").at("ok") == counts[0]);
  CHECK(last.at("counts").at("suspect") == counts[1]);
  CHECK(last.at("counts").at("failed") == counts[2]);
  std::filesystem::remove_all(dir);
}

TEST_CASE("table: a correlated pair of budget inputs is shown together", "[cli][table][budget]") {
  // The phyphox scene's record cannot tell alpha from beta (correlation
  // -0.99998): each alone is listed at 0.034 m/s^2 while g's uncertainty is
  // 0.006. The pair's line must close the budget: the other rows and the
  // pair together add in quadrature to g's uncertainty (to the 1e-6 m/s^2
  // the table prints).
  const std::string scene = std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_pendulum_raw_from_file.json";
  const Run table = run("reduce --format table " + scene);
  const json result = json::parse(run("reduce " + scene).out);
  REQUIRE(table.status == 0);
  const std::smatch m = [&] {
    std::smatch found;
    std::regex_search(table.out, found, std::regex("decay\\.alpha and decay\\.beta are correlated \\((-?[0-9.]+)\\): "
                                                   "together ([0-9.]+) m/s\\^2"));
    return found;
  }();
  REQUIRE(m.size() == 3);
  CHECK_THAT(std::stod(m[1]), WithinAbs(result["g"]["budget_correlation"]["correlation"].get<double>(), 1e-6));
  double variance = std::pow(std::stod(m[2]), 2);
  for (const auto& row : result["g"]["budget"]) {
    if (row["input"] != "decay.alpha" && row["input"] != "decay.beta") variance += std::pow(row["contribution_m_s2"].get<double>(), 2);
  }
  CHECK_THAT(std::sqrt(variance), WithinAbs(result["g"]["uncertainty"].get<double>(), 2e-6));
}

TEST_CASE("The expanded uncertainty, in JSON and the table, as GUM 6 writes it", "[cli][budget][uncertainty]") {
  const json g = json::parse(run("reduce " + kNelsonOlsson).out).at("g");
  const json& e = g.at("expanded");
  // U = k u(g); Nelson & Olsson's ten trials give the period 9 degrees of
  // freedom, the length and amplitude's stated uncertainties infinite ones.
  CHECK_THAT(e.at("uncertainty").get<double>(),
             WithinAbs(e.at("coverage_factor").get<double>() * g.at("uncertainty").get<double>(), 1e-15));
  CHECK(e.at("coverage_probability") == 0.95);
  CHECK(e.at("effective_degrees_of_freedom").get<double>() > 9.0);
  CHECK(g.at("effective_degrees_of_freedom") == e.at("effective_degrees_of_freedom"));
  for (const auto& row : g.at("budget")) {
    if (row.at("input") == "timing.period") {
      CHECK(row.at("type") == "A");
      CHECK(row.at("distribution") == "student_t");
      CHECK(row.at("degrees_of_freedom") == 9);
    } else {
      CHECK(row.at("type") == "B");
      CHECK(row.at("degrees_of_freedom").is_null());  // infinite
    }
  }
  const std::regex line("g = 9\\.8034 \u00B1 0\\.0030 m/s\u00B2 \\(k = 2\\.0[0-9], 95 %, \u03BD_eff = [0-9]+\\)");
  CHECK(std::regex_match(e.at("result").get<std::string>(), line));
  const Run table = run("reduce --format table " + kNelsonOlsson);
  CHECK(std::regex_search(table.out, std::regex("g, expanded         = 9\\.8034 \\+- 0\\.0030 m/s\\^2 \\(k = 2\\.0[0-9], "
                                                "95 %, nu_eff = [0-9]+\\)")));
  CHECK_THAT(table.out, Contains("  timing.period                    0.000951 m/s^2  41.1 %  A   student_t    nu = 9"));
  CHECK_THAT(table.out, Contains("  length                           0.000979 m/s^2  43.6 %  B   normal       nu = \u221E"));
}

TEST_CASE("table: a series' rows of one field are one line, repeated messages once", "[cli][table][budget]") {
  // 20 lengths, each timed three times and its amplitude not recorded: the
  // JSON lists 60 rows and 20 assumptions; the table one line per field and
  // one assumption, with the count and the first paths.
  json scene = {{"schema", "pendulum-g/scene/1"}, {"observations", json::array()}};
  for (int k = 0; k < 20; ++k) {
    const double length = 0.3 + 0.05 * k, t = 20.0 * M_PI * std::sqrt(length / 9.81);
    scene["observations"].push_back({{"length", {{"value", length}, {"uncertainty", 0.001}, {"unit", "m"}}},
                                     {"amplitude", "not recorded"},
                                     {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"},
                                                 {"trials", {t - 0.1, t + 0.05 * (k % 3), t + 0.1}}}}});
  }
  const std::string file = temporary_file();
  std::ofstream(file) << scene.dump();
  const json result = json::parse(run("reduce " + file).out);
  const Run table = run("reduce --format table " + file);
  std::remove(file.c_str());
  CHECK(result["g"]["budget"].size() == 60);
  CHECK(result["assumptions"].size() == 21);  // and the trials' scatter pooled, once
  double periods = 0.0;
  for (const auto& row : result["g"]["budget"]) {
    if (std::regex_match(row["input"].get<std::string>(), std::regex("observations\\[[0-9]+\\]\\.timing\\.period"))) {
      periods += std::pow(row["contribution_m_s2"].get<double>(), 2);
    }
  }
  std::smatch m;
  REQUIRE(std::regex_search(table.out, m, std::regex("\n  20 observations' timing\\.period +([0-9.]+) m/s\\^2 .* A   student_t +nu = 40\n")));
  CHECK_THAT(std::stod(m[1]), WithinAbs(std::sqrt(periods), 1e-6));
  CHECK(table.out.find("observations[1].timing.period") == std::string::npos);
  const std::string once = "(and 19 more alike: observations[1], observations[2], observations[3], ...)\n";
  CHECK_THAT(table.out, Contains("assumption: observations[0].amplitude: not recorded; a hand release" ));
  CHECK_THAT(table.out, Contains(once));
  CHECK(table.out.find("assumption: observations[1]") == std::string::npos);
}
