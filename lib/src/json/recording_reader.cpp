#include "recording_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "pendulum/numeric.hpp"

namespace pendulum::json_reader {

namespace {

RecordingFormat format_at(Object& o) {
  if (!o.has("format")) return RecordingFormat::automatic;
  const std::string name = o.text("format");
  if (const auto family = recording_family({name})) return *family;
  std::string names;
  for (const std::string& f : recording_family_names()) names += (names.empty() ? "\"" : ", \"") + f + "\"";
  throw InputError(o.path("format"), "got " + shown(o.at("format")) + "; expected a recording format: " + names);
}

/// Why the recording `name`, resolved to `file`, is not in `directory` or
/// below; null when it is. By its name first (absolute, ".."), then by where
/// its links lead: the deepest part that exists, resolved, must lie in the
/// directory's resolved path.
const char* leads_out(const std::string& directory, const std::string& name, const std::string& file) {
  namespace fs = std::filesystem;
  const fs::path given(name);
  if (given.is_absolute()) return "an absolute name leads out of it";
  const fs::path normal = given.lexically_normal();
  if (!normal.empty() && *normal.begin() == "..") return "\"..\" leads out of it";
  std::error_code ec;
  const fs::path root = fs::weakly_canonical(fs::absolute(directory, ec), ec);
  if (ec) return nullptr;  // no folder to leave: opening the file says what is wrong
  const fs::path target = fs::weakly_canonical(fs::absolute(file, ec), ec);
  if (ec) return nullptr;
  const fs::path inside = target.lexically_relative(root);
  if (inside.empty() || *inside.begin() == "..") return "a symbolic link leads out of it";
  return nullptr;
}

}  // namespace

std::string scene_file(const std::string& directory, const std::string& name) {
  return (std::filesystem::path(directory) / name).lexically_normal().string();
}

std::string RecordingReader::resolve(Object& o, const std::string& key, const char* what) const {
  const std::string name = o.text(key);
  PENDULUM_FAIL_IF(!files_.directory, o.path(key),
                   "got " + shown(o.at(key)) +
                       "; expected numbers: this scene was read as text, not from a file or standard input, "
                       "so no file it names is opened");
  const std::string file = scene_file(*files_.directory, name);
  if (!files_.allow_outside) {
    const char* why = leads_out(*files_.directory, name, file);
    PENDULUM_FAIL_IF(why, o.path(key),
                     "got " + shown(o.at(key)) + "; expected a file in the scene's folder or below (" +
                         (why ? why : "") + "): a scene's " + what + " are read from elsewhere only with --allow-outside");
  }
  return file;
}

std::size_t RecordingReader::read(Object& o, ParsedScene& out) {
  const std::string name = o.text("recording");
  const std::string at = o.path("recording");
  PENDULUM_FAIL_IF(name.empty() || name.find('\0') != std::string::npos, at,
                   "got " + shown(o.at("recording")) + "; expected the name of a recording file");
  const RecordingFormat format = format_at(o);
  const std::string set = o.has("set") ? o.text("set") : std::string();
  PENDULUM_FAIL_IF(o.has("set") && set.empty(), o.path("set"), "got \"\"; expected the name of a set: a CSV in a zip archive, a PASCO run, a Tracker track");
  const std::string columns = o.has("columns") ? o.text("columns") : std::string();
  PENDULUM_FAIL_IF(o.has("columns") && columns.empty(), o.path("columns"),
                   "got \"\"; expected each column's role and unit in file order (\"t:s,theta:deg\")");
  SwingOptions options;
  if (o.has("bob_width")) options.bob_width = quantity(o, "bob_width", Dimension::length, Range::positive).value;
  if (o.has("range") && o.at("range").is_string()) {
    // "all": the whole record, release, catch and glitches included.
    PENDULUM_FAIL_IF(o.text("range") != "all", o.path("range"),
                     "got " + shown(o.at("range")) + "; expected \"all\" (the whole record) or an object (the time "
                     "range to analyse: from, to, unit)");
    options.whole_record = true;
  } else if (o.has("range")) {
    // {"from": A, "to": B, "unit": "s"}: the file's own clock, as import --range A:B.
    Object range(o.at("range"), o.path("range"), "an object (the time range to analyse: from, to, unit), or \"all\"");
    const double factor = unit_at(range, "unit", Dimension::time).factor;
    const double from = finite_number(range.at("from"), [&] { return range.path("from"); }, "a time") * factor;
    const double to = finite_number(range.at("to"), [&] { return range.path("to"); }, "a time") * factor;
    range.finish();
    PENDULUM_FAIL_IF(!(from < to), o.path("range"),
                     "got from " + format_number(from) + " s to " + format_number(to) +
                         " s; expected the start of the range before its end");
    options.range = std::make_pair(from, to);
  }
  if (o.has("source")) o.text("source");
  o.finish();

  const std::string file = resolve(o, "recording", "recordings");
  const auto same = [&](const Done& d) {
    return d.file == file && d.format == recording_format_name(format) && d.set == set &&
           d.bob_width == options.bob_width && d.summary.column_spec == columns && d.range == options.range &&
           d.whole_record == options.whole_record;
  };
  auto it = std::find_if(done_.begin(), done_.end(), same);
  if (it == done_.end()) {
    const RecordingLimits limits{this->limits(kRecordingInput), within()};
    try {
      done_.push_back({file, recording_format_name(format), set, options.bob_width, options.range, options.whole_record,
                       analyse_recording(file, format, options, limits, set, columns)});
    } catch (const InputError& e) {
      throw InputError(at, e.what());  // "file: message" or "file:line:column: message"
    }
    it = done_.end() - 1;
  }
  out.recordings.push_back({o.path(), name, it->summary});
  return out.recordings.size() - 1;
}

void read_recorded_timing(Object& parent, const std::string& prefix, Observation<double>& value,
                          Observation<double>& sigma, ObservationSource& source, ParsedScene& out,
                          RecordingReader& recordings) {
  Object t(parent.at("timing"), prefix + "timing", "an object (the timing)");
  for (const char* key : {"oscillations_per_trial", "unit", "trials", "resolution", "uncertainty"}) {
    PENDULUM_FAIL_IF(t.has(key), t.path(key),
                     "got both recording and " + std::string(key) +
                         "; expected one of them: the recording gives the periods and their uncertainty");
  }
  RecordingReduction reduction;
  if (t.has("reduce")) {
    reduction.requested = t.text("reduce");
    PENDULUM_FAIL_IF(reduction.requested != "auto" && reduction.requested != "mean_period" &&
                         reduction.requested != "swing_by_swing",
                     t.path("reduce"),
                     "got " + shown(t.at("reduce")) + "; expected \"auto\" (swing by swing where the amplitude's "
                     "change matters against the period's uncertainty, the default), \"mean_period\" or "
                     "\"swing_by_swing\"");
  }
  const std::size_t k = recordings.read(t, out);
  out.recordings[k].reduction = reduction;
  const RecordingSummary& r = out.recordings[k].summary;
  const PeriodEstimate& p = r.swings.period;
  PENDULUM_FAIL_IF(p.periods < 1 || !(p.value > 0.0) || !std::isfinite(p.uncertainty), t.path("recording"),
                   r.file + ": " + std::to_string(p.periods) + " full periods; expected at least one, timed");
  source.trial_count = 1;
  source.recording = k;
  value.oscillations_per_trial = sigma.oscillations_per_trial = p.periods;
  value.period = p.value;
  sigma.period = p.uncertainty;
  out.assumptions.push_back(t.path() + ": from the recording " + r.file + " (" + recording_format_name(r.format) +
                            ", " + std::to_string(p.periods) + " full periods): one trial of all of them, the "
                            "period's uncertainty from the crossing times (docs/recordings.md)");
  if (const auto& range = r.swings.analysed; range && !r.swings.cuts.empty()) {
    std::string cut;
    for (const Cut& c : r.swings.cuts) {
      cut += (cut.empty() ? "" : "; ") + format_number(c.start, 6) + " to " + format_number(c.end, 6) + " s, " + c.why;
    }
    out.assumptions.push_back(t.path("recording") + ": " + r.file + ": the clean stretch " +
                              format_number(range->first, 6) + " to " + format_number(range->second, 6) +
                              " s is analysed (cut: " + cut + "); \"range\": \"all\" keeps the whole record");
  }
  for (const Glitch& g : r.swings.glitches) {
    out.warnings.push_back(t.path("recording") + ": " + r.file + ": from " + format_number(g.start, 6) + " s to " +
                           format_number(g.end, 6) + " s " +
                           (g.cause ? std::string(g.cause) + " (its half swings' peaks rise " + format_number(g.worst, 3) +
                                          " robust sigmas)"
                                    : "the recording does not fit the swing (" + format_number(g.worst, 3) +
                                          " robust sigmas)") +
                           ": its period's uncertainty allows for it; a \"range\" cuts it");
  }
}

DecayData read_recorded_decay(Object& decay, ParsedScene& out, RecordingReader& recordings) {
  Object d(decay.at("data"), "decay.data", "an object (the decay record)");
  for (const char* key : {"time_unit", "times", "amplitude_unit", "amplitudes", "sigma", "sigmas"}) {
    PENDULUM_FAIL_IF(d.has(key), d.path(key),
                     "got both recording and " + std::string(key) +
                         "; expected one of them: the recording gives the times and the amplitudes");
  }
  const std::size_t k = recordings.read(d, out);
  const RecordingSummary& r = out.recordings[k].summary;
  DecayData data = r.swings.decay;
  PENDULUM_FAIL_IF(data.times.size() < 3, d.path("recording"),
                   r.file + ": " + std::to_string(data.times.size()) + " swing amplitudes; expected at least 3 " +
                       "for a decay record (a photogate gives them with bob_width)");
  validate_decay_data(data, d.path("recording"));
  // A gyroscope or accelerometer follows the bob it is in (docs/phone.md).
  if (sensor_in_bob(r.kind)) data.angle_of = AngleOf::body;
  out.assumptions.push_back(d.path() + ": from the recording " + r.file + ", " + std::to_string(data.times.size()) +
                            " swing amplitudes, without sigmas (the fit scales by its residuals)");
  return data;
}

void reduce_swing_by_swing(ParsedScene& out) {
  if (out.sources.empty() || !out.sources[0].recording) return;
  SceneRecording& recording = out.recordings[*out.sources[0].recording];
  RecordingReduction& reduction = *recording.reduction;
  const SwingAnalysis& a = recording.summary.swings;
  reduction.decay_corrected = out.apparatus.decay.has_value() || out.decay_data.has_value();
  // The part of the change beyond theta0^2/16 decides, with or without a decay
  // record: every record that reduced as one mean period before issue 19's
  // item 6 still does (their shifts are below 0.1), and a scene without a decay
  // keeps its one mean period until that part matters.
  reduction.shift_sigmas = amplitude_shift_sigmas(a, true);
  const bool asked = reduction.requested == "swing_by_swing";
  PENDULUM_FAIL_IF(asked && out.series, out.sources[0].path + "timing.reduce",
                   "got \"swing_by_swing\" in a series; expected it in a scene of one observation, whose "
                   "recording becomes the series of its swings");
  const bool matters = reduction.shift_sigmas > kSwingBySwingShift;
  if (out.series || !(asked || (reduction.requested == "auto" && matters))) return;
  const std::string shift = format_number(reduction.shift_sigmas, 3) + " sigmas of the period (" +
                            "of the exact factor beyond theta0^2/16)";
  if (!out.sources[0].amplitude_from_recording) {
    PENDULUM_FAIL_IF(asked, "amplitude",
                     "got an amplitude beside timing.reduce \"swing_by_swing\"; expected none: each group of "
                     "swings is corrected at its own amplitude from the recording");
    out.warnings.push_back("timing.recording: " + recording.summary.file + ": its amplitude's change moves the "
                           "finite-amplitude correction by " + shift + ": one mean period at the scene's amplitude "
                           "is not its period there; leave amplitude out to reduce it swing by swing");
    return;
  }
  reduction.groups = swing_groups(a);
  PENDULUM_FAIL_IF(asked && reduction.groups.empty(), "timing.reduce",
                   "got \"swing_by_swing\" for " + recording.summary.file + " (" + std::to_string(a.period.periods) +
                       " periods" + (a.smooth_amplitudes.empty() ? ", no amplitudes" : "") +
                       "); expected a recording with amplitudes and at least two groups of " +
                       std::to_string(periods_per_group(a.period.periods)) + " periods");
  if (reduction.groups.empty()) return;
  reduction.swing_by_swing = true;
  const Observation<double> value = out.observations[0], sigma = out.observation_uncertainties[0];
  const ObservationSource source = out.sources[0];
  out.observations.clear();
  out.observation_uncertainties.clear();
  out.sources.clear();
  for (std::size_t j = 0; j < reduction.groups.size(); ++j) {
    const SwingGroup& g = reduction.groups[j];
    Observation<double> v = value, u = sigma;
    v.period = g.period;
    u.period = g.uncertainty;
    v.oscillations_per_trial = u.oscillations_per_trial = g.periods;
    v.amplitude = g.amplitude;
    // The smooth curve's error is common to the groups: one shared input, not an independent one of each.
    u.amplitude = g.amplitude_uncertainty;
    ObservationSource s = source;
    s.path = "swings[" + std::to_string(j) + "].";
    s.shared = {setting_key(v.setting), "amplitude"};
    s.amplitude_raw = degrees(g.amplitude);
    s.amplitude_unit = "deg";
    out.observations.push_back(v);
    out.observation_uncertainties.push_back(u);
    out.sources.push_back(s);
  }
  out.series = out.swing_by_swing = true;
  if (out.apparatus.decay) out.apparatus.decay->over_timing = out.apparatus_uncertainty.decay->over_timing = false;
  // What the one observation said of its timing and amplitude no longer holds.
  auto& said = out.assumptions;
  said.erase(std::remove_if(said.begin(), said.end(),
                            [](const std::string& s) {
                              return s.rfind("timing: from the recording", 0) == 0 || s.rfind("amplitude: ", 0) == 0;
                            }),
             said.end());
  const SwingGroup &first = reduction.groups.front(), &last = reduction.groups.back();
  said.push_back("timing: reduced swing by swing: the recording " + recording.summary.file + "'s amplitude falls from " +
                 format_number(degrees(a.start_amplitude), 4) + " to " +
                 format_number(degrees(a.end_amplitude), 4) + " deg, which moves the finite-amplitude correction by " +
                 shift + ", over " + format_number(kSwingBySwingShift, 2) + ": a series at one length of " +
                 std::to_string(reduction.groups.size()) + " groups of " + std::to_string(first.periods) +
                 " periods (swings[]), each timed by its own crossings and corrected at its own amplitude, " +
                 format_number(degrees(first.amplitude), 4) + " deg to " +
                 format_number(degrees(last.amplitude), 4) + " deg (docs/recordings.md)" +
                 (reduction.decay_corrected ? "; the decay correction (Eq. 50) is not applied over them" : ""));
}

}  // namespace pendulum::json_reader
