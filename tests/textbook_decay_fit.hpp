#pragma once
// The textbook Ceres set-up for Eq. (25): one automatically differentiated
// residual block per point, DENSE_QR, converged tightly. It is the reference
// the fast fit (lib/src/decay_fit.cpp) must agree with, in the tests and in
// tests/benchmarks/bench_decay_fit.cpp. Its definition includes Ceres, and
// so glog, whose CHECK macro would replace Catch's: keep it out of test files.
#include <array>

#include "pendulum/decay_fit.hpp"

namespace pendulum::test {

/// (alpha, beta, theta0m) minimising the weighted squares, from `start`.
std::array<double, 3> textbook_decay_fit(const DecayData& d, std::array<double, 3> start);

}  // namespace pendulum::test
