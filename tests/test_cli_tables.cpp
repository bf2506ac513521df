// pendulum-g import TABLE and the scenes that name a table (docs/series.md,
// "Tables"; docs/physical.md, "A pivot scan typed as a table").
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"

using Catch::Matchers::Contains;
using nlohmann::json;

namespace {
const std::string kData = PENDULUM_DATA_DIR;
const std::string kTests = PENDULUM_TESTS_DIR;

double g_of(const Run& r) { return json::parse(r.out).at("g").at("value").get<double>(); }
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

TEST_CASE("import of a headerless pivot scan reads a table, not blocking times", "[cli][tables]") {
  const Run r = run("import " + kTests + "/tables/headerless_pivot_scan.txt");
  REQUIRE(r.status == 0);
  const json scene = json::parse(r.out);
  CHECK(scene.at("fit") == json{"radius_of_gyration"});
  CHECK(scene.at("observations").size() == 9);
  CHECK(scene.at("import").at("columns")[0].at("decided_by") == "content");
  CHECK_THAT(r.err, Contains("no unit; read as m"));
}

TEST_CASE("reduce TABLE says what to do instead of 'not valid JSON'", "[cli][tables]") {
  const Run r = run("reduce " + kData + "/pendulum_lengths_table.csv");
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Contains("a table of settings and periods, not a scene (JSON); expected a scene: make one with "
                             "pendulum-g import TABLE > scene.json"));
  CHECK_THAT(r.err, !Contains("not valid JSON"));
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
