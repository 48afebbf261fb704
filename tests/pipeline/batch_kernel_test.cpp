// The streaming kernels (one face, many end points) agree element by element with the scalar
// tests, OR into the blocked array and leave skipped entries alone.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "pipeline/fixed_mt.h"
#include "pipeline/reference_mt.h"
#include "pipeline/stress_cases.h"

namespace rc::pipeline {
namespace {

// End points aimed at the face so that roughly half the segments hit.
struct Stream {
  Triangle face;
  Vec3 start;
  std::vector<Vec3> ends;
};

Stream make_stream(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
  Stream s{{{0.2, 0.3, 0.5}, {0.8, 0.35, 0.45}, {0.4, 0.9, 0.55}}, {0.5, 0.5, 0.05}, {}};
  while (s.ends.size() < n) {
    const Vec3 target = s.face.v0 + 1.2 * u() * s.face.edge1() + 1.2 * u() * s.face.edge2();
    const Vec3 end = s.start + (0.8 + 0.5 * u()) * (target - s.start);
    if (end.x >= 0 && end.x < 1 && end.y >= 0 && end.y < 1 && end.z >= 0 && end.z < 1) s.ends.push_back(end);
  }
  return s;
}

TEST(PipelineBatch, FixedKernelMatchesScalarTestOnBothIntegerPaths) {
  const Stream s = make_stream(1003, 1);  // not a multiple of any vector width
  for (int bits : {7, 11, 15, 16, 23, 31}) {
    const FaceRecord face = make_face_record(s.face, bits);
    const FixedVec3 start = quantize_point(s.start, bits);
    std::vector<std::int64_t> x, y, z;
    std::vector<std::uint8_t> expected;
    for (const Vec3& e : s.ends) {
      const FixedVec3 q = quantize_point(e, bits);
      x.push_back(q.x);
      y.push_back(q.y);
      z.push_back(q.z);
      expected.push_back(segment_hits(face, start, q, bits));
    }
    std::vector<std::uint8_t> blocked(s.ends.size(), 0);
    occlude_face(face, start, x.data(), y.data(), z.data(), x.size(), bits, blocked.data());
    EXPECT_EQ(blocked, expected) << bits << " bits";
    // Every instruction-set variant this CPU can run, with and without a (all-clear) mask.
    const std::vector<std::uint8_t> no_skip(s.ends.size(), 0);
    for (KernelIsa isa : supported_kernel_isas()) {
      for (const std::uint8_t* skip : {static_cast<const std::uint8_t*>(nullptr), no_skip.data()}) {
        std::vector<std::uint8_t> b(s.ends.size(), 0);
        occlude_face(isa, face, start, x.data(), y.data(), z.data(), x.size(), bits, b.data(), skip);
        EXPECT_EQ(b, expected) << bits << " bits, " << name(isa) << (skip ? ", masked" : "");
      }
    }
    std::size_t hits = 0;
    for (auto b : expected) hits += b;
    EXPECT_GT(hits, 200u);
    EXPECT_LT(hits, 800u);
  }
}

// The kernels on 32-bit end-point banks (widths up to 15) answer as the scalar test does, on
// every variant, with and without a mask, ORing into what is already blocked; wider widths are
// refused.
TEST(PipelineBatch, KernelOn32BitBanksMatchesScalarTest) {
  const Stream s = make_stream(1003, 4);
  for (int bits = kMinFracBits; bits <= 15; ++bits) {
    const FaceRecord face = make_face_record(s.face, bits);
    const FixedVec3 start = quantize_point(s.start, bits);
    std::vector<std::int32_t> x, y, z;
    std::vector<std::uint8_t> before, skip, expected, expected_masked;
    for (std::size_t i = 0; i < s.ends.size(); ++i) {
      const FixedVec3 q = quantize_point(s.ends[i], bits);
      x.push_back(static_cast<std::int32_t>(q.x));
      y.push_back(static_cast<std::int32_t>(q.y));
      z.push_back(static_cast<std::int32_t>(q.z));
      before.push_back(i % 7 == 0);
      skip.push_back(i % 5 == 0);
      const bool hit = segment_hits(face, start, q, bits);
      expected.push_back(before.back() || hit);
      expected_masked.push_back(before.back() || (hit && !skip.back()));
    }
    for (KernelIsa isa : supported_kernel_isas()) {
      for (bool masked : {false, true}) {
        std::vector<std::uint8_t> b = before;
        occlude_kernel32(isa, bits, masked)(face, start, x.data(), y.data(), z.data(), x.size(), bits, b.data(),
                                            masked ? skip.data() : nullptr, 0);
        EXPECT_EQ(b, masked ? expected_masked : expected) << bits << " bits, " << name(isa) << (masked ? ", masked" : "");
      }
    }
  }
  EXPECT_THROW(occlude_kernel32(KernelIsa::Baseline, 16, false), std::invalid_argument);
  EXPECT_THROW(occlude_kernel32(KernelIsa::Baseline, 31, true), std::invalid_argument);
}

TEST(PipelineBatch, FixedKernelOrsIntoBlockedAndHonoursTheSkipMask) {
  const Stream s = make_stream(500, 2);
  const int bits = 15;
  const FaceRecord face = make_face_record(s.face, bits);
  const FixedVec3 start = quantize_point(s.start, bits);
  std::vector<std::int64_t> x, y, z;
  for (const Vec3& e : s.ends) {
    const FixedVec3 q = quantize_point(e, bits);
    x.push_back(q.x);
    y.push_back(q.y);
    z.push_back(q.z);
  }
  std::vector<std::uint8_t> blocked(s.ends.size()), skip(s.ends.size());
  for (std::size_t i = 0; i < blocked.size(); ++i) {
    blocked[i] = i % 3 == 0;  // already blocked by an earlier face
    skip[i] = i % 5 == 0;     // own face of this segment
  }
  const std::vector<std::uint8_t> before = blocked;
  for (KernelIsa isa : supported_kernel_isas()) {
    for (int kernel_bits : {15, 31}) {
      std::vector<std::uint8_t> b = before;
      occlude_face(isa, face, start, x.data(), y.data(), z.data(), x.size(), kernel_bits, b.data(), skip.data());
      for (std::size_t i = 0; i < b.size(); ++i) {
        const bool hit = segment_hits(face, start, {x[i], y[i], z[i]}, kernel_bits);
        const bool want = skip[i] ? before[i] != 0 : (before[i] != 0 || hit);
        ASSERT_EQ(b[i] != 0, want) << i << " " << name(isa) << " " << kernel_bits;
      }
    }
  }
  occlude_face(face, start, x.data(), y.data(), z.data(), 0, bits, nullptr);  // empty stream
}

TEST(PipelineBatch, BaselineVariantAlwaysExistsAndUnsupportedOnesAreRefused) {
  const auto isas = supported_kernel_isas();
  ASSERT_FALSE(isas.empty());
  EXPECT_EQ(isas.front(), KernelIsa::Baseline);
  EXPECT_LE(best_kernel_isa(), isas.back());  // RC2000SIM_SIMD may cap it (kernel_isa_test.cpp)
  for (KernelIsa isa : {KernelIsa::X86_64_V3, KernelIsa::X86_64_V4}) {
    if (is_supported(isa)) continue;
    const FaceRecord face{{1, 1, 1}, {2, 0, 0}, {0, 2, 0}};
    std::uint8_t b = 0;
    const std::int64_t c = 1;
    EXPECT_THROW(occlude_face(isa, face, {1, 1, 1}, &c, &c, &c, 1, 15, &b), std::invalid_argument);
  }
}

TEST(PipelineBatch, FloatKernelMatchesScalarFloatReference) {
  const Stream s = make_stream(777, 3);
  std::vector<float> x, y, z;
  for (const Vec3& e : s.ends) {
    x.push_back(static_cast<float>(e.x));
    y.push_back(static_cast<float>(e.y));
    z.push_back(static_cast<float>(e.z));
  }
  std::vector<std::uint8_t> skip(s.ends.size(), 0);
  skip[10] = 1;
  for (KernelIsa isa : supported_kernel_isas()) {
    for (const std::uint8_t* mask : {static_cast<const std::uint8_t*>(nullptr), static_cast<const std::uint8_t*>(skip.data())}) {
      std::vector<std::uint8_t> blocked(s.ends.size(), 0);
      occlude_face_float(isa, s.face, s.start, x.data(), y.data(), z.data(), x.size(), blocked.data(), mask);
      for (std::size_t i = 0; i < s.ends.size(); ++i) {
        const Vec3 end{x[i], y[i], z[i]};  // the kernel sees float end points
        const bool skipped = mask != nullptr && i == 10;
        ASSERT_EQ(blocked[i] != 0, !skipped && segment_hits_ref_float(s.face, s.start, end)) << i << name(isa);
      }
    }
  }
}

}  // namespace
}  // namespace rc::pipeline
