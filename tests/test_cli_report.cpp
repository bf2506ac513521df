// The pendulum-g command's report: the self-contained HTML page and the SVG
// plots, of scenes and of recordings.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <vector>
#include <string>

#include "catalogue.hpp"
#include "cli_run.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;

namespace {

const std::string kDecayScene = std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986_decay.json";

}  // namespace

TEST_CASE("report: one self-contained HTML page, the same bytes twice", "[cli][report]") {
  const std::string dir = temporary_directory();
  struct Case {
    std::string scene;
    std::size_t plots;  // corrections, budget, and the decay record when there is one
  };
  for (const Case& c : {Case{kNelsonOlsson, 2}, Case{kDecayScene, 3}}) {
    INFO(c.scene);
    const Run first = run("report " + c.scene + " -o " + dir + "/first.html");
    REQUIRE(first.status == 0);
    CHECK(first.out.empty());
    CHECK(first.err.empty());
    const Run second = run("report " + c.scene + " --output " + dir + "/second.html");
    REQUIRE(second.status == 0);
    const std::string page = pendulum::test::read_text(dir + "/first.html");
    CHECK(page == pendulum::test::read_text(dir + "/second.html"));
    CHECK(page == run("report " + c.scene).out);  // standard output by default

    CHECK(page.rfind("<!DOCTYPE html>\n<html lang=\"en\">", 0) == 0);
    CHECK(external_reference(page) == "");
    CHECK(occurrences(page, "<svg ") == c.plots);
    CHECK(occurrences(page, "<title id=") == c.plots);
    CHECK(occurrences(page, "<desc id=") == c.plots);
    // The numbers of `reduce --format table` (README): g and the comparison.
    CHECK_THAT(page, Contains("g = 9.8034 \u00B1 0.0015 m/s\u00B2"));
    CHECK_THAT(page, Contains("+0.00080 m/s\u00B2 = +0.54 combined standard uncertainties"));
    CHECK_THAT(page, Contains("Nelson &amp; Olsson (1986)"));
    // Rounded to its uncertainty, 596.0018 +- 119.1828 us (reduce).
    CHECK_THAT(page, Contains("<td>Finite amplitude</td><td class=\"num\">+596</td><td class=\"num\">119</td>"));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("report: the measured period's trials and oscillations, counted in words", "[cli][report]") {
  // Nelson & Olsson's ten trials of 100 oscillations; a recording is one
  // trial of its full periods (timer_missed_stamp.txt: 40, docs/recordings.md).
  CHECK_THAT(run("report " + kNelsonOlsson).out, Contains("(10 trials of 100 oscillations)"));
  const Run recording = run("report " + std::string(PENDULUM_DATA_DIR) + "/recordings/timer_missed_stamp_scene.json");
  REQUIRE(recording.status == 0);
  CHECK_THAT(recording.out, Contains("(1 trial of 40 oscillations)"));
}

TEST_CASE("report: bad input fails as reduce does and leaves no file", "[cli][report][errors]") {
  const std::string dir = temporary_directory();
  json scene = json::parse(pendulum::test::read_text(kNelsonOlsson));
  scene["bob"]["diameter"]["unit"] = "inch";
  const std::string bad = dir + "/bad.json";
  std::ofstream(bad) << scene.dump();

  const Run reduce = run("reduce " + bad);
  const Run report = run("report " + bad + " -o " + dir + "/report.html");
  CHECK(reduce.status == 1);
  CHECK(report.status == 1);
  CHECK(report.out.empty());
  CHECK(report.err == reduce.err);  // the same message, naming the file and the JSON path
  CHECK_THAT(report.err, Contains("bad.json: bob.diameter.unit: got \"inch\""));
  // Nothing written: no report, no temporary file beside it.
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) files.push_back(entry.path().filename());
  CHECK(files == std::vector<std::string>{"bad.json"});

  // An earlier report stays as it was.
  std::ofstream(dir + "/report.html") << "earlier";
  CHECK(run("report " + bad + " -o " + dir + "/report.html").status == 1);
  CHECK(pendulum::test::read_text(dir + "/report.html") == "earlier");

  const Run unwritable = run("report " + kNelsonOlsson + " -o " + dir + "/missing/report.html");
  CHECK(unwritable.status == 5);
  CHECK_THAT(unwritable.err, Contains("output: cannot write " + dir + "/missing/report.html: No such file or directory"));
  const Run directory = run("report " + kNelsonOlsson + " -o " + dir);
  CHECK(directory.status == 5);
  CHECK_THAT(directory.err, Contains("output: cannot write " + dir + ": Is a directory"));
  // A device is written in place, never replaced by a file (/dev/stdout here).
  const Run device = run("report " + kNelsonOlsson + " -o /dev/stdout");
  CHECK(device.status == 0);
  CHECK(device.out == run("report " + kNelsonOlsson).out);
  std::filesystem::remove_all(dir);
}

TEST_CASE("report --plot: one plot as an SVG file", "[cli][report]") {
  const Run corrections = run("report " + kNelsonOlsson + " --plot corrections");
  REQUIRE(corrections.status == 0);
  CHECK(corrections.out.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) ==
        0);
  CHECK_THAT(corrections.out, Contains("<title id=\"corrections-title\">Corrections to the period</title>"));
  CHECK(corrections.out == run("report --format svg --plot corrections " + kNelsonOlsson).out);
  CHECK(run("report " + kDecayScene + " --plot decay").status == 0);

  const Run no_record = run("report " + kNelsonOlsson + " --plot decay");
  CHECK(no_record.status == 1);
  CHECK(no_record.out.empty());
  CHECK_THAT(no_record.err, Contains("decay.data: the scene has no decay record to plot"));
  CHECK(run("report " + kNelsonOlsson + " --format svg").status == 2);  // which plot?
  CHECK(run("report " + kNelsonOlsson + " --format html --plot budget").status == 2);
  CHECK(run("report " + kNelsonOlsson + " --plot residuals").status == 2);
}

TEST_CASE("report: a page for every valid scene of the catalogue, extreme or suspicious", "[cli][report]") {
  const json catalogue =
      json::parse(pendulum::test::read_text(std::string(PENDULUM_TESTS_DIR) + "/valid_scenes.json"));
  const json base = json::parse(pendulum::test::read_text(kNelsonOlsson));
  const std::string file = temporary_file();
  // A number printed from NaN or infinity, not a word holding those letters.
  const std::regex non_finite("(^|[^A-Za-z])-?(nan|inf)", std::regex::icase);
  for (const json& entry : catalogue.at("cases")) {
    std::ofstream(file, std::ios::binary) << pendulum::test::catalogue_text(entry, base);
    const Run r = run("report --allow-outside " + file);
    INFO(entry.at("name").get<std::string>() << "\nstderr: " << r.err);
    REQUIRE(r.status == 0);
    CHECK(external_reference(r.out) == "");
    CHECK_FALSE(std::regex_search(r.out, non_finite));
    CHECK(occurrences(r.out, "<svg ") >= 1);
    CHECK(r.out.size() > 10000);
  }
  std::remove(file.c_str());
}

TEST_CASE("report: text from the scene is escaped, never markup", "[cli][report]") {
  const std::string dir = temporary_directory();
  json scene = json::parse(pendulum::test::read_text(kNelsonOlsson));
  scene["title"] = "<script>alert(\"g\")</script> & <b>co</b>";
  scene["source"] = "notebook p. 3 <img onerror=x>";
  std::ofstream(dir + "/odd.json") << scene.dump();
  const Run r = run("report " + dir + "/odd.json");
  REQUIRE(r.status == 0);
  CHECK(external_reference(r.out) == "");
  CHECK_THAT(r.out, Contains("<h2>&lt;script&gt;alert(&quot;g&quot;)&lt;/script&gt; &amp; &lt;b&gt;co&lt;/b&gt;</h2>"));
  CHECK_THAT(r.out, Contains("notebook p. 3 &lt;img onerror=x&gt;"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("report: a series, its fit and the textbook line", "[cli][report]") {
  const std::string series = std::string(PENDULUM_DATA_DIR) + "/pendulum_lengths_series.json";
  const Run r = run("report " + series);
  REQUIRE(r.status == 0);
  CHECK(external_reference(r.out) == "");
  CHECK(occurrences(r.out, "<svg ") == 3);  // corrections of the first observation, budget, series
  CHECK_THAT(r.out, Contains("<h3>Series fit</h3>"));
  CHECK_THAT(r.out, Contains("g of the textbook line (no corrections)"));
  const Run plot = run("report " + series + " --plot series");
  REQUIRE(plot.status == 0);
  CHECK_THAT(plot.out, Contains("<title id=\"series-title\">Series: T\u00B2 against length"));
  const Run single = run("report " + kNelsonOlsson + " --plot series");
  CHECK(single.status == 1);
  CHECK_THAT(single.err, Contains("observations: the scene is not a series of observations"));
}

namespace {

const std::string kRecordings = std::string(PENDULUM_DATA_DIR) + "/recordings/";

}  // namespace

TEST_CASE("report RECORDING: one page with the signal, the amplitudes and the periods", "[cli][report][recording]") {
  const std::string dir = temporary_directory();
  struct Case {
    std::string file, options;
    std::size_t plots;  // signal (sampled, or a gate's states), amplitude and period-amplitude (with amplitudes)
  };
  const std::regex non_finite("(^|[^A-Za-z])-?(nan|inf)", std::regex::icase);
  for (const Case& c : {Case{"phyphox_gyroscope.csv", "", 3}, Case{"phyphox_pendulum_raw.tsv", "", 3},
                        Case{"phyphox_linear_acceleration.csv", "", 3}, Case{"phyphox_acceleration.csv", "", 3},
                        Case{"pasco_rotary.csv", "", 3}, Case{"tracker_xy.txt", "", 3},
                        Case{"tracker_theta.csv", "", 3},
                        Case{"vernier_photogate.csv", "--bob-width-m 0.025 --length-m 0.80", 3},
                        Case{"vernier_photogate.csv", "", 1}, Case{"plain_blocking_times.txt", "", 0}}) {
    const std::string file = kRecordings + c.file;
    INFO(c.file << " " << c.options);
    const Run first = run("report " + c.options + " " + file + " -o " + dir + "/first.html");
    REQUIRE(first.status == 0);
    CHECK(first.out.empty());
    CHECK(first.err.empty());
    REQUIRE(run("report " + c.options + " " + file + " -o " + dir + "/second.html").status == 0);
    const std::string page = pendulum::test::read_text(dir + "/first.html");
    CHECK(page == pendulum::test::read_text(dir + "/second.html"));
    CHECK(page == run("report " + c.options + " " + file).out);
    CHECK(external_reference(page) == "");
    CHECK_FALSE(std::regex_search(page, non_finite));
    CHECK(occurrences(page, "<svg ") == c.plots);
    CHECK(occurrences(page, "<title id=") == c.plots);
    CHECK(occurrences(page, "<desc id=") == c.plots);
    // What import found: the family and the full periods with their crossings.
    const json imported = json::parse(run("import " + c.options + " " + file).out);
    CHECK_THAT(page, Contains("Format: " + imported.at("format").get<std::string>() + ", "));
    CHECK_THAT(page, Contains("<td>" + std::to_string(imported.at("periods").get<int>()) + " ("));
  }
  // The family forced as for import: the same page; one that does not fit fails.
  const std::string gyroscope = kRecordings + "phyphox_gyroscope.csv";
  CHECK(run("report --format phyphox " + gyroscope).out == run("report " + gyroscope).out);
  const Run wrong = run("report --format vernier " + gyroscope + " -o " + dir + "/wrong.html");
  CHECK(wrong.status == 1);
  CHECK(wrong.err == run("import --format vernier " + gyroscope).err);
  CHECK_FALSE(std::filesystem::exists(dir + "/wrong.html"));
  // A set as for import: the track of a Tracker export of several, named on the page.
  const std::string tracks = kRecordings + "tracker_two_tracks.txt";
  const Run track = run("report --set \"mass b\" " + tracks);
  CHECK(track.status == 0);
  CHECK_THAT(track.out, Contains("tracker_two_tracks.txt/mass B"));
  const json imported = json::parse(run("import --set \"mass b\" " + tracks).out);
  CHECK_THAT(track.out, Contains("<td>" + std::to_string(imported.at("periods").get<int>()) + " ("));
  const Run no_track = run("report " + tracks + " -o " + dir + "/no_track.html");
  CHECK(no_track.status == 1);
  CHECK(no_track.err == run("import " + tracks).err);
  CHECK_FALSE(std::filesystem::exists(dir + "/no_track.html"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("report RECORDING --plot: one plot of a recording as an SVG file", "[cli][report][recording]") {
  const std::string gyroscope = kRecordings + "phyphox_gyroscope.csv";
  for (const char* name : {"signal", "amplitude", "period-amplitude"}) {
    INFO(name);
    const Run plot = run("report " + gyroscope + " --plot " + name);
    REQUIRE(plot.status == 0);
    CHECK(plot.out.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    CHECK_THAT(plot.out, Contains("<title id=\"" + std::string(name) + "-title\">"));
    CHECK(plot.out == run("report --format svg --format phyphox --plot " + std::string(name) + " " + gyroscope).out);
  }
  // Every crossing is marked: 22 in the gyroscope file (import's table).
  CHECK_THAT(run("report " + gyroscope + " --plot signal").out, Contains("detected crossing (22)"));

  // A photogate's gate states are drawn as the beam's state, stepping at each event.
  const Run gate = run("report " + kRecordings + "vernier_photogate.csv --plot signal");
  CHECK(gate.status == 0);
  CHECK_THAT(gate.out, Contains("beam: blocked (1) or open (0)"));
  const Run events = run("report " + kRecordings + "plain_blocking_times.txt --plot signal");
  CHECK(events.status == 1);
  CHECK_THAT(events.err, Contains("plain_blocking_times.txt: a column of blocking times has no signal to plot"));
  const Run scene_plot = run("report " + gyroscope + " --plot decay");
  CHECK(scene_plot.status == 1);
  CHECK_THAT(scene_plot.err,
             Contains("no plot \"decay\" for a recording; this one has: signal, amplitude, period-amplitude"));
  const Run recording_plot = run("report " + kNelsonOlsson + " --plot signal");
  CHECK(recording_plot.status == 1);
  CHECK_THAT(recording_plot.err, Contains("no plot \"signal\""));
  CHECK(run("report " + gyroscope + " --format svg").status == 2);  // which plot?
}

TEST_CASE("report RECORDING: a bad recording fails as import does and leaves no file", "[cli][report][recording][errors]") {
  const std::string dir = temporary_directory();
  const std::string bad = std::string(PENDULUM_TESTS_DIR) + "/bad_recordings/";
  for (const char* file : {"truncated_row.csv", "not_a_number.csv", "two_swings.csv", "no_oscillation.csv",
                           "unknown_header.csv", "time_backwards.csv", "mixed_delimiters.csv"}) {
    INFO(file);
    const Run import = run("import " + bad + file);
    const Run report = run("report " + bad + file + " -o " + dir + "/report.html");
    CHECK(import.status == 1);
    CHECK(report.status == 1);
    CHECK(report.out.empty());
    CHECK(report.err == import.err);
    CHECK(std::filesystem::is_empty(dir));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("report: a pivot scan and Kater's pendulum, plotted as pivot scans", "[cli][report][pivot]") {
  const std::string scan = std::string(PENDULUM_DATA_DIR) + "/metre_stick_pivot_scan.json";
  const Run r = run("report " + scan);
  REQUIRE(r.status == 0);
  CHECK(external_reference(r.out) == "");
  CHECK(occurrences(r.out, "<svg ") == 3);  // corrections of the first observation, budget, pivot scan
  CHECK_THAT(r.out, Contains("<h3>Pivot scan</h3>"));
  CHECK_THAT(r.out, !Contains("Series fit"));
  CHECK_THAT(r.out, Contains("pivot position x (m)"));
  const Run plot = run("report " + scan + " --plot pivot-scan");
  REQUIRE(plot.status == 0);
  CHECK_THAT(plot.out, Contains("<title id=\"pivot-scan-title\">Pivot scan: period T against pivot position"));
  CHECK(run("report " + scan + " --plot series").out == plot.out);  // the scene's plot of its observations
  const Run kater = run("report " + std::string(PENDULUM_DATA_DIR) + "/kater_reversible_pendulum.json");
  REQUIRE(kater.status == 0);
  CHECK_THAT(kater.out, Contains("<h3>Kater's pendulum</h3>"));
  CHECK_THAT(kater.out, Contains("Bessel&#39;s formula on their ideal periods gives g = 9.81206 m/s^2"));
  CHECK_THAT(kater.out, Contains("1 period correction, each"));
  const Run simple = run("report " + std::string(PENDULUM_DATA_DIR) + "/pendulum_lengths_series.json --plot pivot-scan");
  CHECK(simple.status == 1);
  CHECK_THAT(simple.err, Contains("observations: the scene is not a pivot scan"));
}

TEST_CASE("report: a scene that names a recording shows its swings once", "[cli][report][recording]") {
  // timing and decay.data name the same file: one recording section with
  // its signal (read again by report), amplitude and period plots.
  const std::string scene = std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_pendulum_raw_from_file.json";
  const Run r = run("report " + scene);
  REQUIRE(r.status == 0);
  CHECK(occurrences(r.out, "<h3>Recording <code>") == 1);
  CHECK(occurrences(r.out, "<h4>Amplitude against time") == 1);
  CHECK(occurrences(r.out, "<h4>Period against amplitude") == 1);
  CHECK(occurrences(r.out, "<h4>Signal") == 1);
  CHECK(occurrences(r.out, "<svg ") == 6);  // corrections, budget, decay, signal, amplitude, period
  CHECK(external_reference(r.out) == "");
  CHECK(run("report " + scene).out == r.out);
}
