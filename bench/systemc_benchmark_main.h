// For benchmarks that link SystemC, whose library owns main() and calls sc_main: the body of their
// sc_main, which runs Google Benchmark as BENCHMARK_MAIN would.
#pragma once

#include <benchmark/benchmark.h>

namespace rc::bench {

inline int run_benchmarks(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace rc::bench
