#pragma once
// What a series repeats once per observation, said once for people (issue
// 39, item 8): the budget's rows of one field grouped, and messages that
// differ only by their observation's index collapsed. The JSON keeps every
// row and message.

#include <cstddef>
#include <string>
#include <vector>

#include "pendulum/analysis.hpp"

namespace pendulum {

/// `path` without its observation's prefix ("observations[12].timing.period"
/// -> "timing.period"); a path of no observation as it is.
std::string field_of(const std::string& path);

/// Budget rows of one field: `rows` indexes the budget (largest first, as the
/// budget is), `together` their contributions in quadrature (independent
/// inputs: one per observation). A field of one row is a group of one.
struct BudgetGroup {
  std::string field;
  std::vector<std::size_t> rows;
  double together = 0.0;
};

/// The rows grouped by field, largest `together` first; `paths` and
/// `contributions` of the budget, in its order.
std::vector<BudgetGroup> group_budget(const std::vector<std::string>& paths, const std::vector<double>& contributions);

/// "57 observations' timing.period", or the one row's path.
std::string group_name(const BudgetGroup& group, const std::vector<std::string>& paths);

/// A group's rows as GUM describes them: "A", or "A/B" where they differ;
/// the distributions likewise; their share of u(g)^2 together; their
/// degrees of freedom ("9", "2 to 9", `infinite` for infinite ones: "∞").
struct GroupEvaluation {
  std::string type, distribution, dof;
  double variance_share = 0.0;
};
GroupEvaluation group_evaluation(const BudgetGroup& group, const std::vector<BudgetEntry>& budget,
                                 const std::string& infinite);

/// The messages with those that differ only by their observations' indices
/// said once: the first as written, then "(and 56 more alike: observations[1],
/// observations[2], observations[3], ...)".
std::vector<std::string> collapse_repeats(const std::vector<std::string>& messages);

}  // namespace pendulum
