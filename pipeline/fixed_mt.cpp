#include "pipeline/fixed_mt.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace rc::pipeline {

namespace {

// Stores every block output into a Trace, indexed by the block enums.
struct TraceProbe {
  Trace* trace;
  void multiplier(Multiplier m, std::int64_t v) { trace->multipliers[static_cast<int>(m)] = v; }
  void add_sub(AddSub a, std::int64_t v) { trace->add_subs[static_cast<int>(a)] = v; }
};

bool in_range(const FixedVec3& v, Quantity q, int bits) {
  const ValueRange r = value_range(q, bits);
  return r.contains(v.x) && r.contains(v.y) && r.contains(v.z);
}

// One face against a stream of end points. Always inlined, so that each instruction-set variant
// below compiles the whole loop, core included, for its own instruction set.
// Bank: the end points' integer type in memory (64-bit, or 32-bit for widths <= 15, which saves
// narrowing them in every pass).
template <class Int, bool kMasked, bool kGuarded, class Bank>
[[gnu::always_inline]] inline void occlude_loop(const FaceRecord& face, const FixedVec3& start,
                                                const Bank* __restrict end_x,
                                                const Bank* __restrict end_y,
                                                const Bank* __restrict end_z, std::size_t n,
                                                int bits, std::uint8_t* __restrict blocked,
                                                const std::uint8_t* __restrict skip, int t_guard) {
  [[maybe_unused]] const Int guard = Int(t_guard);
  const IntVec3<Int> v0 = vec_cast<Int>(face.v0), e1 = vec_cast<Int>(face.edge1),
                     e2 = vec_cast<Int>(face.edge2), s = vec_cast<Int>(start);
  // The face and start are the same for every end point, so the compiler hoists tvec, qvec and
  // t out of the loop: the per-ray work is what the hardware's streamed inputs feed.
  for (std::size_t i = 0; i < n; ++i) {
    assert(is_position({end_x[i], end_y[i], end_z[i]}, bits));
    const IntVec3<Int> end{Int(end_x[i]), Int(end_y[i]), Int(end_z[i])};
    bool hit;
    if constexpr (kGuarded) {
      hit = pipeline_hits(v0, e1, e2, s, end, bits, guard);
    } else {
      hit = pipeline_hits(v0, e1, e2, s, end, bits);
    }
    if constexpr (kMasked) hit &= skip[i] == 0;
    blocked[i] |= std::uint8_t(hit);
  }
}

// Every (integer path, mask, instruction set) combination as a plain function, so a table can
// pick one at run time and the tests can run each.
using OccludeFn = OccludeKernel;
struct OccludeKernels {
  OccludeFn narrow, narrow_masked, wide, wide_masked;
  OccludeKernel32 banks32, banks32_masked;
};

#define RC_OCCLUDE_PARAMS                                                                    \
  const FaceRecord &face, const FixedVec3 &start, const std::int64_t *end_x,                \
      const std::int64_t *end_y, const std::int64_t *end_z, std::size_t n, int bits,        \
      std::uint8_t *blocked, const std::uint8_t *skip, int t_guard
#define RC_OCCLUDE32_PARAMS                                                                  \
  const FaceRecord &face, const FixedVec3 &start, const std::int32_t *end_x,                \
      const std::int32_t *end_y, const std::int32_t *end_z, std::size_t n, int bits,        \
      std::uint8_t *blocked, const std::uint8_t *skip, int t_guard
#define RC_OCCLUDE_ARGS face, start, end_x, end_y, end_z, n, bits, blocked, skip, t_guard
#define RC_DEFINE_OCCLUDE_KERNELS(isa, target)                                                 \
  target void occlude32_##isa(RC_OCCLUDE_PARAMS) {                                           \
    if (t_guard == 0) {                                                                      \
      occlude_loop<std::int32_t, false, false>(RC_OCCLUDE_ARGS);                             \
    } else {                                                                                 \
      occlude_loop<std::int32_t, false, true>(RC_OCCLUDE_ARGS);                              \
    }                                                                                        \
  }                                                                                          \
  target void occlude32_masked_##isa(RC_OCCLUDE_PARAMS) {                                    \
    if (t_guard == 0) {                                                                      \
      occlude_loop<std::int32_t, true, false>(RC_OCCLUDE_ARGS);                              \
    } else {                                                                                 \
      occlude_loop<std::int32_t, true, true>(RC_OCCLUDE_ARGS);                               \
    }                                                                                        \
  }                                                                                          \
  target void occlude64_##isa(RC_OCCLUDE_PARAMS) {                                           \
    if (t_guard == 0) {                                                                      \
      occlude_loop<std::int64_t, false, false>(RC_OCCLUDE_ARGS);                             \
    } else {                                                                                 \
      occlude_loop<std::int64_t, false, true>(RC_OCCLUDE_ARGS);                              \
    }                                                                                        \
  }                                                                                          \
  target void occlude64_masked_##isa(RC_OCCLUDE_PARAMS) {                                    \
    if (t_guard == 0) {                                                                      \
      occlude_loop<std::int64_t, true, false>(RC_OCCLUDE_ARGS);                              \
    } else {                                                                                 \
      occlude_loop<std::int64_t, true, true>(RC_OCCLUDE_ARGS);                               \
    }                                                                                        \
  }                                                                                          \
  target void occlude32_banks32_##isa(RC_OCCLUDE32_PARAMS) {                                 \
    if (t_guard == 0) {                                                                      \
      occlude_loop<std::int32_t, false, false>(RC_OCCLUDE_ARGS);                             \
    } else {                                                                                 \
      occlude_loop<std::int32_t, false, true>(RC_OCCLUDE_ARGS);                              \
    }                                                                                        \
  }                                                                                          \
  target void occlude32_banks32_masked_##isa(RC_OCCLUDE32_PARAMS) {                          \
    if (t_guard == 0) {                                                                      \
      occlude_loop<std::int32_t, true, false>(RC_OCCLUDE_ARGS);                              \
    } else {                                                                                 \
      occlude_loop<std::int32_t, true, true>(RC_OCCLUDE_ARGS);                               \
    }                                                                                        \
  }                                                                                          \
  constexpr OccludeKernels kOcclude_##isa{occlude32_##isa,         occlude32_masked_##isa,   \
                                         occlude64_##isa,         occlude64_masked_##isa,   \
                                         occlude32_banks32_##isa, occlude32_banks32_masked_##isa};

RC_DEFINE_OCCLUDE_KERNELS(baseline, )
#if RC_HAVE_ISA_VARIANTS
RC_DEFINE_OCCLUDE_KERNELS(v3, RC_TARGET_X86_64_V3)
RC_DEFINE_OCCLUDE_KERNELS(v4, RC_TARGET_X86_64_V4)
#endif
#undef RC_DEFINE_OCCLUDE_KERNELS
#undef RC_OCCLUDE_ARGS
#undef RC_OCCLUDE_PARAMS
#undef RC_OCCLUDE32_PARAMS

const OccludeKernels& occlude_kernels(KernelIsa isa) {
#if RC_HAVE_ISA_VARIANTS
  return *pick_variant(isa, &kOcclude_baseline, &kOcclude_v3, &kOcclude_v4);
#else
  return *pick_variant(isa, &kOcclude_baseline, &kOcclude_baseline, &kOcclude_baseline);
#endif
}

// The narrowest integer type whose products cannot overflow at this width (bit_bounds.h): 32-bit
// lanes up to 15 bits, 64-bit ones above. (16-bit lanes at 7 bits, where the products fit, ran
// slower when the compiler vectorised them from these 64-bit banks: 2.3 G tests/s against 2.9 G
// on 32-bit lanes with AVX-512, 0.9 G against 1.3 G with AVX2, bench_pipeline.)
OccludeFn select_kernel(const OccludeKernels& k, int bits, bool masked) {
  if (core_fits<std::int32_t>(bits)) return masked ? k.narrow_masked : k.narrow;
  return masked ? k.wide_masked : k.wide;
}

}  // namespace

std::int64_t quantize_coordinate(double x, FracBits bits) {
  if (!(x >= 0.0 && x < 1.0)) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", x);
    throw std::out_of_range(std::string("coordinate ") + text +
                            " is outside [0, 1): normalise the scene before quantising");
  }
  // Scaling by a power of two is exact, so this is floor(x * 2^bits) with no rounding.
  return static_cast<std::int64_t>(std::floor(std::ldexp(x, bits)));
}

FixedVec3 quantize_point(const Vec3& p, FracBits bits) {
  return {quantize_coordinate(p.x, bits), quantize_coordinate(p.y, bits),
          quantize_coordinate(p.z, bits)};
}

FaceRecord make_face_record(const Triangle& triangle, FracBits bits) {
  const FixedVec3 v0 = quantize_point(triangle.v0, bits);
  return {v0, quantize_point(triangle.v1, bits) - v0, quantize_point(triangle.v2, bits) - v0};
}

bool has_no_area(const FaceRecord& face) {
  // Edges are 1.N differences, below 2^32 in magnitude: each product fits 64 bits, each difference
  // of two products needs 65, so the cross product is taken in 128 bits.
  using Wide = __int128;
  const FixedVec3& a = face.edge1;
  const FixedVec3& b = face.edge2;
  return Wide(a.y) * b.z - Wide(a.z) * b.y == 0 && Wide(a.z) * b.x - Wide(a.x) * b.z == 0 &&
         Wide(a.x) * b.y - Wide(a.y) * b.x == 0;
}

bool is_position(const FixedVec3& p, FracBits bits) { return in_range(p, Quantity::Position, bits); }

bool is_face_record(const FaceRecord& face, FracBits bits) {
  // The edges must be differences of two in-range positions, not just in the 1.N range.
  return is_position(face.v0, bits) && in_range(face.edge1, Quantity::Difference, bits) &&
         in_range(face.edge2, Quantity::Difference, bits) &&
         is_position(face.v0 + face.edge1, bits) && is_position(face.v0 + face.edge2, bits);
}

FixedVec3 segment_direction(const FixedVec3& start, const FixedVec3& end) { return end - start; }

Stage1Result stage1(const FaceRecord& face, const FixedVec3& start, const FixedVec3& direction,
                    FracBits bits) {
  NoProbe probe;
  return stage1(face.v0, face.edge2, start, direction, bits, probe);
}

Stage2Result stage2(const FaceRecord& face, const Stage1Result& s1, FracBits bits) {
  NoProbe probe;
  return stage2(face.edge1, s1, bits, probe);
}

Stage3Result stage3(const FaceRecord& face, const FixedVec3& direction, const Stage1Result& s1,
                    const Stage2Result& s2, FracBits bits, int t_guard) {
  assert(is_valid_t_guard(t_guard));
  NoProbe probe;
  Stage3Result r = stage3(face.edge2, direction, s1, s2, bits, probe);
  if (t_guard != 0) r.hit = core::decide(r, std::int64_t(t_guard));
  return r;
}

Trace trace(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end, FracBits bits, int t_guard) {
  assert(is_face_record(face, bits) && is_position(start, bits) && is_position(end, bits));
  validate_t_guard(t_guard);
  Trace t;
  t.bits = bits;
  TraceProbe probe{&t};
  t.values = run_pipeline(face.v0, face.edge1, face.edge2, start, end, bits, probe);
  if (t_guard != 0) t.values.stage3.hit = core::decide(t.values.stage3, std::int64_t(t_guard));
  return t;
}

bool segment_hits(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end, FracBits bits, int t_guard) {
  assert(is_face_record(face, bits) && is_position(start, bits) && is_position(end, bits));
  if (t_guard == 0) return pipeline_hits(face.v0, face.edge1, face.edge2, start, end, bits);
  validate_t_guard(t_guard);
  return pipeline_hits(face.v0, face.edge1, face.edge2, start, end, bits, std::int64_t(t_guard));
}

void occlude_face(const FaceRecord& face, const FixedVec3& start, const std::int64_t* end_x,
                  const std::int64_t* end_y, const std::int64_t* end_z, std::size_t n, FracBits bits,
                  std::uint8_t* blocked, const std::uint8_t* skip, int t_guard) {
  // Checked once: the culled backend calls this for every face with a handful of candidates.
  static const OccludeKernels& best = occlude_kernels(best_kernel_isa());
  assert(is_face_record(face, bits) && is_position(start, bits));
  if (t_guard != 0) validate_t_guard(t_guard);
  select_kernel(best, bits, skip != nullptr)(face, start, end_x, end_y, end_z, n, bits, blocked, skip, t_guard);
}

OccludeKernel occlude_kernel(KernelIsa isa, FracBits bits, bool masked) {
  return select_kernel(occlude_kernels(isa), bits, masked);
}

OccludeKernel32 occlude_kernel32(KernelIsa isa, FracBits bits, bool masked) {
  if (!core_fits<std::int32_t>(bits)) {
    throw std::invalid_argument("occlude_kernel32: 32-bit end-point banks need a width of at most 15 bits, not " +
                                std::to_string(int(bits)));
  }
  const OccludeKernels& k = occlude_kernels(isa);
  return masked ? k.banks32_masked : k.banks32;
}

void occlude_face(KernelIsa isa, const FaceRecord& face, const FixedVec3& start,
                  const std::int64_t* end_x, const std::int64_t* end_y, const std::int64_t* end_z,
                  std::size_t n, FracBits bits, std::uint8_t* blocked, const std::uint8_t* skip, int t_guard) {
  assert(is_face_record(face, bits) && is_position(start, bits));
  validate_t_guard(t_guard);
  select_kernel(occlude_kernels(isa), bits, skip != nullptr)(face, start, end_x, end_y, end_z, n, bits, blocked, skip,
                                                             t_guard);
}

}  // namespace rc::pipeline
