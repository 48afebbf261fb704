// The ray split (board/bank_layout.h, docs/board.md "Ray split"): the limit split follows the
// pass-timing formula's every term, so a layout with more banks is never slower, and it is never
// slower than the paper's nominal split; the cycle-level wrapper takes exactly the formula's cycles
// under it, and the results are the CPU's answer (the host packs and the wrapper unpacks with the
// same split).
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "board/cycle_wrapper.h"
#include "tests/board/board_test_support.h"

namespace rc::board::test {
namespace {

struct Clocks {
  const char* name;
  std::uint64_t device_ps, bank_ps;
};
// The RC2000's two-lane design (52.5 MHz) on 100 MHz banks, and sec 5.6's 176.9 MHz design on the
// same banks (the banks slower than the device: every ray bank and the result bank can limit).
const Clocks kClocks[] = {{"52.5MHz", 19048, 10000}, {"176.9MHz", 5653, 10000}};

WrapperTiming timing_of(const Clocks& c) {
  WrapperTiming t;
  t.device_period = sc_time(static_cast<double>(c.device_ps), SC_PS);
  t.bank_period = sc_time(static_cast<double>(c.bank_ps), SC_PS);
  return t;
}

// The layout of `lanes` at `bits` on `banks` 4 MiB banks with results `store`, or none when the
// banks cannot feed the lanes.
std::optional<BankLayout> layout_of(unsigned lanes, int bits, unsigned banks, ResultStore store, RaySplitRule rule,
                                    const WrapperTiming& t) {
  try {
    BankLayout L = make_bank_layout(lanes, banks, bits, 32, 4u << 20);
    L = place_results(std::move(L), store, store == ResultStore::on_chip ? (std::uint64_t{1} << 22) : 0);
    return place_split(std::move(L), rule, t.bank_period.value(), t.device_period.value());
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

const std::uint64_t kRays[] = {1, 2, 3, 37, 100, 1001, 4479, 65536};
const std::uint64_t kFaces[] = {1, 2, 3, 4, 8, 280};

// Lanes 1..12 at 7, 15 and 31 bits, banks 5..64 (run --banks' range), both clocks, results in the
// bank and on chip: the pass's device cycles under the limit split never grow with the banks. With
// results in the bank (every profile's, the paper's design) at any face count; on chip from 8 faces a
// pass: the end-of-pass write-out (one word per packet) can grow by more than 1 to 4 faces' stream
// shrinks when more banks move rays to a group of fewer lanes (docs/board.md, "Ray split").
TEST(RaySplit, MoreBanksAreNeverSlower) {
  std::size_t compared = 0;
  for (const Clocks& clocks : kClocks) {
    const WrapperTiming t = timing_of(clocks);
    for (ResultStore store : {ResultStore::bank, ResultStore::on_chip})
      for (int bits : {7, 15, 31})
        for (unsigned lanes = 1; lanes <= 12; ++lanes)
          for (std::uint64_t rays : kRays) {
            std::optional<std::vector<std::uint64_t>> before;  // total per face count, fewer banks
            unsigned before_banks = 0;
            for (unsigned banks = 5; banks <= 64; ++banks) {
              const std::optional<BankLayout> L = layout_of(lanes, bits, banks, store, RaySplitRule::limit, t);
              if (!L) continue;
              const RaySplit split = split_rays(*L, rays);
              ASSERT_TRUE(split.fits);
              std::vector<std::uint64_t> totals;
              for (std::uint64_t faces : kFaces) totals.push_back(pass_timing(*L, t, split, faces, true).total);
              if (before) {
                for (std::size_t f = 0; f < totals.size(); ++f) {
                  if (store == ResultStore::on_chip && kFaces[f] < 8) continue;
                  EXPECT_LE(totals[f], (*before)[f])
                      << clocks.name << " results " << to_string(store) << ' ' << bits << " bits " << lanes << " lanes "
                      << rays << " rays " << kFaces[f] << " faces: " << banks << " banks after " << before_banks;
                  ++compared;
                }
              }
              before = totals;
              before_banks = banks;
            }
          }
  }
  EXPECT_GT(compared, 10000u);
}

// On every layout the limit split's stream (a face that does not clear) is the fewest cycles: never
// more than the nominal split's, and every ray is placed once, in order.
TEST(RaySplit, LimitIsNeverSlowerThanNominal) {
  for (const Clocks& clocks : kClocks) {
    const WrapperTiming t = timing_of(clocks);
    for (ResultStore store : {ResultStore::bank, ResultStore::on_chip})
      for (int bits : {7, 15, 31})
        for (unsigned lanes = 1; lanes <= 12; ++lanes)
          for (unsigned banks = 5; banks <= 40; ++banks) {
            const auto limit = layout_of(lanes, bits, banks, store, RaySplitRule::limit, t);
            const auto nominal = layout_of(lanes, bits, banks, store, RaySplitRule::nominal, t);
            if (!limit) continue;
            for (std::uint64_t rays : kRays) {
              const RaySplit a = split_rays(*limit, rays), b = split_rays(*nominal, rays);
              EXPECT_LE(stream_cycles(*limit, t, a, false), stream_cycles(*nominal, t, b, false))
                  << clocks.name << ' ' << bits << " bits " << lanes << " lanes " << banks << " banks " << rays << " rays";
              std::uint64_t sum = 0;
              for (std::size_t g = 0; g < a.rays.size(); ++g) {
                EXPECT_EQ(a.first_ray[g], sum);
                sum += a.rays[g];
              }
              EXPECT_EQ(sum, rays);
            }
          }
  }
}

// The walk-through's case: 5 lanes at 15 bits (groups of 2, 2 and 1 lanes), 176.9 MHz design on
// 100 MHz banks, 1001 rays against 280 faces. The result bank moves floor(n * 5653 / 10000) words
// in n device cycles; the nominal split gives the 1-lane group its nominal share and so stretches
// the stream when its banks grow, the limit split does not.
TEST(RaySplit, FiveLanesWorkedExample) {
  const WrapperTiming t = timing_of(kClocks[1]);
  std::vector<std::uint64_t> nominal, limit;
  for (unsigned banks : {9u, 10u, 11u}) {
    const BankLayout n = *layout_of(5, 15, banks, ResultStore::bank, RaySplitRule::nominal, t);
    const BankLayout l = *layout_of(5, 15, banks, ResultStore::bank, RaySplitRule::limit, t);
    nominal.push_back(pass_timing(n, t, split_rays(n, 1001), 280, true).total);
    limit.push_back(pass_timing(l, t, split_rays(l, 1001), 280, true).total);
  }
  EXPECT_EQ(nominal, (std::vector<std::uint64_t>{501543, 501600, 501649}));
  EXPECT_EQ(limit, (std::vector<std::uint64_t>{501476, 501476, 501476}));
}

struct Bench {
  std::unique_ptr<Rc2000> board;
  std::unique_ptr<ScriptedHost> host;
  std::vector<PassRecord> passes;
  std::vector<std::vector<std::uint8_t>> blocked;

  Bench(const std::string& name, const BoardParams& params, const std::vector<PassData>& data, int bits) {
    board = std::make_unique<Rc2000>(name.c_str(), params);
    board->wrapper().on_pass([this](const PassRecord& r) { passes.push_back(r); });
    host = std::make_unique<ScriptedHost>((name + "_host").c_str(), *board, [this, data, bits](ScriptedHost& h) {
      for (const PassData& d : data) {
        blocked.push_back(run_pass(h, d));
        EXPECT_EQ(blocked.back(), expected_blocked(d, bits));  // the host packed what the wrapper read
      }
    });
  }
};

// Where the splits differ (5 lanes at 15 bits on 10 banks, 176.9 MHz design on 100 MHz banks): the
// fast and the cycle-level wrapper take the formula's cycles under each split, to the cycle, and
// both splits give the CPU's answer bit for bit.
TEST(RaySplit, FormulaAndCycleModelAgreeUnderEitherSplit) {
  const int bits = 15;
  const std::vector<PassData> data = {crossing_pass(1001, bits, 3, 11), crossing_pass(37, bits, 2, 5),
                                      crossing_pass(1, bits, 1, 1)};
  auto params = [&](RaySplitRule rule, WrapperModel model) {
    BoardParams p = round_params(5, bits, 10, model);
    p.timing.device_period = sc_time(5653, SC_PS);
    p.timing.bank_period = sc_time(10000, SC_PS);
    p.ray_split = rule;
    return p;
  };
  Bench fl("fast_limit", params(RaySplitRule::limit, WrapperModel::fast), data, bits);
  Bench cl("cycle_limit", params(RaySplitRule::limit, WrapperModel::cycle), data, bits);
  Bench fn("fast_nominal", params(RaySplitRule::nominal, WrapperModel::fast), data, bits);
  Bench cn("cycle_nominal", params(RaySplitRule::nominal, WrapperModel::cycle), data, bits);
  test::run_until_finished(hosts_of(std::vector<Bench*>{&fl, &cl, &fn, &cn}));
  for (const Bench* b : {&fl, &cl, &fn, &cn}) ASSERT_EQ(b->passes.size(), data.size());
  for (std::size_t i = 0; i < data.size(); ++i) {
    for (const auto& [fast, cycle] : {std::pair{&fl, &cl}, std::pair{&fn, &cn}}) {
      const BankLayout& L = fast->board->layout();
      const PassTiming formula =
          pass_timing(L, fast->board->params().timing, split_rays(L, data[i].ends.size()), data[i].faces.size(), true);
      EXPECT_EQ(fast->passes[i].cycles, formula.total) << "pass " << i << ' ' << to_string(L.ray_split);
      EXPECT_EQ(cycle->passes[i].cycles, formula.total) << "pass " << i << ' ' << to_string(L.ray_split);
      EXPECT_EQ(fast->passes[i].lane_rays, cycle->passes[i].lane_rays);
      EXPECT_EQ(fast->passes[i].end - fast->passes[i].start, cycle->passes[i].end - cycle->passes[i].start);
    }
    EXPECT_EQ(fl.blocked[i], fn.blocked[i]);  // the same answer under either split
  }
  // The splits differ on the long pass, and the limit split's is shorter.
  EXPECT_NE(fl.passes[0].lane_rays, fn.passes[0].lane_rays);
  EXPECT_LT(fl.passes[0].cycles, fn.passes[0].cycles);
  // Limit: the result bank (a read-modify-write per packet of two lanes, 0.5653 words a device
  // cycle) bounds every split; the first group alone keeps up with it, so it takes 1000 rays and the
  // last group the odd one. Nominal: every group its nominal share, the result bank's words the same
  // but the 1-lane group's odd packets cost more of them.
  EXPECT_EQ(fl.passes[0].cycles, 4538u);
  EXPECT_EQ(fn.passes[0].cycles, 4662u);
  EXPECT_EQ(fl.passes[0].lane_rays, (std::vector<std::uint64_t>{1500, 1500, 0, 0, 3}));
  EXPECT_EQ(fn.passes[0].lane_rays, (std::vector<std::uint64_t>{645, 645, 645, 645, 423}));
}

}  // namespace
}  // namespace rc::board::test
