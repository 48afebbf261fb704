// The pass timing of docs/board.md, checked three ways: against the formula worked out by hand,
// between the fast model (one event per pass) and the cycle-level model (clocked pipeline), and
// for the result bits against the CPU's fixed-point answer.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "board/cycle_wrapper.h"
#include "tests/board/board_test_support.h"

namespace rc::board::test {
namespace {

struct Observed {
  std::vector<PassRecord> passes;
  std::vector<std::vector<std::uint8_t>> blocked;
  std::vector<sc_time> start_written;  // when the host's START write was issued
};

// One board running `passes` one after another from a scripted host.
struct Bench {
  std::unique_ptr<Rc2000> board;
  std::unique_ptr<ScriptedHost> host;
  Observed seen;

  Bench(const char* name, const BoardParams& params, std::vector<PassData> passes, int bits) {
    board = std::make_unique<Rc2000>(name, params);
    board->wrapper().on_pass([this](const PassRecord& r) { seen.passes.push_back(r); });
    host = std::make_unique<ScriptedHost>((std::string(name) + "_host").c_str(), *board,
                                          [this, passes, bits](ScriptedHost& h) {
                                            for (const PassData& d : passes) {
                                              seen.blocked.push_back(run_pass(h, d));
                                              EXPECT_EQ(seen.blocked.back(), expected_blocked(d, bits));
                                            }
                                          });
  }
};

void run_until_finished(const std::vector<Bench*>& benches) { test::run_until_finished(hosts_of(benches)); }

// Both models, same passes: same cycles, same completion offsets, same bits.
void expect_models_agree(const Bench& fast, const Bench& cycle) {
  ASSERT_FALSE(fast.seen.passes.empty());
  ASSERT_EQ(fast.seen.passes.size(), cycle.seen.passes.size());
  ASSERT_EQ(fast.seen.blocked.size(), fast.seen.passes.size());
  for (std::size_t i = 0; i < fast.seen.passes.size(); ++i) {
    EXPECT_EQ(fast.seen.passes[i].cycles, cycle.seen.passes[i].cycles) << "pass " << i;
    EXPECT_EQ(fast.seen.passes[i].end - fast.seen.passes[i].start, cycle.seen.passes[i].end - cycle.seen.passes[i].start);
    EXPECT_EQ(fast.seen.passes[i].lane_rays, cycle.seen.passes[i].lane_rays);
    EXPECT_EQ(fast.seen.blocked[i], cycle.seen.blocked[i]);
  }
}

const std::vector<std::uint64_t> kRays = {1, 2, 37, 100, 1001};

// One face x R rays, 1 and 2 lanes (15 bits: two coordinates per word, one X/Y/Z triple).
//   fetch  = ceil((Lr 2 + 9 words) * 10 ns / 20 ns) = 6   (own-face table in spare bank 5)
//   stream = ceil(R / lanes)   (banks give 2 words per device cycle: no stall)
//   total  = start 2 + setup 1 + fetch 6 + stream + latency 37 + finish 1 = 47 + ceil(R / lanes)
TEST(PassTiming, OneFaceMatchesFormulaAndCycleModel) {
  const int bits = 15;
  std::vector<PassData> passes;
  for (std::uint64_t r : kRays) passes.push_back(crossing_pass(r, bits, 1, static_cast<unsigned>(r)));
  Bench fast1("fast1", round_params(1, bits), passes, bits);
  Bench cycle1("cycle1", round_params(1, bits, 6, WrapperModel::cycle), passes, bits);
  Bench fast2("fast2", round_params(2, bits), passes, bits);
  Bench cycle2("cycle2", round_params(2, bits, 6, WrapperModel::cycle), passes, bits);
  run_until_finished({&fast1, &cycle1, &fast2, &cycle2});

  const sc_time Pd(20, SC_NS);
  ASSERT_EQ(fast1.seen.passes.size(), kRays.size());
  ASSERT_EQ(fast2.seen.passes.size(), kRays.size());
  for (std::size_t i = 0; i < kRays.size(); ++i) {
    const std::uint64_t R = kRays[i];
    EXPECT_EQ(fast1.seen.passes[i].cycles, 47 + R) << "R = " << R;
    EXPECT_EQ(fast2.seen.passes[i].cycles, 47 + (R + 1) / 2) << "R = " << R;
    EXPECT_EQ(fast1.seen.passes[i].end - fast1.seen.passes[i].start, (47 + R) * Pd);
    EXPECT_EQ(fast2.seen.passes[i].lane_rays, (std::vector<std::uint64_t>{(R + 1) / 2, R / 2}));
    // The pass starts on the first device clock edge at or after START.
    EXPECT_EQ(fast1.seen.passes[i].start.value() % Pd.value(), 0u);
  }
  expect_models_agree(fast1, cycle1);
  expect_models_agree(fast2, cycle2);
}

// Several faces with own-face masks (rays ending on face f, and the shooter's face 2): both models
// mask the same rays and take the same time; the formula for 1 lane: 2 + F * (1 + 6) + F * R + 38.
TEST(PassTiming, OwnFaceMasksAgreeBetweenModels) {
  const int bits = 15;
  std::vector<PassData> passes;
  for (std::uint64_t r : {5u, 64u, 203u}) {
    PassData d = crossing_pass(r, bits, 5, 7 * static_cast<unsigned>(r));
    d.source_face = 2;
    passes.push_back(d);
  }
  Bench fast1("fast1", round_params(1, bits), passes, bits);
  Bench cycle1("cycle1", round_params(1, bits, 6, WrapperModel::cycle), passes, bits);
  Bench fast2("fast2", round_params(2, bits), passes, bits);
  Bench cycle2("cycle2", round_params(2, bits, 6, WrapperModel::cycle), passes, bits);
  run_until_finished({&fast1, &cycle1, &fast2, &cycle2});
  EXPECT_EQ(fast1.seen.passes[1].cycles, 2 + 5 * 7 + 5 * 64 + 38u);
  // Two lanes share result words: faces after the first read-modify-write (2 accesses per packet
  // of 2 rays = 1 per device cycle at 2 bank cycles per device cycle): no stall, 32 cycles a face.
  EXPECT_EQ(fast2.seen.passes[1].cycles, 2 + 5 * 7 + 5 * 32 + 38u);
  expect_models_agree(fast1, cycle1);
  expect_models_agree(fast2, cycle2);
}

// Banks at 40 MHz (25 ns) under a 50 MHz device: a bank gives 0.8 words per device cycle, so
// one lane stalls: stream = ceil(1.25 R), fetch = ceil(11 * 1.25) = 14.
TEST(PassTiming, SlowBanksStallTheLanes) {
  const int bits = 15;
  std::vector<PassData> passes;
  for (std::uint64_t r : {1u, 37u, 100u}) passes.push_back(crossing_pass(r, bits, 1, static_cast<unsigned>(r)));
  BoardParams fast = round_params(1, bits), cycle = round_params(1, bits, 6, WrapperModel::cycle);
  fast.timing.bank_period = cycle.timing.bank_period = sc_time(25, SC_NS);
  Bench f("fast", fast, passes, bits), c("cycle", cycle, passes, bits);
  run_until_finished({&f, &c});
  EXPECT_EQ(f.seen.passes[0].cycles, 2 + 1 + 14 + 2 + 37 + 1u);   // ceil(1.25) = 2
  EXPECT_EQ(f.seen.passes[1].cycles, 2 + 1 + 14 + 47 + 37 + 1u);  // ceil(46.25) = 47
  EXPECT_EQ(f.seen.passes[2].cycles, 2 + 1 + 14 + 125 + 37 + 1u);
  EXPECT_NE(f.seen.passes[2].limit.find("bank"), std::string::npos);
  expect_models_agree(f, c);
}

// Two lanes of 31-bit coordinates (one per word) on 6 and 7 banks, the variants of sec 4.1: lane 1
// reads X, Y, Z from one bank (1/3 rate) or two (2/3 rate). 100 rays split as lanes allow:
//   6 banks: n = 75 cycles: lane 0 takes 75 rays, lane 1 floor(75 / 3) = 25; stream 75
//   7 banks: n = 60: lane 0 60 rays, lane 1 2 * 60 / 3 = 40; stream 60
// (5 banks: 100 cycles; both are the "too few banks for full rate" stall of lane 1.)
TEST(PassTiming, SixAndSevenBankVariantsRunTheSecondLaneSlower) {
  const int bits = 31;
  const std::vector<PassData> passes = {crossing_pass(100, bits, 1, 3), crossing_pass(7, bits, 1, 4)};
  Bench f6("fast6", round_params(2, bits, 6), passes, bits);
  Bench c6("cycle6", round_params(2, bits, 6, WrapperModel::cycle), passes, bits);
  Bench f7("fast7", round_params(2, bits, 7), passes, bits);
  Bench c7("cycle7", round_params(2, bits, 7, WrapperModel::cycle), passes, bits);
  run_until_finished({&f6, &c6, &f7, &c7});
  // fetch: no spare bank is left, so the own-face word follows the record: ceil((2 + 10) / 2) = 6.
  EXPECT_EQ(f6.seen.passes[0].cycles, 2 + 1 + 6 + 75 + 37 + 1u);
  EXPECT_EQ(f6.seen.passes[0].lane_rays, (std::vector<std::uint64_t>{75, 25}));
  EXPECT_EQ(f7.seen.passes[0].cycles, 2 + 1 + 6 + 60 + 37 + 1u);
  EXPECT_EQ(f7.seen.passes[0].lane_rays, (std::vector<std::uint64_t>{60, 40}));
  // 7 rays, 6 banks: n = 6 gives 6 + 2 = 8 >= 7: lane 0 six rays, lane 1 one ray (3 cycles).
  EXPECT_EQ(f6.seen.passes[1].lane_rays, (std::vector<std::uint64_t>{6, 1}));
  EXPECT_EQ(f6.seen.passes[1].cycles, 2 + 1 + 6 + 6 + 37 + 1u);
  expect_models_agree(f6, c6);
  expect_models_agree(f7, c7);
}

}  // namespace
}  // namespace rc::board::test
