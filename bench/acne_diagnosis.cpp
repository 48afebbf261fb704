// Why the fixed-point pipeline's visibility differs from double precision on smooth meshes, and
// what the host-side fixes (host_sw/radiosity/segment_fixes.h) do about it (docs/radiosity.md,
// "Fixed-point acne and its fixes"). Not a benchmark: a measurement program.
//
//   acne_diagnosis mechanism SCENE PATCH_LEVELS BITS[,BITS...] STEPS PER_STEP
//     Along the double solver's trajectory (its first STEPS steps), every needed segment is asked of
//     double precision and of the pipeline at each width; of the segments that differ, up to PER_STEP
//     per step (evenly spaced) are examined face by face: which faces decide them (the faces the
//     pipeline finds hitting and double does not, or the reverse), whether those share a vertex with the
//     segment's start face or end face (ring 1) or a neighbour's (ring 2), where along the segment the
//     deciding face's plane is crossed (in LSBs of the width from either end), and the angle between the
//     segment and the face it leaves or reaches there.
//   acne_diagnosis fixes SCENE PATCH_LEVELS BITS[,BITS...] FIX[;FIX...]
//     FIX: none | offset:K | rings:R | guard:G, or several joined by '+' (guard:G: lanes at BITS + G,
//     coordinates at BITS, i.e. run --bits BITS+G --coordinate-bits BITS). Per width and fix: relative RMSE and max of
//     patch radiosity against the double solve (the accuracy command's definitions), the visibility
//     decisions that differ along the double solve's trajectory, steps, and the host's re-tests per segment.
//   (SCENE "box": the embedded Cornell Box.)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/radiosity/segment_fixes.h"
#include "host_sw/visibility/comparing_visibility.h"
#include "host_sw/visibility/visibility_factory.h"
#include "pipeline/fixed_mt.h"
#include "pipeline/reference_mt.h"
#include "scenes/prepare.h"

using namespace rc;

namespace {

std::vector<std::string> split(const std::string& s, char c) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, c);) out.push_back(part);
  return out;
}

struct Classes {
  std::uint64_t differ = 0, examined = 0;
  std::uint64_t fixed_only = 0, double_only = 0;  // of the examined
  std::uint64_t ring1 = 0, ring2 = 0, other = 0;  // every decider within ring 1 / ring 2 of start or end face; some beyond
  std::uint64_t at_start = 0, at_end = 0;         // decider adjacent (ring 1) to the start face / the end face only
  std::uint64_t off = 0;  // the first decider's plane is not crossed between the ends (t <= 0 or t >= 1)
  std::uint64_t near_start = 0, near_end = 0, middle = 0;  // else: crossing within 8 LSBs of start / of end / between
  std::uint64_t angle[4]{};
  std::uint64_t small_det = 0;  // the first decider's pipeline |det| below 16 LSBs                                 // segment vs the face it leaves/reaches: <1, 1-5, 5-20, >=20 degrees
};

// Watches the double solve: asks each width's pipeline the same batch and examines what differs.
class Diagnose : public VisibilityBackend {
 public:
  Diagnose(std::vector<int> widths, std::size_t per_step) : widths_(std::move(widths)), per_step_(per_step), classes_(widths_.size()) {
    for (int b : widths_) pipelines_.push_back(make_software_visibility("fast", b, 0));
  }
  std::string name() const override { return "diagnose"; }
  void submit(const SegmentBatch& batch) override {
    batch_ = batch;
    reference_.submit(batch);
    for (auto& p : pipelines_) p->submit(batch);
  }
  void collect(std::vector<std::uint8_t>& blocked) override {
    reference_.collect(blocked);
    std::vector<std::uint8_t> fixed;
    for (std::size_t w = 0; w < widths_.size(); ++w) {
      pipelines_[w]->collect(fixed);
      std::vector<std::size_t> differing;
      for (std::size_t s = 0; s < batch_.size(); ++s) {
        if (batch_.is_needed(s) && (fixed[s] != 0) != (blocked[s] != 0)) differing.push_back(s);
      }
      classes_[w].differ += differing.size();
      const std::size_t take = std::min(per_step_, differing.size());
      for (std::size_t k = 0; k < take; ++k) examine(w, differing[k * differing.size() / take], fixed[differing[k * differing.size() / take]] != 0);
    }
    for (std::size_t s = 0; s < batch_.size(); ++s) segments_ += batch_.is_needed(s) ? 1 : 0;
  }
  std::uint64_t tests_performed() const override { return 0; }
  const std::vector<Classes>& classes() const { return classes_; }
  std::uint64_t segments() const { return segments_; }

 private:
  void load_triangles(const std::vector<Triangle>& faces) override {
    faces_ = faces;
    reference_.load_faces(faces, sheets());
    for (auto& p : pipelines_) p->load_faces(faces, sheets());
    ring1_ = vertex_neighbours(faces, 1);
    ring2_ = vertex_neighbours(faces, 2);
  }
  static bool in(const std::vector<std::vector<int>>& n, int of, int f) {
    return of >= 0 && std::binary_search(n[static_cast<std::size_t>(of)].begin(), n[static_cast<std::size_t>(of)].end(), f);
  }
  void examine(std::size_t w, std::size_t s, bool fixed_blocks) {
    const int bits = widths_[w];
    Classes& c = classes_[w];
    ++c.examined;
    ++(fixed_blocks ? c.fixed_only : c.double_only);
    const Vec3 a = batch_.start, b = batch_.ends[s];
    const int sf = batch_.source_face, ef = batch_.end_faces[s];
    const pipeline::FixedVec3 qa = pipeline::quantize_point(a, bits), qb = pipeline::quantize_point(b, bits);
    std::vector<int> deciders;
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
      if (sheets().same(f, sf) || sheets().same(f, ef)) continue;
      const bool hit = fixed_blocks ? pipeline::segment_hits(pipeline::make_face_record(faces_[f], bits), qa, qb, bits)
                                    : pipeline::segment_hits_ref(faces_[f], a, b);
      if (hit) deciders.push_back(f);
    }
    bool all1 = !deciders.empty(), all2 = !deciders.empty();
    for (int f : deciders) {
      all1 &= in(ring1_, sf, f) || in(ring1_, ef, f);
      all2 &= in(ring2_, sf, f) || in(ring2_, ef, f);
    }
    ++(all1 ? c.ring1 : all2 ? c.ring2 : c.other);
    if (deciders.empty()) return;
    const int f = deciders.front();
    if (in(ring1_, sf, f) && !in(ring1_, ef, f)) ++c.at_start;
    if (in(ring1_, ef, f) && !in(ring1_, sf, f)) ++c.at_end;
    const Vec3 n = faces_[f].cross();
    const Vec3 d = b - a;
    const double denom = glm::dot(n, d);
    const double t = denom != 0 ? glm::dot(n, faces_[f].v0 - a) / denom : 0.5;
    const double length_lsb = glm::length(d) * std::ldexp(1.0, bits);
    const bool near_start = t * length_lsb <= 8, near_end = (1 - t) * length_lsb <= 8;
    ++(!(t > 0 && t < 1) ? c.off : near_start ? c.near_start : near_end ? c.near_end : c.middle);
    const Triangle& at = faces_[static_cast<std::size_t>(near_end ? ef : sf)];
    const double sine = std::abs(glm::dot(at.normal(), glm::normalize(d)));
    const double degrees = std::asin(std::min(1.0, sine)) * 180.0 / M_PI;
    ++c.angle[degrees < 1 ? 0 : degrees < 5 ? 1 : degrees < 20 ? 2 : 3];
    const pipeline::Trace first = pipeline::trace(pipeline::make_face_record(faces_[f], bits), qa, qb, bits);
    if (std::llabs(static_cast<long long>(first.values.stage2.det)) < 16) ++c.small_det;
    if (details_ > 0 && w == 0) {
      --details_;
      const double lsb = std::ldexp(1.0, -bits);
      const Vec3 un = glm::normalize(n);
      const pipeline::Trace tr = pipeline::trace(pipeline::make_face_record(faces_[f], bits), qa, qb, bits);
      std::printf("detail %d bits: %s blocks; start face %d (%s), end face %d (%s), decider %d (%s) of %zu, plane crossed at "
                  "%.1f LSB from start, %.1f from end; end %.2f LSB from the decider's plane, start %.2f; decider area %.3g LSB^2; "
                  "segment vs decider %.2f deg; pipeline det %lld t*s %lld u*s %lld v*s %lld (LSB)\n",
                  bits, fixed_blocks ? "fixed" : "double", sf, surface(sf).c_str(), ef, surface(ef).c_str(), f, surface(f).c_str(),
                  deciders.size(), t * length_lsb, (1 - t) * length_lsb, glm::dot(un, b - faces_[f].v0) / lsb,
                  glm::dot(un, a - faces_[f].v0) / lsb, faces_[f].area() / lsb / lsb,
                  std::asin(std::min(1.0, std::abs(glm::dot(un, glm::normalize(d))))) * 180.0 / M_PI, static_cast<long long>(tr.values.stage2.det),
                  static_cast<long long>(tr.values.stage3.t_signed), static_cast<long long>(tr.values.stage3.u_signed),
                  static_cast<long long>(tr.values.stage3.v_signed));
    }
  }
  std::string surface(int f) const { return scene_ ? scene_->surface_name(scene_->faces[static_cast<std::size_t>(f)].surface) : ""; }

 public:
  const Scene* scene_ = nullptr;
  int details_ = 0;

 private:

  std::vector<int> widths_;
  std::size_t per_step_;
  std::vector<Classes> classes_;
  std::vector<std::unique_ptr<VisibilityBackend>> pipelines_;
  FloatVisibility reference_;
  SegmentBatch batch_;
  std::vector<Triangle> faces_;
  std::vector<std::vector<int>> ring1_, ring2_;
  std::uint64_t segments_ = 0;
};

SceneOptions scene_options(const std::string& file, int patch_levels) {
  SceneOptions o;
  if (file != "box") o.file = file;
  o.patch_levels = patch_levels;
  return o;
}

double pct(std::uint64_t a, std::uint64_t b) { return b ? 100.0 * double(a) / double(b) : 0.0; }

int mechanism(const Scene& scene, const std::vector<int>& widths, int steps, std::size_t per_step) {
  Diagnose d(widths, per_step);
  d.scene_ = &scene;
  if (const char* n = std::getenv("ACNE_DETAILS")) d.details_ = std::atoi(n);
  SolverOptions o;
  o.fixed_steps = steps;  // 0: to convergence
  ProgressiveRadiosity(scene, d, o).run();
  std::printf("%zu faces, %zu patches; %d steps (0: all) of the double solve, %llu needed segments\n", scene.faces.size(),
              scene.patches.size(), steps, static_cast<unsigned long long>(d.segments()));
  std::printf("%5s %8s %8s | %6s %6s | %6s %6s %6s | %6s %6s | %6s %6s %6s %6s | %5s %5s %5s %5s | %6s\n", "bits", "differ%", "examined",
              "fixed", "double", "ring1", "ring2", "other", "@start", "@end", "off", "t~0", "t~1", "mid", "<1d", "1-5d", "5-20", ">20d", "det<16");
  for (std::size_t w = 0; w < widths.size(); ++w) {
    const Classes& c = d.classes()[w];
    const auto e = c.examined;
    std::printf("%5d %8.3f %8llu | %6.1f %6.1f | %6.1f %6.1f %6.1f | %6.1f %6.1f | %6.1f %6.1f %6.1f %6.1f | %5.1f %5.1f %5.1f %5.1f | %6.1f\n", widths[w],
                pct(c.differ, d.segments()), static_cast<unsigned long long>(e), pct(c.fixed_only, e), pct(c.double_only, e), pct(c.ring1, e),
                pct(c.ring2, e), pct(c.other, e), pct(c.at_start, e), pct(c.at_end, e), pct(c.off, e), pct(c.near_start, e), pct(c.near_end, e),
                pct(c.middle, e), pct(c.angle[0], e), pct(c.angle[1], e), pct(c.angle[2], e), pct(c.angle[3], e), pct(c.small_det, e));
  }
  std::printf("columns after 'examined': %% of the examined differing segments. fixed/double: which side blocks. ring1/ring2/other:\n"
              "every deciding face shares a vertex with the start or end face / is within two such steps / some is farther.\n"
              "@start/@end: the first decider is a ring-1 neighbour of the start face only / the end face only. off: the segment\n"
              "does not cross its plane at all (t <= 0 or >= 1 in double); t~0, t~1, mid: it does, within 8 LSBs of the start /\n"
              "of the end / between. Last four: angle between the segment and\n"
              "the face it leaves (or reaches, for t~1). det<16: the first decider's |det| in the pipeline is below 16 LSBs.\n");
  return 0;
}

struct Fix {
  std::string name;
  SegmentFixOptions options;
  int guard = 0;  // lanes at bits + guard, coordinates at bits (SegmentFixOptions::coordinate_bits)
};

Fix parse_fix(const std::string& text) {
  Fix f{text, {}};
  if (text == "none") return f;
  for (const std::string& part : split(text, '+')) {
    const auto colon = part.find(':');
    const std::string key = part.substr(0, colon);
    const int value = std::atoi(part.substr(colon + 1).c_str());
    if (key == "offset") f.options.offset_lsb = value;
    else if (key == "guard") f.guard = value;
    else if (key == "tguard") f.options.t_guard = value;  // the guard band on t, in the lanes (--t-guard)
    else if (key == "rings") f.options.neighbour_rings = value;
    else throw std::invalid_argument("unknown fix '" + part + "'");
  }
  return f;
}

int fixes(const Scene& scene, const std::vector<int>& widths, const std::vector<Fix>& list) {
  const auto t0 = std::chrono::steady_clock::now();
  FloatVisibility reference_visibility;
  const SolverResult reference = ProgressiveRadiosity(scene, reference_visibility, SolverOptions{}).run();
  double mean = 0;
  for (const Spectrum& b : reference.radiosity) for (double v : b.band) mean += v;
  mean /= double(reference.radiosity.size() * kBands);
  std::printf("%zu faces, %zu patches; double solve %d steps (%.0f s)\n", scene.faces.size(), scene.patches.size(), reference.steps,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  std::printf("%5s %-18s %6s %11s %11s %9s %13s %9s %9s\n", "bits", "fix", "steps", "rel. RMSE", "rel. max", "differ%", "re-tests/seg",
              "false%", "missing%");
  for (int bits : widths) {
    for (const Fix& fix : list) {
      SegmentFixOptions fo = fix.options;
      fo.bits = bits + fix.guard;
      if (fix.guard != 0) fo.coordinate_bits = bits;
      SolverOptions so;
      so.fixes = fo;
      auto pipeline = make_software_visibility("fast", fo.bits, 0, fo.t_guard);
      const SolverResult solved = ProgressiveRadiosity(scene, *pipeline, so).run();
      double sq = 0, max_abs = 0;
      for (std::size_t p = 0; p < solved.radiosity.size(); ++p) {
        for (std::size_t k = 0; k < kBands; ++k) {
          const double e = solved.radiosity[p].band[k] - reference.radiosity[p].band[k];
          sq += e * e;
          max_abs = std::max(max_abs, std::abs(e));
        }
      }
      const double rmse = std::sqrt(sq / double(solved.radiosity.size() * kBands));
      FloatVisibility double_answer;
      auto shadow_pipeline = make_software_visibility("fast", fo.bits, 0, fo.t_guard);
      FixedSegmentsVisibility shadow(*shadow_pipeline, fo);
      ComparingVisibility compare(double_answer, shadow);
      ProgressiveRadiosity(scene, compare, SolverOptions{}).run();
      const auto differ = compare.shadow_blocks_answer_clear() + compare.answer_blocks_shadow_clear();
      // false: the pipeline blocks a segment double finds clear (a false shadow); missing: the reverse.
      std::printf("%5d %-18s %6d %11.3e %11.3e %9.3f %13.2f %9.3f %9.3f\n", bits, fix.name.c_str(), solved.steps, rmse / mean,
                  max_abs / mean, pct(differ, compare.segments_compared()),
                  double(solved.fix_tests) / double(solved.segments ? solved.segments : 1),
                  pct(compare.shadow_blocks_answer_clear(), compare.segments_compared()),
                  pct(compare.answer_blocks_shadow_clear(), compare.segments_compared()));
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc >= 6 && std::string(argv[1]) == "mechanism" && argc == 7) {
      std::vector<int> widths;
      for (const std::string& b : split(argv[4], ',')) widths.push_back(std::atoi(b.c_str()));
      const Scene scene = prepare_scene(scene_options(argv[2], std::atoi(argv[3]))).scene;
      return mechanism(scene, widths, std::atoi(argv[5]), static_cast<std::size_t>(std::atoi(argv[6])));
    }
    if (argc == 6 && std::string(argv[1]) == "fixes") {
      std::vector<int> widths;
      for (const std::string& b : split(argv[4], ',')) widths.push_back(std::atoi(b.c_str()));
      std::vector<Fix> list;
      for (const std::string& f : split(argv[5], ';')) list.push_back(parse_fix(f));
      const Scene scene = prepare_scene(scene_options(argv[2], std::atoi(argv[3]))).scene;
      return fixes(scene, widths, list);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "acne_diagnosis: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "usage: acne_diagnosis mechanism SCENE PATCH_LEVELS BITS[,..] STEPS PER_STEP\n"
                       "       acne_diagnosis fixes SCENE PATCH_LEVELS BITS[,..] 'none;offset:K;rings:R;guard:G;tguard:G;offset:K+rings:R'\n");
  return 2;
}
