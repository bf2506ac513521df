// The recording reader's number fast path (lib/src/recordings/number.hpp:
// Clinger's, std::from_chars behind it) against std::from_chars alone
// (libstdc++ 12 parses decimals with a copy of fast_float inside) and
// fast_float::from_chars (Debian's libfast-float-dev 3.9, header-only, so
// inlined like ours), on the same text: 10^6 numbers, each followed by a tab,
// in the two spellings recordings use. "phyphox": 1.234567890E-1, as phyphox
// writes every value (uniform in +-5, as a gyroscope's rad/s, and in 0 to
// 3600, as times); "decimals": %.4f of the same values, as Tracker, Logger Pro
// and OpenCV scripts write. Every method must give the same doubles bit for
// bit, or the benchmark stops with an error. Usage:
//   bench_numbers --benchmark_repetitions=9 --benchmark_enable_random_interleaving=true
#include <benchmark/benchmark.h>
#include <fast_float/fast_float.h>

#include <charconv>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "number.hpp"

namespace {

/// 10^6 numbers in `format`, each followed by a tab (seed 11).
const std::string& text(const char* format) {
  static std::string phyphox, decimals;
  std::string& out = std::strcmp(format, "%.9E") == 0 ? phyphox : decimals;
  if (!out.empty()) return out;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> rate(-5.0, 5.0), time(0.0, 3600.0);
  char cell[64];
  for (int i = 0; i < 1000000; ++i) {
    const int n = std::snprintf(cell, sizeof cell, format, i % 4 == 0 ? time(rng) : rate(rng));
    out.append(cell, static_cast<std::size_t>(n)).push_back('\t');
  }
  return out;
}

/// The reader's way: the fast path, std::from_chars where it does not apply.
const char* ours(const char* p, const char* end, double& v) {
  const char* stop = pendulum::recording_text::fast_number(p, end, '.', v);
  return stop ? stop : std::from_chars(p, end, v).ptr;
}
const char* standard(const char* p, const char* end, double& v) { return std::from_chars(p, end, v).ptr; }
const char* fast_float_peer(const char* p, const char* end, double& v) { return fast_float::from_chars(p, end, v).ptr; }

template <const char* (*Parse)(const char*, const char*, double&)>
std::vector<double> parse_all(const std::string& s) {
  std::vector<double> values;
  values.reserve(1000000);
  const char* end = s.data() + s.size();
  for (const char* p = s.data(); p < end;) {
    double v;
    p = Parse(p, end, v) + 1;  // past the tab
    values.push_back(v);
  }
  return values;
}

template <const char* (*Parse)(const char*, const char*, double&)>
void BM_Parse(benchmark::State& state, const char* format) {
  const std::string& s = text(format);
  const std::vector<double> mine = parse_all<ours>(s), theirs = parse_all<Parse>(s);
  if (mine.size() != 1000000 ||
      std::memcmp(mine.data(), theirs.data(), mine.size() * sizeof(double)) != 0) {
    state.SkipWithError("the methods disagree on a number");
    return;
  }
  const char* end = s.data() + s.size();
  for (auto _ : state) {
    double sum = 0.0;
    for (const char* p = s.data(); p < end;) {
      double v;
      p = Parse(p, end, v) + 1;
      sum += v;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 1000000);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * s.size()));
}

}  // namespace

int main(int argc, char** argv) {
  for (const auto& [spelling, format] : {std::pair{"phyphox", "%.9E"}, std::pair{"decimals", "%.4f"}}) {
    const std::string name = std::string("BM_Parse/") + spelling + "/";
    benchmark::RegisterBenchmark((name + "ours").c_str(), BM_Parse<ours>, format)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((name + "std_from_chars").c_str(), BM_Parse<standard>, format)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((name + "fast_float").c_str(), BM_Parse<fast_float_peer>, format)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
