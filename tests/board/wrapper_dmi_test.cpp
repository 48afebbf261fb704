// The wrapper's DMI to the banks (wrapper_base.h): one cached region per bank page it touches, asked
// for through the local bus; an invalidation from a bank (translated by the local bus) drops exactly
// the cached regions it overlaps, and the next pass asks for them again; words that straddle pages
// (2-byte pages under 4-byte words) give the same result words, times and bank traffic as whole
// pages, in both wrapper models.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "tests/board/board_test_support.h"

namespace rc::board::test {
namespace {

std::vector<std::size_t> region_counts(const Rc2000& board) {
  std::vector<std::size_t> n;
  for (unsigned b = 0; b < board.params().banks; ++b) n.push_back(board.wrapper().dmi_cache(b).regions().size());
  return n;
}

std::vector<std::uint64_t> request_counts(const Rc2000& board) {
  std::vector<std::uint64_t> n;
  for (unsigned b = 0; b < board.params().banks; ++b) n.push_back(board.wrapper().dmi_cache(b).report().requests);
  return n;
}

TEST(WrapperDmi, InvalidationDropsTheOverlappingPagesAndTheNextPassAsksAgain) {
  Rc2000 board("rc2000", round_params(1));  // 1 MiB banks of 64 KiB pages
  const unsigned results = board.layout().result_bank;
  const PassData d = crossing_pass(100, 15, 2, 3);
  std::vector<std::uint8_t> first, second;
  std::vector<std::size_t> regions_after_pass, regions_after_miss, regions_after_hit;
  std::vector<std::uint64_t> requests_after_pass;
  std::uint64_t dropped_by_miss = 0;
  ScriptedHost host("host", board, [&](ScriptedHost& h) {
    first = run_pass(h, d);
    regions_after_pass = region_counts(board);
    requests_after_pass = request_counts(board);
    // The bank's second page: the wrapper holds none of it (100 result words are in page 0).
    board.bank(results).in->invalidate_direct_mem_ptr(0x1'0000, 0x1'FFFF);
    regions_after_miss = region_counts(board);
    dropped_by_miss = board.wrapper().dmi_cache(results).report().dropped;
    // Page 0, in the bank's addresses; the local bus translates it to the wrapper's.
    board.bank(results).in->invalidate_direct_mem_ptr(0x100, 0x103);
    regions_after_hit = region_counts(board);
    second = run_pass(h, d);
  });
  run_until_finished({&host});

  ASSERT_TRUE(host.finished);
  EXPECT_EQ(first, expected_blocked(d, 15));
  EXPECT_EQ(second, first);
  // One page per bank the pass touched (faces, own-face table, rays, results), one request each.
  for (unsigned b = 0; b < board.params().banks; ++b) {
    EXPECT_EQ(requests_after_pass[b], regions_after_pass[b]) << "bank " << b;
    EXPECT_LE(regions_after_pass[b], 1u) << "bank " << b;
  }
  EXPECT_EQ(regions_after_pass[results], 1u);
  EXPECT_EQ(regions_after_miss, regions_after_pass);
  EXPECT_EQ(dropped_by_miss, 0u);
  std::vector<std::size_t> expected_after_hit = regions_after_pass;
  expected_after_hit[results] = 0;  // exactly the result bank's page 0, no other bank's
  EXPECT_EQ(regions_after_hit, expected_after_hit);
  EXPECT_EQ(board.wrapper().dmi_cache(results).report().dropped, 1u);
  // The second pass asks again for the result page only.
  std::vector<std::uint64_t> expected_requests = requests_after_pass;
  expected_requests[results] += 1;
  EXPECT_EQ(request_counts(board), expected_requests);
  EXPECT_EQ(region_counts(board), regions_after_pass);
  EXPECT_EQ(board.bank(results).report().dmi_grants, 2u);
  EXPECT_EQ(board.bank(board.layout().face_bank).report().dmi_grants, 1u);
}

struct Step {
  PassData data;
  bool clear = true;
};

// A clearing pass, one with own-face masks and the shooter's face over 5 faces, the same rays against
// 3 other faces ORed onto the previous words (read-modify-writes of words two lanes share).
std::vector<Step> steps() {
  std::vector<Step> s;
  s.push_back({crossing_pass(37, 15, 1, 37), true});
  PassData masked = crossing_pass(100, 15, 5, 700);
  masked.source_face = 2;
  s.push_back({masked, true});
  PassData other = masked;
  other.faces = crossing_pass(1, 15, 3, 9).faces;
  other.end_faces.assign(other.ends.size(), -1);
  other.source_face = -1;
  s.push_back({other, false});
  return s;
}

struct Bench {
  std::unique_ptr<Rc2000> board;
  std::unique_ptr<ScriptedHost> host;
  std::vector<PassRecord> passes;
  std::vector<std::vector<std::uint8_t>> blocked;
  std::vector<std::vector<std::uint8_t>> result_bytes;  // the result bank's words after each pass

  Bench(const std::string& name, const BoardParams& params, std::uint64_t page_bytes) {
    board = std::make_unique<Rc2000>(name.c_str(), params, page_bytes);
    board->wrapper().on_pass([this](const PassRecord& r) { passes.push_back(r); });
    host = std::make_unique<ScriptedHost>((name + "_host").c_str(), *board, [this](ScriptedHost& h) {
      for (const Step& s : steps()) {
        blocked.push_back(run_pass(h, s.data, s.clear));
        const RaySplit split = split_rays(board->layout(), s.data.ends.size());
        result_bytes.push_back(
            board->bank(board->layout().result_bank).debug_bytes(0, split.result_words * board->layout().word_bits / 8));
      }
    });
  }
};

TEST(WrapperDmi, WordsAcrossPagesGiveTheSameResultsTimesAndTraffic) {
  struct Pair {
    std::string name;
    std::unique_ptr<Bench> whole, split;
  };
  std::vector<Pair> pairs;
  for (WrapperModel model : {WrapperModel::fast, WrapperModel::cycle}) {
    for (ResultStore store : {ResultStore::bank, ResultStore::on_chip}) {
      BoardParams p = round_params(2, 15, 6, model);
      p.results = store;
      p.result_store_bits = 1u << 20;
      const std::string name = std::string(model == WrapperModel::fast ? "fast" : "cycle") +
                               (store == ResultStore::bank ? "_bank" : "_chip");
      pairs.push_back({name, std::make_unique<Bench>(name + "_whole", p, 64u << 10),
                       std::make_unique<Bench>(name + "_split", p, 2)});
    }
  }
  std::vector<const ScriptedHost*> hosts;
  for (const Pair& p : pairs) hosts.push_back(p.whole->host.get()), hosts.push_back(p.split->host.get());
  run_until_finished(hosts);

  for (const Pair& p : pairs) {
    const Bench& w = *p.whole;
    const Bench& s = *p.split;
    ASSERT_EQ(w.passes.size(), 3u) << p.name;
    ASSERT_EQ(s.passes.size(), 3u) << p.name;
    EXPECT_EQ(w.blocked[0], expected_blocked(steps()[0].data, 15)) << p.name;
    EXPECT_EQ(s.blocked, w.blocked) << p.name;
    EXPECT_EQ(s.result_bytes, w.result_bytes) << p.name;
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(s.passes[i].start, w.passes[i].start) << p.name << " pass " << i;
      EXPECT_EQ(s.passes[i].end, w.passes[i].end) << p.name << " pass " << i;
      EXPECT_EQ(s.passes[i].cycles, w.passes[i].cycles) << p.name << " pass " << i;
    }
    for (unsigned b = 0; b < 6; ++b) {
      const tlmx::SramBankReport rw = w.board->bank(b).report(), rs = s.board->bank(b).report();
      EXPECT_EQ(rs.reads, rw.reads) << p.name << " bank " << b;
      EXPECT_EQ(rs.writes, rw.writes) << p.name << " bank " << b;
      EXPECT_EQ(rs.busy, rw.busy) << p.name << " bank " << b;
      // With 2-byte pages every word the wrapper touched is two regions, each granted once.
      const tlmx::SparseDmiCache& cache = s.board->wrapper().dmi_cache(b);
      EXPECT_EQ(cache.report().requests, rs.dmi_grants) << p.name << " bank " << b;
      EXPECT_EQ(cache.regions().size(), rs.dmi_grants) << p.name << " bank " << b;
      for (const tlmx::DmiRegion& r : cache.regions()) {
        ASSERT_EQ(r.end - r.start, 1u) << p.name << " bank " << b;
        ASSERT_EQ(r.start % 2, 0u) << p.name << " bank " << b;
      }
    }
  }
}

}  // namespace
}  // namespace rc::board::test
