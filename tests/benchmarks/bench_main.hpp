#pragma once
// main() of a benchmark that can also export its data sets for a peer
// (scipy) to fit: `bench_X --export DIR` calls export_data(DIR), anything
// else runs Google Benchmark.
#include <benchmark/benchmark.h>

#include <cstring>
#include <string>

namespace pendulum::bench {

template <class Export>
int main_with_export(int argc, char** argv, Export&& export_data) {
  if (argc == 3 && std::strcmp(argv[1], "--export") == 0) return export_data(std::string(argv[2]));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace pendulum::bench
