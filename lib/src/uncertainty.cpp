#include "pendulum/uncertainty.hpp"

#include <algorithm>
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

std::vector<VarianceComponent> variance_components(const std::vector<InputShare>& inputs,
                                                   const std::vector<PairShare>& pairs, VarianceComponent birge) {
  std::vector<VarianceComponent> components;
  VarianceComponent pooled{0.0, kInfiniteDof}, lengths{0.0, kInfiniteDof};
  for (std::size_t j = 0; j < inputs.size(); ++j) {
    const auto paired = [&](const PairShare& pr) { return pr.a == j || pr.b == j; };
    if (std::any_of(pairs.begin(), pairs.end(), paired)) continue;
    const InputShare& in = inputs[j];
    VarianceComponent& sum = in.shared == SharedVariance::pooled_trials ? pooled : lengths;
    if (in.shared == SharedVariance::none) {
      components.push_back({in.variance, in.dof});
    } else {
      sum = {sum.variance + in.variance, in.dof};
    }
  }
  for (const VarianceComponent& shared : {pooled, lengths}) {
    if (shared.variance > 0.0) components.push_back(shared);
  }
  for (const PairShare& pr : pairs) {
    components.push_back({std::max(inputs[pr.a].variance + inputs[pr.b].variance + pr.cross, 0.0),
                          std::min(inputs[pr.a].dof, inputs[pr.b].dof)});
  }
  if (birge.variance > 0.0) components.push_back(birge);
  return components;
}

double coverage_factor(double dof, double probability) {
  const double tail = 0.5 * (1.0 + probability);
  if (!(dof <= 1e6)) return boost::math::quantile(boost::math::normal_distribution<double>(), tail);
  return boost::math::quantile(boost::math::students_t_distribution<double>(std::floor(dof)), tail);
}

}  // namespace pendulum
