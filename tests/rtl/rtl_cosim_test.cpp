// Co-simulation of the Verilog pipeline (rtl/mt_pipeline.v, Verilated) against the C++ bit-exact
// model (pipeline/fixed_mt.h): at 7, 11, 15, 23 and 31 fractional bits, random integer inputs over the
// whole ranges (corners included) and every kind of the stress suite (pipeline/stress_cases.h) give the
// same hit bit (with the t_guard input at 0, and at 1, 2, 4 and 255), streamed one test per clock; and a valid bit sampled at rising edge c is in the last
// register after edge c + 36, for the consumer to sample at edge c + 37: 37 register stages exactly.
// Without Verilator (or a width not built) each test prints "SKIP: <reason>" and is skipped.
#include <cstdint>
#include <deque>
#include <iostream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/fixed_mt.h"
#include "pipeline/stress_cases.h"
#include "rtl/sim/rtl_pipeline.h"

namespace rc::rtl {
namespace {

using pipeline::FaceRecord;
using pipeline::FixedVec3;

#define REQUIRE_MODEL(bits, array)                                  \
  do {                                                              \
    const std::string why = rtl_unavailable_reason(bits, array);    \
    if (!why.empty()) {                                             \
      std::cout << "SKIP: RTL co-simulation: " << why << "\n";      \
      GTEST_SKIP() << why;                                          \
    }                                                               \
  } while (0)

struct Case {
  RtlInputs in;
  bool expected;
};

Case make_case(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end, int bits) {
  Case c;
  c.in.valid = true;
  c.in.face = face;
  c.in.start = start;
  c.in.end = end;
  c.expected = pipeline::segment_hits(face, start, end, bits);
  return c;
}

// Random positions, mostly uniform, a quarter of the coordinates at the ends of the range (0, 1, 2^N - 2,
// 2^N - 1) so that every register meets its extreme values.
std::vector<Case> random_cases(int bits, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::int64_t top = (std::int64_t(1) << bits) - 1;
  std::uniform_int_distribution<std::int64_t> any(0, top);
  std::uniform_int_distribution<int> pick(0, 15);
  auto coordinate = [&] {
    switch (pick(rng)) {
      case 0: return std::int64_t(0);
      case 1: return std::int64_t(1);
      case 2: return top - 1;
      case 3: return top;
      default: return any(rng);
    }
  };
  auto point = [&] { return FixedVec3{coordinate(), coordinate(), coordinate()}; };
  std::vector<Case> cases;
  cases.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const FixedVec3 v0 = point(), v1 = point(), v2 = point();
    const FaceRecord face{v0, v1 - v0, v2 - v0};
    cases.push_back(make_case(face, point(), point(), bits));
  }
  return cases;
}

std::vector<Case> stress_cases(int bits, std::size_t per_kind, std::uint64_t seed) {
  std::vector<Case> cases;
  for (int k = 0; k < pipeline::kCaseKindCount; ++k)
    for (const pipeline::StressCase& s :
         pipeline::make_stress_cases(static_cast<pipeline::CaseKind>(k), bits, per_kind, seed + k))
      cases.push_back(make_case(pipeline::make_face_record(s.triangle, bits), pipeline::quantize_point(s.start, bits),
                                pipeline::quantize_point(s.end, bits), bits));
  return cases;
}

// Streams the cases one per clock, every `gap`-th clock idle, and checks each result at exactly 37
// edges after the one that sampled it (out_valid low at every other edge). Returns the hits seen.
std::size_t stream(RtlPipeline& rtl, const std::vector<Case>& cases, unsigned gap) {
  std::deque<std::pair<std::uint64_t, std::size_t>> in_flight;  // (sampling edge, case)
  std::size_t next = 0, hits = 0, mismatches = 0;
  std::uint64_t edge = 0;
  while (next < cases.size() || !in_flight.empty()) {
    RtlInputs in;  // idle: valid low; t_guard is a static input, held through idle cycles (all cases share it)
    if (!cases.empty()) in.t_guard = cases.front().in.t_guard;
    if (next < cases.size() && (gap == 0 || edge % gap != gap - 1)) {
      in = cases[next].in;
      in_flight.emplace_back(edge, next++);
    }
    rtl.clock(in);  // edge `edge`
    // After edge e the last register holds what edge e - 36 sampled: the consumer takes it at e + 1.
    const bool due = !in_flight.empty() && in_flight.front().first + kRtlLatency - 1 == edge;
    EXPECT_EQ(rtl.out_valid(), due) << "out_valid after edge " << edge;
    if (due) {
      const Case& c = cases[in_flight.front().second];
      if (rtl.out_hit() != c.expected && ++mismatches <= 5)
        ADD_FAILURE() << "case " << in_flight.front().second << ": RTL " << rtl.out_hit() << ", C++ " << c.expected
                      << " (start " << c.in.start.x << "," << c.in.start.y << "," << c.in.start.z << " end "
                      << c.in.end.x << "," << c.in.end.y << "," << c.in.end.z << ") t_guard " << c.in.t_guard;
      hits += rtl.out_hit();
      in_flight.pop_front();
    }
    ++edge;
  }
  EXPECT_EQ(mismatches, 0u);
  return hits;
}

class RtlCosim : public ::testing::TestWithParam<int> {};

TEST_P(RtlCosim, ValidBitLeavesExactly37EdgesAfterItEntered) {
  const int bits = GetParam();
  REQUIRE_MODEL(bits, false);
  auto rtl = make_rtl_pipeline(bits);
  for (int e = 0; e < 50; ++e) {  // empty after reset
    rtl->clock({});
    ASSERT_FALSE(rtl->out_valid()) << "edge " << e;
  }
  const std::vector<Case> one = random_cases(bits, 1, 1);
  rtl->clock(one[0].in);  // sampled at edge 0
  for (unsigned e = 1; e < 3 * kRtlLatency; ++e) {
    rtl->clock({});
    EXPECT_EQ(rtl->out_valid(), e == kRtlLatency - 1) << "after edge " << e;
    if (e == kRtlLatency - 1) {
      EXPECT_EQ(rtl->out_hit(), one[0].expected);
    }
  }
  // reset empties the valid chain
  rtl->clock(one[0].in);
  rtl->reset();
  for (unsigned e = 0; e < 2 * kRtlLatency; ++e) {
    rtl->clock({});
    EXPECT_FALSE(rtl->out_valid());
  }
}

TEST_P(RtlCosim, RandomInputsEqualTheCppPipelineBitForBit) {
  const int bits = GetParam();
  REQUIRE_MODEL(bits, false);
  auto rtl = make_rtl_pipeline(bits);
  const std::vector<Case> cases = random_cases(bits, 100000, 1000 + bits);
  std::size_t expected_hits = 0;
  for (const Case& c : cases) expected_hits += c.expected;
  EXPECT_EQ(stream(*rtl, cases, 0), expected_hits);
  EXPECT_GT(expected_hits, 100u);  // the comparison saw hits, not only misses
  EXPECT_EQ(stream(*rtl, random_cases(bits, 2000, 7 + bits), 5), [&] {
    std::size_t h = 0;
    for (const Case& c : random_cases(bits, 2000, 7 + bits)) h += c.expected;
    return h;
  }());  // with idle cycles between tests
}

TEST_P(RtlCosim, StressCasesEqualTheCppPipelineBitForBit) {
  const int bits = GetParam();
  REQUIRE_MODEL(bits, false);
  auto rtl = make_rtl_pipeline(bits);
  const std::vector<Case> cases = stress_cases(bits, 3000, 77);
  std::size_t expected_hits = 0;
  for (const Case& c : cases) expected_hits += c.expected;
  EXPECT_EQ(stream(*rtl, cases, 0), expected_hits);
  EXPECT_GT(expected_hits, 1000u);
}

// The t_guard input (the guard band on t): with g in {1, 2, 4, 255} held for a whole stream, the RTL
// gives the C++ model's guarded test (pipeline::segment_hits(..., g)) bit for bit; the stress cases put
// crossings near both ends and faces of a few LSBs, so the guard turns hits into misses.
TEST_P(RtlCosim, GuardBandOnTEqualsTheCppPipelineBitForBit) {
  const int bits = GetParam();
  REQUIRE_MODEL(bits, false);
  auto rtl = make_rtl_pipeline(bits);
  std::size_t flipped = 0;
  for (int g : {1, 2, 4, 255}) {
    std::vector<Case> cases = stress_cases(bits, 1500, 300 + g);
    const std::vector<Case> random = random_cases(bits, 20000, 4000 + bits + g);
    cases.insert(cases.end(), random.begin(), random.end());
    std::size_t expected_hits = 0;
    for (Case& c : cases) {
      c.in.t_guard = g;
      const bool unguarded = c.expected;
      c.expected = pipeline::segment_hits(c.in.face, c.in.start, c.in.end, bits, g);
      flipped += c.expected != unguarded;
      expected_hits += c.expected;
    }
    EXPECT_EQ(stream(*rtl, cases, g == 2 ? 5 : 0), expected_hits) << "g " << g;
  }
  EXPECT_GT(flipped, 100u);
}

// The hand-computed case of TGuard.OneLsbOfGuardTurnsAHandComputedHitAtTheStartIntoAMiss (7 bits: t*s = 1,
// |det| = 61): a hit with t_guard 0, a miss with 1.
TEST(RtlCosimGuard, OneLsbOfGuardTurnsTheHandComputedHitIntoAMiss) {
  REQUIRE_MODEL(7, false);
  auto rtl = make_rtl_pipeline(7);
  for (int g : {0, 1}) {
    Case c = make_case({{0, 0, 10}, {100, 0, 0}, {0, 100, 0}}, {20, 20, 9}, {20, 20, 109}, 7);
    c.in.t_guard = g;
    std::vector<Case> one{c};
    rtl->clock(c.in);
    RtlInputs idle;
    idle.t_guard = g;
    for (unsigned e = 1; e < kRtlLatency; ++e) rtl->clock(idle);
    ASSERT_TRUE(rtl->out_valid());
    EXPECT_EQ(rtl->out_hit(), g == 0) << "t_guard " << g;
  }
}

INSTANTIATE_TEST_SUITE_P(Widths, RtlCosim, ::testing::Values(7, 11, 15, 23, 31),
                         [](const auto& width) { return std::to_string(width.param) + "Bits"; });

// The array-multiplier build (SOFT_MULTS = 1, what synthesis without block multipliers maps) computes
// the same bits as the `*` build and the C++ model.
TEST(RtlCosimArray, ArrayMultipliersEqualTheCppPipelineAt15Bits) {
  REQUIRE_MODEL(15, true);
  auto rtl = make_rtl_pipeline(15, true);
  std::vector<Case> cases = random_cases(15, 30000, 4242);
  const std::vector<Case> stress = stress_cases(15, 1000, 99);
  cases.insert(cases.end(), stress.begin(), stress.end());
  std::size_t expected_hits = 0;
  for (const Case& c : cases) expected_hits += c.expected;
  EXPECT_EQ(stream(*rtl, cases, 0), expected_hits);
}

TEST(RtlCosimErrors, WidthsNotBuiltAreRefusedByName) {
  if (!rtl_models_built()) {
    EXPECT_THROW(make_rtl_pipeline(15), std::invalid_argument);
    EXPECT_NE(rtl_unavailable_reason(15).find("Verilator"), std::string::npos);
    return;
  }
  const std::string why = rtl_unavailable_reason(8);
  EXPECT_NE(why.find("not 8"), std::string::npos) << why;
  EXPECT_THROW(make_rtl_pipeline(8), std::invalid_argument);
}

}  // namespace
}  // namespace rc::rtl
