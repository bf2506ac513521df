// The verdict on a result (status.hpp): the slips named from g's ratio to the
// expected g, and hand timing that draws no outlier warning (issue 14).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "pendulum/amplitude.hpp"
#include "pendulum/reduce_scene.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/json/scene_json.hpp"
#include "pendulum/status.hpp"

using namespace pendulum;
using Catch::Matchers::Contains;

namespace {

/// g = 4 pi^2 L / T^2 (Nelson & Olsson Eq. 5) for a length and a period.
double textbook_g(double length, double period) { return 4.0 * kPi * kPi * length / (period * period); }

}  // namespace

TEST_CASE("Each slip is named from the ratio it makes in g", "[status]") {
  // The ratios follow from g = 4 pi^2 L / T^2 with the slip applied to L or
  // T of a 1 m pendulum with a 2.006 s period.
  const double l = 1.0, t = 2.006, g = textbook_g(l, t);
  struct Case {
    double slipped_g;
    const char* named;
  };
  const Case cases[] = {
      {textbook_g(l, t / 2.0), "half swings are counted"},          // 20 half swings as oscillations
      {textbook_g(l, 2.0 * t), "half the oscillations timed"},      // 10 oscillations typed as 5
      {textbook_g(10.0 * l, t), "a length in mm is written as cm"},  // 1000 mm typed in cm
      {textbook_g(l / 10.0, t), "a length in cm is written as mm"},
      {textbook_g(100.0 * l, t), "a length in cm is written as m"},
      {textbook_g(l, t / 10.0), "one period per trial is typed with oscillations_per_trial 10"},
      {textbook_g(l / 100.0, t), "a length in m is written as cm"},
      {textbook_g(l, 10.0 * t), "trials of 10 oscillations are typed with oscillations_per_trial 1"},
      {textbook_g(1000.0 * l, t), "a length in mm is written as m"},
      {textbook_g(l / 1000.0, t), "a length in m is written as mm"},
      {textbook_g(l, t / 60.0), "trials in min are written as s"},
      {textbook_g(l, 60.0 * t), "trials in s are written as min"},
      {textbook_g(l, t / 1000.0), "trials in s are written as ms"},
      {textbook_g(l, 1000.0 * t), "trials in ms are written as s"},
      // A 1 m rod pivoted at its end swings as a simple pendulum of 2/3 m.
      {textbook_g(l, 2.0 * kPi * std::sqrt(2.0 / 3.0 * l / g)), "a uniform rod or beam pivoted at its end"},
  };
  for (const Case& c : cases) {
    INFO(c.named);
    const auto slip = name_slip(c.slipped_g / g);
    REQUIRE(slip);
    CHECK_THAT(*slip, Contains(c.named));
  }
  // No slip within 15% of a ratio of 1 (a few percent from hand timing), of
  // 2 or of 30, between the slips' ratios; nor at 0, infinity or NaN.
  for (double ratio : {1.0, 1.1, 0.9, 2.0, 0.5, 30.0, 1.0 / 30.0, 0.0, HUGE_VAL, std::nan("")}) {
    INFO(ratio);
    CHECK_FALSE(name_slip(ratio));
  }
  // The tolerance's edge: x1.15 either way.
  CHECK(name_slip(4.0 * 1.149));
  CHECK_FALSE(name_slip(4.0 * 1.151));
  CHECK(name_slip(4.0 / 1.149));
  CHECK_FALSE(name_slip(4.0 / 1.151));
}

TEST_CASE("Hand timing draws no outlier warning, a miscounted oscillation does", "[status][timing]") {
  // 300 seeded scenes of a 1 m pendulum at 5 deg and standard gravity, five
  // trials of 10 oscillations each timed by hand: 10 T + N(0, 0.05 s),
  // rounded to the phone's 0.01 s. T = 2 pi sqrt(L/g) (1 + the exact
  // finite-amplitude correction), the only correction of this scene.
  const double length = 1.0, theta0 = 5.0 * kPi / 180.0;
  const double period = 2.0 * kPi * std::sqrt(length / kStandardGravity) * (1.0 + finite_amplitude_agm(theta0));
  std::mt19937_64 random(14);
  std::normal_distribution<double> hand(0.0, 0.05);
  int clean_warnings = 0, clean_suspect = 0, miscounts_missed = 0;
  for (int scene = 0; scene < 300; ++scene) {
    nlohmann::json trials = nlohmann::json::array();
    for (int i = 0; i < 5; ++i) trials.push_back(std::round((10.0 * period + hand(random)) * 100.0) / 100.0);
    nlohmann::json doc = {
        {"length", {{"value", length}, {"unit", "m"}}},
        {"amplitude", {{"value", 5}, {"unit", "deg"}}},
        {"air", "vacuum"},  // else a warning about the air for a ball of unknown material
        {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"resolution", 0.01}, {"trials", trials}}}};
    const ParsedScene clean = parse_scene(doc.dump());
    const Analysis a = reduce_scene(clean);
    clean_warnings += !clean.warnings.empty() || !a.warnings.empty();
    clean_suspect += a.status != ResultStatus::ok;
    // One oscillation too many counted in the third trial: one period more.
    doc["timing"]["trials"][2] = trials[2].get<double>() + period;
    const ParsedScene miscounted = parse_scene(doc.dump());
    bool warned = false;
    for (const auto& w : miscounted.warnings) warned = warned || w.find("miscounted oscillation") != std::string::npos;
    miscounts_missed += !warned;
  }
  CHECK(clean_warnings == 0);
  CHECK(clean_suspect == 0);
  CHECK(miscounts_missed == 0);
}

TEST_CASE("A frequency typed is named only where it is far from the period it stands for", "[status][timing]") {
  // One oscillation a trial at 25.9 cm (T 1.02 s at standard gravity) read
  // 0.958 s, 6 % short: 1/1.044, and a class's table had it named a
  // frequency typed, its status suspect. Where N T^2 lies within 10 % of
  // 1 s^2 a frequency is no further off than a 10 % reading: only the plain
  // warning. At 1 m (T 2.006 s) 0.4985 s is 1/2.006, a frequency.
  auto named = [](double length, double trial) {
    nlohmann::json doc = {{"length", {{"value", length}, {"unit", "m"}}},
                          {"amplitude", {{"value", 5}, {"unit", "deg"}}},
                          {"air", "vacuum"},
                          {"timing", {{"oscillations_per_trial", 1}, {"unit", "s"}, {"resolution", 0.001}, {"trials", {trial}}}}};
    try {
      const ParsedScene s = parse_scene(doc.dump());
      for (const auto& w : s.suspicions) {
        if (w.find("a frequency (Hz) typed") != std::string::npos) return true;
      }
    } catch (const InputError& e) {
      return std::string(e.what()).find("a frequency (Hz) typed") != std::string::npos;
    }
    return false;
  };
  CHECK_FALSE(named(0.259, 0.958));
  CHECK(named(1.0, 0.4985));
}

TEST_CASE("Pasted trials: two thirds of six or more equal anywhere, rarely by chance", "[status][timing]") {
  auto pasted = [](const std::vector<double>& trials) {
    nlohmann::json doc = {
        {"length", {{"value", 1.0}, {"unit", "m"}}},
        {"amplitude", {{"value", 5}, {"unit", "deg"}}},
        {"air", "vacuum"},
        {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"resolution", 0.01}, {"trials", trials}}}};
    const ParsedScene s = parse_scene(doc.dump());
    for (const auto& w : s.suspicions) {
      if (w.find("pasted?") != std::string::npos) return true;
    }
    return false;
  };
  // Four of six anywhere (the issue-21 slip), in a run, all of four; three of six and four of five are not.
  CHECK(pasted({20.07, 20.11, 19.98, 20.11, 20.11, 20.11}));
  CHECK(pasted({20.11, 20.07, 20.11, 19.98, 20.11, 20.11}));
  CHECK(pasted({20.07, 20.11, 20.11, 20.11, 20.11, 19.98}));
  CHECK(pasted({20.11, 20.11, 20.11, 20.11}));
  CHECK(pasted({20.11, 20.02, 20.11, 20.11, 19.95, 20.11, 20.11}));  // 5 of 7
  CHECK_FALSE(pasted({20.11, 20.07, 20.11, 19.98, 20.11, 20.03}));
  CHECK_FALSE(pasted({20.11, 20.07, 20.11, 20.11, 20.11}));
  CHECK_FALSE(pasted({20.11, 20.02, 20.11, 20.11, 19.95, 20.11, 20.05}));  // 4 of 7, apart
  // Clean: six trials of 10 T + N(0, 0.05 s) rounded to 0.01 s. Some value
  // holds 4 or more of them with probability 0.00337 (mpmath, 30 digits:
  // the sum over the 0.01 s cells of the binomial tail, averaged over the
  // mean's place in its cell), 3.37 of 1000 scenes on average; 10 or more is
  // a Poisson(3.37) tail of 0.003. Three of six would be 63 (0.063).
  const double period = 2.0 * kPi * std::sqrt(1.0 / kStandardGravity) * (1.0 + finite_amplitude_agm(5.0 * kPi / 180.0));
  std::mt19937_64 random(21);
  std::normal_distribution<double> hand(0.0, 0.05);
  int flagged = 0;
  for (int scene = 0; scene < 1000; ++scene) {
    std::vector<double> trials;
    for (int i = 0; i < 6; ++i) trials.push_back(std::round((10.0 * period + hand(random)) * 100.0) / 100.0);
    flagged += pasted(trials);
  }
  CHECK(flagged <= 9);
}

namespace {

/// The scene reduced once to find its g, then with trials that give the
/// site's expected g, less `late` s each (a stopwatch started late) and its
/// length less `short_by` (m): the reasons of its verdict.
std::vector<std::string> reasons_with(nlohmann::json doc, double late, double short_by) {
  const Analysis first = reduce_scene(parse_scene(doc.dump()));
  REQUIRE(first.expected_g);
  // g T^2 is fixed for one geometry (Eq. 5 and a physical pendulum's alike).
  const double scale = std::sqrt(first.g.value / first.expected_g->value);
  for (auto& t : doc["timing"]["trials"]) t = std::round((t.get<double>() * scale - late) * 100.0) / 100.0;
  if (short_by > 0.0) doc["length"]["value"] = doc["length"]["value"].get<double>() - short_by * 100.0;  // cm
  return reduce_scene(parse_scene(doc.dump())).status_reasons;
}

bool names(const std::vector<std::string>& reasons, const std::string& words) {
  for (const auto& r : reasons) {
    if (r.find(words) != std::string::npos) return true;
  }
  return false;
}

const nlohmann::json kSite = {{"latitude", {{"value", 48.0}, {"unit", "deg"}}},
                              {"height", {{"value", 250.0}, {"unit", "m"}}},
                              {"height_reference", "sea_level"}};

}  // namespace

TEST_CASE("The top of the bob and a late start are named for a box, a cylinder and a physical pendulum", "[status]") {
  // A phone (docs/phone.md: a 7.5 x 16 x 0.8 cm box of 190 g) and a 2 x 6 cm
  // brass cylinder on a 60 cm string, five trials of 10 oscillations read
  // to 0.01 s; taped to the top of the bob, the length is short by half the
  // bob's height (80 and 30 mm).
  const nlohmann::json phone = {{"shape", "box"},
                                {"width", {{"value", 7.5}, {"unit", "cm"}}},
                                {"height", {{"value", 16}, {"uncertainty", 0.05}, {"unit", "cm"}}},
                                {"depth", {{"value", 0.8}, {"unit", "cm"}}},
                                {"mass", {{"value", 190}, {"unit", "g"}}}};
  const nlohmann::json cylinder = {{"shape", "cylinder"},
                                   {"diameter", {{"value", 2}, {"unit", "cm"}}},
                                   {"height", {{"value", 6}, {"uncertainty", 0.05}, {"unit", "cm"}}},
                                   {"mass", {{"value", 160}, {"unit", "g"}}}};
  for (const auto& [bob, half_height] : {std::pair{phone, "80"}, std::pair{cylinder, "30"}}) {
    INFO(bob.dump());
    const nlohmann::json doc = {
        {"bob", bob},
        {"length", {{"value", 60.0}, {"uncertainty", 0.1}, {"unit", "cm"}}},
        {"amplitude", {{"value", 5}, {"unit", "deg"}}},
        {"air", {{"pressure", {{"value", 985}, {"unit", "hPa"}}}, {"temperature", {{"value", 22}, {"unit", "degC"}}}}},
        {"site", kSite},
        {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"resolution", 0.01},
                    {"trials", {16.02, 16.05, 15.99, 16.03, 16.01}}}}};
    const auto top = reasons_with(doc, 0.0, std::stod(half_height) / 1000.0);
    CHECK(names(top, "the length taped to the top of the bob? Adding the bob's half height (" + std::string(half_height) +
                         " mm)"));
    CHECK(names(top, "length.measured_to \"top_of_bob\""));
    CHECK(names(reasons_with(doc, 0.8, 0.0), "a stopwatch started late or stopped early by about 0.8 s?"));
  }
  // A physical pendulum at one pivot (tests/valid_scenes.json's steel rod
  // with a brass weight, period 1.88 s), 0.8 s late in each of 20 oscillations.
  nlohmann::json rod = {
      {"pivot_position", {{"value", 0.05}, {"uncertainty", 0.0002}, {"unit", "m"}}},
      {"amplitude", {{"value", 3}, {"uncertainty", 0.5}, {"unit", "deg"}}},
      {"timing", {{"oscillations_per_trial", 20}, {"unit", "s"}, {"resolution", 0.01}, {"trials", {37.58, 37.6, 37.59}}}},
      {"body",
       {{"parts",
         {{{"shape", "cylinder"}, {"radius", {{"value", 6}, {"unit", "mm"}}}, {"length", {{"value", 1.2}, {"unit", "m"}}},
           {"axis", "body"}, {"density", {{"value", 7850}, {"unit", "kg/m^3"}}}, {"position", {{"value", 0.6}, {"unit", "m"}}}},
          {{"shape", "cylinder"}, {"radius", {{"value", 30}, {"unit", "mm"}}}, {"inner_radius", {{"value", 6}, {"unit", "mm"}}},
           {"length", {{"value", 40}, {"unit", "mm"}}}, {"axis", "body"}, {"density", {{"value", 8.5}, {"unit", "g/cm^3"}}},
           {"position", {{"value", 1.0}, {"unit", "m"}}}}}}}},
      {"air", "vacuum"},
      {"site", kSite}};
  const auto late = reasons_with(rod, 0.8, 0.0);
  CHECK(names(late, "a stopwatch started late or stopped early by about 0.8 s?"));
  CHECK_FALSE(names(reasons_with(rod, 0.0, 0.0), "stopwatch"));
}
