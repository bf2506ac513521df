// The pendulum-g command's import: recordings into timing and decay, a scene
// naming a recording, phyphox's zip export, the catalogue of bad recordings.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>
#include <string>

#include "catalogue.hpp"
#include "cli_run.hpp"
#include "scene_files.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("import: a phone recording becomes timing and decay that a scene takes as they are",
          "[cli][import]") {
  const std::string file = std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_gyroscope.csv";
  const Run r = run("import " + file);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const json out = json::parse(r.out);
  std::vector<std::string> keys;
  const nlohmann::ordered_json in_order = nlohmann::ordered_json::parse(r.out);
  for (const auto& item : in_order.items()) keys.push_back(item.key());
  // The format and the set read (null here: no zip, PASCO run or Tracker
  // track), the five keys of before issue 19; then what the reader used,
  // the glitches, the stretch analysed, what it cut, the whole record's
  // period beside it (issue 38), and the notes.
  CHECK(keys == std::vector<std::string>{"format", "set", "periods", "period", "amplitude_range", "timing", "decay",
                                         "columns", "glitches", "analysed_range", "cut", "whole_record_period",
                                         "notes"});
  CHECK(out.at("format") == "phyphox");
  CHECK(out.at("periods") == 10);
  const double period = out.at("period").at("value").get<double>();
  CHECK(out.at("period").at("unit") == "s");
  CHECK_THAT(out.at("timing").at("trials")[0].get<double>() / out.at("timing").at("oscillations_per_trial").get<int>(),
             WithinAbs(period, 1e-12));
  // Pasted into the Nelson-Olsson scene with this pendulum's length and
  // amplitude, the scene reduces: the period it reads is the recording's.
  json scene = json::parse(pendulum::test::read_text(kNelsonOlsson));
  scene["timing"] = out.at("timing");
  scene["decay"] = out.at("decay");
  scene["length"] = {{"value", 0.80}, {"unit", "m"}, {"uncertainty", 0.001}};
  scene["amplitude"] = {{"value", out.at("amplitude_range").at("start")}, {"unit", "deg"}};
  const std::string scene_file = temporary_file();
  std::ofstream(scene_file) << scene.dump();
  const Run reduced = run("reduce " + scene_file);
  std::remove(scene_file.c_str());
  INFO(reduced.err);
  REQUIRE(reduced.status == 0);
  CHECK_THAT(json::parse(reduced.out).at("period").at("measured").at("value").get<double>(), WithinAbs(period, 1e-9));

  const Run table = run("import --format table " + file);
  REQUIRE(table.status == 0);
  CHECK_THAT(table.out, Contains("period") && Contains("+-"));
  const Run forced = run("import --format tracker " + file);
  CHECK(forced.status == 1);
  CHECK(forced.out.empty());
  CHECK_THAT(forced.err, Contains("does not fit a tracker export"));
}

namespace {

/// Runs pendulum-g from the folder `dir`, as a student would.
Run run_in(const std::string& dir, const std::string& args) {
  const auto before = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  const Run r = run(args);
  std::filesystem::current_path(before);
  return r;
}

}  // namespace

TEST_CASE("A scene naming a recording reduces as the scene import's output pasted, from any folder",
          "[cli][import][scene]") {
  const std::string recordings = std::string(PENDULUM_DATA_DIR) + "/recordings";
  const std::string scene = recordings + "/phyphox_pendulum_raw_from_file.json";
  // The same scene with import's timing, decay and start amplitude pasted in.
  const json imported = json::parse(run("import " + recordings + "/phyphox_pendulum_raw.tsv").out);
  json pasted = json::parse(pendulum::test::read_text(scene));
  pasted["timing"] = imported.at("timing");
  pasted["decay"] = imported.at("decay");
  pasted["amplitude"] = {{"value", imported.at("amplitude_range").at("start")}, {"unit", "deg"},
                         {"of", imported.at("amplitude_range").at("of")}};
  // A gyroscope turns with the bob: import says its angles are the bob's (docs/phone.md).
  CHECK(imported.at("amplitude_range").at("of") == "body");
  CHECK(imported.at("decay").at("data").at("of") == "body");
  const std::string pasted_file = temporary_file();
  std::ofstream(pasted_file) << pasted.dump();
  const json expected = json::parse(run("reduce " + pasted_file).out);
  std::remove(pasted_file.c_str());
  const double g = expected.at("g").at("value").get<double>();

  const Run r = run("reduce " + scene);  // from the build folder: the scene's folder decides
  INFO(r.err);
  REQUIRE(r.status == 0);
  // 19 amplitudes over 16 s fix the decay's total rate only (docs/decay_fit.md).
  CHECK(r.err.rfind("pendulum-g: warning: decay fit: the record cannot tell linear from quadratic damping", 0) == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // that warning alone
  const json result = json::parse(r.out);
  // The pasted numbers went through decimal text and degrees: equal to rounding.
  CHECK_THAT(result.at("g").at("value").get<double>(), WithinRel(g, 1e-12));
  CHECK_THAT(result.at("g").at("uncertainty").get<double>(),
             WithinRel(expected.at("g").at("uncertainty").get<double>(), 1e-9));
  CHECK_THAT(result.at("period").at("measured").at("value").get<double>(),
             WithinRel(expected.at("period").at("measured").at("value").get<double>(), 1e-15));
  CHECK(result.at("period").at("oscillations_per_trial") == imported.at("periods"));
  CHECK(result.at("decay_fit").at("points") == expected.at("decay_fit").at("points"));
  // Its beta is the bob's, as the pasted record's "of" says (docs/output.md, decay_fit).
  CHECK(result.at("decay_fit").at("angle_of") == "body");
  CHECK(expected.at("decay_fit").at("angle_of") == "body");
  // Where the timing and the decay record came from; no other key changed.
  const json& from = result.at("recordings");
  REQUIRE(from.size() == 2);
  CHECK(from[0].at("path") == "timing");
  CHECK(from[1].at("path") == "decay.data");
  CHECK(from[0].at("recording") == "phyphox_pendulum_raw.tsv");
  CHECK(from[0].at("file") == recordings + "/phyphox_pendulum_raw.tsv");
  CHECK(from[0].at("format") == "phyphox");
  CHECK(from[0].at("periods") == imported.at("periods"));
  CHECK(from[0].at("period") == imported.at("period"));
  json without = result;
  without.erase("recordings");
  without.erase("input");
  without.erase("assumptions");
  json expected_without = expected;
  expected_without.erase("input");
  expected_without.erase("assumptions");
  std::vector<std::string> keys, expected_keys;
  for (const auto& item : without.items()) keys.push_back(item.key());
  for (const auto& item : expected_without.items()) expected_keys.push_back(item.key());
  CHECK(keys == expected_keys);

  // Standard input: relative to the current folder.
  const Run here = run_in(recordings, "reduce - < " + scene);
  CHECK(here.status == 0);
  CHECK_THAT(json::parse(here.out).at("g").at("value").get<double>(), WithinRel(g, 1e-12));
  const Run elsewhere = run_in(PENDULUM_DATA_DIR, "reduce - < " + scene);
  CHECK(elsewhere.status == 1);
  CHECK(elsewhere.out.empty());
  CHECK_THAT(elsewhere.err, Contains("timing.recording: phyphox_pendulum_raw.tsv: cannot open the file"));

  // batch (a file, and stdin from the scene's folder), report and fit-decay.
  for (const Run& b : {run("batch " + scene), run_in(recordings, "batch - < " + scene)}) {
    INFO(b.err);
    CHECK(b.status == 0);
    CHECK_THAT(json::parse(b.out.substr(0, b.out.find('\n'))).at("g_m_s2").get<double>(), WithinRel(g, 1e-12));
  }
  const std::string html = temporary_file() + ".html";
  CHECK(run("report " + scene + " -o " + html).status == 0);
  CHECK(std::filesystem::file_size(html) > 1000);
  std::remove(html.c_str());
  const Run decay = run("fit-decay " + scene);
  REQUIRE(decay.status == 0);
  const json fit = json::parse(decay.out);
  CHECK(fit.at("points") == imported.at("decay").at("data").at("times").size());
  CHECK(fit.at("recordings")[1].at("path") == "decay.data");
}

TEST_CASE("import: phyphox's zip export reads its best set, or the one named", "[cli][import][zip]") {
  // data/recordings/phyphox_export.zip holds the three phyphox CSVs of
  // data/recordings byte for byte (tests/tools/make_phyphox_zips.py): each set
  // must give what its CSV gives.
  const std::string recordings = std::string(PENDULUM_DATA_DIR) + "/recordings/";
  const std::string zip = recordings + "phyphox_export.zip";
  const std::pair<std::string, std::string> sets[] = {
      {"", "phyphox_gyroscope.csv"},  // by default the rate: a gyroscope beats the accelerometers
      {" --set Accelerometer", "phyphox_acceleration.csv"},
      {" --set 'Linear Acceleration.csv'", "phyphox_linear_acceleration.csv"}};
  for (const auto& [option, csv] : sets) {
    INFO(option);
    const Run r = run("import" + option + " " + zip);
    REQUIRE(r.status == 0);
    const json from_zip = json::parse(r.out), from_csv = json::parse(run("import " + recordings + csv).out);
    CHECK(from_zip.at("period") == from_csv.at("period"));
    CHECK(from_zip.at("periods") == from_csv.at("periods"));
    CHECK(from_zip.at("amplitude_range") == from_csv.at("amplitude_range"));
    CHECK(from_zip.at("set") != nullptr);
    CHECK(from_csv.at("set") == nullptr);
  }
  CHECK(json::parse(run("import --set gyroscope " + zip).out).at("set") == "Gyroscope.csv");
  const Run table = run("import --format table " + zip);
  CHECK_THAT(table.out, Contains("set                    Gyroscope.csv"));
  const Run missing = run("import --set Magnetometer " + zip);
  CHECK(missing.status == 1);
  CHECK_THAT(missing.err, Contains("a zip archive with no set \"Magnetometer\"; expected one of its CSV sets: "
                                   "\"Gyroscope.csv\", \"Accelerometer.csv\", \"Linear Acceleration.csv\""));
  // A scene names the zip and its set; the output says which set was read.
  const std::string scene = temporary_file();
  std::ofstream(scene) << json{{"timing", {{"recording", zip}, {"set", "Linear Acceleration.csv"}}},
                               {"length", {{"value", 0.8}, {"unit", "m"}}}}
                              .dump();
  const Run reduced = run("reduce --allow-outside " + scene);
  std::remove(scene.c_str());
  INFO(reduced.err);
  REQUIRE(reduced.status == 0);
  const json result = json::parse(reduced.out);
  CHECK(result.at("recordings")[0].at("set") == "Linear Acceleration.csv");
  CHECK(result.at("period").at("measured").at("value") ==
        json::parse(run("import " + recordings + "phyphox_linear_acceleration.csv").out).at("period").at("value"));
}

TEST_CASE("A scene's amplitude from a video track carries the track's uncertainty into g's budget",
          "[cli][import]") {
  // import's amplitude_range.start_uncertainty (deg) is the scene's amplitude
  // uncertainty; a gyroscope's is null, and its amplitude stays without one.
  for (const std::string file : {"tracker_xy.txt", "phyphox_gyroscope.csv"}) {
    INFO(file);
    const std::string recording = std::string(PENDULUM_DATA_DIR) + "/recordings/" + file;
    const json imported = json::parse(run("import " + recording).out);
    const json& sigma = imported.at("amplitude_range").at("start_uncertainty");
    const std::string scene = temporary_file();
    std::ofstream(scene) << json{{"timing", {{"recording", recording}}},
                                 {"length", {{"value", 0.8}, {"unit", "m"}, {"uncertainty", 0.001}}}}
                                .dump();
    const Run reduced = run("reduce --allow-outside " + scene);
    std::remove(scene.c_str());
    REQUIRE(reduced.status == 0);
    const json result = json::parse(reduced.out);
    bool in_budget = false;
    for (const auto& row : result.at("g").at("budget")) in_budget |= row.at("input") == "amplitude";
    CHECK(in_budget == sigma.is_number());
    if (sigma.is_number()) {
      CHECK(sigma.get<double>() > 0.0);
      CHECK_THAT(reduced.out, Contains("from its swings' scatter and its circle's radius"));
    }
  }
}

TEST_CASE("A scene naming a named pipe or an unreadable file fails at once, naming both", "[cli][import][errors]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(temporary_file() + ".d");
  fs::create_directory(dir);
  const json scene = {{"timing", {{"recording", "run.csv"}}},
                      {"length", {{"value", 0.8}, {"unit", "m"}}},
                      {"amplitude", {{"value", 5}, {"unit", "deg"}}}};
  std::ofstream(dir / "scene.json") << scene.dump();
  // A FIFO without a writer: refused, not waited on.
  REQUIRE(mkfifo((dir / "run.csv").c_str(), 0600) == 0);
  const Run pipe = run("reduce " + (dir / "scene.json").string());
  CHECK(pipe.status == 1);
  CHECK(pipe.out.empty());
  CHECK_THAT(pipe.err, Contains("timing.recording: " + (dir / "run.csv").string() + ": not a regular file"));
  fs::remove(dir / "run.csv");
  // A file its owner may not read (root reads it all the same).
  fs::copy_file(std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_gyroscope.csv", dir / "run.csv");
  fs::permissions(dir / "run.csv", fs::perms::none);
  const Run locked = run("reduce " + (dir / "scene.json").string());
  if (geteuid() != 0) {
    CHECK(locked.status == 1);
    CHECK_THAT(locked.err, Contains("timing.recording: " + (dir / "run.csv").string() +
                                    ": cannot open the file: Permission denied"));
  }
  fs::remove_all(dir);
}

TEST_CASE("import: catalogue of bad recordings (tests/bad_recordings/)", "[cli][import][errors]") {
  const std::string dir = std::string(PENDULUM_TESTS_DIR) + "/bad_recordings/";
  const json expected = json::parse(pendulum::test::read_text(dir + "expected.json"));
  REQUIRE(expected.size() >= 8);
  for (const auto& [name, message] : expected.items()) {
    INFO(name);
    const Run r = run("import " + dir + name);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Contains(message.get<std::string>()));
    CHECK_FALSE(pendulum::test::says_nan(r.err));
  }
  // A huge file (sparse: 2 GiB of nothing on disk) is refused before reading.
  const std::string huge = temporary_file();
  std::filesystem::resize_file(huge, std::uintmax_t{2} << 30);
  const Run big = run("import " + huge);
  std::remove(huge.c_str());
  CHECK(big.status == 1);
  CHECK(big.out.empty());
  CHECK_THAT(big.err, Contains("bytes; expected at most"));
  // A named pipe is refused without waiting for a writer.
  const std::string fifo = temporary_file();
  std::remove(fifo.c_str());
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  const Run pipe = run("import " + fifo);
  std::remove(fifo.c_str());
  CHECK(pipe.status == 1);
  CHECK_THAT(pipe.err, Contains("not a regular file"));
}

TEST_CASE("import: a track with too few swings' peaks for a smooth curve shows their range, not NaN",
          "[cli][import]") {
  // A Tracker track at 6.5 frames/s: a half swing of 0.9 s holds 5 or 6
  // samples (5.8 on average), a peak needs 6 strictly between its crossings
  // (swings.cpp, sparse_peak), and a swing's amplitude the peaks of its
  // neighbours too. Fewer than half the swings get one (the null start below
  // says so; the 7.6 frames/s this test had, 6 or 7 samples, now gives most
  // a peak): no smooth curve, hence no start or end of it. The table printed
  // "nan deg" for them.
  const std::string dir = pendulum::test::new_temporary_directory("pendulum-g-sparse-track");
  const std::string file = dir + "/sparse.txt";
  {
    std::ofstream o(file);
    const double l = 0.8, w = std::sqrt(9.81 / l), fps = 6.5;
    o << "mass A\nt\tx\ty\n";
    for (int k = 0; k < 60 * fps; ++k) {
      const double t = k / fps, theta = 0.2 * std::exp(-0.003 * t) * std::cos(w * t);
      o << t << '\t' << l * std::sin(theta) << '\t' << -l * std::cos(theta) << '\n';
    }
  }
  const Run r = run("import " + file);
  REQUIRE(r.status == 0);
  const json range = json::parse(r.out).at("amplitude_range");
  CHECK(range.at("start").is_null());
  CHECK(range.at("end").is_null());
  // The swings that have one lie within the release's 0.2 rad (11.46 deg)
  // and its decay by e^(-0.003 t) over 60 s (9.57 deg at the end).
  CHECK(range.at("min").get<double>() > 9.5);
  CHECK(range.at("max").get<double>() < 11.46);
  const Run table = run("import --format table " + file);
  REQUIRE(table.status == 0);
  CHECK_THAT(table.out, !Contains("nan"));
  CHECK_THAT(table.out, Contains("amplitude              none at the first crossing (too few swings have one); the "
                                 "swings' from "));
  std::filesystem::remove_all(dir);
}

TEST_CASE("reduce RECORDING --length reduces it as a scene naming it, without the length it says what to do",
          "[cli][import][scene]") {
  const std::string recording = std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_pendulum_raw.tsv";
  const std::string scene = temporary_file();
  std::ofstream(scene) << json{{"timing", {{"recording", recording}}},
                               {"length", {{"value", 0.8}, {"uncertainty", 0.0005}, {"unit", "m"}}}}
                              .dump();
  const Run named = run("reduce --allow-outside " + scene);
  std::remove(scene.c_str());
  REQUIRE(named.status == 0);
  const Run direct = run("reduce " + recording + " --length 0.8 --length-uncertainty 0.0005");
  INFO(direct.err);
  REQUIRE(direct.status == 0);
  const json a = json::parse(direct.out), b = json::parse(named.out);
  CHECK(a.at("g") == b.at("g"));
  CHECK(a.at("period") == b.at("period"));
  CHECK(a.at("recordings").at(0).at("recording") == "phyphox_pendulum_raw.tsv");
  // Without the length: what to do, not "not valid JSON".
  const Run bare = run("reduce " + recording);
  CHECK(bare.status == 1);
  CHECK(bare.out.empty());
  CHECK_THAT(bare.err, Contains("a recording, not a scene (JSON)") && Contains("--length L") &&
                           !Contains("not valid JSON"));
  // Options out of place are usage errors.
  CHECK(run("reduce " + recording + " --length -0.8").status == 2);
  CHECK(run("reduce " + recording + " --length-uncertainty 0.001").status == 2);
}

TEST_CASE("reduce RECORDING --length and --length-uncertainty check against the table of ranges", "[cli][import]") {
  // Was: inf a 309-digit bound, nan "length.value: got null" (exit 1), 0x1 read as 1 m, 1e300 the scene's refusal.
  const std::string recording = std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_pendulum_raw.tsv";
  const std::string length_range = "m; expected a laboratory pendulum, 1 mm to 1 km long";
  const std::string uncertainty_range = "m; expected a length's standard uncertainty from 0 to 1 km";
  for (const auto& [options, message] : std::vector<std::pair<std::string, std::string>>{
           {"--length inf", "--length: got inf " + length_range},
           {"--length nan", "--length: got NaN " + length_range},
           {"--length 1e300", "--length: got 1e+300 " + length_range},
           {"--length 0", "--length: got 0 " + length_range},
           {"--length 0x1", "--length: got \"0x1\"; expected a decimal number: a laboratory pendulum"},
           {"--length 0.8 --length-uncertainty inf", "--length-uncertainty: got inf " + uncertainty_range},
           {"--length 0.8 --length-uncertainty nan", "--length-uncertainty: got NaN " + uncertainty_range},
           {"--length 0.8 --length-uncertainty -1", "--length-uncertainty: got -1 " + uncertainty_range}}) {
    const Run r = run("reduce " + recording + " " + options);
    INFO(options << "\nstderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, StartsWith(message));
  }
}

TEST_CASE("A swing pumped up at the start: the JSON's glitch and the reduction's warning name the growth",
          "[cli][import]") {
  // The ramp of test_recordings.cpp's pumped swing (T = 1 s, 20 to 60 deg
  // over the first 8 s, steady to 40 s, 100 Hz; no noise: the growth alone
  // marks it), kept whole by "range": "all": the growth stays a glitch of
  // the record, and both outputs say what it is rather than "does not fit".
  const std::string recording = temporary_file() + ".csv";
  {
    std::ofstream f(recording);
    f << "t (s),theta (deg)\n";
    for (int k = 0; k < 4000; ++k) {
      const double t = k / 100.0;
      f << t << ',' << (20.0 + 40.0 * std::min(t / 8.0, 1.0)) * std::sin(2.0 * M_PI * t) << '\n';
    }
  }
  const Run whole = run("import --range all " + recording);
  INFO(whole.err);
  REQUIRE(whole.status == 0);
  const json glitches = json::parse(whole.out).at("glitches");
  REQUIRE(glitches.size() == 1);
  CHECK_THAT(glitches[0].at("cause").get<std::string>(), StartsWith("the swing grows"));
  const std::string scene = temporary_file();
  std::ofstream(scene) << json{{"timing", {{"recording", recording}, {"range", "all"}}},
                               {"length", {{"value", 0.2485}, {"uncertainty", 0.0005}, {"unit", "m"}}}}
                              .dump();
  const Run reduced = run("reduce --allow-outside " + scene);
  std::remove(scene.c_str());
  std::remove(recording.c_str());
  INFO(reduced.err);
  REQUIRE(reduced.status == 0);
  const json warnings = json::parse(reduced.out).at("warnings");
  CHECK(std::any_of(warnings.begin(), warnings.end(), [](const json& w) {
    const std::string text = w.get<std::string>();
    return text.find("s the swing grows: a hand or a drive pumping it") != std::string::npos &&
           text.find("does not fit the swing") == std::string::npos;
  }));
}

TEST_CASE("import --format scene: a whole scene that reduce refuses until its placeholders are filled in",
          "[cli][import][scene]") {
  // The scene sits beside the recording, as its notes ask; what the file
  // cannot tell (the length, its uncertainty, the bob) is a placeholder that
  // reduce names. Filled in, it reduces with the period `import` gives.
  namespace fs = std::filesystem;
  const fs::path dir = temporary_file() + "_scene";
  fs::create_directories(dir);
  fs::copy_file(std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_gyroscope.csv", dir / "gyro.csv");
  const Run imported = run("import --format scene " + (dir / "gyro.csv").string());
  INFO(imported.err);
  REQUIRE(imported.status == 0);
  json scene = json::parse(imported.out);
  CHECK(scene.at("timing") == json{{"recording", "gyro.csv"}});
  CHECK(scene.at("decay").at("data") == json{{"recording", "gyro.csv"}});
  CHECK_FALSE(scene.contains("amplitude"));  // the recording gives it
  const fs::path file = dir / "scene.json";
  std::ofstream(file) << scene.dump();
  const Run unfilled = run("reduce " + file.string());
  CHECK(unfilled.status == 1);
  CHECK(unfilled.out.empty());
  CHECK_THAT(unfilled.err, Contains("length.value: got \"fill in: pivot to the bob's centre\"; expected a number"));
  scene["length"]["value"] = 0.8, scene["length"]["uncertainty"] = 0.0005;
  scene.erase("bob");
  std::ofstream(file) << scene.dump();
  const Run filled = run("reduce " + file.string());
  const Run summary = run("import " + (dir / "gyro.csv").string());
  fs::remove_all(dir);
  INFO(filled.err);
  REQUIRE(filled.status == 0);
  REQUIRE(summary.status == 0);
  CHECK(json::parse(filled.out).at("period").at("measured").at("value") ==
        json::parse(summary.out).at("period").at("value"));
  // The options that changed the reading go into the scene's reference.
  const std::string track = std::string(PENDULUM_DATA_DIR) + "/recordings/tracker_headerless_xy.txt";
  const Run declared = run("import --format scene --columns t:s,x:m,y:m --range 1:20 --length-m 0.8 " + track);
  REQUIRE(declared.status == 0);
  const json d = json::parse(declared.out);
  CHECK(d.at("timing") == json{{"recording", "tracker_headerless_xy.txt"},
                               {"columns", "t:s,x:m,y:m"},
                               {"range", {{"from", 1.0}, {"to", 20.0}, {"unit", "s"}}}});
  CHECK(d.at("length").at("value") == 0.8);
  // An option a scene cannot say is bad usage, not a scene that reads otherwise.
  const Run stamps = run("import --format scene --stamps-per-period 1 " + std::string(PENDULUM_DATA_DIR) +
                         "/recordings/vernier_photogate.csv");
  CHECK(stamps.status == 2);
  CHECK(stamps.out.empty());
  CHECK_THAT(stamps.err, Contains("--stamps-per-period with --format scene: a scene cannot say it"));
}
