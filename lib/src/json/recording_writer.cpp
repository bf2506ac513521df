// The document of `pendulum-g import RECORDING` (docs/recordings.md): the
// period, the amplitudes, and the `timing` and `decay` parts of a scene.
#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "pendulum/numeric.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/recordings/swings.hpp"

namespace pendulum {
namespace {

nlohmann::ordered_json summary_json(const RecordingSummary& r) {
  const SwingAnalysis& a = r.swings;
  const int n = a.period.periods;
  const std::string source = std::string("pendulum-g import: ") + recording_format_name(r.format) +
                             " recording " + r.file + (r.set.empty() ? "" : "/" + r.set);
  nlohmann::ordered_json out;
  out["format"] = recording_format_name(r.format);
  out["set"] = r.set.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.set);
  out["periods"] = n;
  out["period"] = {{"value", a.period.value}, {"uncertainty", a.period.uncertainty}, {"unit", "s"}};
  // Whose angle the amplitudes are: a phone's sensor turns with the bob it
  // is in (docs/phone.md); paste it with them as the scene's "of".
  const char* of = sensor_in_bob(r.kind) ? "body" : "pendulum";
  if (a.decay.amplitudes.empty()) {
    out["amplitude_range"] = nullptr;
  } else {
    // start: the scene's `amplitude`, at the first crossing, where the timing starts.
    const auto [lo, hi] = std::minmax_element(a.decay.amplitudes.begin(), a.decay.amplitudes.end());
    // In degrees by the product with kDegreesPerRadian, not degrees(): the
    // stored output was written so, and the JSON prints the last bit.
    // null where the recording cannot say (swings.hpp, start_amplitude_uncertainty).
    const nlohmann::ordered_json start_uncertainty =
        std::isfinite(a.start_amplitude_uncertainty) ? nlohmann::ordered_json(a.start_amplitude_uncertainty * kDegreesPerRadian)
                                                     : nlohmann::ordered_json(nullptr);
    out["amplitude_range"] = {{"start", a.start_amplitude * kDegreesPerRadian}, {"start_uncertainty", start_uncertainty},
                              {"end", a.end_amplitude * kDegreesPerRadian},     {"min", *lo * kDegreesPerRadian},
                              {"max", *hi * kDegreesPerRadian},                 {"unit", "deg"},
                              {"of", of}};
  }
  // One trial of all the periods: its uncertainty is used as is (docs/scene.md).
  out["timing"] = {{"oscillations_per_trial", n},
                   {"unit", "s"},
                   {"trials", {n * a.period.value}},
                   {"uncertainty", n * a.period.uncertainty},
                   {"source", source}};
  if (a.decay.times.size() < 3) {
    out["decay"] = nullptr;
  } else {
    std::vector<double> degrees(a.decay.amplitudes.size());
    std::transform(a.decay.amplitudes.begin(), a.decay.amplitudes.end(), degrees.begin(),
                   [](double x) { return x * kDegreesPerRadian; });
    out["decay"] = {{"data",
                     {{"time_unit", "s"},
                      {"times", a.decay.times},
                      {"amplitude_unit", "deg"},
                      {"amplitudes", degrees},
                      {"of", of},
                      {"source", source}}}};
  }
  nlohmann::ordered_json columns = nlohmann::ordered_json::array();
  for (const RecordingColumn& c : r.columns) {
    columns.push_back({{"column", c.index},
                       {"name", c.name},
                       {"role", c.role},
                       {"unit", c.unit.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(c.unit)},
                       {"decided_by", c.decided_by},
                       {"why", c.why}});
  }
  out["columns"] = columns;
  // Stretches that do not fit the swing (swings.hpp, step 7).
  out["glitches"] = nlohmann::ordered_json::array();
  for (const Glitch& g : a.glitches) {
    out["glitches"].push_back({{"from", g.start},
                               {"to", g.end},
                               {"unit", "s"},
                               {"worst_robust_sigmas", g.worst},
                               {"cause", g.cause ? nlohmann::ordered_json(g.cause) : nlohmann::ordered_json(nullptr)}});
  }
  // The stretch analysed (a typed range, or the clean stretch by default;
  // null: the whole record), what the clean stretch cut, and the whole
  // record's period beside it (swings.hpp, step 8).
  out["analysed_range"] = a.analysed ? nlohmann::ordered_json{{"from", a.analysed->first},
                                                              {"to", a.analysed->second},
                                                              {"unit", "s"},
                                                              {"by", a.cuts.empty() ? "range" : "clean stretch"}}
                                     : nlohmann::ordered_json(nullptr);
  out["cut"] = nlohmann::ordered_json::array();
  for (const Cut& c : a.cuts) {
    out["cut"].push_back({{"from", c.start},
                          {"to", c.end},
                          {"unit", "s"},
                          {"why", c.why},
                          {"worst_robust_sigmas", c.worst},
                          {"periods_carried", c.periods_carried > 0.0 ? nlohmann::ordered_json(c.periods_carried)
                                                                      : nlohmann::ordered_json(nullptr)},
                          {"alone", c.period_alone ? nlohmann::ordered_json{{"value", c.period_alone->value},
                                                                            {"uncertainty", c.period_alone->uncertainty},
                                                                            {"unit", "s"},
                                                                            {"of", c.small_amplitude ? "T0" : "T"},
                                                                            {"agrees_with_kept", c.agrees}}
                                                   : nlohmann::ordered_json(nullptr)}});
  }
  out["whole_record_period"] = a.whole_record_period ? nlohmann::ordered_json{{"value", a.whole_record_period->value},
                                                                              {"uncertainty", a.whole_record_period->uncertainty},
                                                                              {"unit", "s"}}
                                                     : nlohmann::ordered_json(nullptr);
  // What the reader decided and dropped, then what the analysis decided or
  // mended; each note with the line it names (null: none).
  out["notes"] = nlohmann::ordered_json::array();
  for (const auto* list : {&r.notes, &a.notes}) {
    for (const RecordingNote& note : *list) {
      out["notes"].push_back({{"line", note.line ? nlohmann::ordered_json(note.line) : nlohmann::ordered_json(nullptr)},
                              {"text", note.text}});
    }
  }
  return out;
}

}  // namespace

std::string recording_json(const RecordingSummary& r) {
  return summary_json(r).dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string recording_scene(const RecordingSummary& r, const RecordingReference& ref) {
  nlohmann::ordered_json reference{{"recording", ref.recording}};
  if (!ref.format.empty()) reference["format"] = ref.format;
  if (!ref.set.empty()) reference["set"] = ref.set;
  if (!ref.columns.empty()) reference["columns"] = ref.columns;
  const RecordingReference& o = ref;
  if (o.whole_record) reference["range"] = "all";
  if (o.range) reference["range"] = {{"from", o.range->first}, {"to", o.range->second}, {"unit", "s"}};
  if (o.bob_width) reference["bob_width"] = {{"value", *o.bob_width}, {"unit", "m"}};
  const bool amplitudes = !r.swings.decay.amplitudes.empty();
  constexpr const char* kFill = "fill in: ";
  nlohmann::ordered_json scene;
  scene["schema"] = "pendulum-g/scene/1";
  scene["title"] = ref.recording + (r.set.empty() ? "" : "/" + r.set);
  scene["notes"] = std::string("Written by pendulum-g import --format scene from ") + recording_format_name(r.format) +
                   " recording " + ref.recording + ". Save it beside the recording; replace each \"" + kFill +
                   "...\" with your measurement (reduce names the first left); delete bob for a bob small "
                   "against the length.";
  scene["timing"] = reference;
  // Three swings' amplitudes are a decay record (json/recording_reader.cpp).
  if (r.swings.decay.amplitudes.size() >= 3) scene["decay"] = {{"data", reference}};
  scene["length"] = {{"value", o.length ? nlohmann::ordered_json(*o.length)
                                        : nlohmann::ordered_json(std::string(kFill) + "pivot to the bob's centre")},
                     {"uncertainty", std::string(kFill) + "its standard uncertainty"},
                     {"unit", "m"},
                     {"measured_to", "center"}};
  if (!amplitudes) {
    scene["amplitude"] = {{"value", std::string(kFill) + "the release angle (the recording gives none)"},
                          {"unit", "deg"}};
  }
  scene["bob"] = {{"diameter", {{"value", std::string(kFill) + "the bob's diameter"}, {"unit", "mm"}}}};
  return scene.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace pendulum
