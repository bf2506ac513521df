// The output of `pendulum-g clock` (docs/clock.md): JSON and a table.
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "pendulum/json/output.hpp"
#include "pendulum/printable.hpp"
#include "writer.hpp"

namespace pendulum {
namespace {

using json = nlohmann::ordered_json;

constexpr double kArcminute = kPi / 10800.0;  // rad

/// {"value": x, "unit": u}, with "uncertainty" when there is one; null
/// replaces a value that is not finite (a rate at the end of the swing).
json quantity(double value, const char* unit, std::optional<double> sigma = std::nullopt) {
  json j;
  j["value"] = std::isfinite(value) ? json(value) : json(nullptr);
  if (sigma) j["uncertainty"] = *sigma;
  j["unit"] = unit;
  return j;
}

const char* route_description(ClockRoute r) {
  switch (r) {
    case ClockRoute::cycloid: return "undamped cycloidal pendulum, closed form (Feinstein App. H)";
    case ClockRoute::circular_elliptic: return "undamped circular pendulum, elliptic integrals (Eqs. D-1, D-2)";
    case ClockRoute::cycloid_damped: return "linearly damped cycloidal pendulum, closed form (App. I)";
    case ClockRoute::circular_rk4: return "linearly damped circular pendulum, RK4 (App. G)";
  }
  return "";
}

json clock_document(const ClockScene& s, const ClockAnalysis& a, const std::string& input) {
  const double per_arcsec = kRadPerArcsecond;
  json route = {{"name", route_name(a.choice.route)},
                                  {"description", route_description(a.choice.route)}};
  if (a.choice.rk4_steps) route["rk4_steps_per_period"] = a.choice.rk4_steps;
  route["accuracy_asked_s_day"] = s.accuracy;
  route["error_bound_s_day"] = a.choice.error_bound;
  route["rate_error_bound_s_day_per_arcsec"] =
      std::isfinite(a.choice.rate_bound) ? json(a.choice.rate_bound * per_arcsec)
                                         : json(nullptr);
  json cancel;
  if (a.cancelling_semi_amplitude) {
    cancel = quantity(*a.cancelling_semi_amplitude / kArcminute, "arcmin");
  } else {
    cancel["value"] = nullptr;
  }
  cancel["note"] = a.cancelling_note;
  cancel["equation"] = "Feinstein (2005) Sec. IX";
  json rate = quantity(a.impulse_error_rate * per_arcsec, "s/day/arcsec");
  rate["equation"] = "Feinstein (2005) Eq. (D-2)";
  if (!std::isfinite(a.impulse_error_rate)) rate["note"] = "unbounded: the impulse is at the end of the swing";
  return {
      {"schema", "pendulum-g/clock/1"},
      {"input", input},
      {"title", s.title},
      {"path", s.path == ClockPath::circular ? "circular" : "cycloidal"},
      {"damped", s.damped},
      {"route", route},
      {"length", quantity(s.length.value, "m", s.length.sigma)},
      {"g", quantity(s.g.value, "m/s^2", s.g.sigma)},
      {"semi_amplitude", quantity(s.semi_amplitude.value / kArcminute, "arcmin", s.semi_amplitude.sigma / kArcminute)},
      {"Q", s.q.value},
      {"impulse",
       {{"location", quantity(a.location / kArcminute, "arcmin")},
        {"relative_location", a.location / s.semi_amplitude.value},
        {"direction", s.direction == ImpulseDirection::away ? "away" : "toward"},
        {"impulsed_semi_amplitude", quantity(a.impulsed_amplitude / kArcminute, "arcmin")}}},
      {"period",
       {{"small_amplitude", quantity(a.small_amplitude_period, "s")},
        {"free", quantity(a.free_period, "s", a.period_sigma)},
        {"impulsed", quantity(a.impulsed_period, "s", a.period_sigma)}}},
      {"circular_error", [&] {
         auto j = quantity(a.circular_error.value, "s/day", a.circular_error.sigma);
         j["equation"] = "Feinstein (2005) Eq. (E-2)";
         return j;
       }()},
      {"circular_error_rate", [&] {
         auto j = quantity(a.circular_error_rate * per_arcsec, "s/day/arcsec");
         j["equation"] = "Feinstein (2005) Eq. (E-4)";
         return j;
       }()},
      {"impulse_error", [&] {
         auto j = quantity(a.impulse_error, "s/day", a.impulse_error_sigma);
         if (!a.impulse_error_sigma) {
           j["uncertainty"] = nullptr;
           j["note"] = "uncertainty unbounded: the error's derivative is infinite at the end of the swing";
         }
         j["equation"] = "Feinstein (2005) Eq. (D-1)";
         return j;
       }()},
      {"impulse_error_rate", rate},
      {"impulse_error_amplitude_rate", [&] {
         auto j = quantity(a.impulse_error_amplitude_rate * per_arcsec, "s/day/arcsec");
         j["meaning"] = "change with the semi-amplitude at a fixed impulse location and Q (not Feinstein's rate)";
         return j;
       }()},
      {"daily_loss", [&] {
         auto j = quantity(a.circular_error.value + a.impulse_error, "s/day");
         j["meaning"] = "circular plus impulse error: seconds a day the clock loses against its small-amplitude free swing";
         return j;
       }()},
      {"cancelling_semi_amplitude", cancel},
      {"amplitude_insensitive_semi_amplitude", [&] {
         json j;
         if (a.insensitive_semi_amplitude) {
           j = quantity(*a.insensitive_semi_amplitude / kArcminute, "arcmin");
         } else {
           j["value"] = nullptr;
         }
         j["meaning"] = "circular plus impulse error does not change with the amplitude there, the impulse "
                        "at a fixed location and Q (not in Feinstein; docs/clock.md)";
         return j;
       }()},
  };
}

std::string format(const char* spec, double x) {
  if (!std::isfinite(x)) return "unbounded";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, spec, x);
  return buffer;
}

}  // namespace

std::string clock_table(const ClockScene& s, const ClockAnalysis& a) {
  std::ostringstream out;
  auto row = [&](const char* name, const std::string& value, const char* unit) {
    char line[160];
    std::snprintf(line, sizeof line, "%-34s %18s  %s\n", name, value.c_str(), unit);
    out << line;
  };
  if (!s.title.empty()) out << one_line(s.title, kShownTitleBytes, true) << "\n";
  out << "route: " << route_name(a.choice.route) << " (" << route_description(a.choice.route) << ")";
  if (a.choice.rk4_steps) out << ", " << a.choice.rk4_steps << " steps a period";
  out << "\n";
  row("semi-amplitude", format("%.4f", s.semi_amplitude.value / kArcminute), "arcmin");
  row("impulse location", format("%.4f", a.location / kArcminute), "arcmin");
  row("impulse direction", s.direction == ImpulseDirection::away ? "away" : "toward", "");
  row("Q", format("%.6g", s.q.value), "");
  row("period, small amplitude", format("%.9f", a.small_amplitude_period), "s");
  row("period, free swing", format("%.9f", a.free_period), "s");
  row("period, impulsed", format("%.9f", a.impulsed_period), "s");
  row("circular error (E-2)", format("%.6g", a.circular_error.value), "s/day");
  row("  rate of change (E-4)", format("%.5e", a.circular_error_rate * kRadPerArcsecond), "s/day/arcsec");
  row("impulse error (D-1)", format("%.6g", a.impulse_error), "s/day");
  row("  rate of change (D-2)", format("%.5e", a.impulse_error_rate * kRadPerArcsecond), "s/day/arcsec");
  row("  per arc second of amplitude", format("%.5e", a.impulse_error_amplitude_rate * kRadPerArcsecond),
      "s/day/arcsec");
  row("  error bound of the route", format("%.2g", a.choice.error_bound), "s/day");
  row("daily loss (circular + impulse)", format("%.6g", a.circular_error.value + a.impulse_error), "s/day");
  row("cancelling semi-amplitude (IX)",
      a.cancelling_semi_amplitude ? format("%.4f", *a.cancelling_semi_amplitude / kArcminute) : "none",
      a.cancelling_semi_amplitude ? "arcmin" : "");
  out << "  (" << a.cancelling_note << ")\n";
  row("amplitude-insensitive semi-amplitude",
      a.insensitive_semi_amplitude ? format("%.4f", *a.insensitive_semi_amplitude / kArcminute) : "none",
      a.insensitive_semi_amplitude ? "arcmin" : "");
  out << "  (impulse at a fixed location: d(circular + impulse error)/d(amplitude) = 0)\n";
  return out.str();
}


std::string clock_json(const ClockScene& scene, const ClockAnalysis& analysis, const std::string& input) {
  return json_text(clock_document(scene, analysis, input), 2);
}

}  // namespace pendulum
