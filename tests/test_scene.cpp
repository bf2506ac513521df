// Reading scene files: units, derived values, and errors that name the path.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "pendulum/reduce_scene.hpp"
#include "pendulum/json/scene_json.hpp"
#include "reference.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("The Nelson-Olsson file reads as published", "[scene]") {
  const ParsedScene s = parse_scene(test::nelson_olsson_text());
  // Eq. (4): T = 3.47880 +- 0.00017 s from Table I.
  CHECK_THAT(s.observations[0].period, WithinRel(3.4788, 1e-13));
  CHECK_THAT(s.observation_uncertainties[0].period, WithinAbs(0.00017, 0.000005));
  CHECK(s.sources[0].trial_count == 10);
  CHECK(s.observations[0].oscillations_per_trial == 100);
  CHECK_THAT(s.observations[0].length, WithinRel(test::kLength, 1e-15));
  CHECK_THAT(s.observation_uncertainties[0].length, WithinRel(0.0003, 1e-12));
  CHECK_THAT(s.observations[0].amplitude, WithinRel(test::kAmplitude, 1e-15));
  CHECK_THAT(s.apparatus.bob->diameter, WithinRel(0.061, 1e-15));
  CHECK_THAT(*s.apparatus.bob->mass, WithinRel(test::kBobMass, 1e-15));
  REQUIRE(s.apparatus.air);
  CHECK_THAT(s.apparatus.air->temperature, WithinRel(298.65, 1e-15));
  CHECK_THAT(s.apparatus.air->pressure, WithinRel(100440.0, 1e-15));
  REQUIRE(s.apparatus.cap_screw);
  CHECK(s.apparatus.cap_screw->mass_deficit == Approx(0.0061));
  REQUIRE(s.apparatus.decay);
  CHECK(s.apparatus.decay->beta == Approx(test::kBeta));
  CHECK(s.warnings.empty());
  CHECK(s.assumptions.empty());
  // Each field's SI unit comes with it (fields.hpp): the budget's units.
  std::string beta_unit;
  zip_apparatus(s.apparatus, s.apparatus, [&](const Field& f, const double&, const double&) {
    if (std::string(f.path) == "decay.beta") beta_unit = f.unit;
  });
  CHECK(beta_unit == "1/(s rad)");
}

namespace {
// The Nelson-Olsson scene with an RFC 7386 merge patch applied.
std::string patched(const char* patch) {
  auto doc = nlohmann::json::parse(test::nelson_olsson_text());
  doc.merge_patch(nlohmann::json::parse(patch));
  return doc.dump();
}

void check_error(const std::string& text, const std::string& path, const std::string& message) {
  try {
    parse_scene(text);
    FAIL("no error; expected one at " << path);
  } catch (const InputError& e) {
    CHECK(e.path() == path);
    CHECK_THAT(std::string(e.what()), Contains(message));
  }
}
}  // namespace

TEST_CASE("Units convert to SI, offsets for temperatures only", "[scene][units]") {
  const ParsedScene s = parse_scene(patched(R"J({
    "length": {"value": 300.44, "unit": "cm", "uncertainty": 0.03},
    "amplitude": {"value": 0.05, "unit": "rad", "uncertainty": 0.005},
    "air": {"pressure": {"value": 753.4, "unit": "mmHg"},
            "temperature": {"value": 77.9, "unit": "degF", "uncertainty": 1.8},
            "molar_mass": null, "viscosity": null},
    "decay": {"beta": {"value": 5.5327e-5, "unit": "1/(s deg)"}}})J"));
  CHECK_THAT(s.observations[0].length, WithinRel(3.0044, 1e-15));
  CHECK_THAT(s.observation_uncertainties[0].length, WithinRel(0.0003, 1e-12));
  CHECK(s.observations[0].amplitude == 0.05);
  CHECK_THAT(s.apparatus.air->pressure, WithinRel(753.4 * 133.322387415, 1e-15));  // conventional mmHg
  CHECK_THAT(s.apparatus.air->temperature, WithinAbs(298.65, 1e-9));
  CHECK_THAT(s.apparatus_uncertainty.air->temperature, WithinRel(1.0, 1e-12));
  CHECK_THAT(s.apparatus.decay->beta, WithinRel(5.5327e-5 * 180.0 / M_PI, 1e-15));
  // Defaults are announced, never silent.
  CHECK(s.assumptions.size() == 2);
  CHECK_THAT(s.apparatus.air->molar_mass, WithinRel(0.02896, 1e-15));
}

TEST_CASE("Bad scenes fail at the right path", "[scene][errors]") {
  check_error("", "", "not valid JSON");
  check_error("[1, 2]", "", "expected a JSON object");
  check_error(patched(R"J({"length": {"value": -3.0}})J"), "length.value", "got -3 m; expected a positive length");
  check_error(patched(R"J({"length": {"unit": "furlong"}})J"), "length.unit", "expected a unit of a length: m, cm");
  check_error(patched(R"J({"bob": {"mass": {"unit": "cm"}}})J"), "bob.mass.unit", "got \"cm\"; expected a unit of a mass");
  check_error(patched(R"J({"bob": {"colour": "red"}})J"), "bob.colour", "unknown key");
  check_error(patched(R"J({"lenght": 3})J"), "lenght", "unknown key");
  check_error(patched(R"J({"amplitude": {"value": 180}})J"), "amplitude.value", "expected an amplitude below 180 deg");
  check_error(patched(R"J({"amplitude": {"value": 0}})J"), "amplitude.value", "expected a positive angle");
  check_error(patched(R"J({"timing": {"trials": []}})J"), "timing.trials", "expected a non-empty array");
  check_error(patched(R"J({"timing": {"trials": [347.8, "x"]}})J"), "timing.trials[1]", "expected a time");
  check_error(patched(R"J({"timing": {"trials": [347.8, -1]}})J"), "timing.trials[1]", "expected a positive time");
  check_error(patched(R"J({"timing": {"oscillations_per_trial": 2.5}})J"), "timing.oscillations_per_trial",
              "expected a positive whole number");
  check_error(patched(R"J({"ring": {"mass": null}})J"), "ring.mass", "missing");
  check_error(patched(R"J({"air": "thin"})J"), "air", "expected \"vacuum\"");
  check_error(patched(R"J({"length": {"value": "3.0044"}})J"), "length.value", "expected a number");
  check_error(patched(R"J({"bob": {"mass": {"uncertainty": -0.1}}})J"), "bob.mass.uncertainty",
              "expected a non-negative uncertainty");
  check_error(patched(R"J({"length": {"value": 0.02}})J"), "length.value", "expected more than the bob radius");
  check_error(patched(R"J({"cap": {"mass": {"value": 900}}})J"), "cap.mass.value", "lighter than the bob");
  check_error(patched(R"J({"air": {"temperature": {"value": -300}}})J"), "air.temperature.value",
              "expected a positive temperature");
  check_error(patched(R"J({"support": {"stiffness": null}})J"), "support", "expected at least one");
  check_error(patched(R"J({"schema": "pendulum-g/scene/9"})J"), "schema", "expected \"pendulum-g/scene/1\"");
}

TEST_CASE("A single trial needs a stated uncertainty or resolution", "[scene]") {
  const char* one = R"J({"timing": {"trials": [347.88], "resolution": null}})J";
  check_error(patched(one), "timing.trials", "got a single trial");
  const ParsedScene s = parse_scene(patched(R"J({"timing": {"trials": [347.88]}})J"));
  // Resolution 0.01 s, uniform: 0.01/sqrt(12) per trial, over 100 oscillations.
  CHECK_THAT(s.observation_uncertainties[0].period, WithinRel(0.01 / std::sqrt(12.0) / 100.0, 1e-12));
  CHECK(s.assumptions.size() == 1);
}

TEST_CASE("Nesting deep enough to overflow the stack is refused", "[scene][errors]") {
  // Found by hand before the nesting limit: 200000 nested arrays crashed
  // pendulum-g with SIGSEGV (the JSON library's dump recursed once a level).
  const std::string text = std::string(500000, '[') + std::string(500000, ']');
  check_error(text, "[0][0][0][0][0][0][0][0][0][0]", "got values nested more than 10 deep");
}

TEST_CASE("Error messages are one line of printable ASCII", "[scene][errors]") {
  // The input's raw bytes (an escape, DEL, invalid UTF-8) are shown escaped
  // and long values cut: the fuzzer found DEL and 1000-character messages.
  const std::string texts[] = {
      "{\"ti\\u001bming\": 1}", "{\"length\": \"\xff\"}", "\x7f",
      "{\"" + std::string(100000, 'k') + "\": 1}", "[\"" + std::string(100000, 'v') + "\"]"};
  for (const std::string& text : texts) {
    try {
      parse_scene(text);
      FAIL("no error");
    } catch (const InputError& e) {
      const std::string message = e.what();
      INFO(message);
      CHECK(message.size() < 400);
      CHECK(std::all_of(message.begin(), message.end(),
                        [](unsigned char c) { return c >= 0x20 && c < 0x7f; }));
    }
  }
}

TEST_CASE("Plausibility warnings start at their thresholds", "[scene][warnings]") {
  auto warnings = [](const char* patch) { return parse_scene(patched(patch)).warnings; };
  // The expected period scales as sqrt(length): 3.0044 m / 0.955^2 puts the
  // measured period 4.5% short of it, 3.0044 m / 0.945^2 5.5%; the warning
  // starts at 5%.
  CHECK(warnings(R"J({"length": {"value": 3.29418}})J").empty());
  REQUIRE(warnings(R"J({"length": {"value": 3.36429}})J").size() == 1);
  CHECK_THAT(warnings(R"J({"length": {"value": 3.36429}})J")[0], Contains("5.5% shorter"));
  // The small-angle lab ends at 20 deg.
  CHECK(warnings(R"J({"amplitude": {"value": 19.9}})J").empty());
  REQUIRE(warnings(R"J({"amplitude": {"value": 20.1}})J").size() == 1);
  CHECK_THAT(warnings(R"J({"amplitude": {"value": 20.1}})J")[0],
             Contains("20.1 deg is over the 20 deg of a small-angle lab"));
  // A trial is off when it lies over 5 x the largest of 1.4826 x MAD, the
  // resolution, and, on a timer read to 0.01 s by hand, a reaction time of
  // 0.1 s from the median. With the published trials but the last: median
  // 347.865 s, MAD 0.035 s (1.4826 MAD = 0.0519 s), so the limit is 0.5 s
  // by hand...
  const char* near = R"J({"timing": {"trials": [347.84, 347.87, 347.86, 347.91, 347.91, 347.94, 347.84, 347.81, 347.84, 348.36]}})J";
  const char* far = R"J({"timing": {"trials": [347.84, 347.87, 347.86, 347.91, 347.91, 347.94, 347.84, 347.81, 347.84, 348.37]}})J";
  CHECK(warnings(near).empty());
  REQUIRE(warnings(far).size() == 1);
  CHECK_THAT(warnings(far)[0], Contains("timing.trials[9]: 348.37 s is 0.505 s from the median trial 347.865 s"));
  CHECK_THAT(warnings(far)[0], Contains("a hand's reaction time (0.1 s)"));
  // ...and 0.2595 s on a gate read to 1 ms.
  const char* gate_near = R"J({"timing": {"resolution": 0.001, "trials": [347.84, 347.87, 347.86, 347.91, 347.91, 347.94, 347.84, 347.81, 347.84, 348.11]}})J";
  const char* gate_far = R"J({"timing": {"resolution": 0.001, "trials": [347.84, 347.87, 347.86, 347.91, 347.91, 347.94, 347.84, 347.81, 347.84, 348.13]}})J";
  CHECK(warnings(gate_near).empty());
  REQUIRE(warnings(gate_far).size() == 1);
  CHECK_THAT(warnings(gate_far)[0], Contains("timing.trials[9]: 348.13 s is 0.265 s from the median trial 347.865 s"));
  // The published trials scatter by 0.05333 s: a stated one-trial uncertainty
  // warns below a third of that.
  CHECK(warnings(R"J({"timing": {"uncertainty": 0.018}})J").empty());
  REQUIRE(warnings(R"J({"timing": {"uncertainty": 0.0177}})J").size() == 1);
}

TEST_CASE("A stated one-trial uncertainty is a floor, like the resolution", "[scene]") {
  // Published trials: standard deviation 0.05333 s; stated 0.1 s is larger,
  // so the period's uncertainty is 0.1 / sqrt(10) / 100.
  const ParsedScene s = parse_scene(patched(R"J({"timing": {"uncertainty": 0.1}})J"));
  CHECK_THAT(s.observation_uncertainties[0].period, WithinRel(0.1 / std::sqrt(10.0) / 100.0, 1e-12));
}

TEST_CASE("A UTF-16 scene (Notepad's \"Unicode\") reads as its UTF-8 text", "[scene][encoding]") {
  // A title with a degree sign (U+00B0, one UTF-16 unit) and an astral
  // character, U+1F30D (a globe: the surrogate pair D83C DF0D).
  std::string utf8 = test::nelson_olsson_text();
  const std::string title = "3\xc2\xb0 swing \xf0\x9f\x8c\x8d";
  utf8.replace(utf8.find("Nelson & Olsson (1986): Leybold"), 31, title);
  // UTF-16 code units of the text, each ASCII byte one unit.
  std::vector<unsigned> units;
  for (std::size_t i = 0; i < utf8.size();) {
    const auto c = static_cast<unsigned char>(utf8[i]);
    if (c < 0x80) {
      units.push_back(c), i += 1;
    } else if (c < 0xe0) {
      units.push_back((c & 0x1f) << 6 | (utf8[i + 1] & 0x3f)), i += 2;
    } else {  // the four-byte emoji: U+1F30D
      units.push_back(0xd83c), units.push_back(0xdf0d), i += 4;
    }
  }
  auto encode = [&](bool little) {
    std::string out = little ? "\xff\xfe" : "\xfe\xff";
    for (unsigned u : units) {
      const char lo = static_cast<char>(u & 0xff), hi = static_cast<char>(u >> 8);
      out += little ? std::string{lo, hi} : std::string{hi, lo};
    }
    return out;
  };
  const ParsedScene expected = parse_scene(utf8);
  for (bool little : {true, false}) {
    const ParsedScene s = parse_scene(encode(little));
    CHECK(s.title.rfind(title, 0) == 0);
    CHECK(s.title == expected.title);
    CHECK(s.observations[0].period == expected.observations[0].period);
  }
  // A lone surrogate, or an odd byte count, is refused with the fix.
  std::string broken = encode(true);
  broken[2] = '\x00', broken[3] = '\xdc';
  CHECK_THROWS_WITH(parse_scene(broken), Contains("UTF-16 text with a lone low surrogate at byte 2") &&
                                             Contains("save it as UTF-8"));
  CHECK_THROWS_WITH(parse_scene(encode(true) + "x"), Contains("an odd number of bytes"));
}

TEST_CASE("A length measured to the top or bottom of the bob is referred to its centre", "[scene]") {
  // N&O's bob: 6.10 +- 0.01 cm, so the radius is 3.05 cm +- 0.005 cm.
  const ParsedScene centre = parse_scene(test::nelson_olsson_text());
  const ParsedScene top = parse_scene(patched(R"J({"length": {"value": 2.9739, "measured_to": "top_of_bob"}})J"));
  const ParsedScene bottom = parse_scene(patched(R"J({"length": {"value": 3.0349, "measured_to": "bottom_of_bob"}})J"));
  CHECK_THAT(top.observations[0].length, WithinAbs(3.0044, 1e-15));
  CHECK_THAT(bottom.observations[0].length, WithinAbs(3.0044, 1e-15));
  // The radius's 0.005 cm is the bob's, not the length's: the length keeps
  // its own 0.03 cm and the analysis moves it with bob.diameter.
  CHECK(top.observation_uncertainties[0].length == 0.0003);
  CHECK(bottom.observation_uncertainties[0].length == 0.0003);
  CHECK(top.sources[0].knot_to_center_sign == 1.0);
  CHECK(bottom.sources[0].knot_to_center_sign == -1.0);
  CHECK(centre.sources[0].knot_to_center_sign == 0.0);

  // dg/d(bob.diameter) as the budget gives it, against central differences
  // of the whole reduction in the diameter the file gives (step 1e-4 cm).
  // Through the length it is +-(1/2) dg/dl, close to (1/2) g/l; the rest,
  // the bob's own corrections, is the same for the top, the bottom and the
  // centre (half the sum; half the difference is the length's share).
  const auto diameter_sensitivity = [](const ParsedScene& s) {
    for (const auto& b : reduce_scene(s).budget)
      if (b.input == "bob.diameter") return b.sensitivity;
    FAIL("no bob.diameter in the budget");
    return 0.0;
  };
  const auto finite_difference = [](const std::string& to, double length) {
    const auto g_at = [&](double diameter_cm) {
      const std::string patch = R"J({"length": {"value": )J" + std::to_string(length) + R"J(, "measured_to": ")J" + to +
                                R"J("}, "bob": {"diameter": {"value": )J" + std::to_string(diameter_cm) + "}}}";
      return reduce_scene(parse_scene(patched(patch.c_str()))).g.value;
    };
    const double h = 1e-4;  // cm
    return (g_at(6.10 + h) - g_at(6.10 - h)) / (2 * h * 0.01);
  };
  const double at_top = diameter_sensitivity(top), at_bottom = diameter_sensitivity(bottom);
  CHECK_THAT(at_top, WithinRel(finite_difference("top_of_bob", 2.9739), 1e-5));
  CHECK_THAT(at_bottom, WithinRel(finite_difference("bottom_of_bob", 3.0349), 1e-5));
  CHECK_THAT((at_top + at_bottom) / 2.0, WithinRel(diameter_sensitivity(centre), 1e-3));
  CHECK_THAT((at_top - at_bottom) / 2.0, WithinRel(reduce_scene(centre).g.value / 3.0044 / 2.0, 1e-3));
}

TEST_CASE("A scene naming a recording: read only where the caller says the scene's folder is", "[scene][recordings]") {
  const std::string text = R"({"timing": {"recording": "phyphox_gyroscope.csv"},
                               "length": {"value": 0.8, "unit": "m"}})";
  // Text alone (the fuzzer, a library call): no file is opened.
  try {
    parse_scene(text);
    FAIL("a recording read without a folder");
  } catch (const InputError& e) {
    CHECK(e.path() == "timing.recording");
    CHECK_THAT(e.what(), Contains("this scene was read as text"));
  }
  // With the folder: the recording's period, its periods as one trial, and
  // its amplitude at the start of the timing, exactly as analyse_recording gives them.
  const std::string folder = std::string(PENDULUM_DATA_DIR) + "/recordings";
  const ParsedScene s = parse_scene(text, {folder});
  const RecordingSummary r = analyse_recording(folder + "/phyphox_gyroscope.csv");
  REQUIRE(s.recordings.size() == 1);
  CHECK(s.recordings[0].path == "timing");
  CHECK(s.sources[0].recording == std::size_t{0});
  CHECK(s.sources[0].trial_count == 1);
  CHECK(s.observations[0].period == r.swings.period.value);
  CHECK(s.observation_uncertainties[0].period == r.swings.period.uncertainty);
  CHECK(s.observations[0].oscillations_per_trial == r.swings.period.periods);
  CHECK(s.observations[0].amplitude == r.swings.start_amplitude);
  CHECK_FALSE(s.decay_data);

  CHECK(scene_directory("-") == ".");
  CHECK(scene_directory("scene.json") == ".");
  CHECK(scene_directory("class/a.json") == "class");
  CHECK(scene_directory("/data/a.json") == "/data");
}
