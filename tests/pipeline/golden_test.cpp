// Bit-exactness against golden vectors from an independent Python model (plain integers):
// every multiplier and add/sub output, the decision and the exact reference, at every width.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "golden_file.h"
#include "pipeline/exact_mt.h"
#include "pipeline/fixed_mt.h"

namespace rc::pipeline {
namespace {

const golden::File& golden_file() {
  static const golden::File file = golden::load();
  return file;
}

std::string where(const golden::CaseLine& c) {
  return "golden line " + std::to_string(c.line_number) + " (" + c.kind + ", " +
         std::to_string(c.bits) + " bits)";
}

TEST(PipelineGolden, CoversEveryWidthAndEveryKind) {
  std::set<int> widths;
  std::set<std::string> kinds;
  for (const auto& c : golden_file().cases) {
    widths.insert(c.bits);
    kinds.insert(c.kind);
  }
  EXPECT_EQ(widths.size(), static_cast<std::size_t>(kMaxFracBits - kMinFracBits + 1));
  for (const char* k : {"random", "crossing", "edge", "vertex", "grazing", "parallel",
                        "near_coplanar", "degenerate", "end_on_triangle", "extreme", "max_magnitude"}) {
    EXPECT_TRUE(kinds.count(k)) << k;
  }
}

TEST(PipelineGolden, QuantisationMatches) {
  ASSERT_FALSE(golden_file().quantisations.empty());
  for (const auto& q : golden_file().quantisations) {
    EXPECT_EQ(quantize_coordinate(std::strtod(q.x_text.c_str(), nullptr), q.bits), q.q)
        << q.x_text << " at " << q.bits << " bits";
  }
}

TEST(PipelineGolden, FaceRecordsMatch) {
  ASSERT_FALSE(golden_file().faces.empty());
  for (const auto& f : golden_file().faces) {
    double v[9];
    for (int i = 0; i < 9; ++i) v[i] = std::strtod(f.vertex_text[i].c_str(), nullptr);
    const Triangle t{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}};
    EXPECT_EQ(make_face_record(t, f.bits), f.record) << f.bits << " bits";
  }
}

TEST(PipelineGolden, TraceMatchesEveryBlock) {
  ASSERT_GT(golden_file().cases.size(), 500u);
  for (const auto& c : golden_file().cases) {
    SCOPED_TRACE(where(c));
    const Trace t = trace(c.face, c.start, c.end, c.bits);
    EXPECT_EQ(t.values.direction, c.direction);
    for (int m = 0; m < kMultiplierCount; ++m) {
      EXPECT_EQ(t.multipliers[m], c.multipliers[m]) << name(static_cast<Multiplier>(m));
    }
    for (int a = 0; a < kAddSubCount; ++a) {
      EXPECT_EQ(t.add_subs[a], c.add_subs[a]) << name(static_cast<AddSub>(a));
    }
    EXPECT_EQ(t.values.stage3.sign, c.sign);
    EXPECT_EQ(t.values.stage3.abs_det, c.abs_det);
    EXPECT_EQ(t.hit(), c.hit);
  }
}

TEST(PipelineGolden, NamedStageOutputsAreTheBlockOutputs) {
  for (const auto& c : golden_file().cases) {
    SCOPED_TRACE(where(c));
    const auto add = [&](AddSub a) { return c.add_subs[static_cast<int>(a)]; };
    const auto mul = [&](Multiplier m) { return c.multipliers[static_cast<int>(m)]; };
    const Trace t = trace(c.face, c.start, c.end, c.bits);
    const PipelineValues<std::int64_t>& v = t.values;
    EXPECT_EQ(v.stage1.pvec, (FixedVec3{add(AddSub::PvecX), add(AddSub::PvecY), add(AddSub::PvecZ)}));
    EXPECT_EQ(v.stage1.tvec, (FixedVec3{add(AddSub::TvecX), add(AddSub::TvecY), add(AddSub::TvecZ)}));
    EXPECT_EQ(v.stage2.qvec, (FixedVec3{add(AddSub::QvecX), add(AddSub::QvecY), add(AddSub::QvecZ)}));
    EXPECT_EQ(v.stage2.det, add(AddSub::Det));
    EXPECT_EQ(v.stage3.u, add(AddSub::U));
    EXPECT_EQ(v.stage3.v, add(AddSub::V));
    EXPECT_EQ(v.stage3.t, add(AddSub::T));
    EXPECT_EQ(v.stage3.u_signed, mul(Multiplier::SignU));
    EXPECT_EQ(v.stage3.v_signed, mul(Multiplier::SignV));
    EXPECT_EQ(v.stage3.t_signed, mul(Multiplier::SignT));
    EXPECT_EQ(v.stage3.uv_sum, add(AddSub::UPlusV));
  }
}

TEST(PipelineGolden, StageFunctionsAndKernelsAgreeWithTheGolden) {
  for (const auto& c : golden_file().cases) {
    SCOPED_TRACE(where(c));
    const FixedVec3 dir = segment_direction(c.start, c.end);
    const Stage1Result s1 = stage1(c.face, c.start, dir, c.bits);
    const Stage2Result s2 = stage2(c.face, s1, c.bits);
    const Stage3Result s3 = stage3(c.face, dir, s1, s2, c.bits);
    EXPECT_EQ(s2.det, c.add_subs[static_cast<int>(AddSub::Det)]);
    EXPECT_EQ(s3.uv_sum, c.add_subs[static_cast<int>(AddSub::UPlusV)]);
    EXPECT_EQ(s3.hit, c.hit);
    EXPECT_EQ(segment_hits(c.face, c.start, c.end, c.bits), c.hit);
    // The batch kernel on a one-element stream, on its 32-bit or 64-bit path by width.
    std::uint8_t blocked = 0;
    occlude_face(c.face, c.start, &c.end.x, &c.end.y, &c.end.z, 1, c.bits, &blocked);
    EXPECT_EQ(blocked != 0, c.hit);
    // The 128-bit instantiation of the same core has room to spare, so agreeing with it means the
    // 64-bit one did not overflow.
    const auto wide = [](const FixedVec3& v) { return vec_cast<__int128>(v); };
    EXPECT_EQ(pipeline_hits(wide(c.face.v0), wide(c.face.edge1), wide(c.face.edge2), wide(c.start),
                            wide(c.end), c.bits),
              c.hit);
  }
}

TEST(PipelineGolden, ExactReferenceMatches) {
  for (const auto& c : golden_file().cases) {
    SCOPED_TRACE(where(c));
    const ExactValues e = exact_values(c.face, c.start, c.end);
    EXPECT_TRUE(e.det == c.exact_det && e.u == c.exact_u && e.v == c.exact_v && e.t == c.exact_t);
    EXPECT_EQ(e.hit, c.exact_hit);
  }
}

}  // namespace
}  // namespace rc::pipeline
