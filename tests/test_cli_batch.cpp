// The pendulum-g command's batch: a class of scenes, folders with odd
// entries, the class of issue 14, and its HTML class report.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>
#include <string>

#include "cli_run.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

TEST_CASE("batch: a class of scenes, one bad file among them", "[cli][batch]") {
  char dir_template[] = "/tmp/pendulum-g-batch-XXXXXX";
  REQUIRE(mkdtemp(dir_template));
  const std::string dir = dir_template;
  const std::string good = pendulum::test::read_text(kNelsonOlsson);
  std::ofstream(dir + "/a_student.json") << good;
  std::ofstream(dir + "/b_student.json") << "{\"length\": ";
  json vacuum = json::parse(good);
  vacuum["air"] = "vacuum";
  vacuum.erase("site");
  std::ofstream(dir + "/c_student.json") << vacuum.dump();

  const Run r = run("batch --jobs 2 " + dir);
  CHECK(r.status == 1);  // one scene failed
  std::istringstream lines(r.out);
  std::vector<json> summary;
  for (std::string line; std::getline(lines, line);) summary.push_back(json::parse(line));
  REQUIRE(summary.size() == 4);  // and the class line
  CHECK(summary[0].at("input") == dir + "/a_student.json");
  CHECK(summary[0].at("ok") == true);
  CHECK_THAT(summary[0].at("g_m_s2").get<double>(), WithinAbs(9.8034, 0.00005));
  CHECK(summary[0].at("largest_budget_input") == "length");
  CHECK_THAT(summary[0].at("z").get<double>(), WithinAbs(0.54, 0.005));
  CHECK(summary[1].at("ok") == false);
  CHECK_THAT(summary[1].at("error").get<std::string>(), Contains("not valid JSON"));
  CHECK(summary[2].at("ok") == true);
  CHECK(summary[2].at("z").is_null());  // no site
  // In vacuum there is no buoyancy or added mass: g is lower by their 638 us.
  CHECK(summary[2].at("g_m_s2").get<double>() < summary[0].at("g_m_s2").get<double>());
  CHECK(summary[0].at("status") == "ok");
  CHECK(summary[0].at("warnings") == json::array());
  CHECK(summary[1].at("status") == "failed");
  CHECK(summary[3].at("class") == true);
  CHECK(summary[3].at("counts") == json({{"ok", 2}, {"suspect", 0}, {"failed", 1}}));
  CHECK(summary[3].at("g_of_ok").at("count") == 2);
  // The mean and the sample standard deviation of the two ok scenes' g.
  const double g0 = summary[0].at("g_m_s2"), g2 = summary[2].at("g_m_s2");
  CHECK_THAT(summary[3].at("g_of_ok").at("mean_m_s2").get<double>(), WithinAbs((g0 + g2) / 2.0, 1e-12));
  CHECK_THAT(summary[3].at("g_of_ok").at("standard_deviation_m_s2").get<double>(),
             WithinAbs(std::abs(g0 - g2) / std::sqrt(2.0), 1e-12));

  const Run csv = run("batch --format csv " + dir + "/a_student.json " + dir + "/b_student.json");
  CHECK(csv.status == 1);
  CHECK(csv.out.rfind("input,ok,g_m_s2,g_uncertainty_m_s2,", 0) == 0);
  CHECK(std::count(csv.out.begin(), csv.out.end(), '\n') == 4);  // header, 2 rows, class line
  CHECK_THAT(csv.out, Contains("\n# class: 1 ok, 0 suspect, 1 failed; g of the ok scenes: mean 9.80340 m/s^2 (1 scene)\n"));

  std::ofstream(dir + "/list.txt") << "# the good ones\n" << dir << "/a_student.json\n" << dir << "/c_student.json\n";
  const Run listed = run("batch --list " + dir + "/list.txt");
  CHECK(listed.status == 0);
  CHECK(std::count(listed.out.begin(), listed.out.end(), '\n') == 3);

  std::ofstream(dir + "/lines.jsonl") << json::parse(good).dump() << "\n\n" << vacuum.dump() << "\n";
  const Run piped = run("batch - < " + dir + "/lines.jsonl");
  CHECK(piped.status == 0);
  CHECK_THAT(piped.out, Contains("\"input\":\"stdin:3\""));

  // Pretty-printed files one after another (cat *.json): one scene each,
  // named by the line it starts on (issue 14: it was one error per line).
  std::ofstream(dir + "/pretty.txt") << json::parse(good).dump(2) << "\n" << vacuum.dump(2) << "\n";
  const Run cat = run("batch - < " + dir + "/pretty.txt");
  CHECK(cat.status == 0);
  CHECK(std::count(cat.out.begin(), cat.out.end(), '\n') == 3);
  CHECK_THAT(cat.out, Contains("\"input\":\"stdin:1\""));
  // A list's lines may carry spaces around the name.
  std::ofstream(dir + "/spaced.txt") << "  " << dir << "/a_student.json \t\n";
  CHECK(run("batch --list " + dir + "/spaced.txt").status == 0);

  CHECK(run("batch").status == 1);
  std::filesystem::remove_all(dir);
}

TEST_CASE("batch skips a named pipe in a folder instead of waiting on it", "[cli][batch]") {
  // Regression: a FIFO called x.json in a folder made batch wait forever.
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(temporary_file() + ".d");
  fs::create_directory(dir);
  fs::copy_file(kNelsonOlsson, dir / "a.json");
  REQUIRE(mkfifo((dir / "x.json").c_str(), 0600) == 0);
  const Run r = run("batch " + dir.string());
  fs::remove_all(dir);
  CHECK(r.status == 0);
  CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 2);  // a.json and the class line
  CHECK_THAT(r.err, Contains("skipped") && Contains("x.json") && Contains("not a regular file"));
}

TEST_CASE("batch on the class of issue 14: who is off, and why", "[cli][batch][status]") {
  // tests/tools/make_class.cpp writes thirty files, each a student's scene
  // with the slip its notes name (or none); davis.json.txt and drafts/ are to
  // be skipped with a note, CLARK.JSON read.
  char dir_template[] = "/tmp/pendulum-g-class-XXXXXX";
  REQUIRE(mkdtemp(dir_template));
  const std::string dir = dir_template;
  int status = 0;
  pendulum::test::command_output(std::string(PENDULUM_MAKE_CLASS) + " " + dir, status);
  REQUIRE(status == 0);
  const Run r = run("batch " + dir);
  CHECK(r.status == 1);  // some scenes failed
  CHECK_THAT(r.err, Contains("pendulum-g: note: skipped " + dir + "/davis.json.txt: not a .json file; rename it to davis.json"));
  CHECK_THAT(r.err, Contains("pendulum-g: note: skipped " + dir + "/drafts: a folder"));
  std::istringstream lines(r.out);
  std::map<std::string, json> rows;
  json last;
  for (std::string line; std::getline(lines, line);) {
    last = json::parse(line);
    if (last.contains("input")) rows[last.at("input").get<std::string>().substr(dir.size() + 1)] = last;
  }
  REQUIRE(rows.size() == 29);  // thirty files, davis.json.txt skipped
  // Each student's slip, the status it must get and the words that name it.
  // A period exactly 10 times off (baker, martin) falls on either side of
  // the factor-10 refusal with the trials' noise; named either way.
  struct Expected {
    const char* file;
    std::vector<std::string> statuses;
    const char* named;
  };
  const Expected expected[] = {
      {"baker.json", {"suspect", "failed"}, "a length in cm is written as m"},
      {"evans.json", {"failed"}, "a trailing comma at line"},
      {"fischer.json", {"failed"}, "lenght: unknown key; did you mean length?"},
      {"hughes.json", {"suspect"}, "half swings are counted as oscillations"},
      {"jones.json", {"suspect"}, "a length in mm is written as cm"},
      {"lee.json", {"suspect"}, "a barometer's 1013 hPa written as Pa?"},
      {"martin.json", {"suspect", "failed"}, "one period per trial is typed with oscillations_per_trial 10"},
      {"nguyen.json", {"suspect"}, "radians written as deg?"},
      {"okafor.json", {"suspect", "failed"}, "a mass in kg written as g"},
      {"quinn.json", {"suspect"}, "timing.oscillations_per_trial is half the oscillations timed"},
      {"singh.json", {"suspect"}, "combined standard uncertainties from the site's expected"},
      {"usman.json", {"suspect"}, "a miscounted oscillation? Count again, or drop the trial"},
  };
  int suspect = 0, failed = 0;
  std::vector<double> ok_g;
  for (const auto& [file, row] : rows) {
    INFO(file << ": " << row.dump());
    const Expected* e = nullptr;
    for (const auto& x : expected) e = file == x.file ? &x : e;
    const std::string s = row.at("status");
    if (!e) {
      CHECK(s == "ok");  // no slip, and within 3 combined sigma of the site's g
      ok_g.push_back(row.at("g_m_s2"));
      continue;
    }
    CHECK(std::find(e->statuses.begin(), e->statuses.end(), s) != e->statuses.end());
    const std::string why = s == "failed" ? row.at("error").dump() : row.at("status_reasons").dump();
    CHECK_THAT(why, Contains(e->named));
    suspect += s == "suspect";
    failed += s == "failed";
  }
  CHECK(rows.count("CLARK.JSON") == 1);
  CHECK(rows.at("garcia.json").at("status") == "ok");  // UTF-16, read
  CHECK(last.at("class") == true);
  CHECK(last.at("counts") == json({{"ok", ok_g.size()}, {"suspect", suspect}, {"failed", failed}}));
  double mean = 0.0, ss = 0.0;
  for (double g : ok_g) mean += g / ok_g.size();
  for (double g : ok_g) ss += (g - mean) * (g - mean);
  CHECK_THAT(last.at("g_of_ok").at("mean_m_s2").get<double>(), WithinAbs(mean, 1e-12));
  CHECK_THAT(last.at("g_of_ok").at("standard_deviation_m_s2").get<double>(),
             WithinAbs(std::sqrt(ss / (ok_g.size() - 1)), 1e-12));
  std::filesystem::remove_all(dir);
}

TEST_CASE("batch --report: the class, sorted, failures, a section per scene", "[cli][batch][report]") {
  const std::string dir = temporary_directory();
  const std::string cls = std::string(PENDULUM_DATA_DIR) + "/class";
  const Run r = run("batch --jobs 2 --report " + dir + "/class.html " + cls);
  CHECK(r.status == 1);  // student_c fails
  CHECK(occurrences(r.out, "\n") == 4);  // the summary as without --report: three scenes and the class line
  const std::string page = pendulum::test::read_text(dir + "/class.html");
  CHECK(external_reference(page) == "");
  CHECK_THAT(page, Contains("3 scenes: 2 reduced, 1 failed."));
  // The rows link to the sections; student_c has a row among the failures only.
  for (const char* s : {"href=\"#scene-1\"", "href=\"#scene-2\"", "id=\"scene-1\"", "id=\"scene-2\""}) {
    INFO(s);
    CHECK(occurrences(page, s) >= 1);
  }
  CHECK(page.find("scene-3") == std::string::npos);
  // The path with a break opportunity after each '/' (a long path wraps in its column).
  std::string shown = cls + "/student_c.json";
  for (std::size_t at = shown.find('/'); at != std::string::npos; at = shown.find('/', at + 7)) {
    shown.insert(at + 1, "<wbr/>");
  }
  CHECK_THAT(page, Contains("<td class=\"file\"><code>" + shown + "</code></td><td>bob.diameter.unit: got &quot;inch&quot;"));
  // docs/instructors.md: A at +0.54, B at +5.18 combined standard uncertainties, in that order (by g).
  const std::size_t a = page.find("<td class=\"num\">+0.54</td>"), b = page.find("<td class=\"num\">+5.18</td>");
  CHECK(a != std::string::npos);
  CHECK(b != std::string::npos);
  CHECK(a < b);
  // One worker or two, the same page.
  CHECK(run("batch --jobs 1 --report " + dir + "/again.html " + cls).status == 1);
  CHECK(page == pendulum::test::read_text(dir + "/again.html"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("batch --site: the class's lab for the scenes that name none, each scene's own site kept", "[cli][batch]") {
  char dir_template[] = "/tmp/pendulum-g-batch-XXXXXX";
  REQUIRE(mkdtemp(dir_template));
  const std::string dir = dir_template;
  const json own = json::parse(pendulum::test::read_text(kNelsonOlsson));
  json none = own, typed = own;
  none.erase("site");
  // The same lab typed into the scene: --site must give it exactly.
  typed["site"] = {{"latitude", {{"value", 52.37}, {"unit", "deg"}}},
                   {"height", {{"value", 5}, {"unit", "m"}}},
                   {"height_reference", "sea_level"}};
  std::ofstream(dir + "/a_own.json") << own.dump();
  std::ofstream(dir + "/b_none.json") << none.dump();
  std::ofstream(dir + "/c_typed.json") << typed.dump();
  auto lines_of = [](const Run& r) {
    std::istringstream in(r.out);
    std::vector<json> out;
    for (std::string line; std::getline(in, line);) out.push_back(json::parse(line));
    return out;
  };
  const std::vector<json> without = lines_of(run("batch --jobs 1 " + dir));
  const Run r = run("batch --jobs 1 --site 52.37,5 " + dir);
  CHECK(r.status == 0);
  const std::vector<json> with = lines_of(r);
  REQUIRE(with.size() == 4);
  REQUIRE(without.size() == 4);
  CHECK(with[0].at("expected_g_m_s2") == without[0].at("expected_g_m_s2"));  // the scene's own site
  CHECK(without[1].at("expected_g_m_s2").is_null());
  CHECK(with[1].at("expected_g_m_s2") == with[2].at("expected_g_m_s2"));
  CHECK(with[1].at("z") == with[2].at("z"));
  // A space after the comma, as people type it, reads the same.
  const std::vector<json> spaced = lines_of(run("batch --jobs 1 --site '52.37, 5' " + dir));
  REQUIRE(spaced.size() == 4);
  CHECK(spaced[1].at("expected_g_m_s2") == with[1].at("expected_g_m_s2"));
  // A slip in the option is a usage error (exit 2) naming what it takes.
  for (const auto& [value, message] :
       {std::pair<std::string, std::string>{"52.37", "expected LATITUDE_DEG,HEIGHT_M"},
        {"52.37,5,1", "expected LATITUDE_DEG,HEIGHT_M"},
        {"0x10,5", "expected LATITUDE_DEG,HEIGHT_M"},
        {"95,5", "got 95 deg; expected a latitude from -90 to 90 deg"},
        {"52,5e9", "expected a height on Earth"}}) {
    INFO(value);
    const Run bad = run("batch --site " + value + " " + dir);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK_THAT(bad.err, Contains("--site: ") && Contains(message));
  }
  std::filesystem::remove_all(dir);
}
