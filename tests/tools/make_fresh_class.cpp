// Writes the fresh class of issue 21 into a folder: 25 scene files, 12
// clean and 13 with one slip each, none of them a slip of the issue-14 class
// (tests/tools/make_class.cpp). Each student swings a 30.0 mm brass ball
// (120.2 g: 8500 kg/m^3) on a thin string in one laboratory (latitude 48 deg,
// 250 m above sea level) at a length of their own, 0.50 m + 0.04 m per
// place in the roll, and times five trials of ten oscillations with a phone.
// Drawn from the simple pendulum's model (every correction, the exact
// amplitude factor) at the site's WGS84 normal gravity, seeded (21), per
// student in the order length, amplitude, six trials (the sixth used by one
// slip only):
//   lengths taped to the ball's centre, true + N(0, 1 mm), rounded to 1 mm;
//   amplitudes 6 deg + N(0, 0.5 deg), written as 6 +- 1 deg;
//   trials 10 T + N(0, 0.05 s) (a hand's reaction time), rounded to 0.01 s.
// Then each student's slip, if any, is applied to what they wrote (the
// table below, and docs/instructors.md). The decay record (one student) is
// drawn from the air's drag theory (drag.hpp, Eqs. 26-27, 63-64) for this
// ball, read every minute for ten minutes to 0.01 deg.
//
// Usage: make_fresh_class FOLDER   (the folder must exist)
// tests/test_cli_class_report.cpp runs batch on it; docs/instructors.md shows the output.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "pendulum/damping.hpp"
#include "simulations/decay_simulation.hpp"
#include "pendulum/drag.hpp"
#include "pendulum/json/scene_json.hpp"
#include "simulations/series_simulation.hpp"
#include "pendulum/site.hpp"

namespace {

using json = nlohmann::ordered_json;

/// What a student wrote differently from what they measured: `apply` gets
/// the scene, the true period (s) and the student's six hand-timed trials.
struct Student {
  const char* file;
  const char* slip;  ///< "" for none
  std::function<void(json&, double period, const json& six)> apply;
};

double rounded(double x, double step) { return std::round(x / step) * step; }

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 || argv[1][0] == '-') {  // an option is no folder (--help once made one)
    std::cerr << "usage: make_fresh_class FOLDER\n";
    return 2;
  }
  const std::filesystem::path folder = argv[1];
  constexpr double kDeg = pendulum::kPi / 180.0;
  constexpr double kLatitude = 48.0, kHeight = 250.0;
  constexpr int kOscillations = 10, kTrials = 5;
  const double g = pendulum::normal_gravity(kLatitude, kHeight);

  const json lab = {
      {"bob",
       {{"diameter", {{"value", 30.0}, {"uncertainty", 0.1}, {"unit", "mm"}}},
        {"mass", {{"value", 120.2}, {"uncertainty", 0.1}, {"unit", "g"}}}}},
      {"air",
       {{"pressure", {{"value", 985}, {"unit", "hPa"}}}, {"temperature", {{"value", 22.8}, {"unit", "degC"}}}}},
      {"site",
       {{"latitude", {{"value", kLatitude}, {"unit", "deg"}}},
        {"height", {{"value", kHeight}, {"unit", "m"}}},
        {"height_reference", "sea_level"}}}};
  json one = lab;
  one["length"] = {{"value", 1.0}, {"unit", "m"}};
  one["amplitude"] = {{"value", 6.0}, {"unit", "deg"}};
  one["timing"] = {{"oscillations_per_trial", 10}, {"unit", "s"}, {"resolution", 0.01}, {"trials", {20.07}}};
  const pendulum::Apparatus<double> apparatus = pendulum::parse_scene(one.dump()).apparatus;

  auto none = [](json&, double, const json&) {};
  auto set_trials = [](json& s, json trials) { s["timing"]["trials"] = std::move(trials); };
  const Student roll[] = {
      {"abbott.json", "", none},
      {"bauer.json", "a stopwatch's lap mode: cumulative times",
       [&](json& s, double, const json& six) {
         json laps = json::array();
         double total = 0.0;
         for (int i = 0; i < kTrials; ++i) laps.push_back(rounded(total += six[i].get<double>(), 0.01));
         set_trials(s, laps);
       }},
      {"castro.json", "", none},
      {"dubois.json", "the same value pasted into every trial",
       [&](json& s, double, const json& six) { set_trials(s, json::array({six[0], six[0], six[0], six[0], six[0]})); }},
      {"eriksen.json", "", none},
      {"farah.json", "four of six trials pasted",
       [&](json& s, double, const json& six) { set_trials(s, json::array({six[0], six[1], six[1], six[1], six[1], six[5]})); }},
      {"gallo.json", "", none},
      {"haddad.json", "a frequency (1/period, Hz) typed where the trial times belong",
       [&](json& s, double, const json& six) {
         json f = json::array();
         for (int i = 0; i < kTrials; ++i) f.push_back(rounded(kOscillations / six[i].get<double>(), 0.001));
         s["timing"]["oscillations_per_trial"] = 1;
         set_trials(s, f);
       }},
      {"ivanova.json", "", none},
      {"jensen.json", "a length in inches typed as m",
       [](json& s, double, const json&) {
         s["length"] = {{"value", rounded(s["length"]["value"].get<double>() / 2.54, 0.01)}, {"uncertainty", 0.1},
                        {"unit", "m"}};
       }},
      {"kowalski.json", "", none},
      {"larsen.json", "a decay record in minutes labelled s", none},  // written below
      {"moreau.json", "", none},
      {"novak.json", "73 degF typed as degC", [](json& s, double, const json&) {
         s["air"]["temperature"] = {{"value", 73}, {"unit", "degC"}};
       }},
      {"ortiz.json", "", none},
      {"perez.json", "the length taped to the top of the ball, stated to 0.5 mm",
       [](json& s, double, const json&) {
         s["length"]["value"] = rounded(s["length"]["value"].get<double>() - 1.5, 0.05);
         s["length"]["uncertainty"] = 0.05;
       }},
      {"quist.json", "", none},
      {"romano.json", "a stopwatch started 0.8 s late in every trial",
       [&](json& s, double, const json& six) {
         json late = json::array();
         for (int i = 0; i < kTrials; ++i) late.push_back(rounded(six[i].get<double>() - 0.8, 0.01));
         set_trials(s, late);
       }},
      {"sato.json", "", none},
      {"tanaka.json", "a zero length uncertainty", [](json& s, double, const json&) { s["length"]["uncertainty"] = 0; }},
      {"ueda.json", "", none},
      {"vidal.json", "trials in min typed as s",
       [&](json& s, double, const json& six) {
         json minutes = json::array();
         for (int i = 0; i < kTrials; ++i) minutes.push_back(rounded(six[i].get<double>() / 60.0, 0.001));
         set_trials(s, minutes);
       }},
      {"weber.json", "the air's temperature in K typed as degC", [](json& s, double, const json&) {
         s["air"]["temperature"] = {{"value", 296.0}, {"unit", "degC"}};
       }},
      {"xu.json", "the ball's mass in g typed as kg",
       [](json& s, double, const json&) { s["bob"]["mass"]["unit"] = "kg"; }},
      {"yilmaz.json", "", none},
  };

  pendulum::NormalDeviates noise(21);
  int place = 0;
  for (const Student& student : roll) {
    const double length = 0.50 + 0.04 * place++;
    const double taped = rounded((length + 0.001 * noise.next()) * 100.0, 0.1);  // cm
    const double amplitude = (6.0 + 0.5 * noise.next()) * kDeg;
    const double p[2] = {g, 0.0};
    const pendulum::Observation<double> truth{0.0, length, amplitude, kOscillations};
    const double period =
        pendulum::model_period(p, truth, apparatus, pendulum::cheapest_amplitude_method(amplitude, 0.0));
    json six = json::array();
    for (int i = 0; i < 6; ++i) six.push_back(rounded(kOscillations * period + 0.05 * noise.next(), 0.01));
    const std::string name = std::string(student.file).substr(0, std::string(student.file).find('.'));
    json scene = {{"title", "Pendulum lab: " + name}};
    if (*student.slip) scene["notes"] = std::string("make_fresh_class: ") + student.slip;
    json trials(six.begin(), six.begin() + kTrials);
    scene["timing"] = {{"oscillations_per_trial", kOscillations}, {"unit", "s"}, {"resolution", 0.01}, {"trials", trials}};
    scene["length"] = {{"value", taped}, {"uncertainty", 0.2}, {"unit", "cm"}};
    scene["amplitude"] = {{"value", 6}, {"uncertainty", 1}, {"unit", "deg"}};
    scene.update(lab);
    if (name == "larsen") {
      // Read every minute for ten minutes from the amplitude timed; written as s.
      pendulum::Observation<double> o = truth;
      o.period = period;
      const auto drag = *pendulum::predict_drag(apparatus, o);
      json times = json::array(), amplitudes = json::array();
      for (int minute = 0; minute <= 10; ++minute) {
        times.push_back(minute);
        amplitudes.push_back(rounded(pendulum::decayed_amplitude(6.0 * kDeg, drag.alpha, drag.beta, 60.0 * minute) / kDeg, 0.01));
      }
      scene["decay"] = {{"data",
                         {{"time_unit", "s"}, {"amplitude_unit", "deg"}, {"sigma", 0.02}, {"times", times},
                          {"amplitudes", amplitudes}}}};
    }
    student.apply(scene, period, six);
    std::ofstream(folder / student.file, std::ios::binary) << scene.dump(2) << "\n";
  }
  return 0;
}
