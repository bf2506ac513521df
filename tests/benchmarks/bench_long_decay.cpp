// Speed against error for a long decay (docs/recordings.md, "A long decay,
// swing by swing"): a rotary sensor's 375 s log (tests/long_decay.hpp,
// seed 40 + start) released at 5 to 90 deg, reduced (a) as one mean period
// at the start amplitude, (a') the same with the decay correction (Eq. 50),
// (b) one mean period at the swings' mean amplitude, (c) swing by swing.
// Each benchmark times the reduction of the parsed scene (reduce_scene(); for (c)
// with the grouping, swing_groups()); reading and analysing the recording,
// common to all, is BM_ReadRecording. Counters: the error of g against the
// simulation's (the length is exact, so g's uncertainty is the period's),
// in its own standard uncertainties and in ppm, and the rule's shift.
//   bench_long_decay [google-benchmark flags]
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <numeric>
#include <string>

#include "../long_decay.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/reduce_scene.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/recordings/swing_series.hpp"
#include "pendulum/json/scene_json.hpp"

namespace {

using namespace pendulum;
using namespace pendulum::test;

constexpr double kDuration = 375.0;

std::string folder_for(int start_deg) {
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("pendulum_g_bench_long_decay_" + std::to_string(start_deg))).string();
  if (!std::filesystem::exists(dir + "/decay.csv")) {
    std::filesystem::create_directories(dir);
    write_long_decay(dir + "/decay.csv", start_deg, kDuration, 40 + start_deg);
  }
  return dir;
}

void BM_ReadRecording(benchmark::State& state) {
  const std::string file = folder_for(static_cast<int>(state.range(0))) + "/decay.csv";
  for (auto _ : state) {
    const RecordingSummary r = analyse_recording(file);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_ReadRecording)->Arg(81)->Unit(benchmark::kMillisecond);

void BM_Reduce(benchmark::State& state) {
  const int start = static_cast<int>(state.range(0));
  const auto method = static_cast<LongDecayMethod>(state.range(1));
  SceneFiles files;
  files.directory = folder_for(start);
  const RecordingSummary r = analyse_recording(*files.directory + "/decay.csv");
  const auto& theta = r.swings.decay.amplitudes;
  const double mean_deg = std::accumulate(theta.begin(), theta.end(), 0.0) / theta.size() * 180.0 / M_PI;
  const ParsedScene scene = parse_scene(long_decay_scene("decay.csv", method, mean_deg), files);
  const bool by_swing = method == LongDecayMethod::swing_by_swing;
  Analysis a;
  try {
    a = reduce_scene(scene);
  } catch (const InputError& refused) {  // Eq. 50 beyond its first order at 90 deg: a row, not an abort
    state.SkipWithError(refused.what());
    return;
  }
  for (auto _ : state) {
    if (by_swing) {
      const std::vector<SwingGroup> groups = swing_groups(scene.recordings[0].summary.swings);
      benchmark::DoNotOptimize(groups);
    }
    a = reduce_scene(scene);
    benchmark::DoNotOptimize(a);
  }
  const double sigma = a.g.uncertainty.value_or(NAN);
  state.counters["g_error_sigma"] = (a.g.value - kLongDecayG) / sigma;
  state.counters["g_error_ppm"] = (a.g.value - kLongDecayG) / kLongDecayG * 1e6;
  state.counters["g_sigma_ppm"] = sigma / kLongDecayG * 1e6;
  state.counters["observations"] = static_cast<double>(scene.observations.size());
  const SwingAnalysis& s = r.swings;
  state.counters["shift_sigmas"] = amplitude_shift_sigmas(s, true);
  state.counters["shift_sigmas_no_decay"] = amplitude_shift_sigmas(s, false);
}
BENCHMARK(BM_Reduce)
    ->ArgsProduct({{5, 10, 20, 30, 45, 60, 81, 90}, {0, 1, 2, 3}})
    ->ArgNames({"start_deg", "method"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
