// The functional half of `rc2000sim paper`, one Table 2 scene at a time: the scene solved and
// recorded exactly as prepare_paper_scenes solves it (the paper's construction, every segment,
// point form factors, the bit-exact fast backend at 15 bits, recorded to the paper's steps and on
// to our own convergence, at most 10% more; alone, so its backend's workers use every core). The three 4,480-patch scenes are most
// of paper's CPU time, and not only for visibility: 70/4480 has 70 faces and still costs about as
// much as the other five small scenes together (the solver's per-step work over 4,480 receivers).
//
//   build/bench/bench_paper_scenes [--benchmark_filter=BM_PaperScene/faces:70/patches:4480]
//
// Counters: ns_per_receiver_step = the solve's time / (steps x (patches - 1)): what each
// receiver of each step costs, visibility included.
#include <benchmark/benchmark.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "bench/systemc_benchmark_main.h"
#include "host_sw/studies/paper_workload.h"
#include "host_sw/studies/workload.h"
#include "profiles/profile_document.h"

namespace {

void BM_PaperScene(benchmark::State& state) {
  const rc::PaperRow& row = [&]() -> const rc::PaperRow& {
    static std::vector<rc::PaperRow> rows = rc::load_paper_table(rc::default_paper_table_path());
    for (const rc::PaperRow& r : rows)
      if (r.faces == state.range(0) && r.patches == state.range(1)) return r;
    throw std::runtime_error("bench_paper_scenes: no Table 2 row with these counts");
  }();
  double steps = 0;
  for (auto _ : state) {
    const std::vector<rc::PaperScene> solved = rc::prepare_paper_scenes({row}, "fast", 15, nullptr);
    steps = solved.front().functional.result.steps;
    benchmark::DoNotOptimize(solved.front().functional.recording);
  }
  state.counters["steps"] = steps;
  // Wall seconds per 1e-9 receiver-steps: nanoseconds per receiver-step (shown with an "s").
  state.counters["ns_per_receiver_step"] =
      benchmark::Counter(steps * (row.patches - 1) * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(row.label());
}
BENCHMARK(BM_PaperScene)
    ->ArgNames({"faces", "patches"})
    ->Args({70, 280})
    ->Args({70, 1120})
    ->Args({70, 4480})
    ->Args({280, 280})
    ->Args({280, 1120})
    ->Args({280, 4480})
    ->Args({1120, 1120})
    ->Args({1120, 4480})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

// SystemC's library owns main() and calls sc_main (bench/systemc_benchmark_main.h).
int sc_main(int argc, char** argv) { return rc::bench::run_benchmarks(argc, argv); }
