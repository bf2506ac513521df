#include "textbook_decay_fit.hpp"

#include <ceres/ceres.h>

#include "pendulum/damping.hpp"

namespace pendulum::test {
namespace {

struct PointResidual {
  double t, theta, w;
  template <class T>
  bool operator()(const T* p, T* r) const {
    r[0] = (decayed_amplitude(p[2], p[0], p[1], T(t)) - theta) * w;
    return true;
  }
};

}  // namespace

std::array<double, 3> textbook_decay_fit(const DecayData& d, std::array<double, 3> start) {
  ceres::Problem problem;
  for (std::size_t i = 0; i < d.times.size(); ++i) {
    const double w = d.sigmas.empty() ? 1.0 : 1.0 / d.sigmas[i];
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PointResidual, 1, 3>(
                                 new PointResidual{d.times[i], d.amplitudes[i], w}),
                             nullptr, start.data());
  }
  problem.SetParameterLowerBound(start.data(), 0, 0.0);
  problem.SetParameterLowerBound(start.data(), 1, 0.0);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.logging_type = ceres::SILENT;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-20;
  options.parameter_tolerance = 1e-15;
  options.max_num_iterations = 500;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  return start;
}

}  // namespace pendulum::test
