// End-to-end wall time of the paper's eight Cornell Box configurations (Table 2: 70/280 ...
// 1120/4480 faces/patches) solved with the fast bit-exact visibility backend: the full
// ProgressiveRadiosity run, run for the paper's step counts (385 / 1488 / 5889 steps for 280 /
// 1120 / 4480 patches) unless told otherwise. Prints wall seconds per scene and in total, and the
// segment-face tests actually run against what the brute-force backend would have run.
//
//   build-fast/bench/visibility_wall                  # all 8 scenes, 15 bits, all cores
//   build-fast/bench/visibility_wall --bits 23 --threads 1 --steps 200
//   build-fast/bench/visibility_wall --converge       # 99.5% convergence instead of step counts
//   build-fast/bench/visibility_wall --brute --only 70/280   # FixedPointVisibility, for reference
//
// Options: --bits N (7..31, default 15), --threads T (0 = all cores, default), --steps S (every
// scene), --converge, --only F/P (one scene), --brute.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "host_sw/visibility/fast_visibility.h"
#include "host_sw/visibility/fixed_visibility.h"
#include "host_sw/radiosity/radiosity.h"
#include "scenes/prepare.h"

namespace {

struct PaperScene {
  int faces, patches;
  int face_levels, patch_levels;  // from the 70-face refinement of the Cornell Box
  int steps;                      // the paper's lighting steps for this patch count
};

// 70 faces, split into 4^face_levels faces, each split into 4^patch_levels patches.
constexpr PaperScene kPaperScenes[] = {
    {70, 280, 0, 1, 385},       {70, 1120, 0, 2, 1488},    {70, 4480, 0, 3, 5889},
    {280, 280, 1, 0, 385},      {280, 1120, 1, 1, 1488},   {280, 4480, 1, 2, 5889},
    {1120, 1120, 2, 0, 1488},   {1120, 4480, 2, 1, 5889},
};

// Answers "clear" for every segment without testing anything: what the solver costs on its own.
class NoVisibility : public rc::VisibilityBackend {
 public:
  std::string name() const override { return "none"; }
  void load_triangles(const std::vector<rc::Triangle>& ) override {}
  void submit(const rc::SegmentBatch& batch) override { n_ = batch.size(); }
  void collect(std::vector<std::uint8_t>& blocked) override { blocked.assign(n_, 0); }
  std::uint64_t tests_performed() const override { return 0; }

 private:
  std::size_t n_ = 0;
};

struct Options {
  int bits = 15;
  int threads = 0;
  int steps = 0;
  bool converge = false;
  bool brute = false;
  bool none = false;
  std::string only;
};

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr, "visibility_wall: %s\nusage: visibility_wall [--bits N] [--threads T] "
                       "[--steps S | --converge] [--only FACES/PATCHES] [--brute]\n", why);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage(("missing value after " + arg).c_str());
      return argv[++i];
    };
    if (arg == "--bits") o.bits = std::atoi(value());
    else if (arg == "--threads") o.threads = std::atoi(value());
    else if (arg == "--steps") o.steps = std::atoi(value());
    else if (arg == "--only") o.only = value();
    else if (arg == "--converge") o.converge = true;
    else if (arg == "--brute") o.brute = true;
    else if (arg == "--no-visibility") o.none = true;
    else usage(("unknown option " + arg).c_str());
  }
  return o;
}

struct SceneRun {
  double seconds = 0;
  int steps = 0;
  std::uint64_t segments = 0, tests = 0, brute_force = 0;
};

SceneRun run_scene(const PaperScene& p, const Options& o) {
  rc::SceneOptions scene_options;
  scene_options.face_target = 70;
  scene_options.face_levels = p.face_levels;
  scene_options.patch_levels = p.patch_levels;
  const rc::Scene scene = rc::prepare_scene(scene_options).scene;
  if (static_cast<int>(scene.faces.size()) != p.faces || static_cast<int>(scene.patches.size()) != p.patches) {
    std::fprintf(stderr, "scene has %zu faces and %zu patches, expected %d and %d\n",
                 scene.faces.size(), scene.patches.size(), p.faces, p.patches);
    std::exit(1);
  }
  rc::SolverOptions solver;
  if (!o.converge) solver.fixed_steps = o.steps > 0 ? o.steps : p.steps;

  std::unique_ptr<rc::VisibilityBackend> backend;
  rc::FastFixedVisibility* fast = nullptr;
  if (o.none) {
    backend = std::make_unique<NoVisibility>();
  } else if (o.brute) {
    backend = std::make_unique<rc::FixedPointVisibility>(o.bits);
  } else {
    auto f = std::make_unique<rc::FastFixedVisibility>(o.bits, o.threads);
    fast = f.get();
    backend = std::move(f);
  }
  const auto begin = std::chrono::steady_clock::now();
  const rc::SolverResult result = rc::ProgressiveRadiosity(scene, *backend, solver).run();
  const auto end = std::chrono::steady_clock::now();

  SceneRun r;
  r.seconds = std::chrono::duration<double>(end - begin).count();
  r.steps = result.steps;
  r.segments = result.segments;
  r.tests = backend->tests_performed();
  r.brute_force = fast ? fast->brute_force_tests() : r.tests;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::printf("backend %s, %d bits, %s\n", o.brute ? "fixed (brute force)" : "fast", o.bits,
              o.converge ? "99.5% convergence" : "fixed step counts");
  std::printf("%6s %8s %6s %9s %12s %16s %18s %10s\n", "faces", "patches", "steps", "wall s",
              "segments", "tests run", "brute-force tests", "run/brute");
  double total = 0;
  std::uint64_t tests = 0, brute = 0;
  for (const PaperScene& p : kPaperScenes) {
    if (!o.only.empty() && o.only != std::to_string(p.faces) + "/" + std::to_string(p.patches)) continue;
    const SceneRun r = run_scene(p, o);
    total += r.seconds;
    tests += r.tests;
    brute += r.brute_force;
    std::printf("%6d %8d %6d %9.3f %12llu %16llu %18llu %10.2e\n", p.faces, p.patches, r.steps,
                r.seconds, static_cast<unsigned long long>(r.segments),
                static_cast<unsigned long long>(r.tests), static_cast<unsigned long long>(r.brute_force),
                r.brute_force ? double(r.tests) / double(r.brute_force) : 0.0);
    std::fflush(stdout);
  }
  std::printf("total wall %.3f s, tests run %llu of %llu brute force (%.2e)\n", total,
              static_cast<unsigned long long>(tests), static_cast<unsigned long long>(brute),
              brute ? double(tests) / double(brute) : 0.0);
  return 0;
}
