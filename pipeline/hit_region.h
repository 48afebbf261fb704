// Which end points can the pipeline report as hitting one face from one start point? A
// conservative answer, so that a visibility backend can skip the rest without changing a bit.
//
// For a fixed face and start, tvec, qvec and t are fixed (they never see the direction), and the
// pipeline's det, u and v are linear functions of the direction d = end - start up to a small,
// proven truncation error. The strict decision then turns into four linear conditions on d that
// every hit satisfies (docs/fast-visibility.md has the derivation):
//
//   det beyond t:  s * det > |t|          (the end lies beyond the face's plane)
//   u > 0:         s * u > 0              (three planes through the start and the face's edges)
//   v > 0:         s * v > 0
//   u + v < det:   s * (det - u - v) > 0
//
// with s = sign(t) (t == 0 never hits). Each becomes A . d >= c with an integer vector A and a
// threshold c lowered by the largest error truncation can add. The region they bound is the
// face's shadow frustum seen from the start, widened by the truncation error; outside it the
// pipeline cannot report a hit.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>

#include "pipeline/fixed_format.h"

namespace rc::pipeline {

using Wide = __int128;

// An inclusive interval of exact errors.
struct ErrorRange {
  Wide lo = 0, hi = 0;
};

// What the conditions take from the face alone (docs/fast-visibility.md, "Tighter bounds"):
// computed once per face, reused for every start.
struct FaceErrorTerms {
  FixedVec3 n_det{};               // edge2 x edge1: det = d . n_det / M^2 + error
  std::int64_t l1_edge1 = 0;
  std::int64_t pvec_lo[3]{}, pvec_hi[3]{};  // M pvec_i - (d x edge2)_i over every d
  Wide loss_det = 0;               // what det's three floors can drop, in units of 1/M
  ErrorRange det;                  // M^2 det - d . n_det over every d
};
FaceErrorTerms face_error_terms(const FaceRecord& face, FracBits bits);

// The four conditions in exact integer arithmetic: a hit at direction d requires
// a[k] . d >= c[k] for every k. For the tests and the proof, not for speed.
struct ExactHitConditions {
  bool empty = false;  // t == 0: no direction can hit
  std::array<std::array<__int128, 3>, 4> a{};
  std::array<__int128, 4> c{};

  bool allows(const FixedVec3& direction) const;
};
ExactHitConditions exact_hit_conditions(const FaceRecord& face, const FixedVec3& start, FracBits bits);

// The same four conditions in double precision, moved into end-point space, with thresholds
// lowered by a margin that covers every rounding of the double evaluation, so that
// may_hit(end) is true whenever ExactHitConditions::allows(end - start) is.
class HitRegion {
 public:
  // Throws std::invalid_argument for a width outside 7..31. Requires a valid face record and
  // start position (as pipeline::segment_hits does).
  HitRegion(const FaceRecord& face, const FixedVec3& start, FracBits bits);
  // The same with the face's terms computed beforehand (face_error_terms(face, bits)).
  HitRegion(const FaceRecord& face, const FaceErrorTerms& terms, const FixedVec3& start, FracBits bits);

  // True when t == 0: the pipeline reports a miss for every end point.
  bool empty() const { return empty_; }

  // False only if no hit can end at (x, y, z), the pipeline's integer coordinates (units of
  // 2^-bits) held as doubles.
  [[gnu::always_inline]] bool may_hit(double x, double y, double z) const {
    bool inside = true;  // all four planes, without branches: the outcome is unpredictable
    for (int k = 0; k < 4; ++k) inside &= ax_[k] * x + ay_[k] * y + az_[k] * z >= threshold_[k];
    return inside;
  }

  // kBoxes boxes at once in single precision: bit j of the result is 0 only if no hit can end in
  // box j. bound[0] holds the boxes' lower corners, bound[1] the upper ones, per axis and box;
  // they must enclose the points (lower corners rounded down to float, upper ones up) and lie
  // within [0, 2^bits]. The float thresholds carry a wider margin than the double ones (2^-20
  // instead of 2^-44 of the same scale), which covers single-precision rounding.
  static constexpr int kBoxes = 8;  // one AVX register of floats; the lane mask packs 8 bytes
  // One 32-bit lane per box (GCC/Clang vector extensions: one AVX register, two SSE registers,
  // or NEON, whichever the caller is compiled for).
  using IntLanes = std::int32_t __attribute__((vector_size(4 * kBoxes)));
  using FloatLanes = float __attribute__((vector_size(4 * kBoxes)));  // one float lane per box

  // kBoxes boxes' bounds loaded into lanes once (lo[i], hi[i]: axis i's lower and upper bounds),
  // for a caller that tests the same boxes against several regions.
  struct BoxLanes {
    FloatLanes lo[3], hi[3];
  };
  [[gnu::always_inline]] static void load_boxes(const float bound[2][3][kBoxes], BoxLanes& boxes) {
    for (int i = 0; i < 3; ++i) {
      std::memcpy(&boxes.lo[i], bound[0][i], sizeof boxes.lo[i]);
      std::memcpy(&boxes.hi[i], bound[1][i], sizeof boxes.hi[i]);
    }
  }

  // The same test with the answer as lanes, for callers that combine several regions' answers
  // lane by lane: ORs `flag` into lane j of `lanes` where may_hit_boxes would set bit j.
  [[gnu::always_inline]] void add_box_lanes(const BoxLanes& boxes, std::int32_t flag, IntLanes& lanes) const {
    IntLanes inside;
    box_lanes(boxes, inside);
    lanes |= inside & flag;
  }

  [[gnu::always_inline]] unsigned may_hit_boxes(const float bound[2][3][kBoxes]) const {
    BoxLanes boxes;
    load_boxes(bound, boxes);
    IntLanes inside;
    box_lanes(boxes, inside);
    return lane_mask(inside);
  }

  // Bit j set where lane j is all ones; every lane must be all ones or zero (a comparison's result).
  [[gnu::always_inline]] static unsigned lane_mask(const IntLanes& lanes) {
    // Narrow to bytes, keep bit j of byte j, and sum the bytes into the top byte with one
    // multiplication.
    static_assert(kBoxes == 8, "the lane mask packs one byte per box into 64 bits");
    using ByteLanes = std::int8_t __attribute__((vector_size(kBoxes)));
    const ByteLanes bytes = __builtin_convertvector(lanes, ByteLanes);
    std::uint64_t packed;
    std::memcpy(&packed, &bytes, sizeof packed);
    return static_cast<unsigned>(((packed & 0x8040201008040201ull) * 0x0101010101010101ull) >> 56);
  }

 private:
  // Lane j of `inside` all ones, unless no hit can end in box j (then zero). An output
  // parameter, not a return value: a vector return would change the ABI between the clones.
  // Each term is the box corner maximising it: the coefficient times the upper bound plus the
  // coefficient times the lower one, where one of the two coefficients is zero. The zero product
  // adds nothing (exactly), and the bounds stay where they are, the same for every region (no
  // corner picked per region and plane).
  [[gnu::always_inline]] void box_lanes(const BoxLanes& b, IntLanes& inside) const {
    inside = IntLanes{} - 1;
    for (int k = 0; k < 4; ++k) {
      FloatLanes v = upper_float_[k][0] * b.hi[0];
      v = lower_float_[k][0] * b.lo[0] + v;
      v = upper_float_[k][1] * b.hi[1] + v;
      v = lower_float_[k][1] * b.lo[1] + v;
      v = upper_float_[k][2] * b.hi[2] + v;
      v = lower_float_[k][2] * b.lo[2] + v;
      inside &= v >= threshold_float_[k];
    }
  }

  // Every member is set by the constructor, once (no default initialisers: zeroing them first
  // and then writing them again cost a fifth of a region's construction).
  bool empty_;
  // Plane k: ax_[k] * x + ay_[k] * y + az_[k] * z >= threshold_[k] for every possible hit.
  double ax_[4], ay_[4], az_[4], threshold_[4];
  // The same in float, each coefficient where it maximises its term: upper_float_[k][i] if
  // it is positive (it multiplies a box's upper bound), else lower_float_[k][i]; the other is 0.
  float upper_float_[4][3], lower_float_[4][3], threshold_float_[4];
};

}  // namespace rc::pipeline
