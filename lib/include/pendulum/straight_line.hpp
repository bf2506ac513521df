#pragma once
/// \file straight_line.hpp
/// \brief The weighted straight line the textbook answers and the fits'
/// starts are drawn from.

#include <vector>

namespace pendulum {

/// A weighted straight line y = slope x + intercept (intercept 0 when
/// `with_intercept` is false) with the effective-variance weights
/// sigma_y^2 + slope^2 sigma_x^2 (one refinement of the slope), and the
/// parameters' covariance.
struct StraightLine {
  double slope, intercept;
  double var_slope, var_intercept, cov;
};
StraightLine fit_straight_line(const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& sigma_x, const std::vector<double>& sigma_y,
                               bool with_intercept);

}  // namespace pendulum
