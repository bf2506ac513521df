#pragma once
/// \file models/physical_pendulum.hpp
/// \brief The period model of a rigid body swinging about pivots along its
/// axis (a metre stick, a bar with holes, Kater's reversible pendulum), or
/// a series of uniform rods each pivoted at its end (a body per observation):
/// T0 = 2 pi sqrt((k^2 + h^2)/(g h)) (Kelley 1993, Eqs. 55-56), times the
/// finite-amplitude factor, the air's buoyancy and the damping rows, with
/// g, the radius of gyration k and the centre of mass's position as its
/// parameters (docs/physical.md).

#include <array>
#include <cmath>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "pendulum/air.hpp"
#include "pendulum/bodies.hpp"
#include "pendulum/corrections.hpp"
#include "pendulum/estimate.hpp"
#include "pendulum/period_model.hpp"

namespace pendulum {

/// The lowest period of a body of radius of gyration k (m) in gravity g
/// (m/s^2): T0 = 2 pi sqrt(2k/g) (s), at the pivot distance h = k, where
/// d/dh (k^2 + h^2)/h = 0 (Kelley Eq. 55).
template <class T>
T minimum_period(const T& g, const T& k) {
  return ideal_period(T(2.0 * k), g);
}

/// The pivot distance (m) with the same period as h (m), k the radius of
/// gyration (m): h' = k^2/h, since (k^2 + h^2)/h is symmetric under
/// h -> k^2/h; hung on the other side of the centre at h', the body is
/// Kater's reversible pendulum, the pivots l = h + h' apart.
template <class T>
T conjugate_pivot_distance(const T& k, const T& h) {
  return k * k / h;
}

/// Bessel's formula for Kater's reversible pendulum: g (m/s^2) from the
/// periods T1, T2 (s) about two pivots on opposite sides of the centre of
/// mass at distances h1, h2 (m) from it:
///   g = 8 pi^2 / [(T1^2 + T2^2)/(h1 + h2) + (T1^2 - T2^2)/(h1 - h2)].
/// h1 + h2 is the pivots' separation, measured precisely; h1 - h2 needs the
/// centre only roughly, because T1^2 - T2^2 is small. Exact for the ideal
/// periods (T^2 h = (4 pi^2/g)(k^2 + h^2) at each pivot); h1 != h2.
/// Reference: F. W. Bessel (1828); Nelson & Olsson (1986) Sec. V.
template <class T>
T bessel_g(const T& t1, const T& t2, const T& h1, const T& h2) {
  return 8.0 * kPi * kPi / ((t1 * t1 + t2 * t2) / (h1 + h2) + (t1 * t1 - t2 * t2) / (h1 - h2));
}

/// What the fit of a physical pendulum adds (docs/physical.md): the fitted
/// curve T(h)'s minimum, each pivot's conjugate of equal period, and for
/// Kater's reversible pendulum Bessel's closed form. Uncertainties from the
/// fitted parameters' covariance; a k or a centre taken from the body's
/// parts counts as exact.
struct PivotScan {
  /// 2 pi sqrt(2k/g) (s), the ideal period at h = k, and that h = k (m):
  /// one body's, so none for a series of rods.
  std::optional<Estimate> minimum_period, minimum_pivot_distance;
  /// x_c - k and x_c + k (m), in the frame of pivot_position, when the centre is known.
  std::vector<Estimate> minimum_pivot_positions;
  struct Conjugate {
    Estimate equivalent_length;      ///< l = (k^2 + h^2)/h (m)
    Estimate pivot_distance;         ///< h' = k^2/h (m), of the same period
    std::optional<Estimate> pivot_position;  ///< h' on the other side of the centre (m): Kater's pair
  };
  std::vector<Conjugate> conjugates;  ///< one per observation
  /// Kater's reversible pendulum (two pivot positions on opposite sides of
  /// a measured centre): Bessel's formula on the ideal periods (m/s^2).
  std::optional<double> bessel_g;
  /// k and the centre (m) as the body's parts give them, where the fit
  /// replaces them: its check (a warning beyond 3 standard uncertainties).
  std::optional<double> parts_radius_of_gyration, parts_center_of_mass_position;
  /// The textbook curve T0 = 2 pi sqrt((k^2 + h^2)/(g h)) without corrections:
  /// the straight line of T^2 h against h^2 on the measured periods (Kelley
  /// Eq. 55; physical_start), which for Kater's two pivots is Bessel's
  /// formula on the measured periods. g's uncertainty from the periods' and
  /// pivots' with k and the centre held at the line's.
  struct Textbook {
    Estimate g;  ///< (m/s^2)
    /// k (m), the body's where it gives one; none for rods, each its own.
    std::optional<double> radius_of_gyration;
    /// x_c (m), in the frame of pivot_position; empty for pivot distances.
    std::optional<double> center_of_mass_position;
  };
  std::optional<Textbook> textbook;
};

struct PhysicalPendulum {
  static constexpr const char* kName = "physical_pendulum";
  static constexpr std::array<Setting, 3> kSettings{
      {Setting::pivot_distance, Setting::pivot_position, Setting::rod_length}};
  /// The finite amplitude and the damping rows hold for any body; buoyancy is
  /// the body's own (own_corrections); the ball pendulum's parts and its
  /// sphere's added mass do not describe a rigid body, whose moment of inertia
  /// holds them (the reader refuses those parts: check_parts_apply).
  static constexpr std::array<CorrectionUse, kCorrectionCount> kCorrectionUse = [] {
    std::array<CorrectionUse, kCorrectionCount> use{};
    for (auto& u : use) u = CorrectionUse::not_applicable;
    for (CorrectionId id : {CorrectionId::finite_amplitude, CorrectionId::linear_damping,
                            CorrectionId::quadratic_damping, CorrectionId::amplitude_decay}) {
      use[static_cast<int>(id)] = CorrectionUse::applies;
    }
    use[static_cast<int>(CorrectionId::buoyancy)] = CorrectionUse::replaced;
    return use;
  }();
  /// Why the added-mass row is not a rigid body's, shown where the body's
  /// buoyancy is known.
  static constexpr const char* kAddedMassNotApplicable =
      "Eqs. (54)-(62) are for a sphere; a bar's potential-flow added mass (strip_added_inertia) needs swings "
      "much smaller than its section, which a pendulum's are not (docs/physical.md, Added mass)";
  static constexpr int kParameters = 3;
  enum Parameter { g, radius_of_gyration, center_of_mass_position };
  static constexpr std::array<ParameterInfo, kParameters> kParameterInfo{{
      {"g", "m/s^2", "local acceleration of gravity"},
      {"radius_of_gyration", "m", "the body's radius of gyration about its centre of mass, k = sqrt(I_c/M)"},
      {"center_of_mass_position", "m", "where the centre of mass is along the body, in the frame of pivot_position"},
  }};
  /// Starting values where the data give none (SI); the analysis starts a
  /// scan from a linear fit instead.
  static constexpr std::array<double, kParameters> kDefaults{{kStandardGravity, 0.1, 0.0}};

  /// The fitted parameters in their reported form: only k^2 enters the
  /// period, so a fit may land on either sign of k; k is reported positive.
  static void canonicalise(double* p) { p[radius_of_gyration] = std::abs(p[radius_of_gyration]); }

  /// Where the fit starts: the straight line T^2 h = (4 pi^2/g)(h^2 + k^2)
  /// on the measured periods, the centre searched (physical_start, analysis.hpp).
  static std::array<double, kParameters> start(const ParsedScene& scene, const std::array<bool, kParameters>& fitted);
  /// Its results beside the fit's: the pivot scan, with Kater's Bessel g.
  using Results = PivotScan;
  /// Sets them on every fit (FitReport::set_results) and warns of the
  /// parts' k and centre against the fit's, the buoyancy a body of unknown
  /// volume lacks (models/physical_pendulum.cpp).
  static void report(const FitState<kParameters>& fit, Analysis& out);
  /// Its results in the output (models/physical_pendulum.cpp): each
  /// observation's "conjugate_pivot" and "fit.pivot_scan", and the table's
  /// lines of them; an observation has none of its own. Throws
  /// std::logic_error on a null `scan`, which report() never leaves.
  static void put_fit_results(const Results* scan, JsonOut& fit);
  static void put_observation_results(const Results*, JsonOut&) {}
  static void fit_results_lines(const Results* scan, std::ostream& os);
  static void observation_results_lines(const Results*, std::ostream&) {}

  /// center_of_mass_position, body, temperature, with the checks across
  /// its observations (models/physical_reader.cpp). After "fit".
  static void read_keys(json_reader::Object& top, ParsedScene& out);
  /// The unknowns besides g a scene of observations alone (a table's: no
  /// parts, no measured centre) fits: k, and the centre from pivot positions
  /// (read_keys refuses the scene otherwise); none for rods, each of which
  /// gives its own.
  static constexpr std::array<bool, kParameters> unknowns_of_observations_alone(Setting s) {
    return {false, s != Setting::rod_length, s == Setting::pivot_position};
  }
  /// Its parts are checked as read_keys reads them.
  static void check_scene(const ParsedScene&) {}
  /// At standard gravity from the body's k and centre (measured or from
  /// its parts, also where the fit replaces them) with every correction;
  /// none where the fit finds them (models/physical_pendulum.cpp).
  static std::optional<Expectation> expectation(const ParsedScene& scene, const Observation<double>& o);
  /// None before the fit: its damping rows depend on the equivalent
  /// length, which needs k and the centre, that the fit may find.
  static void check_rows(const ParsedScene&, const Observation<double>&) {}
  /// None: the warnings are a ball's air and mass (without air, the body's
  /// buoyancy row says why it is skipped).
  static std::vector<std::string> skipped_part_warnings(const ParsedScene&, double) { return {}; }
  static constexpr SuspectCauses kSuspectCauses{
      "the pivots, the radius of gyration and the centre of mass",
      "the pivots, and the body's parts (masses, dimensions, positions and their units)",
      "a pivot position misread, a miscounted oscillation, a body that is not rigid",
      "the pivot positions' reference point (every pivot and the centre of mass from the same end)",
      "the pivot positions' reference point; the amplitude; a miscounted oscillation", false};

  /// k (m): the body's (from its parts) when it has one, else the parameter.
  template <class T>
  static T gyration(const T* p, const Apparatus<T>& app) {
    return app.body && app.body->radius_of_gyration ? *app.body->radius_of_gyration : p[radius_of_gyration];
  }

  /// k (m) of the body an observation hangs: a rod of length L its own,
  /// sqrt(L^2/12) (thin_rod, Kelley 1993 Fig. 9), else gyration(p, app).
  template <class T, class Set>
  static T gyration_at(const T* p, const Set& o, const Apparatus<T>& app) {
    using std::sqrt;
    return o.setting == Setting::rod_length ? T(sqrt(thin_rod(o.length).gyration_squared)) : gyration(p, app);
  }

  /// h (m), the pivot to the centre of mass: the observation's pivot
  /// distance, a rod's half length (its end), or its pivot position's
  /// distance from the centre (the measured one when the scene gives it,
  /// else the parameter).
  template <class T, class Set>
  static T pivot_distance(const T* p, const Set& o, const Apparatus<T>& app) {
    using std::abs;
    if (o.setting == Setting::rod_length) return thin_rod(o.length).half_length;
    if (o.setting != Setting::pivot_position) return o.length;
    const T& center = app.body && app.body->center_of_mass_position ? *app.body->center_of_mass_position
                                                                     : p[center_of_mass_position];
    return abs(o.length - center);
  }

  /// Every length of the body at its temperature over the same length at the
  /// temperature it was measured at: (1 + w C)/(1 + w C_ref), C in degC
  /// (Kelley Eq. 41 at both); 1 without a temperature.
  template <class T>
  static T thermal_scale(const Apparatus<T>& app) {
    if (!app.body || !app.body->temperature) return T(1.0);
    const auto& b = *app.body;
    const T celsius = *b.temperature - kZeroCelsius, reference = *b.reference_temperature - kZeroCelsius;
    return thermal_length(T(1.0), *b.expansion_coefficient, celsius) /
           thermal_length(T(1.0), *b.expansion_coefficient, reference);  // Eq. (41)
  }

  /// l = (k^2 + h^2)/h (Kelley Eq. 55) at the body's temperature (m), for
  /// an observation or its swing (whatever has `length` and `setting`); a
  /// rod pivoted at its end gives 2L/3 (Kelley Eq. 45).
  template <class T, class Set>
  static T equivalent(const T* p, const Set& o, const Apparatus<T>& app) {
    return thermal_scale(app) * equivalent_length(gyration_at(p, o, app), pivot_distance(p, o, app));  // Eq. (55)
  }

  /// The period at parameters p = (g (m/s^2), k (m), x_c (m)):
  /// T0 = 2 pi sqrt(l/g) with l = (k^2 + h^2)/h (Eqs. 55-56), times T/T0 of
  /// the rows kCorrectionUse declares (visit_model_corrections): the
  /// finite amplitude (Eq. 56's K), the damping rows (a decay record), and
  /// the body's buoyancy (own_corrections). The ball pendulum's rows (bob,
  /// ring, cap, wire, added mass of a sphere, support) are skipped: the
  /// body's moment of inertia holds its mass distribution.
  template <class T>
  static PeriodPrediction<T> predict(const T* p, const Observation<T>& o, const Apparatus<T>& app,
                                     const AmplitudeChoice& amplitude) {
    return prediction_of<PhysicalPendulum>(p, o, app, amplitude);  // T0: Eq. (56)
  }

  /// The rows it owns (kCorrectionUse), in air: the buoyancy of a body whose
  /// mass and volume are known, m_air/(2M) (Nelson & Olsson Eq. 16, exact for
  /// a uniform body, whose centre of buoyancy is its centre of mass), and why
  /// the added-mass row is skipped. Without air, visit_corrections's reason.
  template <class T, class Sink>
  static void own_corrections(const Apparatus<T>& app, const Swing<T>&, Sink& sink) {
    if (!app.air) return;
    if (const auto r = body_buoyancy(app)) {
      sink.set(CorrectionId::buoyancy, *r, "eq16_body");
      sink.skip({CorrectionId::added_mass}, kAddedMassNotApplicable);
    } else {
      sink.skip({CorrectionId::buoyancy, CorrectionId::added_mass},
                "needs the body's mass and volume (a body given in parts with densities)");
    }
  }

  /// The part of an observation's swing that no parameter changes (the
  /// setting as measured, the working frequency, the timing's duration):
  /// a fit may compute it once per observation.
  template <class T>
  static Swing<T> swing(const Observation<T>& o) {
    return Swing<T>::of(o, T(0.0));
  }

  /// The swing the corrections act on at p: the measured one with its
  /// setting made the equivalent length.
  template <class T>
  static Swing<T> swing_at(const T* p, Swing<T> measured, const Apparatus<T>& app) {
    measured.length = equivalent(p, measured, app);
    measured.setting = Setting::length;
    return measured;
  }

  /// predict()'s composition without the rows: the corrections that apply
  /// to a rigid body and its buoyancy.
  template <class T>
  static Composition<T> composition(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude) {
    return model_composition<PhysicalPendulum>(app, s, amplitude);
  }

  /// The closed form for one observation with g the only unknown:
  /// g = 4 pi^2 l (T/T0)^2 / T^2. The corrections do not depend on g, so T
  /// is g^(-1/2) times the rest, and g = (T at g = 1 / T)^2.
  template <class T>
  static T solve_g(const T* p, const Observation<T>& o, const Apparatus<T>& app, const AmplitudeChoice& amplitude) {
    T unit[kParameters] = {T(1.0), p[radius_of_gyration], p[center_of_mass_position]};
    const T ratio = predicted_period<PhysicalPendulum>(unit, swing(o), app, amplitude) / o.period;
    return ratio * ratio;
  }

 private:
  static constexpr double kZeroCelsius = 273.15;  // K

  /// m_air/(2M) for a body of known mass and volume in air (Eq. 16).
  template <class T>
  static std::optional<T> body_buoyancy(const Apparatus<T>& app) {
    if (!app.air || !app.body || !app.body->mass || !app.body->volume) return std::nullopt;
    const T rho = air_density(app.air->pressure, app.air->temperature, app.air->molar_mass);
    return buoyancy(T(rho * *app.body->volume), *app.body->mass);  // Eq. (16)
  }
};

}  // namespace pendulum
