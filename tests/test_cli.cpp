// The pendulum-g command: Table II of Nelson & Olsson (1986) from the bundled
// data, the catalogue of bad scenes (tests/bad_scenes.json), each of which
// must fail with its message, a non-zero exit and nothing on stdout, and the
// catalogue of valid scenes (tests/valid_scenes.json), extreme or suspicious,
// each of which must work and warn as listed.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "catalogue.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

namespace {

struct Run {
  int status;
  std::string out;
  std::string err;
};

// A new empty file in the temporary directory.
std::string temporary_file() {
  char name[] = "/tmp/pendulum-g-test-XXXXXX";
  const int fd = mkstemp(name);
  REQUIRE(fd >= 0);
  close(fd);
  return name;
}

// Runs pendulum-g with `args` (shell words) and captures everything.
Run run(const std::string& args) {
  const std::string err_file = temporary_file();
  const std::string command = std::string(PENDULUM_G_EXE) + " " + args + " 2>" + err_file;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  std::string out;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  const int raw = pclose(pipe);
  Run r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out, pendulum::test::read_text(err_file)};
  std::remove(err_file.c_str());
  return r;
}

const std::string kNelsonOlsson = std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986.json";

const json& correction(const json& result, const std::string& id) {
  for (const auto& c : result.at("corrections")) {
    if (c.at("id") == id) return c;
  }
  FAIL("no correction " << id);
  throw;
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
  CHECK_THAT(result.at("g").at("uncertainty").get<double>(), WithinAbs(0.0014, 0.00005));
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
  CHECK_THAT(r.out, Contains("g                   = 9.8034"));
}

TEST_CASE("The scene may come on standard input", "[cli]") {
  const Run r = run("reduce - < " + kNelsonOlsson);
  REQUIRE(r.status == 0);
  CHECK(json::parse(r.out).at("input") == "-");
}

TEST_CASE("A file name that is not UTF-8 is echoed, not an internal error", "[cli]") {
  // Found by hand: the JSON writer threw on the name's byte 0xff (exit 3).
  const std::string base = temporary_file();
  const std::string file = base + "-\xff.json";
  std::ofstream(file, std::ios::binary) << pendulum::test::read_text(kNelsonOlsson);
  const Run r = run("reduce '" + file + "'");
  std::remove(file.c_str());
  std::remove(base.c_str());
  REQUIRE(r.status == 0);
  CHECK_THAT(json::parse(r.out).at("input").get<std::string>(), Contains("-\xef\xbf\xbd.json"));
}

TEST_CASE("Catalogue of bad scenes", "[cli][errors]") {
  const json catalogue = json::parse(pendulum::test::read_text(std::string(PENDULUM_TESTS_DIR) + "/bad_scenes.json"));
  const json base = json::parse(pendulum::test::read_text(kNelsonOlsson));
  const std::string file = temporary_file();
  for (const json& entry : catalogue.at("cases")) {
    const std::string name = entry.at("name");
    std::ofstream(file, std::ios::binary) << pendulum::test::catalogue_text(entry, base);
    const Run r = run("reduce " + file);
    INFO(name << "\nstderr: " << r.err);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Contains(entry.at("error").get<std::string>()));
    // One line (docs/output.md), so no raw newline from the input, and no
    // sanitizer report after it.
    CHECK(r.err.rfind("pendulum-g: error: ", 0) == 0);
    CHECK(r.err.find('\n') == r.err.size() - 1);
  }
  std::remove(file.c_str());
}

namespace {

// Every number of a result is finite and no uncertainty is -0. The JSON
// library writes NaN and inf as null, so a null may stand only where a
// skipped correction has no value.
void check_numbers(const json& result) {
  const json flat = result.flatten();
  for (const auto& [pointer, value] : flat.items()) {
    INFO(pointer);
    const json& original = result.at(json::json_pointer(pointer));  // flatten() nulls {} and []
    if (original.is_null()) {
      const std::string parent = pointer.substr(0, pointer.rfind('/'));
      CHECK(parent.rfind("/corrections/", 0) == 0);
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

TEST_CASE("Catalogue of valid scenes, extreme or suspicious", "[cli]") {
  const json catalogue =
      json::parse(pendulum::test::read_text(std::string(PENDULUM_TESTS_DIR) + "/valid_scenes.json"));
  const json base = json::parse(pendulum::test::read_text(kNelsonOlsson));
  const std::string file = temporary_file();
  for (const json& entry : catalogue.at("cases")) {
    std::ofstream(file, std::ios::binary) << pendulum::test::catalogue_text(entry, base);
    const Run r = run("reduce " + file);
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
    CHECK(r.err == err);
    const Run table = run("reduce --format table " + file);
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
}
