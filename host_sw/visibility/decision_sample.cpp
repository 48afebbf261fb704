#include "host_sw/visibility/decision_sample.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>
#include <stdexcept>

#include "host_sw/radiosity/jobs.h"
#include "host_sw/radiosity/worker_pool.h"
#include "pipeline/fixed_mt.h"
#include "pipeline/float_mt.h"
#include "pipeline/reference_mt.h"

namespace rc {

DecisionSampler::DecisionSampler(std::size_t size, std::uint64_t seed) : size_(size), state_(seed) {
  sample_.reserve(size);
}

std::uint64_t DecisionSampler::next_random() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

void DecisionSampler::observe(const SegmentBatch& batch, const std::vector<std::uint8_t>& blocked) {
  if (size_ == 0) return;
  for (std::size_t s = 0; s < batch.size(); ++s) {
    if (!batch.is_needed(s)) continue;
    ++population_;
    std::size_t slot = sample_.size();
    if (sample_.size() == size_) {
      // Algorithm R: the i-th segment replaces a uniform slot with probability size / i. The draw
      // is a 128-bit multiply-shift (no modulo bias beyond 2^-64, the same on every machine).
      slot = static_cast<std::size_t>((static_cast<unsigned __int128>(next_random()) * population_) >> 64);
      if (slot >= size_) continue;
    }
    SampledSegment seg{batch.start, batch.ends[s], batch.source_face, batch.end_faces[s], blocked[s] != 0};
    if (slot == sample_.size()) {
      sample_.push_back(seg);
    } else {
      sample_[slot] = seg;
    }
  }
}

void check_fidelity_options(long long sample, double warn_share) {
  if (sample < 0 || sample > kMaxFidelitySample)
    throw std::invalid_argument("--fidelity-sample: Value " + std::to_string(sample) + " not in range 0 to " +
                                std::to_string(kMaxFidelitySample));
  if (!(warn_share >= 0 && warn_share <= 1)) {
    char text[64];
    std::snprintf(text, sizeof text, "%g", warn_share);
    throw std::invalid_argument(std::string("--fidelity-warn: Value ") + text + " not in range 0 to 1");
  }
}

ShareInterval wilson_interval(std::uint64_t k, std::uint64_t n) {
  if (n == 0) return {};
  const double z = 1.959963984540054;  // the 97.5% point of the normal distribution
  const double nn = static_cast<double>(n), p = static_cast<double>(k) / nn, z2 = z * z;
  const double centre = (p + z2 / (2 * nn)) / (1 + z2 / nn);
  const double half = z / (1 + z2 / nn) * std::sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

namespace {

bool shares_vertex(const Triangle& a, const Triangle& b) {
  const Vec3* av[3] = {&a.v0, &a.v1, &a.v2};
  const Vec3* bv[3] = {&b.v0, &b.v1, &b.v2};
  for (const Vec3* p : av)
    for (const Vec3* q : bv)
      if (*p == *q) return true;
  return false;
}

// The pipeline's own per-face test, in the run's arithmetic.
class PipelineFaces {
 public:
  PipelineFaces(const Scene& scene, const pipeline::Arithmetic& arith, int bits, int t_guard)
      : arith_(arith), bits_(bits), t_guard_(t_guard) {
    if (arith.is_float()) {
      for (const Face& f : scene.faces) float_faces_.push_back(pipeline::make_float_face_record(f.tri, arith.float_format()));
    } else {
      for (const Face& f : scene.faces) fixed_faces_.push_back(pipeline::make_face_record(f.tri, pipeline::FracBits(bits)));
    }
  }
  bool hits(std::size_t face, const Vec3& start, const Vec3& end) const {
    if (arith_.is_float()) {
      const pipeline::FloatFormat fmt = arith_.float_format();
      return pipeline::segment_hits(float_faces_[face], pipeline::round_point(start, fmt), pipeline::round_point(end, fmt), fmt);
    }
    const pipeline::FracBits b(bits_);
    return pipeline::segment_hits(fixed_faces_[face], pipeline::quantize_point(start, b), pipeline::quantize_point(end, b), b,
                                  t_guard_);
  }
  bool fixed() const { return !arith_.is_float(); }
  bool lost(std::size_t face) const { return !arith_.is_float() && pipeline::has_no_area(fixed_faces_[face]); }
  // One grid step of the normalised scene: 2^-bits, or 2^-M for a float format (coordinates below 1).
  double step() const { return std::ldexp(1.0, arith_.is_float() ? -arith_.float_format().fraction_bits() : -bits_); }

 private:
  pipeline::Arithmetic arith_;
  int bits_;
  int t_guard_;
  std::vector<pipeline::FaceRecord> fixed_faces_;
  std::vector<pipeline::FloatFaceRecord> float_faces_;
};

// Whether segment s crosses the plane of `tri` within `reach` of one of its ends.
bool crosses_near_end(const Triangle& tri, const SampledSegment& s, double reach) {
  const Vec3 n = tri.cross(), d = s.end - s.start;
  const double denom = glm::dot(n, d);
  if (denom == 0) return false;
  const double t = glm::dot(n, tri.v0 - s.start) / denom;
  const double length = glm::length(d);
  return std::min(std::fabs(t), std::fabs(1 - t)) * length <= reach;
}

enum class Cause { small_determinant, neighbour, lost_face, near_end, other };

// The exact determinant of Moller-Trumbore for segment s and face tri, edge1 . ((end - start) x edge2):
// the pipeline's det before truncation, in units of the normalised scene.
double exact_determinant(const Triangle& tri, const SampledSegment& s) {
  return glm::dot(tri.edge1(), glm::cross(s.end - s.start, tri.edge2()));
}

// The class of the faces that decide a differing segment: a determinant below the resolution first
// (fixed point), then a neighbour, then a lost face, then a crossing near an end.
Cause classify(const Scene& scene, const SampledSegment& s, const std::vector<int>& deciding, const PipelineFaces& pipe) {
  if (pipe.fixed())
    for (int f : deciding)
      if (std::fabs(exact_determinant(scene.faces[static_cast<std::size_t>(f)].tri, s)) < kSmallDeterminantSteps * pipe.step())
        return Cause::small_determinant;
  const auto near_source_or_end = [&](int f) {
    const Triangle& t = scene.faces[static_cast<std::size_t>(f)].tri;
    return (s.source_face >= 0 && shares_vertex(t, scene.faces[static_cast<std::size_t>(s.source_face)].tri)) ||
           (s.end_face >= 0 && shares_vertex(t, scene.faces[static_cast<std::size_t>(s.end_face)].tri));
  };
  for (int f : deciding)
    if (near_source_or_end(f)) return Cause::neighbour;
  for (int f : deciding)
    if (pipe.lost(static_cast<std::size_t>(f))) return Cause::lost_face;
  for (int f : deciding)
    if (crosses_near_end(scene.faces[static_cast<std::size_t>(f)].tri, s, kNearEndSteps * pipe.step())) return Cause::near_end;
  return Cause::other;
}

void count(DifferenceCauses& c, Cause cause) {
  switch (cause) {
    case Cause::small_determinant: ++c.small_determinant; break;
    case Cause::neighbour: ++c.neighbour; break;
    case Cause::lost_face: ++c.lost_face; break;
    case Cause::near_end: ++c.near_end; break;
    case Cause::other: ++c.other; break;
  }
}

struct SegmentVerdict {
  bool double_blocked = false;
  bool differs = false;
  Cause cause = Cause::other;
};

SegmentVerdict check_segment(const Scene& scene, const SampledSegment& s, const PipelineFaces& pipe) {
  const FaceSheets& sheets = scene.sheets;
  const auto own = [&](int f) { return sheets.same(f, s.source_face) || sheets.same(f, s.end_face); };
  SegmentVerdict v;
  const int faces = static_cast<int>(scene.faces.size());
  for (int f = 0; f < faces && !v.double_blocked; ++f)
    if (!own(f) && pipeline::segment_hits_ref(scene.faces[static_cast<std::size_t>(f)].tri, s.start, s.end)) v.double_blocked = true;
  v.differs = v.double_blocked != s.answer_blocked;
  if (!v.differs) return v;
  // The faces that decide it: every face the blocking side finds.
  std::vector<int> deciding;
  for (int f = 0; f < faces; ++f) {
    if (own(f)) continue;
    const bool hit = s.answer_blocked ? pipe.hits(static_cast<std::size_t>(f), s.start, s.end)
                                      : pipeline::segment_hits_ref(scene.faces[static_cast<std::size_t>(f)].tri, s.start, s.end);
    if (hit) deciding.push_back(f);
  }
  v.cause = classify(scene, s, deciding, pipe);
  return v;
}

std::string with_commas(std::uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, share >= 0.1 ? "%.1f%%" : share >= 0.001 ? "%.2f%%" : "%.3g%%", 100 * share);
  return text;
}

}  // namespace

Fidelity estimate_fidelity(const Scene& scene, const std::vector<SampledSegment>& sample, std::uint64_t population,
                           const pipeline::Arithmetic& arith, int bits, unsigned threads, int t_guard) {
  Fidelity f;
  f.arithmetic = arith.is_float() ? arith.name() : "fixed:" + std::to_string(bits);
  f.population = population;
  f.sampled = sample.size();
  const PipelineFaces pipe(scene, arith, bits, t_guard);
  std::vector<SegmentVerdict> verdicts(sample.size());
  const unsigned n = std::max(1u, std::min<unsigned>(threads ? threads : static_cast<unsigned>(jobs()),
                                                      static_cast<unsigned>(std::max<std::size_t>(1, sample.size() / 64))));
  WorkerPool pool(static_cast<int>(n));
  std::mutex error_mutex;
  std::exception_ptr error;  // a point outside the unit cube (quantize_point): rethrown here, as WorkerPool's jobs must not throw
  pool.start([&](int t) {
    try {
      for (std::size_t i = static_cast<std::size_t>(t); i < sample.size(); i += n) verdicts[i] = check_segment(scene, sample[i], pipe);
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  });
  pool.finish();
  if (error) std::rethrow_exception(error);
  for (std::size_t i = 0; i < sample.size(); ++i) {
    if (!verdicts[i].differs) continue;
    if (sample[i].answer_blocked) {
      ++f.false_shadows;
      count(f.false_causes, verdicts[i].cause);
    } else {
      ++f.missing_shadows;
      count(f.missing_causes, verdicts[i].cause);
    }
  }
  f.exact = f.sampled == f.population;
  f.share = f.sampled ? static_cast<double>(f.differing()) / static_cast<double>(f.sampled) : 0;
  if (f.exact) {
    f.share_low = f.share_high = f.share;
  } else {
    const ShareInterval i = wilson_interval(f.differing(), f.sampled);
    f.share_low = i.low;
    f.share_high = i.high;
  }
  return f;
}

std::string fidelity_line(const Fidelity& f) {
  if (f.sampled == 0) return "not measured: no segment was sampled";
  std::string line = percent(f.share) + " of visibility decisions differ from double precision (";
  if (f.exact) {
    line += "every one of " + with_commas(f.population) + " segments checked";
  } else {
    line += "95%: " + percent(f.share_low) + "-" + percent(f.share_high) + "; " + with_commas(f.sampled) + " of " +
            with_commas(f.population) + " segments checked";
  }
  return line + "; " + with_commas(f.false_shadows) + " false shadows, " + with_commas(f.missing_shadows) + " missing)";
}

std::string fidelity_warning(const Fidelity& f, double warn_share, int bits) {
  if (f.sampled == 0 || !(f.share > warn_share)) return "";
  struct Named {
    std::uint64_t count;
    std::string why;
  };
  const std::string grid = f.arithmetic.rfind("float:", 0) == 0 ? "the " + f.arithmetic.substr(6) + " format's grid"
                                                                 : "the 2^-" + std::to_string(bits) + " grid";
  const Named causes[] = {
      {f.false_causes.small_determinant + f.missing_causes.small_determinant,
       "are decided by a face whose determinant for the segment (the product of the segment and the face's two edges) "
       "is below " + std::to_string(static_cast<int>(kSmallDeterminantSteps)) + " steps of " + grid +
           ": the faces are too small for the width and truncation decides (docs/radiosity.md, Fidelity in every run)"},
      {f.false_causes.neighbour,
       "are blocked by a face that shares a vertex with their start or end face: neighbouring faces of one mesh shadow "
       "each other once the ends round to " + grid + " (shadow acne)"},
      {f.missing_causes.neighbour, "miss a shadow cast by a face that shares a vertex with their start or end face"},
      {f.missing_causes.lost_face, "miss a shadow cast by a face with no area on " + grid},
      {f.false_causes.near_end + f.missing_causes.near_end,
       "are decided by a face crossed within " + std::to_string(static_cast<int>(kNearEndSteps)) + " grid steps of an end"},
      {f.false_causes.other + f.missing_causes.other + f.false_causes.lost_face, "have no cause of these kinds"},
  };
  const Named* top = &causes[0];
  for (const Named& c : causes)
    if (c.count > top->count) top = &c;
  const double of_differing = f.differing() ? static_cast<double>(top->count) / static_cast<double>(f.differing()) : 0;
  char share[64];
  std::snprintf(share, sizeof share, "%.0f%%", 100 * of_differing);
  return "the picture is not faithful: " + percent(f.share) + " of visibility decisions (" + f.arithmetic +
         ") differ from double precision, above the " + percent(warn_share) + " of --fidelity-warn; " + share +
         " of the differing segments " + top->why + ". Try more bits (rc2000sim accuracy measures each width on this "
         "scene)";
}

}  // namespace rc
