#pragma once
/// \file observation.hpp
/// \brief What was measured at one setting of the apparatus: the length, the
/// amplitude and the timing, and the swing the corrections act on.

#include <cstddef>
#include <iterator>
#include <type_traits>

#include "pendulum/fields.hpp"
#include "pendulum/numeric.hpp"

namespace pendulum {

/// Which distance an observation's setting is (its `length`). A ball on a
/// wire is set by its length; a rigid body by where it hangs from, given
/// either way (docs/physical.md). A new one is an entry here and its row at
/// the same place in kSettingInfo, and belongs to one model's kSettings.
enum class Setting {
  length,          ///< pivot to the bob's centre, or to the mark of length_offset
  pivot_distance,  ///< pivot to the body's centre of mass
  pivot_position,  ///< the pivot's place along the body, from a mark on it
  rod_length,      ///< a uniform rod's (or beam's) length, pivoted at its end: each observation its own body
};

/// What the reader and the output say of a setting.
struct SettingInfo {
  Setting setting;     ///< its place in the table (checked at compile time)
  const char* key;     ///< the scene's key, also its JSON path
  const char* symbol;  ///< a table's heading, with " (m)"
  const char* letter;  ///< a table column's declaration (--columns "l:cm,T")
  const char* words;   ///< in words, for messages and the report's headings
  const char* series;  ///< what a table of its observations is, in a title
  bool signed_distance;  ///< whether it may be negative (a position from a mark)
};

/// The settings, indexed by Setting.
inline constexpr SettingInfo kSettingInfo[] = {
    {Setting::length, "length", "L", "l", "length", "a length series", false},
    {Setting::pivot_distance, "pivot_distance", "h", "h", "pivot distance", "a pivot scan", false},
    {Setting::pivot_position, "pivot_position", "x", "x", "pivot position", "a pivot scan", true},
    {Setting::rod_length, "rod_length", "L_rod", "r", "rod length", "a series of rods pivoted at an end", false},
};

namespace detail {
constexpr bool setting_table_follows_enum() {
  for (std::size_t i = 0; i < std::size(kSettingInfo); ++i) {
    if (static_cast<std::size_t>(kSettingInfo[i].setting) != i) return false;
  }
  return true;
}
}  // namespace detail
static_assert(detail::setting_table_follows_enum(), "kSettingInfo must list the settings in Setting order");

/// What the reader and the output say of `s`.
constexpr const SettingInfo& setting_info(Setting s) { return kSettingInfo[static_cast<int>(s)]; }

/// Whose angle an amplitude is. The corrections take the pendulum's (the
/// line from the pivot to the bob's centre); a sensor in the bob (a phone's
/// gyroscope or accelerometer) turns with the bob, which on a string swings
/// further than that line (docs/phone.md, What the sensor sees).
enum class AngleOf {
  pendulum,  ///< the line from the pivot to the bob's centre (a typed amplitude, a tracked bob)
  body,      ///< the bob's own tilt, what a sensor in it measures
};

/// The output's name of whose angle.
inline const char* angle_of_name(AngleOf a) { return a == AngleOf::body ? "body" : "pendulum"; }

/// The scene's key of a setting, which is also its JSON path.
constexpr const char* setting_key(Setting s) { return setting_info(s).key; }

/// One timed setting of the pendulum, in SI units.
template <class T>
struct Observation {
  T period;     ///< mean measured period (s)
  /// The setting's distance (m), named by `setting`: the length from the
  /// pivot to the bob's centre (or to the mark measured to when the scene
  /// fits length_offset), or a rigid body's pivot distance or position.
  T length;
  T amplitude;  ///< amplitude at the start of each timing (rad)
  int oscillations_per_trial = 1;  ///< oscillations in one timing
  Setting setting = Setting::length;
  AngleOf amplitude_of = AngleOf::pendulum;

  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f(Field{"timing.period", "s", FieldRole::period}, a.period, b.period);
    f(Field{setting_key(a.setting), "m", FieldRole::length}, a.length, b.length);
    f(Field{"amplitude", "rad"}, a.amplitude, b.amplitude);
  }
};

/// Visits the observation's scalar fields: f(Field, a_field, b_field); the
/// oscillation count and the setting are copied along.
template <class A, class B, class F>
void zip_observation(A& a, B& b, F&& f) {
  detail::FieldZipper<F> z{f};
  if constexpr (!std::is_const_v<B>) {
    b.oscillations_per_trial = a.oscillations_per_trial;
    b.setting = a.setting;
    b.amplitude_of = a.amplitude_of;
  }
  std::decay_t<A>::zip(a, b, z);
}

/// The same observation with every scalar mapped by f(field, value) -> U.
template <class U, class T, class F>
Observation<U> convert_observation(const Observation<T>& o, F&& f) {
  Observation<U> out;
  zip_observation(o, out, [&](const Field& field, const T& x, U& y) { y = f(field, x); });
  return out;
}

/// The swing the period corrections act on (Nelson & Olsson 1986, Sec. III).
///
/// The corrections that need the pendulum's frequency or g (damping, added
/// mass, stretch, support) take the working values omega = 2 pi / T and
/// g = omega^2 l from the measured period: they are second-order terms, and
/// the difference from T0 changes them by about DeltaT/T (1e-4 of their size).
template <class T>
struct Swing {
  T length;          ///< pivot to the bob's centre (m); a rigid body's setting before its model's turn
  T amplitude;       ///< theta0 (rad)
  T omega;           ///< working angular frequency 2 pi / T (rad/s)
  T trial_duration;  ///< duration of one timing, t_f (s)
  /// What `length` is until a model makes it a pendulum's length (a rigid
  /// body's pivot position or distance, models/physical_pendulum.hpp).
  Setting setting = Setting::length;
  AngleOf amplitude_of = AngleOf::pendulum;  ///< whose angle `amplitude` is

  /// The swing of an observation whose length is off by `length_offset` (m).
  static Swing of(const Observation<T>& o, const T& length_offset) {
    return {o.length + length_offset, o.amplitude, 2.0 * kPi / o.period,
            double(o.oscillations_per_trial) * o.period, o.setting, o.amplitude_of};
  }
  /// g from the working frequency, omega^2 l (m/s^2).
  T working_g() const { return omega * omega * length; }
};

}  // namespace pendulum
