#include "grouping.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace pendulum {

namespace {

constexpr char kObservations[] = "observations[";
constexpr std::size_t kObservationsLength = sizeof kObservations - 1;

/// The length of "observations[12]" at `at` (0 if none is there).
std::size_t index_length(const std::string& s, std::size_t at) {
  if (s.compare(at, kObservationsLength, kObservations) != 0) return 0;
  std::size_t end = at + kObservationsLength;
  while (end < s.size() && std::isdigit(static_cast<unsigned char>(s[end]))) ++end;
  if (end == at + kObservationsLength || end >= s.size() || s[end] != ']') return 0;
  return end + 1 - at;
}

/// `message` with every observation's index as "observations[k]", and the
/// first such reference as written.
std::string without_indices(const std::string& message, std::string& first) {
  std::string out;
  for (std::size_t i = 0; i < message.size();) {
    const std::size_t n = index_length(message, i);
    if (n == 0) {
      out += message[i++];
      continue;
    }
    if (first.empty()) first = message.substr(i, n);
    out += "observations[k]";
    i += n;
  }
  return out;
}

}  // namespace

std::string field_of(const std::string& path) {
  const std::size_t n = index_length(path, 0);
  return n > 0 && n < path.size() && path[n] == '.' ? path.substr(n + 1) : path;
}

std::vector<BudgetGroup> group_budget(const std::vector<std::string>& paths, const std::vector<double>& contributions) {
  std::vector<BudgetGroup> groups;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::string field = field_of(paths[i]);
    auto g = std::find_if(groups.begin(), groups.end(), [&](const BudgetGroup& x) { return x.field == field; });
    if (g == groups.end()) g = groups.insert(groups.end(), BudgetGroup{field, {}, 0.0});
    g->rows.push_back(i);
    g->together = std::hypot(g->together, contributions[i]);
  }
  std::stable_sort(groups.begin(), groups.end(),
                   [](const BudgetGroup& x, const BudgetGroup& y) { return x.together > y.together; });
  return groups;
}

std::string group_name(const BudgetGroup& group, const std::vector<std::string>& paths) {
  if (group.rows.size() == 1) return paths[group.rows.front()];
  return std::to_string(group.rows.size()) + " observations' " + group.field;
}

GroupEvaluation group_evaluation(const BudgetGroup& group, const std::vector<BudgetEntry>& budget,
                                 const std::string& infinite) {
  std::vector<std::string> types, distributions;
  GroupEvaluation out;
  double least = kInfiniteDof, most = 0.0;
  for (const std::size_t row : group.rows) {
    const InputEvaluation& e = budget[row].evaluation;
    types.emplace_back(1, e.type);
    distributions.emplace_back(distribution_name(e.distribution));
    out.variance_share += budget[row].variance_share;
    least = std::min(least, e.dof), most = std::max(most, e.dof);
  }
  const auto common = [](std::vector<std::string> values) {
    std::sort(values.begin(), values.end());
    return values.front() == values.back() ? values.front() : values.front() + "/" + values.back();
  };
  // Whole, as GUM G.4.1 truncates nu_eff (an input's own are whole).
  const auto dof = [&](double nu) { return std::isfinite(nu) ? std::to_string(static_cast<long>(nu)) : infinite; };
  out.type = common(types);
  out.distribution = common(distributions);
  out.dof = dof(least) + (least == most ? "" : " to " + dof(most));
  return out;
}

std::vector<std::string> collapse_repeats(const std::vector<std::string>& messages) {
  // The first three paths name where; the count says how many.
  constexpr std::size_t kNamed = 3;
  struct Repeat {
    std::string key, text;
    std::vector<std::string> others;
  };
  std::vector<Repeat> repeats;
  for (const std::string& m : messages) {
    std::string first;
    const std::string key = without_indices(m, first);
    auto r = std::find_if(repeats.begin(), repeats.end(), [&](const Repeat& x) { return x.key == key; });
    if (r == repeats.end() || first.empty()) {
      repeats.push_back({key, m, {}});
    } else {
      r->others.push_back(first);
    }
  }
  std::vector<std::string> out;
  for (const Repeat& r : repeats) {
    std::string text = r.text;
    if (!r.others.empty()) {
      text += " (and " + std::to_string(r.others.size()) + " more alike:";
      for (std::size_t i = 0; i < r.others.size() && i < kNamed; ++i) text += (i ? ", " : " ") + r.others[i];
      text += std::string(r.others.size() > kNamed ? ", ..." : "") + ")";
    }
    out.push_back(std::move(text));
  }
  return out;
}

}  // namespace pendulum
