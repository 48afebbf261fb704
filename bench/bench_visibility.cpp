// Segments per second of whole visibility steps on real radiosity segments: the fast bit-exact
// backend (FastFixedVisibility), the brute-force bit-exact backend (FixedPointVisibility) and
// Embree 3's rtcOccluded1 (float, the same triangles, the same own-face rule through an occlusion
// filter). The segments are every segment of the first kSteps shooting steps of the paper's
// largest scene (1120 faces, 4480 patches), recorded once by running the solver.
//
//   build-fast/bench/bench_visibility --benchmark_min_time=1
//   build-fast/bench/bench_visibility --benchmark_filter='BM_FastFixed/.*/threads:1'
//       --benchmark_repetitions=5 --benchmark_report_aggregates_only=true   (one line)
//
// BM_FastFixed runs once per instruction-set variant this CPU runs (avx512, avx2, baseline; capped
// by RC2000SIM_SIMD, pipeline/kernel_isa.h), the variants of one width next to each other.
//
// Counters: items_per_second = segments/s (wall clock); on the fast backend, x_embree = its
// segments/s over Embree's on the same segments, Embree run off the clock in every iteration so
// that both see the same machine load; tests_per_segment = kernel tests actually run per segment
// (the brute force runs about 1119).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "host_sw/visibility/fast_visibility.h"
#include "host_sw/visibility/fixed_visibility.h"
#include "host_sw/radiosity/radiosity.h"
#include "pipeline/kernel_isa.h"
#include "scenes/prepare.h"

#if RC_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace {

constexpr int kSteps = 32;

struct Workload {
  std::vector<rc::Triangle> faces;
  std::vector<rc::SegmentBatch> batches;
  std::size_t segments = 0;
};

// Passes every batch on to a backend and keeps a copy.
class Recorder : public rc::VisibilityBackend {
 public:
  Recorder(rc::VisibilityBackend& inner, Workload& out) : inner_(inner), out_(out) {}
  std::string name() const override { return "recorder"; }
  void load_triangles(const std::vector<rc::Triangle>& faces) override {
    out_.faces = faces;
    inner_.load_faces(faces, sheets());
  }
  void submit(const rc::SegmentBatch& batch) override {
    out_.batches.push_back(batch);
    out_.segments += batch.size();
    inner_.submit(batch);
  }
  void collect(std::vector<std::uint8_t>& blocked) override { inner_.collect(blocked); }
  std::uint64_t tests_performed() const override { return inner_.tests_performed(); }

 private:
  rc::VisibilityBackend& inner_;
  Workload& out_;
};

const Workload& workload() {
  static const Workload w = [] {
    rc::SceneOptions options;
    options.face_target = 70;
    options.face_levels = 2;
    options.patch_levels = 1;
    const rc::Scene scene = rc::prepare_scene(options).scene;
    Workload made;
    rc::FastFixedVisibility fast(15, 1);
    Recorder recorder(fast, made);
    rc::SolverOptions solver;
    solver.fixed_steps = kSteps;
    rc::ProgressiveRadiosity(scene, recorder, solver).run();
    return made;
  }();
  return w;
}

// Runs every recorded batch through the backend; returns the number of blocked segments.
std::size_t run_batches(rc::VisibilityBackend& backend, const Workload& w) {
  std::vector<std::uint8_t> blocked;
  std::size_t count = 0;
  for (const rc::SegmentBatch& batch : w.batches) {
    backend.submit(batch);
    backend.collect(blocked);
    for (std::uint8_t b : blocked) count += b;
  }
  return count;
}

#if RC_HAVE_EMBREE

// Embree's answer to the same question: float triangles, each segment a ray from start with
// tnear = 0 and tfar = 1 (direction = end - start), own faces rejected by an occlusion filter.
class EmbreeScene {
 public:
  explicit EmbreeScene(const std::vector<rc::Triangle>& faces) {
    device_ = rtcNewDevice(nullptr);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), 3 * faces.size()));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), faces.size()));
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const rc::Vec3* corners[3] = {&faces[f].v0, &faces[f].v1, &faces[f].v2};
      for (int c = 0; c < 3; ++c) {
        v[9 * f + 3 * c] = static_cast<float>(corners[c]->x);
        v[9 * f + 3 * c + 1] = static_cast<float>(corners[c]->y);
        v[9 * f + 3 * c + 2] = static_cast<float>(corners[c]->z);
        idx[3 * f + c] = static_cast<unsigned>(3 * f + c);
      }
    }
    rtcSetGeometryOccludedFilterFunction(geom, &EmbreeScene::skip_own_faces);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_);
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }

  std::size_t occluded(const rc::SegmentBatch& batch) const {
    OwnFaces context;
    rtcInitIntersectContext(&context.base);
    context.source = static_cast<unsigned>(batch.source_face);
    std::size_t count = 0;
    for (std::size_t s = 0; s < batch.size(); ++s) {
      context.end = static_cast<unsigned>(batch.end_faces[s]);
      RTCRay ray{};
      ray.org_x = static_cast<float>(batch.start.x);
      ray.org_y = static_cast<float>(batch.start.y);
      ray.org_z = static_cast<float>(batch.start.z);
      ray.dir_x = static_cast<float>(batch.ends[s].x - batch.start.x);
      ray.dir_y = static_cast<float>(batch.ends[s].y - batch.start.y);
      ray.dir_z = static_cast<float>(batch.ends[s].z - batch.start.z);
      ray.tnear = 0.0f;
      ray.tfar = 1.0f;
      ray.mask = 0xffffffffu;
      rtcOccluded1(scene_, &context.base, &ray);
      count += ray.tfar < 0.0f;  // Embree sets tfar to -inf on occlusion
    }
    return count;
  }

 private:
  // The context Embree hands to the filter, extended with the segment's own faces.
  struct OwnFaces {
    RTCIntersectContext base;
    unsigned source = 0, end = 0;
  };
  static void skip_own_faces(const RTCFilterFunctionNArguments* args) {
    const auto* own = reinterpret_cast<const OwnFaces*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
      const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
      if (prim == own->source || prim == own->end) args->valid[i] = 0;
    }
  }

  RTCDevice device_;
  RTCScene scene_;
};

const EmbreeScene& embree_scene() {
  static const EmbreeScene scene(workload().faces);
  return scene;
}

std::size_t run_embree(const Workload& w) {
  std::size_t count = 0;
  for (const rc::SegmentBatch& batch : w.batches) count += embree_scene().occluded(batch);
  return count;
}

void BM_EmbreeOccluded1(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t blocked = 0;
  for (auto _ : state) benchmark::DoNotOptimize(blocked = run_embree(w));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w.segments));
  state.counters["blocked"] = static_cast<double>(blocked);
  state.SetLabel(std::to_string(w.faces.size()) + " faces, " + std::to_string(w.segments) + " segments");
}
BENCHMARK(BM_EmbreeOccluded1)->Unit(benchmark::kMillisecond)->UseRealTime();

#endif  // RC_HAVE_EMBREE

// range(0): fractional bits; range(1): threads; the instruction-set variant (kernel_isa.h) is
// the benchmark's name's first part (registered in main). Every iteration also runs Embree on the
// same segments, off the clock, so that x_embree compares the two under the same machine load.
void BM_FastFixed(benchmark::State& state, rc::pipeline::KernelIsa isa) {
  using Clock = std::chrono::steady_clock;
  const Workload& w = workload();
  const int bits = static_cast<int>(state.range(0));
  rc::FastFixedVisibility fast(bits, static_cast<int>(state.range(1)), isa);
  fast.load_faces(w.faces);
  run_batches(fast, w);  // first pass fills the end-point catalogue, as a solver's first steps do
  const std::uint64_t tests_before = fast.tests_performed();
  std::size_t blocked = 0;
  double fast_seconds = 0, embree_seconds = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    benchmark::DoNotOptimize(blocked = run_batches(fast, w));
    fast_seconds += std::chrono::duration<double>(Clock::now() - t0).count();
#if RC_HAVE_EMBREE
    state.PauseTiming();
    const auto t1 = Clock::now();
    benchmark::DoNotOptimize(run_embree(w));
    embree_seconds += std::chrono::duration<double>(Clock::now() - t1).count();
    state.ResumeTiming();
#endif
  }
  const double segments = static_cast<double>(state.iterations() * w.segments);
  state.SetItemsProcessed(static_cast<std::int64_t>(segments));
  state.counters["blocked"] = static_cast<double>(blocked);
  state.counters["tests_per_segment"] = static_cast<double>(fast.tests_performed() - tests_before) / segments;
  if (embree_seconds > 0) state.counters["x_embree"] = embree_seconds / fast_seconds;
}
void BM_BruteForceFixed(benchmark::State& state) {
  const Workload& w = workload();
  rc::FixedPointVisibility brute(static_cast<int>(state.range(0)));
  brute.load_faces(w.faces);
  std::size_t blocked = 0;
  for (auto _ : state) benchmark::DoNotOptimize(blocked = run_batches(brute, w));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w.segments));
  state.counters["blocked"] = static_cast<double>(blocked);
}
BENCHMARK(BM_BruteForceFixed)->ArgName("bits")->Arg(15)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

// BM_FastFixed/<variant>/bits:B/threads:T for every variant allowed (the CPU's, up to the cap
// RC2000SIM_SIMD sets), one thread, the widths side by side, best variant first; and two threads on
// the best variant.
int main(int argc, char** argv) {
  std::vector<rc::pipeline::KernelIsa> isas;
  try {
    isas = rc::pipeline::allowed_kernel_isas();
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "bench_visibility: %s\n", e.what());
    return 1;
  }
  const auto add = [](rc::pipeline::KernelIsa isa, int bits, int threads) {
    const std::string name = std::string("BM_FastFixed/") + rc::pipeline::simd_name(isa);
    benchmark::RegisterBenchmark(name.c_str(), BM_FastFixed, isa)
        ->ArgNames({"bits", "threads"})
        ->Args({bits, threads})
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();  // wall time: the helper threads' work is not on the main thread's clock
  };
  for (int bits : {15, 7, 31, 11, 23}) {
    for (auto isa = isas.rbegin(); isa != isas.rend(); ++isa) add(*isa, bits, 1);
  }
  add(isas.back(), 15, 2);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
