// Public API of the bit-exact fixed-point segment/triangle test: what the board model, the CPU
// fixed-point backend, the benchmarks and the tests all call. No SystemC here.
//
// Every function takes the fractional width `bits` (7..31) and throws std::invalid_argument for
// any other width. Those deciding hits also take the guard band on t, `t_guard` (0..kMaxTGuard LSBs,
// fixed_format.h; 0, the default, is the paper's test): a hit needs t_guard < t*s < |det| - t_guard. Inputs must be in format: positions in [0, 2^bits), face records as built by
// make_face_record (edges are differences of in-range vertices); debug builds assert this.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "pipeline/fixed_format.h"
#include "pipeline/hardware_blocks.h"
#include "pipeline/kernel_isa.h"
#include "pipeline/mt_core.h"
#include "scenes/geometry.h"

namespace rc::pipeline {

// floor(x * 2^bits): the 0.N code of a coordinate. Throws std::out_of_range (naming the value)
// unless 0 <= x < 1.
std::int64_t quantize_coordinate(double x, FracBits bits);
FixedVec3 quantize_point(const Vec3& p, FracBits bits);

// Quantises the three vertices and takes exact differences, so both edges fit signed 1.N.
FaceRecord make_face_record(const Triangle& triangle, FracBits bits);

// True when the quantised face has no area (its edges are zero or parallel on the 2^-bits grid):
// the test's determinant is then 0 for every segment, so the face can block nothing.
bool has_no_area(const FaceRecord& face);

// True if the values are what the hardware can be fed at `bits` (see the header comment).
bool is_position(const FixedVec3& p, FracBits bits);
bool is_face_record(const FaceRecord& face, FracBits bits);

// ---- Stage by stage, for a cycle-level model of the 37-stage pipeline ------------------------
using Stage1Result = Stage1Values<std::int64_t>;
using Stage2Result = Stage2Values<std::int64_t>;
using Stage3Result = Stage3Values<std::int64_t>;

// Input stage: the segment direction end - start (exact, signed 1.N).
FixedVec3 segment_direction(const FixedVec3& start, const FixedVec3& end);
Stage1Result stage1(const FaceRecord& face, const FixedVec3& start, const FixedVec3& direction,
                    FracBits bits);
Stage2Result stage2(const FaceRecord& face, const Stage1Result& s1, FracBits bits);
// Its `hit` is decided with the guard band (t_guard; 0: the paper's test).
Stage3Result stage3(const FaceRecord& face, const FixedVec3& direction, const Stage1Result& s1,
                    const Stage2Result& s2, FracBits bits, int t_guard = 0);

// ---- Everything at once -------------------------------------------------------------------------
// All intermediates of one test: the stage outputs plus the output of every hardware block.
struct Trace {
  int bits = 0;
  PipelineValues<std::int64_t> values;
  std::array<std::int64_t, kMultiplierCount> multipliers{};
  std::array<std::int64_t, kAddSubCount> add_subs{};

  std::int64_t output(Multiplier m) const { return multipliers[static_cast<int>(m)]; }
  std::int64_t output(AddSub a) const { return add_subs[static_cast<int>(a)]; }
  bool hit() const { return values.stage3.hit; }
};
Trace trace(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end, FracBits bits, int t_guard = 0);

// Does the open segment (start, end) cross the triangle's interior? The hardware's answer.
bool segment_hits(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end, FracBits bits, int t_guard = 0);

// The hardware's streaming order (paper sec 4.1): one face, one start point, many end points given
// as structure-of-arrays (the X, Y and Z banks). ORs each hit into blocked[i]; entries with
// skip[i] != 0 are left untouched (skip may be null). The loop is branch-free and vectorised;
// widths <= 15 run on 32-bit lanes, wider ones on 64-bit lanes, both from the same core. A guard band
// (t_guard != 0) runs a loop of its own, so the paper's test (0) keeps its code as it was.
void occlude_face(const FaceRecord& face, const FixedVec3& start, const std::int64_t* end_x,
                  const std::int64_t* end_y, const std::int64_t* end_z, std::size_t n, FracBits bits,
                  std::uint8_t* blocked, const std::uint8_t* skip = nullptr, int t_guard = 0);
// The same on one particular instruction-set variant (tests, benchmarks); the overload above
// uses best_kernel_isa() (kernel_isa.h: the CPU's best, capped by RC2000SIM_SIMD). Throws
// std::invalid_argument if the CPU cannot run it.
void occlude_face(KernelIsa isa, const FaceRecord& face, const FixedVec3& start,
                  const std::int64_t* end_x, const std::int64_t* end_y, const std::int64_t* end_z,
                  std::size_t n, FracBits bits, std::uint8_t* blocked, const std::uint8_t* skip = nullptr,
                  int t_guard = 0);

// The function occlude_face(isa, ...) runs for this width and mask (skip != nullptr), looked up
// and checked once, for a caller that runs many short streams (same arguments, bits as given
// here). Throws std::invalid_argument for a width outside 7..31 or a variant the CPU cannot run.
// The last argument is the guard band on t (0..kMaxTGuard, unchecked here: the caller checks it once).
using OccludeKernel = void (*)(const FaceRecord&, const FixedVec3&, const std::int64_t*, const std::int64_t*,
                               const std::int64_t*, std::size_t, int, std::uint8_t*, const std::uint8_t*, int);
OccludeKernel occlude_kernel(KernelIsa isa, FracBits bits, bool masked);
// The same kernel reading end points from 32-bit banks (every position fits them): for widths up
// to 15, where the arithmetic runs on 32-bit lanes, this saves narrowing the 64-bit banks in
// every pass. Same answers. Throws std::invalid_argument for a width above 15 or a variant the
// CPU cannot run.
using OccludeKernel32 = void (*)(const FaceRecord&, const FixedVec3&, const std::int32_t*, const std::int32_t*,
                                 const std::int32_t*, std::size_t, int, std::uint8_t*, const std::uint8_t*, int);
OccludeKernel32 occlude_kernel32(KernelIsa isa, FracBits bits, bool masked);

}  // namespace rc::pipeline
