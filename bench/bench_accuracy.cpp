// `rc2000sim accuracy` at mesh scale (issue 37, item 4): eight fixed-point widths (7, 11, 15, 17, 19,
// 23, 27, 31) measured on the duck of configs/scenes/cornell-duck.json at --patch-levels 0 (4,250
// faces and patches), against double precision, two ways in the same run so that their ratio does
// not depend on the machine:
//   * BM_AccuracyPerWidth: the way `accuracy` worked before host_sw/studies/fidelity.h: the double-
//     precision solve, then per width one after the other its own solve (the fast backend on every
//     core) and a second double-precision solve whose every answer is checked against the width
//     (ComparingVisibility);
//   * BM_AccuracyFidelity: measure_fidelity: one double-precision solve checked against every width
//     at once, then the widths' own solves, jobs() at a time.
// Both give the same steps, errors and decision counts (checked here, and by
// tests/host_sw/studies/fidelity_test.cpp); the figures are in docs/results/performance.md.
//
//   build/bench/bench_accuracy [--benchmark_filter=Fidelity]
#include <benchmark/benchmark.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "bench/systemc_benchmark_main.h"
#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/radiosity/jobs.h"
#include "host_sw/studies/fidelity.h"
#include "host_sw/visibility/comparing_visibility.h"
#include "host_sw/visibility/visibility_factory.h"
#include "scenes/prepare.h"

namespace {

const std::vector<int> kWidths = {7, 11, 15, 17, 19, 23, 27, 31};

const rc::Scene& duck() {
  static const rc::Scene scene = [] {
    rc::SceneOptions o;
    o.file = std::string(RC_SOURCE_DIR) + "/configs/scenes/cornell-duck.json";
    o.patch_levels = 0;
    return rc::prepare_scene(o).scene;
  }();
  return scene;
}

struct Row {
  int steps = 0;
  double rmse = 0;
  std::uint64_t compared = 0, arithmetic_only = 0, double_only = 0;
  bool operator==(const Row& o) const {
    return steps == o.steps && rmse == o.rmse && compared == o.compared && arithmetic_only == o.arithmetic_only &&
           double_only == o.double_only;
  }
};

std::vector<Row>& rows_of(const char* way) {
  static std::vector<Row> per_width, fidelity;
  return std::string(way) == "per-width" ? per_width : fidelity;
}

void check_agreement() {
  const std::vector<Row>&a = rows_of("per-width"), &b = rows_of("fidelity");
  if (!a.empty() && !b.empty() && a != b) throw std::logic_error("bench_accuracy: the two ways disagree");
}

std::vector<Row> per_width(const rc::Scene& scene, const rc::SolverOptions& solver) {
  rc::FloatVisibility reference_answer;
  const rc::SolverResult reference = rc::ProgressiveRadiosity(scene, reference_answer, solver).run();
  std::vector<Row> rows;
  for (int bits : kWidths) {
    Row r;
    auto answer = rc::make_software_visibility("fast", bits);
    const rc::SolverResult solved = rc::ProgressiveRadiosity(scene, *answer, solver).run();
    r.steps = solved.steps;
    r.rmse = rc::compare_solutions(solved.radiosity, reference.radiosity).rmse;
    rc::FloatVisibility float_answer;
    auto shadow = rc::make_software_visibility("fast", bits);
    rc::ComparingVisibility compare(float_answer, *shadow);
    rc::ProgressiveRadiosity(scene, compare, solver).run();
    r.compared = compare.segments_compared();
    r.arithmetic_only = compare.shadow_blocks_answer_clear();
    r.double_only = compare.answer_blocks_shadow_clear();
    rows.push_back(r);
  }
  return rows;
}

std::vector<Row> fidelity(const rc::Scene& scene, const rc::SolverOptions& solver) {
  std::vector<rc::Arithmetic> arithmetics;
  for (int bits : kWidths) arithmetics.push_back(rc::Arithmetic::fixed(bits));
  const rc::FidelityResult f = rc::measure_fidelity(scene, solver, arithmetics);
  std::vector<Row> rows;
  for (const rc::ArithmeticFidelity& a : f.rows)
    rows.push_back({a.run.result.steps, a.error.rmse, a.decisions.compared, a.decisions.arithmetic_only, a.decisions.double_only});
  return rows;
}

template <std::vector<Row> (*Way)(const rc::Scene&, const rc::SolverOptions&)>
void run(benchmark::State& state, const char* way) {
  const rc::Scene& scene = duck();
  std::vector<Row> rows;
  for (auto _ : state) rows = Way(scene, rc::SolverOptions{});
  rows_of(way) = rows;
  check_agreement();
  state.counters["patches"] = static_cast<double>(scene.patches.size());
  state.counters["widths"] = static_cast<double>(kWidths.size());
  state.counters["jobs"] = rc::jobs();
  state.SetLabel(way);
}

void BM_AccuracyPerWidth(benchmark::State& state) { run<per_width>(state, "per-width"); }
void BM_AccuracyFidelity(benchmark::State& state) { run<fidelity>(state, "fidelity"); }

BENCHMARK(BM_AccuracyPerWidth)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK(BM_AccuracyFidelity)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace

// SystemC's library owns main() and calls sc_main (bench/systemc_benchmark_main.h).
int sc_main(int argc, char** argv) { return rc::bench::run_benchmarks(argc, argv); }
