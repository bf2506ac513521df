// Writes a class of thirty scene files into a folder: the first hour of
// issue 14, an instructor's folder holding the slips real students make.
// Each student swings a 25.4 mm steel ball (66.9 g) on a string in the same
// laboratory (latitude 51 deg, 100 m above sea level), at a length of their
// own, 0.60 m + 0.03 m per place in the roll, and times five trials of ten
// oscillations with a phone. Drawn from the simple pendulum's model (every
// correction, the exact amplitude factor) at the site's WGS84 normal gravity,
// seeded (14), per student in the order length, amplitude, five trials:
//   lengths taped to the ball's centre, true + N(0, 1 mm), rounded to 1 mm;
//   amplitudes 5 deg + N(0, 0.5 deg), written as 5 +- 1 deg;
//   trials 10 T + N(0, 0.05 s) (a hand's reaction time), rounded to 0.01 s.
// Then each student's slip, if any, is applied to what they wrote (the
// table below, and docs/instructors.md); davis.json.txt and the folder
// drafts/ are there to be skipped with a note, CLARK.JSON to be read.
//
// Usage: make_class FOLDER   (the folder must exist)
// tests/test_cli_batch.cpp runs batch on it; docs/instructors.md shows the output.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "simulations/decay_simulation.hpp"
#include "pendulum/json/scene_json.hpp"
#include "simulations/series_simulation.hpp"
#include "pendulum/site.hpp"

namespace {

using json = nlohmann::ordered_json;

/// What a student wrote differently from what they measured.
struct Student {
  const char* file;
  const char* slip;  ///< "" for none
  std::function<void(json&, double period)> apply;
};

/// Text as Windows Notepad saves "Unicode": UTF-16LE with a byte order mark.
std::string utf16(const std::string& ascii) {
  std::string out = "\xff\xfe";
  for (char c : ascii) out += {c, '\0'};
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 || argv[1][0] == '-') {  // an option is no folder (--help once made one)
    std::cerr << "usage: make_class FOLDER\n";
    return 2;
  }
  const std::filesystem::path folder = argv[1];
  constexpr double kDeg = pendulum::kPi / 180.0;
  constexpr double kLatitude = 51.0, kHeight = 100.0;
  constexpr int kOscillations = 10, kTrials = 5;
  const double g = pendulum::normal_gravity(kLatitude, kHeight);

  const json lab = {
      {"bob",
       {{"diameter", {{"value", 25.4}, {"uncertainty", 0.1}, {"unit", "mm"}}},
        {"mass", {{"value", 66.9}, {"uncertainty", 0.1}, {"unit", "g"}}}}},
      {"air",
       {{"pressure", {{"value", 1013}, {"unit", "hPa"}}}, {"temperature", {{"value", 21}, {"unit", "degC"}}}}},
      {"site",
       {{"latitude", {{"value", kLatitude}, {"unit", "deg"}}},
        {"height", {{"value", kHeight}, {"unit", "m"}}},
        {"height_reference", "sea_level"}}}};
  // The apparatus as the reader sees it, with a placeholder observation.
  json one = lab;
  one["length"] = {{"value", 1.0}, {"unit", "m"}};
  one["amplitude"] = {{"value", 5.0}, {"unit", "deg"}};
  one["timing"] = {{"oscillations_per_trial", 10}, {"unit", "s"}, {"resolution", 0.01}, {"trials", {20.07}}};
  const pendulum::Apparatus<double> apparatus = pendulum::parse_scene(one.dump()).apparatus;

  auto none = [](json&, double) {};
  const Student roll[] = {
      {"adams.json", "", none},
      {"baker.json", "a length in cm written as m",
       [](json& s, double) { s["length"]["unit"] = "m"; }},
      {"brown.json", "", none},
      {"chen.json", "", none},
      {"CLARK.JSON", "", none},
      {"davis.json.txt", "", none},
      {"diaz.json", "", none},
      {"evans.json", "a trailing comma", none},  // written below
      {"fischer.json", "length misspelt lenght",
       [](json& s, double) {
         s["lenght"] = s["length"];
         s.erase("length");
       }},
      {"garcia.json", "saved by Notepad as \"Unicode\" (UTF-16)", none},  // written below
      {"hughes.json", "half swings counted as oscillations",
       [](json& s, double) { s["timing"]["oscillations_per_trial"] = 2 * kOscillations; }},
      {"ito.json", "", none},
      {"jones.json", "a length in mm written as cm",
       [](json& s, double) { s["length"]["value"] = s["length"]["value"].get<double>() * 10.0; }},
      {"kim.json", "", none},
      {"lee.json", "air pressure in hPa written as Pa", [](json& s, double) { s["air"]["pressure"]["unit"] = "Pa"; }},
      {"lopez.json", "", none},
      {"martin.json", "one period per trial typed under oscillations_per_trial 10",
       [](json& s, double) {
         for (auto& t : s["timing"]["trials"]) t = std::round(t.get<double>() * 10.0) / 100.0;
       }},
      {"miller.json", "", none},
      {"nguyen.json", "an amplitude of 5 deg written in radians as deg, no uncertainty",
       [](json& s, double) { s["amplitude"] = {{"value", 0.087}, {"unit", "deg"}}; }},
      {"okafor.json", "the bob's mass in kg labelled g",
       [](json& s, double) { s["bob"]["mass"] = {{"value", 0.0669}, {"uncertainty", 0.0001}, {"unit", "g"}}; }},
      {"patel.json", "", none},
      {"quinn.json", "oscillations_per_trial half the oscillations timed",
       [](json& s, double) { s["timing"]["oscillations_per_trial"] = kOscillations / 2; }},
      {"rossi.json", "", none},
      {"singh.json", "the length taped to the top of the ball, stated to 0.5 mm",
       [](json& s, double) {
         s["length"]["value"] = s["length"]["value"].get<double>() - 1.27;
         s["length"]["uncertainty"] = 0.05;
       }},
      {"taylor.json", "", none},
      {"usman.json", "one oscillation too many counted in one trial",
       [](json& s, double period) {
         auto& t = s["timing"]["trials"][3];
         t = std::round((t.get<double>() + period) * 100.0) / 100.0;
       }},
      {"vargas.json", "", none},
      {"wong.json", "", none},
      {"young.json", "", none},
      {"zhang.json", "", none},
  };

  pendulum::NormalDeviates noise(14);
  int place = 0;
  for (const Student& student : roll) {
    const double length = 0.60 + 0.03 * place++;
    const double taped = std::round((length + 0.001 * noise.next()) * 1000.0) / 10.0;  // cm
    const double amplitude = (5.0 + 0.5 * noise.next()) * kDeg;
    const double p[2] = {g, 0.0};
    const pendulum::Observation<double> truth{0.0, length, amplitude, kOscillations};
    const double period =
        pendulum::model_period(p, truth, apparatus, pendulum::cheapest_amplitude_method(amplitude, 0.0));
    json trials = json::array();
    for (int i = 0; i < kTrials; ++i) {
      trials.push_back(std::round((kOscillations * period + 0.05 * noise.next()) * 100.0) / 100.0);
    }
    const std::string name = std::string(student.file).substr(0, std::string(student.file).find('.'));
    json scene = {{"title", "Pendulum lab: " + name}};
    if (*student.slip) scene["notes"] = std::string("make_class: ") + student.slip;
    scene["timing"] = {{"oscillations_per_trial", kOscillations}, {"unit", "s"}, {"resolution", 0.01}, {"trials", trials}};
    scene["length"] = {{"value", taped}, {"uncertainty", 0.2}, {"unit", "cm"}};
    scene["amplitude"] = {{"value", 5}, {"uncertainty", 1}, {"unit", "deg"}};
    scene.update(lab);
    student.apply(scene, period);
    std::string text = scene.dump(2) + "\n";
    if (name == "evans") text.insert(text.rfind("\n}"), ",");
    if (name == "garcia") text = utf16(text);
    std::ofstream(folder / student.file, std::ios::binary) << text;
  }
  // A draft in a subfolder: batch reads one level and says so.
  std::filesystem::create_directories(folder / "drafts");
  std::ofstream(folder / "drafts" / "adams_old.json") << "{}\n";
  return 0;
}
