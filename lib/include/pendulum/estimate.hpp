#pragma once
/// \file estimate.hpp
/// \brief A value with its uncertainty, as the analysis and the period
/// models' own results report them.

#include <optional>

namespace pendulum {

struct ValueWithUncertainty {
  double value;
  double uncertainty;
};

/// A value whose uncertainty may be unknown (a singular fit).
struct Estimate {
  double value;
  std::optional<double> uncertainty;
};

}  // namespace pendulum
