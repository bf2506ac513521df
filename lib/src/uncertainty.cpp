#include "pendulum/uncertainty.hpp"

#include <cmath>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

namespace pendulum {

const char* distribution_name(Distribution d) {
  switch (d) {
    case Distribution::normal: return "normal";
    case Distribution::rectangular: return "rectangular";
    case Distribution::student_t: return "student_t";
  }
  return "";
}

InputEvaluation evaluation_of(const std::vector<InputEvaluation>& given, const std::string& path) {
  for (const InputEvaluation& e : given) {
    if (e.path == path) return e;
  }
  return {path};
}

double welch_satterthwaite(const std::vector<VarianceComponent>& components) {
  double total = 0.0, denominator = 0.0;
  for (const VarianceComponent& c : components) total += c.variance;
  // Each term relative to u_c^2, so that no fourth power under- or overflows.
  for (const VarianceComponent& c : components) {
    if (std::isfinite(c.dof)) denominator += (c.variance / total) * (c.variance / total) / c.dof;
  }
  if (!(total > 0.0) || !(denominator > 0.0)) return kInfiniteDof;
  return 1.0 / denominator;
}

double coverage_factor(double dof, double probability) {
  const double tail = 0.5 * (1.0 + probability);
  if (!(dof <= 1e6)) return boost::math::quantile(boost::math::normal_distribution<double>(), tail);
  return boost::math::quantile(boost::math::students_t_distribution<double>(std::floor(dof)), tail);
}

}  // namespace pendulum
