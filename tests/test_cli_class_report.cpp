// What a student hands in and an instructor reads (issue 21): the fresh
// class of tests/tools/make_fresh_class.cpp (12 clean scenes, 13 with one
// slip each) through batch, as JSON lines, a table, CSV and a report; the
// verdict first on every page; and the text of every bundled report (no
// malformed power of ten, no digits beyond a double's, no external URL, the
// same bytes twice).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "pendulum/report/svg_plot.hpp"
#include "scene_files.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;
using pendulum::test::read_text;

namespace {

struct Run {
  int status;
  std::string out, err;
};

Run run(const std::string& args) {
  char name[] = "/tmp/pendulum-g-report-test-XXXXXX";
  const int fd = mkstemp(name);
  REQUIRE(fd >= 0);
  close(fd);
  int status = 0;
  const std::string out = pendulum::test::command_output(std::string(PENDULUM_G_EXE) + " " + args + " 2>" + name, status);
  Run r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, out, read_text(name)};
  std::remove(name);
  return r;
}

/// A fresh temporary folder, removed with this object.
struct Folder {
  std::string path;
  Folder() {
    char name[] = "/tmp/pendulum-g-fresh-XXXXXX";
    REQUIRE(mkdtemp(name));
    path = name;
  }
  ~Folder() { std::filesystem::remove_all(path); }
};

/// The fresh class, written once per test that needs it.
struct FreshClass : Folder {
  FreshClass() {
    int status = 0;
    pendulum::test::command_output(std::string(PENDULUM_MAKE_FRESH_CLASS) + " " + path, status);
    REQUIRE(status == 0);
  }
};

/// Each slip of the fresh class: the status it must get and the words that
/// name it and its fix (make_fresh_class.cpp's table); every other file is
/// clean and must be ok.
struct Expected {
  const char* file;
  const char* status;
  std::vector<const char*> named;
};
const Expected kSlips[] = {
    {"bauer.json", "failed", {"these look like a stopwatch's lap totals", "give differences"}},
    {"dubois.json", "suspect", {"5 of 5 trials are", "pasted?"}},
    {"farah.json", "suspect", {"4 of 6 trials are", "pasted?"}},
    {"haddad.json", "suspect", {"a frequency (Hz) typed where trial times belong"}},
    {"jensen.json", "suspect", {"a length in inches is written as m", "(\"in\")"}},
    {"larsen.json", "suspect", {"than the air's drag predicts", "times in min labelled s?"}},
    {"novak.json", "suspect", {"73 degF is 22.8 degC", "fix air.temperature.unit (\"degF\")"}},
    {"perez.json", "suspect", {"the length taped to the top of the ball?", "length.measured_to \"top_of_bob\""}},
    {"romano.json", "suspect", {"of a period, too little for a miscounted oscillation", "started late"}},
    {"tanaka.json", "suspect", {"length.uncertainty: 0, but no tape reads a length exactly"}},
    {"vidal.json", "failed", {"trials in min are written as s: fix timing.unit"}},
    {"weber.json", "failed", {"kelvin written as degC?", "(\"K\")"}},
    {"xu.json", "failed", {"a mass in g written as kg?", "fix bob.mass.unit (\"g\")"}},
};

const Expected* slip_of(const std::string& file) {
  for (const auto& e : kSlips) {
    if (file == e.file) return &e;
  }
  return nullptr;
}

std::string base_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

/// RFC 4180 fields of one CSV line (quotes doubled inside quoted fields).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields{""};
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

TEST_CASE("The fresh class: every slip flagged and named with its fix and no clean scene flagged", "[cli][batch][slips]") {
  const FreshClass dir;
  const Run r = run("batch " + dir.path);
  CHECK(r.status == 1);  // four slips are refused, by design
  std::istringstream lines(r.out);
  std::map<std::string, json> rows;
  json last;
  for (std::string line; std::getline(lines, line);) {
    last = json::parse(line);
    if (last.contains("input")) rows[base_name(last.at("input"))] = last;
  }
  REQUIRE(rows.size() == 25);
  int clean = 0;
  for (const auto& [file, row] : rows) {
    INFO(file << ": " << row.dump());
    const Expected* e = slip_of(file);
    if (!e) {
      ++clean;
      CHECK(row.at("status") == "ok");
      continue;
    }
    CHECK(row.at("status") == e->status);
    // The slip is the first reason (or the error): the one the table and the class page give in brief.
    const std::string why = row.at("status") == "failed" ? row.at("error").get<std::string>()
                            : row.at("status_reasons").empty() ? ""
                                                              : row.at("status_reasons")[0].get<std::string>();
    for (const char* words : e->named) CHECK_THAT(why, Contains(words));
  }
  CHECK(clean == 12);
  CHECK(last.at("counts") == json{{"ok", 12}, {"suspect", 9}, {"failed", 4}});
}

TEST_CASE("batch --format table: a line a scene then the class, CSV: the warnings counted and the first given",
          "[cli][batch][table]") {
  const FreshClass dir;
  const Run jsonl = run("batch " + dir.path);
  std::vector<json> rows;
  std::istringstream lines(jsonl.out);
  for (std::string line; std::getline(lines, line);) rows.push_back(json::parse(line));
  REQUIRE(rows.size() == 26);

  const Run table = run("batch --format table " + dir.path);
  CHECK(table.status == 1);
  std::vector<std::string> text;
  std::istringstream table_lines(table.out);
  for (std::string line; std::getline(table_lines, line);) text.push_back(line);
  REQUIRE(text.size() == 1 + 25 + 1);  // header, scenes, class
  CHECK(text.front().rfind("file", 0) == 0);
  CHECK_THAT(text.front(), Contains("status") && Contains("g (m/s^2)") && Contains("reason"));
  const std::size_t status_column = text.front().find("status");
  for (std::size_t i = 0; i < 25; ++i) {
    const json& row = rows[i];
    const std::string& line = text[i + 1];
    INFO(line);
    CHECK(line.rfind(row.at("input").get<std::string>(), 0) == 0);
    CHECK(line.compare(status_column, row.at("status").get<std::string>().size(), row.at("status").get<std::string>()) == 0);
    if (row.at("status") == "ok") {
      // g rounded to its uncertainty, two significant digits: "9.808 +- 0.024".
      CHECK(std::regex_search(line, std::regex("[0-9]\\.[0-9]+ \\+- 0\\.0[0-9]{2}\\b")));
    } else {
      CHECK(line.size() > status_column + 40);  // a reason in brief follows
    }
  }
  CHECK(text.back().rfind("class: 12 ok, 9 suspect, 4 failed; g of the ok scenes: mean ", 0) == 0);

  const Run csv = run("batch --format csv " + dir.path);
  std::istringstream csv_lines(csv.out);
  std::string header;
  std::getline(csv_lines, header);
  const std::vector<std::string> columns = csv_fields(header);
  REQUIRE(columns.back() == "warning_count");
  const auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  int with_warnings = 0;
  for (std::size_t i = 0; i < 25; ++i) {
    std::string line;
    std::getline(csv_lines, line);
    const std::vector<std::string> f = csv_fields(line);
    REQUIRE(f.size() == columns.size());
    const json& row = rows[i];
    INFO(line);
    if (!row.contains("warnings")) continue;  // failed: no warnings column
    CHECK(f[column("warning_count")] == std::to_string(row.at("warnings").size()));
    CHECK(f[column("warnings")] == (row.at("warnings").empty() ? "" : row.at("warnings")[0].get<std::string>()));
    with_warnings += !row.at("warnings").empty();
  }
  CHECK(with_warnings > 0);  // the check above ran on some
  std::string class_line;
  std::getline(csv_lines, class_line);
  CHECK(class_line == "# " + text.back());
}

TEST_CASE("The verdict first and in words on a scene's page and on the class page", "[cli][report][verdict]") {
  const FreshClass dir;
  const Folder out;
  // A suspect scene: the status and its reason before g.
  const Run reduce = run("reduce " + dir.path + "/jensen.json");
  const json result = json::parse(reduce.out);
  REQUIRE(result.at("status") == "suspect");
  REQUIRE(run("report " + dir.path + "/jensen.json -o " + out.path + "/jensen.html").status == 0);
  const std::string page = read_text(out.path + "/jensen.html");
  const std::size_t verdict = page.find("<strong>Status: suspect</strong>"), g = page.find("<p class=\"g\">g = ");
  REQUIRE(verdict != std::string::npos);
  REQUIRE(g != std::string::npos);
  CHECK(verdict < g);
  for (const auto& reason : result.at("status_reasons")) {
    const std::size_t at = page.find(pendulum::report::xml_escape(reason.get<std::string>()));
    CHECK(at != std::string::npos);
    CHECK(at < g);
  }
  // A clean scene says it is ok, and why.
  REQUIRE(run("report " + dir.path + "/abbott.json -o " + out.path + "/abbott.html").status == 0);
  CHECK_THAT(read_text(out.path + "/abbott.html"),
             Contains("<strong>Status: ok</strong> \u2014 g agrees with the expected g (z = "));

  // The class page: counts, the ok results' mean and spread, a status column with the reason.
  run("batch " + dir.path + " --report " + out.path + "/class.html");
  const std::string cls = read_text(out.path + "/class.html");
  CHECK_THAT(cls, Contains("25 scenes: 21 reduced, 4 failed. Status: 12 ok, 9 suspect, 4 failed."));
  CHECK_THAT(cls, Contains("g of the ok results: mean ") && Contains(", standard deviation "));
  CHECK_THAT(cls, Contains("<th scope=\"col\">status</th>"));
  CHECK(std::regex_search(cls, std::regex("<td><strong>suspect</strong>: g [0-9.]+ times the expected g: a length in "
                                          "inches is written as m</td>")));
  CHECK_THAT(cls, Contains("<td><strong>ok</strong></td>"));
  // The class plot on the ok results' scale: the inches slip at its edge with its value.
  CHECK(std::regex_search(cls, std::regex("[0-9]{3}\\.[0-9] \u25B6</text>")));
}

TEST_CASE("Every bundled report: the same bytes twice with no malformed number and no external URL", "[cli][report][text]") {
  const Folder out;
  std::vector<std::string> inputs;
  for (const auto& e : std::filesystem::directory_iterator(PENDULUM_DATA_DIR)) {
    if (e.path().extension() == ".json" && e.path().filename() != "feinstein_2005_clock.json") {
      inputs.push_back(e.path().string());
    }
  }
  for (const auto& e : std::filesystem::directory_iterator(std::string(PENDULUM_DATA_DIR) + "/recordings")) {
    inputs.push_back(e.path().string());
  }
  std::sort(inputs.begin(), inputs.end());
  REQUIRE(inputs.size() >= 17);
  // A digit glued before the base 10 of a power ("100⁵"), a power 10⁰, or
  // more decimals than a double holds; a URL other than the SVG namespace.
  const std::regex malformed("[0-9]10\u207B?(\u2070|\u00B9|\u00B2|\u00B3|\u2074|\u2075|\u2076|\u2077|\u2078|\u2079)|"
                             "\u00D710\u2070|[0-9]\\.[0-9]{13,}");
  const std::regex url("(https?|ftp)://(?!www\\.w3\\.org/2000/svg)");
  int made = 0, correction_rows = 0;
  for (const auto& input : inputs) {
    INFO(input);
    const std::string a = out.path + "/a.html", b = out.path + "/b.html";
    const Run first = run("report " + input + " -o " + a);
    if (first.status != 0) continue;  // a recording's scene that names another file: its own test
    REQUIRE(run("report " + input + " -o " + b).status == 0);
    const std::string page = read_text(a);
    ++made;
    CHECK(page == read_text(b));
    std::smatch m;
    CHECK_FALSE(std::regex_search(page, m, malformed));
    if (!m.empty()) INFO(m.str());
    CHECK_FALSE(std::regex_search(page, url));
    // Each correction's Delta T rounded as its uncertainty: the same decimals,
    // the uncertainty to two significant digits (more only in whole us, and
    // fewer at the table's finest digit, 0.1 ns).
    const std::size_t table = page.find("<table class=\"corrections\">");
    const std::string rows = table == std::string::npos ? "" : page.substr(table, page.find("</table>", table) - table);
    const std::regex row("<td class=\"num\">(\\+|\u2212)?([0-9]+)(\\.[0-9]+)?</td><td class=\"num\">([0-9]+)(\\.[0-9]+)?</td>");
    for (auto it = std::sregex_iterator(rows.begin(), rows.end(), row); it != std::sregex_iterator(); ++it) {
      const std::smatch& cells = *it;
      INFO(cells.str());
      ++correction_rows;
      CHECK(cells[3].length() == cells[5].length());
      const std::string u = cells[4].str() + (cells[5].length() > 0 ? cells[5].str().substr(1) : "");
      // Leading zeros and the zeros a rounding up leaves (0.0996 as 0.100) are not significant.
      const std::size_t first = u.find_first_not_of('0'), last = u.find_last_not_of('0');
      if (cells[5].length() > 0 && first != std::string::npos) CHECK(last - first < 2);
      if (cells[5].length() > 0) CHECK(cells[5].length() <= 5);
    }
    // A scene's page has a verdict; a recording's alone has no g to judge.
    if (input.size() > 5 && input.compare(input.size() - 5, 5, ".json") == 0 &&
        input.find("/recordings/") == std::string::npos) {
      CHECK_THAT(page, Contains("<strong>Status: "));
    }
  }
  CHECK(made >= 15);
  CHECK(correction_rows >= 50);  // the rounding check saw the tables
}

TEST_CASE("The series page's residuals: measured - model over reduce's effective sigma", "[cli][report][residual]") {
  const std::string scene = std::string(PENDULUM_DATA_DIR) + "/pendulum_lengths_series.json";
  const json result = json::parse(run("reduce " + scene).out);
  const Folder out;
  REQUIRE(run("report " + scene + " -o " + out.path + "/series.html").status == 0);
  const std::string page = read_text(out.path + "/series.html");
  CHECK_THAT(page, Contains("Residual: (T measured \u2212 T model) / \u03C3<sub>eff</sub>"));
  // Each row's last cell: -residual_sigma (reduce's is model - measured), to two decimals.
  const std::regex row("<td class=\"num\">([^<]*)</td></tr>");
  std::vector<std::string> cells;
  const std::size_t table = page.find("<table class=\"observations\">");
  const std::string rows = page.substr(table, page.find("</table>", table) - table);
  for (auto it = std::sregex_iterator(rows.begin(), rows.end(), row); it != std::sregex_iterator(); ++it) {
    cells.push_back((*it)[1]);
  }
  const json& observations = result.at("fit").at("observations");
  REQUIRE(cells.size() == observations.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const double residual = observations[k].at("residual_sigma");
    char expected[32];
    std::snprintf(expected, sizeof expected, "%+.2f", -residual);
    std::string text = expected;
    if (text[0] == '-') text.replace(0, 1, "\u2212");
    if (text == "+0.00" || text == "\u22120.00") text = "0.00";
    INFO(k);
    CHECK(cells[k] == text);
  }
}

TEST_CASE("import --format table prints the amplitude_range.start that the docs say to paste", "[cli][import]") {
  const std::string recording = std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_gyroscope.csv";
  const json imported = json::parse(run("import " + recording).out);
  const double start = imported.at("amplitude_range").at("start");
  char expected[32];
  std::snprintf(expected, sizeof expected, "%.3f deg at the first crossing", start);
  CHECK_THAT(run("import --format table " + recording).out, Contains(expected));
}

TEST_CASE("template kater: Kater's pendulum with Bessel's formula, as the bundled scene", "[cli][template]") {
  const Folder out;
  const Run help = run("template --help");
  CHECK_THAT(help.out, Contains("kater") && Contains("Kinds: ball, series, pivot-scan, kater, recording"));
  CHECK_THAT(run("template kater --help").out, Contains("Usage:"));
  REQUIRE(run("template kater > " + out.path + "/kater.json").status == 0);
  const Run r = run("reduce --strict " + out.path + "/kater.json");
  REQUIRE(r.status == 0);
  const json result = json::parse(r.out);
  CHECK(result.at("status") == "ok");
  // The numbers are data/kater_reversible_pendulum.json's: the same g, to the
  // last bit, and the same one warning (the bar's buoyancy, unknown without its parts).
  const json bundled = json::parse(run("reduce " + std::string(PENDULUM_DATA_DIR) + "/kater_reversible_pendulum.json").out);
  CHECK(result.at("g") == bundled.at("g"));
  CHECK(result.at("warnings") == bundled.at("warnings"));
  CHECK_THAT(run("reduce --format table " + out.path + "/kater.json").out, Contains("Bessel's formula"));
}

TEST_CASE("A missing key: its unit and an example, the allowed values, and when its part may be left out",
          "[cli][first-steps]") {
  const Folder out;
  const json base = {{"length", {{"value", 1}, {"unit", "m"}}},
                     {"amplitude", {{"value", 5}, {"unit", "deg"}}},
                     {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"trials", {20.1, 20.0}}}}};
  struct Case {
    json patch;
    std::vector<const char*> words;
  };
  const Case cases[] = {
      {{{"air", {{"temperature", {{"value", 21}, {"unit", "degC"}}}}}},
       {"air.pressure: missing", "\"unit\": \"hPa\"", "air may be left out", "\"vacuum\""}},
      {{{"site", {{"latitude", {{"value", 51}, {"unit", "deg"}}}, {"height", {{"value", 100}, {"unit", "m"}}}}}},
       {"site.height_reference: missing", "\"sea_level\" or \"ellipsoid\""}},
      {{{"bob", {{"mass", {{"value", 67}, {"unit", "g"}}}}}}, {"bob.diameter: missing", "\"unit\": \"mm\"", "bob may be left out"}},
  };
  for (const auto& c : cases) {
    json scene = base;
    scene.merge_patch(c.patch);
    {
      std::ofstream(out.path + "/scene.json") << scene.dump();
    }
    const Run r = run("reduce " + out.path + "/scene.json");
    INFO(r.err);
    CHECK(r.status == 1);
    for (const char* w : c.words) CHECK_THAT(r.err, Contains(w));
  }
}
