// libFuzzer target: the numbers the CLI's options and the Python module's
// arguments take, checked against one table (pendulum/argument_ranges.hpp).
// From the bytes: a range of ranges::all (a range added there is fuzzed here
// unchanged) and a value, either a double (NaN, infinities, subnormals, the
// largest, the range's ends and their neighbours, any bits) or an option's
// text read by decimal_number, which must take decimal text only and read it
// as strtod does. out_of_range() must be empty exactly where accepts() holds,
// else one printable line of at most 200 characters that spells a NaN "NaN"
// and never writes nan or inf for a bound. An accepted value goes to what the
// Python module calls behind its range (python/module.cpp): the answer must
// be finite, or an InputError of one printable line.
#include <fuzzer/FuzzedDataProvider.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <optional>
#include <string>

#include "fuzz_checks.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/argument_ranges.hpp"
#include "pendulum/clock.hpp"
#include "pendulum/clock_scene.hpp"
#include "pendulum/files.hpp"
#include "pendulum/json/scene_json.hpp"
#include "pendulum/recordings/swings.hpp"
#include "pendulum/recordings/table.hpp"
#include "pendulum/reduce_scene.hpp"
#include "pendulum/site.hpp"

namespace {

using namespace pendulum;
using fuzz::require;

constexpr double kInf = std::numeric_limits<double>::infinity();

double any_double(FuzzedDataProvider& in, const ArgumentRange& range) {
  const double sign = in.ConsumeBool() ? 1.0 : -1.0;
  switch (in.ConsumeIntegralInRange(0, 8)) {
    case 0: return sign * std::numeric_limits<double>::quiet_NaN();
    case 1: return sign * kInf;
    case 2: return sign * std::numeric_limits<double>::denorm_min() * in.ConsumeIntegralInRange(1, 1 << 20);
    case 3: return sign * std::numeric_limits<double>::max();
    case 4: return std::nextafter(range.low, sign * kInf);
    case 5: return std::nextafter(range.high, sign * kInf);
    case 6: {
      const auto bits = in.ConsumeIntegral<std::uint64_t>();
      double x;
      std::memcpy(&x, &bits, sizeof x);
      return x;
    }
    case 7: return in.ConsumeFloatingPointInRange(range.low, std::fmin(range.high, std::numeric_limits<double>::max()));
    default: return in.ConsumeFloatingPoint<double>();
  }
}

/// An option's text ("1e300", "0x10", " 5", "+inf"), read as the CLI reads
/// it; nullopt where the CLI refuses it as no decimal number.
std::optional<double> option_text(FuzzedDataProvider& in) {
  const std::string text = in.ConsumeRandomLengthString(40);
  const std::optional<double> value = decimal_number(text);
  if (!value) return std::nullopt;
  require(text.find_first_of("xX \t\n\r\f\v") == std::string::npos, "decimal_number took hexadecimal or spaces",
          text);
  char* end = nullptr;
  const double read = std::strtod(text.c_str(), &end);
  require(end == text.c_str() + text.size() && (read == *value || (std::isnan(read) && std::isnan(*value))) &&
              std::signbit(read) == std::signbit(*value),
          "decimal_number read otherwise than strtod", text);
  return value;
}

bool has_word(const std::string& text, const char* word) {
  std::string lower;
  for (const char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (std::size_t at = lower.find(word); at != std::string::npos; at = lower.find(word, at + 1)) {
    const std::size_t after = at + std::strlen(word);
    if ((at == 0 || !std::isalpha(static_cast<unsigned char>(lower[at - 1]))) &&
        (after == lower.size() || !std::isalpha(static_cast<unsigned char>(lower[after])))) {
      return true;
    }
  }
  return false;
}

/// What out_of_range says of `value`, against accepts(); true where accepted.
bool check_range(const ArgumentRange& range, double value) {
  const std::string why = out_of_range(range, value);
  const std::string detail = std::string(range.argument) + ": " + why;
  require(why.empty() == accepts(range, value), "out_of_range() and accepts() disagree", detail);
  if (why.empty()) return true;
  fuzz::require_clear_message(InputError(range.option, why));
  require(why.size() <= 200, "a range's message over 200 characters", detail);
  const std::string got = why.substr(0, why.find("; expected "));
  require(std::isnan(value) == (got.rfind("got NaN", 0) == 0), "a NaN not spelt NaN", detail);
  require(why.find("-nan") == std::string::npos && !has_word(why.substr(got.size()), "nan") &&
              !has_word(why.substr(got.size()), "inf"),
          "nan or inf written for a bound", detail);
  return false;
}

template <class F>
void finite_or_input_error(F f, const char* what) {
  try {
    const double x = f();
    require(std::isfinite(x), "not finite", what);
  } catch (const InputError& e) {
    fuzz::require_clear_message(e);
  }
}

const std::string kSource = PENDULUM_SOURCE_DIR;
const std::string kScene = read_text(kSource + "/data/nelson_olsson_1986.json", kSceneInput, "a scene file");

/// What the Python module (and the CLI) call behind `range`, with `x` in it
/// and the other arguments drawn from `in`, each checked against its range.
void call_behind(const ArgumentRange& range, double x, FuzzedDataProvider& in) {
  const auto other = [&](const ArgumentRange& r) -> std::optional<double> {
    const double y = any_double(in, r);
    return check_range(r, y) ? std::optional<double>(y) : std::nullopt;
  };
  const auto terms = [&](const ArgumentRange& r) { return static_cast<int>(in.ConsumeIntegralInRange<int>(r.low, r.high)); };
  if (&range == &ranges::amplitude) {
    const int n = terms(ranges::amplitude_terms);
    for (auto m : {AmplitudeMethod::small_angle, AmplitudeMethod::series, AmplitudeMethod::agm}) {
      finite_or_input_error([&] { return finite_amplitude(m, x, n); }, "finite_amplitude");
      finite_or_input_error([&] { return amplitude_error_bound(m, x, n); }, "amplitude_error_bound");
    }
    double many = 0.0;
    require(finite_amplitude_agm_many(&x, &many, 1) == 1 && many == finite_amplitude_agm(x),
            "finite_amplitude_agm_many is not finite_amplitude_agm", "");
    finite_or_input_error([&] { return circular_error(x); }, "circular_error");
  } else if (&range == &ranges::amplitude_deg) {
    // pendulum-g amplitude --theta0-deg: the exact method in degrees, the others in radians.
    const int n = terms(ranges::amplitude_terms);
    finite_or_input_error([&] { return finite_amplitude_agm_deg(x); }, "finite_amplitude_agm_deg");
    for (auto m : {AmplitudeMethod::small_angle, AmplitudeMethod::series}) {
      finite_or_input_error([&] { return finite_amplitude(m, radians(x), n); }, "finite_amplitude (deg)");
      finite_or_input_error([&] { return amplitude_error_bound(m, radians(x), n); }, "amplitude_error_bound (deg)");
    }
  } else if (&range == &ranges::latitude || &range == &ranges::height) {
    const std::optional<double> y = other(&range == &ranges::latitude ? ranges::height : ranges::latitude);
    if (!y) return;
    const double lat = &range == &ranges::latitude ? x : *y, h = &range == &ranges::latitude ? *y : x;
    finite_or_input_error([&] { return normal_gravity(lat, h); }, "normal_gravity");
  } else if (&range == &ranges::semi_amplitude || &range == &ranges::quality) {
    const std::optional<double> y = other(&range == &ranges::semi_amplitude ? ranges::quality : ranges::semi_amplitude);
    if (!y) return;
    const double t0 = &range == &ranges::semi_amplitude ? x : *y, q = &range == &ranges::semi_amplitude ? *y : x;
    const std::optional<double> at = other(ranges::impulse_location(t0));
    finite_or_input_error([&] { return circular_error(t0); }, "circular_error");
    finite_or_input_error([&] { return circular_error_rate(t0); }, "circular_error_rate");
    if (!at || !impulse_over_top(t0, q, ClockPath::circular).empty()) return;
    finite_or_input_error([&] { return impulsed_amplitude(t0, q); }, "impulsed_amplitude");
    finite_or_input_error([&] { return impulse_error_elliptic(t0, *at, q).error; }, "impulse_error_elliptic");
  } else if (&range == &ranges::negligible_fraction || &range == &ranges::series_terms) {
    // reduce(): Nelson and Olsson's scene with these options.
    AnalysisOptions options;
    options.reduction.amplitude_method = AmplitudeMethod::series;
    if (&range == &ranges::negligible_fraction) options.negligible_fraction = x;
    else options.reduction.series_terms = static_cast<int>(x);
    finite_or_input_error([&] { return reduce_scene(parse_scene(kScene), options).g.value; }, "reduce");
  } else if (&range == &ranges::length || &range == &ranges::bob_width || &range == &ranges::stamps_per_period) {
    // read_recording(): a photogate's passages and a timer's blocking times.
    SwingOptions options;
    if (&range == &ranges::length) options.length = x;
    if (&range == &ranges::bob_width) options.bob_width = x;
    if (&range == &ranges::stamps_per_period) options.stamps_per_period = static_cast<int>(x);
    for (const char* file : {"vernier_photogate.csv", "plain_blocking_times.txt"}) {
      finite_or_input_error(
          [&] { return analyse_recording(kSource + "/data/recordings/" + file, RecordingFormat::automatic, options).swings.period.value; },
          file);
    }
  } else if (&range == &ranges::oscillations) {
    // read_table(): a table whose times count no oscillations in their header.
    TableOptions options;
    options.oscillations = static_cast<int>(x);
    finite_or_input_error([&] {
      const SettingsTable t = read_settings_table(kSource + "/tests/tables/headerless_times_of_swings.txt", options);
      return reduce_scene(parse_scene(table_scene(t, "table"))).g.value;
    }, "read_table");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const ArgumentRange& range = *ranges::all[in.ConsumeIntegralInRange<std::size_t>(0, std::size(ranges::all) - 1)];
  const std::optional<double> value = in.ConsumeBool() ? option_text(in) : std::optional<double>(any_double(in, range));
  // A count (series_terms, stamps_per_period, oscillations) is an int, its fraction cut off.
  if (value && check_range(range, *value)) call_behind(range, *value, in);
  return 0;
}
