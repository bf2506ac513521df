// pendulum_g._core: the library's answers in Python's types (docs/python.md).
// The Python package (pendulum_g/__init__.py) wraps these: it turns a dict
// into JSON text and the JSON the library writes into dicts, so that every
// answer is the CLI's own, byte for byte before parsing.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "pendulum/amplitude.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/argument_ranges.hpp"
#include "pendulum/batch.hpp"
#include "pendulum/clock.hpp"
#include "pendulum/clock_scene.hpp"
#include "pendulum/files.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/interrupt.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/output_files.hpp"
#include "pendulum/recordings/swings.hpp"
#include "pendulum/recordings/table.hpp"
#include "pendulum/reduce_scene.hpp"
#include "pendulum/report/report_page.hpp"
#include "pendulum/json/scene_json.hpp"
#include "pendulum/site.hpp"

namespace py = pybind11;

namespace {

/// Whether Ctrl-C was pressed: Python's signal handler ran and raised
/// KeyboardInterrupt, now the error this thread reports.
bool python_signalled() {
  py::gil_scoped_acquire held;
  return PyErr_CheckSignals() != 0;
}

/// A long call: the GIL released for other threads, and Ctrl-C heard
/// (docs/python.md, "Ctrl-C"): the library's checks ask Python, as its
/// interpreter would between two statements, and the call stops with
/// KeyboardInterrupt instead of after the whole reduction.
struct LongCall {
  py::gil_scoped_release unlocked;
  pendulum::InterruptScope interruptible{&python_signalled};
};

using pendulum::AmplitudeMethod;

/// A scene's text and where its recordings are looked for: read from `path`
/// as `reduce PATH` reads it, or given as text as `reduce -` takes it.
struct SceneSource {
  std::string text;
  std::string input;  ///< the result's "input": the path, or "-"
  pendulum::SceneFiles files;
};

SceneSource scene_source(const std::optional<std::string>& path, const std::optional<std::string>& text,
                         const std::string& directory, bool allow_outside) {
  if (path) {
    return {pendulum::read_text(*path, pendulum::kSceneInput, "a scene file"), pendulum::printable_name(*path),
            {pendulum::scene_directory(*path), allow_outside}};
  }
  return {text.value_or(""), "-", {directory, allow_outside}};
}

AmplitudeMethod amplitude_method(const std::string& name) {
  for (auto m : {AmplitudeMethod::small_angle, AmplitudeMethod::series, AmplitudeMethod::agm,
                 AmplitudeMethod::automatic}) {
    if (name == pendulum::method_name(m)) return m;
  }
  if (name == "exact") return AmplitudeMethod::agm;
  throw py::value_error("method: got '" + name + "'; expected exact (or agm), series, small_angle or auto");
}

/// ValueError naming the argument, with the CLI's message for its option,
/// unless `value` lies in `range` (the table both check against).
void check(const pendulum::ArgumentRange& range, double value) {
  const std::string why = pendulum::out_of_range(range, value);
  if (!why.empty()) throw py::value_error(std::string(range.argument) + ": " + why);
}

/// The options of an analysis, checked as the CLI's --negligible-fraction,
/// --amplitude-method and --series-terms are.
pendulum::AnalysisOptions analysis_options(double negligible_fraction, const std::string& method, int series_terms) {
  check(pendulum::ranges::negligible_fraction, negligible_fraction);
  check(pendulum::ranges::series_terms, series_terms);
  pendulum::AnalysisOptions options;
  options.negligible_fraction = negligible_fraction;
  options.reduction.amplitude_method = amplitude_method(method);
  options.reduction.series_terms = series_terms;
  return options;
}

std::string reduce_json(const std::optional<std::string>& path, const std::optional<std::string>& text,
                        const std::string& directory, bool allow_outside, double negligible_fraction,
                        const std::string& method, int series_terms) {
  const pendulum::AnalysisOptions options = analysis_options(negligible_fraction, method, series_terms);
  const SceneSource source = scene_source(path, text, directory, allow_outside);
  const LongCall long_call;
  const pendulum::ParsedScene scene = pendulum::parse_scene(source.text, source.files);
  // An amplitude sweep without its length: T0 and the law, as the CLI's reduce prints them.
  if (!scene.length_measured) return pendulum::sweep_result_json(scene, *pendulum::amplitude_sweep_of(scene), source.input);
  const pendulum::Analysis analysis = pendulum::reduce_scene(scene, options);
  return pendulum::result_json(scene, analysis, options, source.input);
}

std::string fit_decay_json(const std::optional<std::string>& path, const std::optional<std::string>& text,
                           const std::string& directory, bool allow_outside, const std::optional<std::string>& model) {
  const SceneSource source = scene_source(path, text, directory, allow_outside);
  pendulum::DecayFitOptions fit_options;
  if (model) {
    for (auto m : {pendulum::DecayModel::both, pendulum::DecayModel::linear_only, pendulum::DecayModel::quadratic_only}) {
      if (*model == pendulum::decay_model_name(m)) fit_options.model = m;
    }
    if (!fit_options.model) {
      throw py::value_error("model: got '" + *model + "'; expected both, linear_only or quadratic_only");
    }
  }
  const LongCall long_call;
  const pendulum::ParsedScene scene = pendulum::parse_decay_document(source.text, source.files);
  if (!scene.decay_data) throw pendulum::InputError("decay.data", "missing; fit-decay needs a decay record");
  const pendulum::DecayFit fit = pendulum::fit_decay(*scene.decay_data, fit_options);
  std::vector<std::string> warnings = scene.warnings;
  for (auto& w : pendulum::review_decay_fit(fit)) warnings.push_back(std::move(w));
  return pendulum::decay_fit_json(source.input, scene, fit, warnings);
}

/// A numpy array of f(x) over `items`.
template <class Items, class F>
py::array_t<double> column(const Items& items, F f) {
  py::array_t<double> out(static_cast<py::ssize_t>(items.size()));
  double* at = out.mutable_data();
  for (const auto& item : items) *at++ = f(item);
  return out;
}

/// `pendulum-g import RECORDING`'s JSON ("json") and, as numpy arrays, what
/// it summarises: the crossing times, each swing, each full period.
py::dict read_recording(const std::string& path, const std::string& format, const std::string& set,
                        const std::string& columns, std::optional<double> bob_width, std::optional<double> length,
                        std::optional<std::pair<double, double>> range, bool whole_record,
                        std::optional<int> stamps_per_period) {
  const std::optional<pendulum::RecordingFormat> family = pendulum::recording_family({format});
  if (!family) throw py::value_error("format: got '" + format + "'; expected " + pendulum::recording_family_words());
  if (range && !(std::isfinite(range->first) && std::isfinite(range->second) && range->first < range->second)) {
    throw py::value_error("range: got " + std::string(py::repr(py::make_tuple(range->first, range->second))) +
                          "; expected (start, end) in seconds of the recording's clock, start before end");
  }
  if (bob_width) check(pendulum::ranges::bob_width, *bob_width);
  if (length) check(pendulum::ranges::length, *length);
  if (stamps_per_period) check(pendulum::ranges::stamps_per_period, *stamps_per_period);
  pendulum::SwingOptions options;
  options.bob_width = bob_width;
  options.length = length;
  options.range = range;
  options.whole_record = whole_record;
  options.stamps_per_period = stamps_per_period;
  pendulum::RecordingSummary r;
  std::string json;
  {
    const LongCall long_call;
    r = pendulum::analyse_recording(path, *family, options, {}, set, columns);
    json = pendulum::recording_json(r);
  }
  const pendulum::SwingAnalysis& a = r.swings;
  py::dict swings, periods;
  swings["start_s"] = column(a.swings, [](const auto& w) { return w.start; });
  swings["end_s"] = column(a.swings, [](const auto& w) { return w.end; });
  swings["peak_time_s"] = column(a.swings, [](const auto& w) { return w.peak_time; });
  swings["amplitude_deg"] = column(a.swings, [](const auto& w) { return w.amplitude * pendulum::kDegreesPerRadian; });
  periods["time_s"] = column(a.period_curve, [](const auto& p) { return p.time; });
  periods["amplitude_deg"] = column(a.period_curve, [](const auto& p) { return p.amplitude * pendulum::kDegreesPerRadian; });
  periods["period_s"] = column(a.period_curve, [](const auto& p) { return p.period; });
  py::dict out;
  out["json"] = json;
  out["crossings_s"] = column(a.crossings, [](const auto& c) { return c.time; });
  out["swings"] = swings;
  out["period_curve"] = periods;
  return out;
}

/// `pendulum-g import --table TABLE`'s scene (JSON text) and its warnings.
std::pair<std::string, std::vector<std::string>> read_table(const std::string& path, const std::string& columns,
                                                            std::optional<int> oscillations) {
  pendulum::TableOptions options;
  if (oscillations) {
    check(pendulum::ranges::oscillations, *oscillations);
    options.oscillations = *oscillations;
  }
  if (!columns.empty()) options.columns = pendulum::parse_table_column_spec(columns, "columns");
  const LongCall long_call;
  const pendulum::SettingsTable t = pendulum::read_settings_table(path, options);
  std::vector<std::string> warnings;
  for (const auto& w : t.warnings) warnings.push_back(w.text);
  return {pendulum::table_scene(t, pendulum::printable_name(path)), warnings};
}

/// `pendulum-g batch PATHS --format jsonl`'s scene lines (without the class
/// line), and the folder entries it skips with a note, as (path, why).
std::pair<std::vector<std::string>, std::vector<std::pair<std::string, std::string>>> batch_lines(
    const std::vector<std::string>& paths, bool allow_outside) {
  const LongCall long_call;
  std::vector<pendulum::BatchScene> scenes;
  std::vector<std::pair<std::string, std::string>> notes;
  for (const auto& p : paths) {
    std::error_code ec;
    if (!std::filesystem::is_directory(p, ec)) {
      scenes.push_back({p, std::nullopt});
      continue;
    }
    std::vector<pendulum::SkippedEntry> skipped;
    for (auto& f : pendulum::folder_scenes(p, skipped)) scenes.push_back({std::move(f), std::nullopt});
    for (const auto& s : skipped) notes.emplace_back(pendulum::printable_name(s.path), s.why);
  }
  const pendulum::AnalysisOptions options;
  std::vector<std::string> lines;
  for (const auto& scene : scenes) lines.push_back(pendulum::reduce_batch_scene(scene, options, pendulum::BatchFormat::jsonl, false, {std::nullopt, allow_outside}).line.text);
  return {lines, notes};
}

/// `pendulum-g report`'s page for a scene file or recording (path) or scene
/// text, written to `output` whole or not at all (returned when it is
/// empty), and the warnings the CLI prints.
std::pair<std::optional<std::string>, std::vector<std::string>> report(
    const std::optional<std::string>& path, const std::optional<std::string>& text, const std::string& directory,
    bool allow_outside, const std::string& output, const std::string& plot, const std::optional<std::string>& format,
    const std::string& set, const std::string& columns, double negligible_fraction, const std::string& method,
    int series_terms) {
  pendulum::report::ReportRequest request;
  request.file = path.value_or("-");
  request.text = text;
  if (text) request.directory = directory;
  request.allow_outside = allow_outside;
  request.plot = plot;
  if (format) {
    request.family = pendulum::recording_family({*format});
    if (!request.family) {
      throw py::value_error("format: got '" + *format + "'; expected " + pendulum::recording_family_words());
    }
  }
  request.set = set;
  request.columns = columns;
  request.analysis = analysis_options(negligible_fraction, method, series_terms);
  const LongCall long_call;
  if (!output.empty() && path) pendulum::refuse_output_over_inputs(output, {*path});
  pendulum::report::ReportPage page = pendulum::report::make_report_page(
      request, [&](const std::vector<std::string>& recordings) {
        if (!output.empty()) pendulum::refuse_output_over_inputs(output, recordings);
      });
  if (output.empty()) return {std::move(page.text), page.warnings};
  pendulum::write_output(output, page.text);
  return {std::nullopt, page.warnings};
}

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// What a function of `x` writes into: `out` where given (numpy's `out=`: a
/// writable C-contiguous float64 array of x's shape, x itself included), else
/// a new array. A reused array spares the page faults of fresh memory.
py::array_t<double> output_for(const Doubles& x, const py::object& out) {
  if (out.is_none()) return py::array_t<double>(std::vector<py::ssize_t>(x.shape(), x.shape() + x.ndim()));
  if (!py::array_t<double, py::array::c_style>::check_(out)) {
    throw py::type_error("out: expected a C-contiguous numpy array of float64");
  }
  auto a = py::reinterpret_borrow<py::array_t<double>>(out);
  if (!a.writeable()) throw py::value_error("out: the array is read-only");
  if (a.ndim() != x.ndim() || !std::equal(x.shape(), x.shape() + x.ndim(), a.shape())) {
    throw py::value_error("out: its shape is not theta0's");
  }
  return a;
}

/// `x` itself, or a copy of it where `out` overlaps it in part: numpy's out=
/// reads its input as it was, and an output one element ahead of its input
/// would otherwise read what it wrote (x itself as out is safe: each element
/// is read before it is written).
Doubles apart_from(const Doubles& x, const py::array_t<double>& out) {
  const double *a = x.data(), *b = out.data();
  const py::ssize_t n = x.size();
  const bool overlap = a != b && a < b + n && b < a + n;
  return overlap ? Doubles(std::vector<py::ssize_t>(x.shape(), x.shape() + x.ndim()), a) : x;
}

/// ValueError naming element `index` of an array argument, its value and
/// the range it is outside, as check() names a single argument.
py::value_error refused_element(const pendulum::ArgumentRange& range, std::size_t index, double value) {
  return py::value_error(std::string(range.argument) + "[" + std::to_string(index) + "]: " +
                         pendulum::out_of_range(range, value));
}

/// f applied to every element of `x` (any shape) in `range`, into `into` or a
/// new array of that shape; the GIL released over the loop. The first
/// element outside `range` raises refused_element.
template <class F>
py::array_t<double> map_elements(const Doubles& x, const pendulum::ArgumentRange& range, F f,
                                 const py::object& into = py::none()) {
  py::array_t<double> out = output_for(x, into);
  const Doubles source = apart_from(x, out);
  const double* in = source.data();
  double* result = out.mutable_data();
  const auto n = static_cast<std::size_t>(x.size());
  std::size_t i = 0;
  {
    py::gil_scoped_release unlocked;
    for (; i < n && pendulum::accepts(range, in[i]); ++i) result[i] = f(in[i]);
  }
  if (i < n) throw refused_element(range, i, in[i]);
  return out;
}

py::array_t<double> finite_amplitude(const Doubles& theta0, const std::string& method, int terms, bool excess,
                                     const py::object& into) {
  const AmplitudeMethod m = amplitude_method(method);
  if (m == AmplitudeMethod::automatic) throw py::value_error("method: auto needs a tolerance; use exact");
  check(pendulum::ranges::amplitude_terms, terms);
  const double one = excess ? 0.0 : 1.0;
  if (m == AmplitudeMethod::agm) {
    py::array_t<double> out = output_for(theta0, into);
    const Doubles source = apart_from(theta0, out);
    double* result = out.mutable_data();
    const auto n = static_cast<std::size_t>(theta0.size());
    std::size_t stop = 0;
    {
      py::gil_scoped_release unlocked;
      stop = pendulum::finite_amplitude_agm_many(source.data(), result, n);
      for (std::size_t i = 0; i < stop; ++i) result[i] += one;
    }
    if (stop < n) throw refused_element(pendulum::ranges::amplitude, stop, source.data()[stop]);
    return out;
  }
  // The series in sin(theta0/2) hold on the exact method's range.
  return map_elements(theta0, pendulum::ranges::amplitude, [m, terms, one](double t) {
    return one + pendulum::finite_amplitude(m, t, terms);
  }, into);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "pendulum-g's library: the compiled part of the pendulum_g package (docs/python.md)";
  // Ceres reports through glog, to the notebook's stderr; the module reports
  // through its exceptions, as the CLI through its messages (cli/main.cpp).
  FLAGS_minloglevel = google::GLOG_FATAL;

  // InputError(ValueError): what the CLI reports with exit status 1. Its
  // `path` is the JSON path (or file and line) the CLI's message starts with.
  // Allocated once and never freed: the type outlives the interpreter's
  // shutdown order.
  static auto* input_error = new py::exception<pendulum::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const pendulum::InputError& e) {
      py::object instance = py::reinterpret_borrow<py::object>(input_error->ptr())(e.what());
      instance.attr("path") = e.path();
      instance.attr("status") = 1;
      PyErr_SetObject(input_error->ptr(), instance.ptr());
    } catch (const pendulum::OutputError& e) {
      // The CLI's exit status 5: "output: cannot write NAME: reason".
      PyErr_SetString(PyExc_OSError, (std::string("output: ") + e.what()).c_str());
    } catch (const pendulum::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());  // the CLI's exit status 2
    } catch (const pendulum::Interrupted&) {
      // python_signalled() left KeyboardInterrupt (or what a handler raised) set.
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });

  m.def("reduce_json", &reduce_json, py::arg("path"), py::arg("text"), py::arg("directory"),
        py::arg("allow_outside"), py::arg("negligible_fraction"), py::arg("amplitude_method"),
        py::arg("series_terms"),
        "The result JSON of `pendulum-g reduce`, for a scene file (path) or scene text.");
  m.def("fit_decay_json", &fit_decay_json, py::arg("path"), py::arg("text"), py::arg("directory"),
        py::arg("allow_outside"), py::arg("model"), "The JSON of `pendulum-g fit-decay`.");

  m.def("read_recording", &read_recording, py::arg("path"), py::arg("format"), py::arg("set"), py::arg("columns"),
        py::arg("bob_width"), py::arg("length"), py::arg("range"), py::arg("whole_record"), py::arg("stamps_per_period"),
        "`pendulum-g import RECORDING`'s JSON and the crossings, swings and periods as arrays.");
  m.def("read_table", &read_table, py::arg("path"), py::arg("columns"), py::arg("oscillations"),
        "`pendulum-g import --table TABLE`'s scene and its warnings.");
  m.def("batch_lines", &batch_lines, py::arg("paths"), py::arg("allow_outside"),
        "`pendulum-g batch PATHS`'s JSON lines of the scenes, and the entries skipped.");
  m.def("report", &report, py::arg("path"), py::arg("text"), py::arg("directory"), py::arg("allow_outside"),
        py::arg("output"), py::arg("plot"), py::arg("format"), py::arg("set"), py::arg("columns"),
        py::arg("negligible_fraction"), py::arg("amplitude_method"), py::arg("series_terms"),
        "`pendulum-g report`'s page, written to output (or returned), and its warnings.");
  m.def("finite_amplitude", &finite_amplitude, py::arg("theta0"), py::arg("method") = "exact",
        py::arg("terms") = 4, py::arg("excess") = false, py::arg("out") = py::none(),
        "T/T0 at amplitude theta0 (rad, any array shape, 0 <= theta0 < pi): exact (the AGM, Nelson & Olsson "
        "Eq. 8 summed), series (Eq. 8 through `terms` terms) or small_angle (1 + theta0^2/16). "
        "excess=True gives T/T0 - 1 at full relative precision. out: a float64 array of theta0's shape to write "
        "into and return, as numpy's out= (theta0 itself may be it; on an error it holds the elements before "
        "the refused one).");
  m.def(
      "normal_gravity",
      [](const py::array_t<double>& latitude, const py::array_t<double>& height) {
        return py::vectorize([](double lat, double h) {
          check(pendulum::ranges::latitude, lat);
          check(pendulum::ranges::height, h);
          return pendulum::normal_gravity(lat, h);
        })(latitude, height);
      },
      py::arg("latitude"), py::arg("height") = 0.0,
      "Normal gravity |gamma| (m/s^2) of the WGS84 ellipsoid at geographic latitude (deg) and height (m) above "
      "it (GeographicLib::NormalGravity); arrays broadcast.");
  m.def(
      "circular_error",
      [](const py::array_t<double, py::array::c_style | py::array::forcecast>& theta0) {
        return map_elements(theta0, pendulum::ranges::amplitude, [](double t) { return pendulum::circular_error(t); });
      },
      py::arg("theta0"),
      "A clock's circular error (s/day) at semi-amplitude theta0 (rad, 0 <= theta0 < pi): 86400 (2K/pi - 1), "
      "Feinstein (2005) Eq. (E-2).");
  m.def(
      "impulse_error",
      [](const py::array_t<double>& theta0, const py::array_t<double>& location, const py::array_t<double>& q) {
        return py::vectorize([](double t0, double at, double quality) {
          // As a clock scene's semi_amplitude, impulse.location and Q are.
          check(pendulum::ranges::semi_amplitude, t0);
          check(pendulum::ranges::impulse_location(t0), at);
          check(pendulum::ranges::quality, quality);
          const std::string over_top = pendulum::impulse_over_top(t0, quality, pendulum::ClockPath::circular);
          if (!over_top.empty()) throw py::value_error("q: " + over_top);
          return pendulum::impulse_error_elliptic(t0, at, quality).error;
        })(theta0, location, q);
      },
      py::arg("theta0"), py::arg("location"), py::arg("q"),
      "A clock's impulse (escapement) error (s/day) for an impulse away from equilibrium at `location` (rad) in a "
      "swing of semi-amplitude theta0 (rad), quality factor Q, on a circular path, undamped: Feinstein (2005) "
      "Eqs. (D-1), (F-1) in closed form. Arrays broadcast.");
}
