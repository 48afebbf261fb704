// Throughput of the segment/triangle kernels, data laid out as the hardware streams it (paper
// sec 4.1): one face and one start point fixed, end points streamed from X, Y and Z arrays.
// Reports tests per second ("items_per_second").
//
//   build-pipeline/bench/bench_pipeline --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "pipeline/fixed_mt.h"
#include "pipeline/reference_mt.h"

namespace {

constexpr std::size_t kRays = 4096;  // a batch of end points that stays in L1/L2

struct Workload {
  rc::Triangle face;
  rc::Vec3 start;
  std::vector<rc::Vec3> ends;
};

// About a third of the segments hit the face, like a blocker in the middle of a room.
const Workload& workload() {
  static const Workload w = [] {
    std::mt19937_64 rng(2024);
    const auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
    Workload made{{{0.2, 0.3, 0.5}, {0.8, 0.35, 0.45}, {0.4, 0.9, 0.55}}, {0.5, 0.5, 0.05}, {}};
    for (std::size_t i = 0; i < kRays; ++i) made.ends.push_back({u(), u(), 0.5 + 0.49 * u()});
    return made;
  }();
  return w;
}

// range(1) picks the instruction-set variant: 0 baseline (SSE2), 1 x86-64-v3 (AVX2),
// 2 x86-64-v4 (AVX-512); the default entry point uses best_kernel_isa() (the best the CPU
// supports, capped by RC2000SIM_SIMD). Variants the CPU cannot run or above the cap are skipped.
bool select_isa(benchmark::State& state, int index, rc::pipeline::KernelIsa& isa) {
  isa = static_cast<rc::pipeline::KernelIsa>(index);
  state.SetLabel(rc::pipeline::simd_name(isa));
  if (!rc::pipeline::is_supported(isa)) {
    state.SkipWithError("instruction set not supported on this CPU");
    return false;
  }
  if (isa > rc::pipeline::best_kernel_isa()) {
    state.SkipWithError("instruction set above the RC2000SIM_SIMD cap");
    return false;
  }
  return true;
}

// The workload's end points as the X, Y and Z ray banks hold them.
struct QuantisedEnds {
  std::vector<std::int64_t> x, y, z;
  QuantisedEnds(const Workload& w, int bits) {
    for (const rc::Vec3& e : w.ends) {
      const rc::pipeline::FixedVec3 q = rc::pipeline::quantize_point(e, bits);
      x.push_back(q.x);
      y.push_back(q.y);
      z.push_back(q.z);
    }
  }
};

void BM_FixedKernel(benchmark::State& state) {
  const int bits = static_cast<int>(state.range(0));
  rc::pipeline::KernelIsa isa;
  if (!select_isa(state, static_cast<int>(state.range(1)), isa)) return;
  const Workload& w = workload();
  const rc::pipeline::FaceRecord face = rc::pipeline::make_face_record(w.face, bits);
  const rc::pipeline::FixedVec3 start = rc::pipeline::quantize_point(w.start, bits);
  const QuantisedEnds ends(w, bits);
  const std::vector<std::int64_t>&x = ends.x, &y = ends.y, &z = ends.z;
  std::vector<std::uint8_t> blocked(kRays, 0);
  for (auto _ : state) {
    rc::pipeline::occlude_face(isa, face, start, x.data(), y.data(), z.data(), kRays, bits,
                               blocked.data());
    benchmark::DoNotOptimize(blocked.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}
BENCHMARK(BM_FixedKernel)->ArgsProduct({{7, 15, 16, 23, 31}, {0, 1, 2}});

void BM_FixedKernelMasked(benchmark::State& state) {
  const int bits = static_cast<int>(state.range(0));
  const Workload& w = workload();
  const rc::pipeline::FaceRecord face = rc::pipeline::make_face_record(w.face, bits);
  const rc::pipeline::FixedVec3 start = rc::pipeline::quantize_point(w.start, bits);
  const QuantisedEnds ends(w, bits);
  const std::vector<std::int64_t>&x = ends.x, &y = ends.y, &z = ends.z;
  std::vector<std::uint8_t> blocked(kRays, 0), skip(kRays, 0);
  for (std::size_t i = 0; i < kRays; i += 7) skip[i] = 1;
  for (auto _ : state) {
    rc::pipeline::occlude_face(face, start, x.data(), y.data(), z.data(), kRays, bits, blocked.data(),
                               skip.data());
    benchmark::DoNotOptimize(blocked.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}
BENCHMARK(BM_FixedKernelMasked)->Arg(15)->Arg(31);

// The same stream with a guard band on t (--t-guard G): its own loop (fixed_mt.cpp), so the paper's test
// (G = 0, BM_FixedKernel) keeps its code; this measures what the guard's extra subtraction costs.
void BM_FixedKernelTGuard(benchmark::State& state) {
  const int bits = static_cast<int>(state.range(0));
  const int guard = static_cast<int>(state.range(1));
  const Workload& w = workload();
  const rc::pipeline::FaceRecord face = rc::pipeline::make_face_record(w.face, bits);
  const rc::pipeline::FixedVec3 start = rc::pipeline::quantize_point(w.start, bits);
  const QuantisedEnds ends(w, bits);
  const std::vector<std::int64_t>&x = ends.x, &y = ends.y, &z = ends.z;
  std::vector<std::uint8_t> blocked(kRays, 0);
  for (auto _ : state) {
    rc::pipeline::occlude_face(face, start, x.data(), y.data(), z.data(), kRays, bits, blocked.data(), nullptr, guard);
    benchmark::DoNotOptimize(blocked.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}
BENCHMARK(BM_FixedKernelTGuard)->ArgsProduct({{15, 31}, {0, 2}});

// One segment at a time through the scalar entry point: the cost without the streaming layout.
void BM_FixedScalar(benchmark::State& state) {
  const int bits = static_cast<int>(state.range(0));
  const Workload& w = workload();
  const rc::pipeline::FaceRecord face = rc::pipeline::make_face_record(w.face, bits);
  const rc::pipeline::FixedVec3 start = rc::pipeline::quantize_point(w.start, bits);
  std::vector<rc::pipeline::FixedVec3> ends;
  for (const rc::Vec3& e : w.ends) ends.push_back(rc::pipeline::quantize_point(e, bits));
  for (auto _ : state) {
    std::size_t hits = 0;
    for (const auto& e : ends) hits += rc::pipeline::segment_hits(face, start, e, bits);
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}
BENCHMARK(BM_FixedScalar)->Arg(15)->Arg(31);

void BM_FloatKernel(benchmark::State& state) {
  rc::pipeline::KernelIsa isa;
  if (!select_isa(state, static_cast<int>(state.range(0)), isa)) return;
  const Workload& w = workload();
  std::vector<float> x, y, z;
  for (const rc::Vec3& e : w.ends) {
    x.push_back(static_cast<float>(e.x));
    y.push_back(static_cast<float>(e.y));
    z.push_back(static_cast<float>(e.z));
  }
  std::vector<std::uint8_t> blocked(kRays, 0);
  for (auto _ : state) {
    rc::pipeline::occlude_face_float(isa, w.face, w.start, x.data(), y.data(), z.data(), kRays,
                                     blocked.data());
    benchmark::DoNotOptimize(blocked.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}
BENCHMARK(BM_FloatKernel)->Arg(0)->Arg(1)->Arg(2);

void BM_DoubleScalar(benchmark::State& state) {
  const Workload& w = workload();
  for (auto _ : state) {
    std::size_t hits = 0;
    for (const rc::Vec3& e : w.ends) hits += rc::pipeline::segment_hits_ref(w.face, w.start, e);
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}
BENCHMARK(BM_DoubleScalar);

}  // namespace

BENCHMARK_MAIN();
