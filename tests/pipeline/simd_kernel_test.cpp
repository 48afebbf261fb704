// The vectorised streaming kernel (32-bit lanes up to 15 bits, 64-bit above; every
// instruction-set variant this CPU runs) against an independent oracle, the same pipeline on
// 128-bit integers (no overflow possible at any width), on the stress suite's adversarial cases at
// every width 7..31: one face and start per case, the ends of every case of its kind, masked and
// not, with stream lengths that leave a partial vector at the end.
#include <gtest/gtest.h>

#include <vector>

#include "pipeline/fixed_mt.h"
#include "pipeline/mt_core.h"
#include "pipeline/stress_cases.h"

namespace rc::pipeline {
namespace {

bool oracle_hits(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end, int bits) {
  using Wide = __int128;
  return pipeline_hits(vec_cast<Wide>(face.v0), vec_cast<Wide>(face.edge1), vec_cast<Wide>(face.edge2),
                       vec_cast<Wide>(start), vec_cast<Wide>(end), bits);
}

TEST(SimdKernel, EveryVariantMatchesTheWideOracleOnStressCasesAtEveryWidth) {
  constexpr std::size_t kCases = 61;  // ends per stream: not a multiple of any vector width
  std::size_t tested = 0, hits = 0;
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
    for (int k = 0; k < kCaseKindCount; ++k) {
      const auto kind = static_cast<CaseKind>(k);
      const std::vector<StressCase> cases = make_stress_cases(kind, bits, kCases, 1000u * bits + k);
      std::vector<std::int64_t> x, y, z;
      for (const StressCase& c : cases) {
        for (const Vec3& p : {c.end, c.start}) {
          const FixedVec3 q = quantize_point(p, bits);
          x.push_back(q.x), y.push_back(q.y), z.push_back(q.z);
        }
      }
      std::vector<std::uint8_t> skip(x.size());
      for (std::size_t i = 0; i < skip.size(); ++i) skip[i] = i % 3 == 1;
      for (std::size_t f = 0; f < cases.size(); f += 4) {
        const FaceRecord face = make_face_record(cases[f].triangle, bits);
        const FixedVec3 start = quantize_point(cases[f].start, bits);
        std::vector<std::uint8_t> expected(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) expected[i] = oracle_hits(face, start, {x[i], y[i], z[i]}, bits);
        for (const KernelIsa isa : supported_kernel_isas()) {
          for (const bool masked : {false, true}) {
            std::vector<std::uint8_t> got(x.size(), 0);
            occlude_face(isa, face, start, x.data(), y.data(), z.data(), x.size(), bits, got.data(),
                         masked ? skip.data() : nullptr);
            for (std::size_t i = 0; i < x.size(); ++i) {
              const bool want = expected[i] && !(masked && skip[i]);
              ASSERT_EQ(got[i] != 0, want) << bits << " bits, " << name(kind) << ", case " << f << ", end " << i
                                            << ", " << name(isa) << (masked ? ", masked" : "");
            }
          }
        }
        tested += x.size();
        for (std::uint8_t e : expected) hits += e;
      }
    }
  }
  // The streams must exercise both answers, or the comparison proves little.
  EXPECT_GT(hits, tested / 50);
  EXPECT_LT(hits, tested / 2);
}

}  // namespace
}  // namespace rc::pipeline
