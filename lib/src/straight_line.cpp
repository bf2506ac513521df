#include "pendulum/straight_line.hpp"

#include <algorithm>

namespace pendulum {

StraightLine fit_straight_line(const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& sigma_x, const std::vector<double>& sigma_y,
                               bool with_intercept) {
  StraightLine line{0.0, 0.0, 0.0, 0.0, 0.0};
  // Effective variance: the slope of the unweighted-in-x fit first, then
  // once more with sigma_y^2 + slope^2 sigma_x^2. Points stated without
  // uncertainty take the smallest variance of the others; with none stated
  // at all, the line is exact (variances 0).
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<double> var(x.size());
    double smallest = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      var[i] = sigma_y[i] * sigma_y[i] + line.slope * line.slope * sigma_x[i] * sigma_x[i];
      if (var[i] > 0.0 && (smallest == 0.0 || var[i] < smallest)) smallest = var[i];
    }
    const double scale = smallest > 0.0 ? 1.0 : 0.0;
    double s = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double w = smallest > 0.0 ? 1.0 / std::max(var[i], smallest) : 1.0;
      s += w;
      sx += w * x[i];
      sy += w * y[i];
      sxx += w * x[i] * x[i];
      sxy += w * x[i] * y[i];
    }
    if (with_intercept) {
      const double det = s * sxx - sx * sx;
      line.slope = (s * sxy - sx * sy) / det;
      line.intercept = (sxx * sy - sx * sxy) / det;
      line.var_slope = scale * s / det;
      line.var_intercept = scale * sxx / det;
      line.cov = -scale * sx / det;
    } else {
      line.slope = sxy / sxx;
      line.var_slope = scale / sxx;
    }
  }
  return line;
}

}  // namespace pendulum
