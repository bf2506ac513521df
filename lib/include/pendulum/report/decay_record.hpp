#pragma once
/// \file decay_record.hpp
/// \brief A decay record and its fit as a report draws them (a scene's
/// decay.data, or a recording's swings), in SI units.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/decay_fit.hpp"

namespace pendulum::report {

struct Measured {
  double value;
  double uncertainty;
};

struct FitParameterText {
  std::string name, unit;
  double value;
  /// Empty when held fixed, or when fitted and the fit's covariance is
  /// singular: then the report says "uncertainty unknown", never +- 0.
  std::optional<double> uncertainty;
  bool fitted = true;
};

/// A decay record and its fit of Nelson & Olsson (1986) Eq. (25).
struct DecayRecord {
  std::vector<double> times;       ///< (s)
  std::vector<double> amplitudes;  ///< (rad)
  std::vector<double> sigmas;      ///< (rad); empty when the record states none
  /// theta0(t) of the fit at the record's times and on a fine grid, with its
  /// standard uncertainty from the fit's covariance (rad); grid_uncertainty
  /// is empty when the covariance is unknown (singular).
  std::vector<double> fitted;
  std::vector<double> grid, grid_fit, grid_uncertainty;
  std::vector<FitParameterText> parameters;
  std::string model;  ///< which terms were fitted, and why
  double chi2 = 0.0;
  int dof = 0;
  std::string uncertainty_scaling;
};

/// A decay record and its fit, for a report: the fit at the record's times
/// and on a grid of 241 times over it, with the +-1 sigma band from the
/// covariance (Jacobian by ceres::Jet through decayed_amplitude); no band
/// when the covariance is singular. Implemented in scene_report.cpp.
DecayRecord make_decay_record(const DecayData& data, const DecayFit& fit);

}  // namespace pendulum::report
