// finite_amplitude_agm over many amplitudes (pendulum/amplitude.hpp). One
// amplitude at a time, the three cases of detail::finite_amplitude_exact are
// a branch the processor mispredicts on mixed amplitudes and the compiler
// cannot vectorise. Here each block of amplitudes is sorted into the three
// cases without a branch, each case runs as a straight loop over its own
// contiguous values (vectorised: the first two cases are arithmetic and
// sqrt; the third, above 160 deg, calls log and stays scalar), and the
// results go back in place. A block wholly in the first case (below 90 deg)
// is not sorted: the sorting cost more than the formula. Compiled with -ffp-contract=off (lib/CMakeLists.txt),
// so that no multiply-add is fused: the values are the scalar function's, bit
// for bit, in every instruction set.

#include <algorithm>
#include <cstdint>

#include "pendulum/amplitude.hpp"

namespace pendulum {
namespace {

/// Amplitudes per block: the gathered values and indices stay in L1.
constexpr std::size_t kBlock = 256;

// One copy per instruction set, chosen at run time (target_clones takes no
// templates, hence one function per case). GCC inlines the second case's
// formula, which a vectorised loop needs, only when told to (flatten); clang
// (the sanitizer build) refuses flatten beside target_clones.
#if defined(__clang__)
#define PENDULUM_INLINE_ALL
#else
#define PENDULUM_INLINE_ALL , flatten
#endif
#define PENDULUM_CASE_LOOP(name, formula)                                                               \
  __attribute__((target_clones("avx512f", "avx2", "default") PENDULUM_INLINE_ALL)) void name(           \
      const double* in, double* out, std::size_t n) {                                                   \
    for (std::size_t j = 0; j < n; ++j) out[j] = detail::formula(in[j]);                                 \
  }
PENDULUM_CASE_LOOP(one_agm_step_loop, exact_one_agm_step<double>)
PENDULUM_CASE_LOOP(two_agm_steps_loop, exact_two_agm_steps<double>)
#undef PENDULUM_CASE_LOOP
#undef PENDULUM_INLINE_ALL

/// Whether every amplitude is valid and in the first case (most pendulums'
/// every amplitude): such a block needs no sorting. A loop without a branch.
bool all_in_first_case(const double* theta0, std::size_t n) {
  bool valid = true;
  double highest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = theta0[i];
    valid &= t >= 0.0;  // false for NaN
    highest = t > highest ? t : highest;
  }
  return valid && highest <= detail::kOneAgmStepLimit;
}

std::size_t agm_block(const double* theta0, double* excess, std::size_t n) {
  if (all_in_first_case(theta0, n)) {
    one_agm_step_loop(theta0, excess, n);
    return n;
  }
  // Every amplitude is written to all three lists and counted in the one of
  // its case: no branch, and the counts stay in registers.
  double first[kBlock], second[kBlock], third[kBlock];
  std::uint16_t at_first[kBlock], at_second[kBlock], at_third[kBlock];
  std::size_t n1 = 0, n2 = 0, n3 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = theta0[i];
    if (!accepts(ranges::amplitude, t)) return i;
    const bool past_first = t > detail::kOneAgmStepLimit, past_second = t > detail::kTwoAgmStepsLimit;
    // The first case takes the amplitude, the others the deficit pi - theta0.
    first[n1] = t;
    second[n2] = third[n3] = detail::deficit_of(t);
    at_first[n1] = at_second[n2] = at_third[n3] = static_cast<std::uint16_t>(i);
    n1 += !past_first;
    n2 += past_first && !past_second;
    n3 += past_second;
  }
  double result[kBlock];
  one_agm_step_loop(first, result, n1);
  for (std::size_t j = 0; j < n1; ++j) excess[at_first[j]] = result[j];
  two_agm_steps_loop(second, result, n2);
  for (std::size_t j = 0; j < n2; ++j) excess[at_second[j]] = result[j];
  for (std::size_t j = 0; j < n3; ++j) excess[at_third[j]] = detail::exact_nome(third[j]);
  return n;
}

}  // namespace

std::size_t finite_amplitude_agm_many(const double* theta0, double* excess, std::size_t n) {
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t size = std::min(kBlock, n - start);
    const std::size_t stop = agm_block(theta0 + start, excess + start, size);
    if (stop < size) {
      agm_block(theta0 + start, excess + start, stop);  // the amplitudes before the bad one
      return start + stop;
    }
  }
  return n;
}

}  // namespace pendulum
