// The clean stage (stages.hpp): samples in time order, what was dropped said
// line by line.
#include <algorithm>
#include <cmath>

#include "stages.hpp"
#include "../text.hpp"

namespace pendulum::recording_text {

namespace {

/// The positions of a longest non-decreasing subsequence of `t`, in order
/// (patience sorting, O(n log n)).
std::vector<std::size_t> longest_in_order(const std::vector<double>& t) {
  std::vector<std::size_t> tails, before(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    const auto at = std::upper_bound(tails.begin(), tails.end(), t[k], [&](double v, std::size_t i) { return v < t[i]; });
    before[k] = at == tails.begin() ? t.size() : *(at - 1);
    if (at == tails.end()) tails.push_back(k);
    else *at = k;
  }
  std::vector<std::size_t> out(tails.size());
  std::size_t k = tails.empty() ? t.size() : tails.back();
  for (std::size_t i = out.size(); i-- > 0; k = before[k]) out[i] = k;
  return out;
}

std::string seconds(double t) { return format_number(t, 9) + " s"; }

}  // namespace

Cleaned clean_times(const std::vector<double>& time, const std::vector<std::size_t>& rows, const Table& table,
                    bool sampled, const std::string& file) {
  Cleaned out;
  const std::size_t n = time.size();
  const auto line = [&](std::size_t k) { return table.line(rows.empty() ? k : rows[k]); };
  std::size_t first_back = n, repeats = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(time[k])) fail(file, line(k), 1, "an infinite time");
    if (k > 0 && time[k] < time[k - 1] && first_back == n) first_back = k;
    repeats += k > 0 && time[k] == time[k - 1];
  }
  // A few samples out of order (a phone's sensor queue): the longest run in
  // order is kept, the others dropped; more is a file not in time order.
  std::vector<std::size_t> keep;
  if (first_back < n) {
    keep = longest_in_order(time);
    const std::size_t dropped = n - keep.size();
    if (dropped > n / 100) {
      fail(file, line(first_back), 1,
           "time going backwards: " + std::to_string(time[first_back]) + " s after " +
               std::to_string(time[first_back - 1]) + " s on line " + std::to_string(line(first_back - 1)) +
               "; expected increasing times (" + std::to_string(dropped) + " of " + std::to_string(n) +
               " samples out of order; at most 1 % are dropped as a sensor's glitches)");
    }
    for (std::size_t i = 0, j = 0; i < n; ++i) {
      if (j < keep.size() && keep[j] == i) {
        ++j;
        continue;
      }
      const std::size_t prev = j > 0 ? keep[j - 1] : n;
      out.notes.push_back({line(i), "a sample out of time order (t = " + seconds(time[i]) +
                                        (prev < n ? ", after " + seconds(time[prev]) + " on line " + std::to_string(line(prev)) : std::string()) +
                                        "): dropped"});
    }
    repeats = 0;
    for (std::size_t j = 1; j < keep.size(); ++j) repeats += time[keep[j]] == time[keep[j - 1]];
  } else if (repeats > 0) {
    keep.resize(n);
    for (std::size_t k = 0; k < n; ++k) keep[k] = k;
  }
  const auto at = [&](std::size_t j) { return keep.empty() ? j : keep[j]; };
  const std::size_t kept = keep.empty() ? n : keep.size();
  if (repeats > 0) {
    if (repeats * 100 > kept) {
      // The clock prints fewer decimals than its rate needs: every sample is
      // real, the stamps are rounded. Kept, and the rounding step said.
      double quantum = 0.0;
      for (std::size_t j = 1; j < kept; ++j) {
        const double d = time[at(j)] - time[at(j - 1)];
        if (d > 0.0 && (quantum == 0.0 || d < quantum)) quantum = d;
      }
      out.quantum = quantum;
      out.notes.push_back({0, std::to_string(repeats) + " time stamps repeat the one before: the clock ticks in " +
                                  seconds(quantum) + ", so all samples are kept and the stamps' rounding is the clock's"});
    } else {
      std::vector<std::size_t> distinct;
      distinct.reserve(kept);
      for (std::size_t j = 0; j < kept; ++j) {
        if (j > 0 && time[at(j)] == time[at(j - 1)]) {
          out.notes.push_back({line(at(j)), "a repeated sample (t = " + seconds(time[at(j)]) + ", as on line " +
                                                std::to_string(line(at(j - 1))) + "): dropped"});
        } else {
          distinct.push_back(at(j));
        }
      }
      keep = std::move(distinct);
    }
  }
  out.all = keep.empty() || keep.size() == n;
  if (!out.all) out.keep = std::move(keep);
  if (!sampled) return out;
  // Gaps: steps beyond 1.75 of the median (a dropped frame is two steps).
  const std::size_t m = out.all ? n : out.keep.size();
  const auto pos = [&](std::size_t j) { return out.all ? j : out.keep[j]; };
  if (m < 8) return out;
  std::vector<double> steps;
  const std::size_t stride = std::max<std::size_t>(1, m >> 16);
  for (std::size_t j = stride; j < m; j += stride) {
    const double d = time[pos(j)] - time[pos(j - 1)];
    if (d > 0.0) steps.push_back(d);
  }
  if (steps.empty()) return out;
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  const double median = steps[steps.size() / 2];
  std::size_t gaps = 0;
  double longest = 0.0;
  for (std::size_t j = 1; j < m; ++j) {
    const double d = time[pos(j)] - time[pos(j - 1)];
    if (!(d > 1.75 * median)) continue;
    ++gaps;
    longest = std::max(longest, d);
    if (gaps <= 10) {
      // In doubles: a gap of 1e300 steps is no integer's (lround's was then
      // LLONG_MIN, and one less an overflow: fuzz_recording, session 28).
      const double missing = std::round(d / median) - 1.0;
      out.notes.push_back({line(pos(j)), "a gap of " + seconds(d) + " before this sample (" +
                                             (std::isfinite(missing) ? "about " + format_number(missing, 6)
                                                                     : std::string("too many to count")) +
                                             " missing at the median step of " + seconds(median) + ")"});
    }
  }
  if (gaps > 10) {
    out.notes.push_back({0, std::to_string(gaps) + " gaps in all, the longest " + seconds(longest) +
                                "; the first 10 are noted"});
  }
  return out;
}

Cleaned held_frames(const std::vector<double>& time, const std::vector<std::vector<double>>& channels) {
  Cleaned out;
  const std::size_t n = time.size();
  if (channels.empty() || n < 16) return out;
  const auto held = [&](std::size_t k) {
    return std::all_of(channels.begin(), channels.end(), [&](const std::vector<double>& c) { return c[k] == c[k - 1]; });
  };
  // Held frames repeat rows wherever the swing is: with fewer than a tenth
  // of the rows repeating there are none (a pass without allocation, for
  // every sampled recording).
  std::size_t repeats = 0;
  for (std::size_t k = 1; k < n; ++k) repeats += held(k);
  if (10 * repeats < n) return out;
  const std::vector<double>& s = channels.front();
  const double centre = median_of(s);
  std::vector<double> excursion(n);
  for (std::size_t k = 0; k < n; ++k) excursion[k] = std::fabs(s[k] - centre);
  // The extent: the 90th percentile of |s - median|, a knock's few samples aside.
  std::vector<double> sorted = excursion;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(9 * n / 10), sorted.end());
  const double extent = sorted[9 * n / 10];
  // Runs of rows holding one value, by where each starts: in the swing's
  // fast middle (within half its extent of the median) or beyond.
  std::vector<double> middle_runs, outer_runs, frames;
  for (std::size_t k = 1, start = 0; k <= n; ++k) {
    if (k < n && held(k)) continue;
    (excursion[start] < extent / 2.0 ? middle_runs : outer_runs).push_back(static_cast<double>(k - start));
    if (k < n) frames.push_back(time[k] - time[start]), start = k;
  }
  // Frames held by a poll are as long wherever the swing is; a sensor's
  // rounding repeats where the swing is slow, its runs longest where it turns.
  if (!(extent > 0.0) || middle_runs.size() < 8 || outer_runs.size() < 8 || frames.empty()) return out;
  const double middle = median_of(middle_runs);
  std::nth_element(outer_runs.begin(), outer_runs.begin() + static_cast<long>(9 * outer_runs.size() / 10), outer_runs.end());
  const double outer = outer_runs[9 * outer_runs.size() / 10];  // the 90th percentile: the runs at the turns
  if (!(middle >= 2.0) || !(outer <= 2.0 * middle)) return out;
  out.quantum = median_of(frames);
  out.notes.push_back({0, std::to_string(repeats) + " of " + std::to_string(n) + " samples repeat the one before in "
                          "every column, in runs of " + format_number(middle, 3) + " rows (the median) in the "
                          "swing's fast middle and at most " + format_number(outer, 3) + " (9 in 10) where it turns: held frames, a "
                          "new one every " + seconds(out.quantum) + " (the median), so a sample's stamp tells its "
                          "frame's time to that, the crossings' time resolution"});
  return out;
}

}  // namespace pendulum::recording_text
