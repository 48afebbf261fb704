// The pipelined driver's board side alone (docs/board.md, "Pipelined passes"; register_map.h): the
// windows RAY_BASE, RESULT_BASE and TABLE_BASE, and the START queue with its register snapshots,
// driven over PCI by a scripted host. Data goes into its windows by DMA through the bridge; decoys at
// the banks' usual places prove the wrapper reads and writes only through the windows.
//
// Board: round_params(1) (test support): one lane at 15 bits, so a packet is one ray and each of the
// X, Y, Z banks holds one word per ray; 1 MiB banks of 32-bit words (262144); the own-surface table
// in spare bank 5, from word 0 (TABLE_BASE adds to that). Pass times from board/pass_timing.h with
// F faces, R rays and Pd = 20 ns:
//   fetch = ceil((Lr 2 + 9) * 10 ns / 20 ns) = 6    (the table is read in parallel from bank 5)
//   total = start 2 + F * (setup 1 + fetch 6) + F * R (one ray a cycle) + latency 37 + finish 1
//         = 40 + 7 F + F R cycles.
//   A pass refused by its inputs has no faces and no rays: start 2 + latency 37 + finish 1 = 40.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tests/board/board_test_support.h"
#include "tlm/dma_engine.h"

namespace rc::board::test {
namespace {

constexpr std::uint64_t kBankWords = (1u << 20) / 4;
constexpr std::uint8_t kSentinel = 0xA5;

std::uint64_t pass_cycles(std::uint64_t faces, std::uint64_t rays) { return 40 + 7 * faces + faces * rays; }

// Own-surface table entries of a pass: per face, the rays that end on it (one-sided faces).
std::vector<std::uint32_t> table_of(const PassData& d) {
  std::vector<std::uint32_t> table(d.faces.size(), 0);
  for (int e : d.end_faces)
    if (e >= 0) ++table[static_cast<std::size_t>(e)];
  return table;
}

// The words of `values` as bank bytes.
std::vector<std::uint8_t> word_bytes(const std::vector<std::uint32_t>& values) {
  std::vector<std::uint8_t> bytes(values.size() * 4);
  for (std::size_t i = 0; i < values.size(); ++i) store_word(bytes.data(), i, 4, values[i]);
  return bytes;
}

// DMA `bytes` to word `word` of bank `bank` (through PCI and the bridge, timed).
void dma_to(Rc2000& board, unsigned bank, std::uint64_t word, std::vector<std::uint8_t> bytes) {
  if (bytes.empty()) return;
  const tlmx::DmaResult r =
      board.dma.transfer(tlmx::DmaDirection::to_device, bytes.data(), board.bank_pci_address(bank) + 4 * word, bytes.size());
  EXPECT_TRUE(r.ok()) << "DMA to bank " << bank << " word " << word;
}

// The pass's faces at the face bank's word 0, its rays at `ray_base` in every ray bank and its table
// at `table_base` in the table's bank, by DMA; returns its split.
RaySplit send_pass(Rc2000& board, const PassData& d, std::uint64_t ray_base, std::uint64_t table_base) {
  const BankLayout& L = board.layout();
  std::vector<std::uint32_t> faces;
  std::uint64_t words[9];
  for (const pipeline::FaceRecord& f : d.faces) {
    face_record_words(f, words);
    for (std::uint64_t w : words) faces.push_back(static_cast<std::uint32_t>(w));
  }
  dma_to(board, L.face_bank, 0, word_bytes(faces));
  dma_to(board, *L.mask_bank, table_base, word_bytes(table_of(d)));
  std::vector<std::int64_t> x, y, z;
  for (const pipeline::FixedVec3& e : d.ends) x.push_back(e.x), y.push_back(e.y), z.push_back(e.z);
  const RaySplit split = split_rays(L, d.ends.size());
  std::vector<std::vector<std::uint8_t>> images;
  pack_rays(L, split, x.data(), y.data(), z.data(), images);
  for (unsigned b = 0; b < images.size(); ++b) dma_to(board, b, ray_base, images[b]);
  return split;
}

// The registers from RAY_COUNT to MASK_START for pass `d` (face set from face 0, no ray before it).
std::vector<std::uint32_t> pass_registers(const PassData& d) {
  return {static_cast<std::uint32_t>(d.ends.size()), static_cast<std::uint32_t>(d.faces.size()), 0,
          d.source_face < 0 ? reg::kNoFace : static_cast<std::uint32_t>(d.source_face),
          static_cast<std::uint32_t>(d.start.x), static_cast<std::uint32_t>(d.start.y),
          static_cast<std::uint32_t>(d.start.z), 0};
}

std::vector<std::uint8_t> results_at(Rc2000& board, const RaySplit& split, std::uint64_t result_base, std::size_t rays) {
  const unsigned bank = board.layout().result_bank;
  const std::vector<std::uint8_t> words = board.bank(bank).debug_bytes(4 * result_base, 4 * split.result_words);
  std::vector<std::uint8_t> blocked(rays, 0);
  unpack_results(board.layout(), split, words.data(), blocked.data());
  return blocked;
}

// Bank bytes [from, to) all hold the sentinel.
void expect_sentinel(Rc2000& board, unsigned bank, std::uint64_t from, std::uint64_t to, const char* what) {
  const std::vector<std::uint8_t> bytes = board.bank(bank).debug_bytes(from, to - from);
  EXPECT_EQ(bytes, std::vector<std::uint8_t>(to - from, kSentinel)) << what << ": bank " << bank;
}

void fill_sentinel(Rc2000& board, unsigned bank, std::uint64_t bytes) {
  const std::vector<std::uint8_t> fill(bytes, kSentinel);
  board.bank(bank).debug_write(0, fill.data(), fill.size());
}

// A pass whose rays, table and results each live in their own window: the answer is the windowed
// data's, its result words land in the result window and the result bank is untouched elsewhere;
// the decoy rays and table at the banks' word 0 would give another answer.
TEST(PassWindows, RaysTableAndResultsUseTheirWindowsOnly) {
  Rc2000 board("rc2000", round_params(1));
  const BankLayout& L = board.layout();
  ASSERT_EQ(L.bank_words, kBankWords);
  ASSERT_TRUE(L.mask_bank.has_value());
  constexpr std::uint64_t kRayBase = 1000, kResultBase = 3000, kTableBase = 77;
  const PassData real = crossing_pass(90, 15, 3, 11);
  PassData decoy = crossing_pass(90, 15, 3, 12);  // other end points, and no rays on their own faces
  decoy.end_faces.assign(decoy.ends.size(), -1);
  // Reading the decoy rays or the decoy (all-zero) table instead would change the answer.
  PassData wrong_rays = decoy, wrong_table = real;
  wrong_rays.end_faces = real.end_faces;
  wrong_table.end_faces.assign(real.ends.size(), -1);
  const std::vector<std::uint8_t> expected = expected_blocked(real, 15);
  ASSERT_NE(expected_blocked(wrong_rays, 15), expected);
  ASSERT_NE(expected_blocked(wrong_table, 15), expected);

  const std::uint64_t result_bytes = 4 * (kResultBase + 200);
  fill_sentinel(board, L.result_bank, result_bytes);
  std::vector<PassRecord> passes;
  board.wrapper().on_pass([&](const PassRecord& r) { passes.push_back(r); });
  RaySplit split;
  std::uint32_t status = 0, count = 0;
  ScriptedHost host("host", board, [&](ScriptedHost& h) {
    send_pass(board, decoy, 0, 0);
    split = send_pass(board, real, kRayBase, kTableBase);
    h.write(reg::kRayBase, {kRayBase, kResultBase, kTableBase});
    EXPECT_EQ(h.read(reg::kRayBase), kRayBase);
    EXPECT_EQ(h.read(reg::kResultBase), kResultBase);
    EXPECT_EQ(h.read(reg::kTableBase), kTableBase);
    h.write(reg::kRayCount, pass_registers(real));
    h.write(reg::kControl, {reg::kStart | reg::kClear});
    board.irq.wait_raised();
    status = h.read(reg::kStatus);
    count = h.read(reg::kPasses);
    h.write(reg::kStatus, {reg::kDone});
  });
  run_until_finished({&host});
  ASSERT_TRUE(host.finished);
  EXPECT_EQ(status, reg::kDone);
  EXPECT_EQ(count, 1u);
  ASSERT_EQ(passes.size(), 1u);
  EXPECT_EQ(passes[0].cycles, pass_cycles(3, 90));
  EXPECT_EQ(results_at(board, split, kResultBase, real.ends.size()), expected);
  expect_sentinel(board, L.result_bank, 0, 4 * kResultBase, "before the result window");
  expect_sentinel(board, L.result_bank, 4 * (kResultBase + split.result_words), result_bytes, "after the result window");
}

// A window that puts one word of the pass beyond its bank refuses the pass with ERROR and code 6
// (kWindowOverrun), at once (40 cycles), writing no result; the same window one word lower runs.
// A 90-ray pass of 1 face has 90 words in each ray bank and 1 table word.
TEST(PassWindows, AWindowBeyondItsBankIsErrorSix) {
  Rc2000 board("rc2000", round_params(1));
  const BankLayout& L = board.layout();
  const PassData d = crossing_pass(90, 15, 1, 3);
  const std::uint64_t result_words = split_rays(L, 90).result_words;
  struct Case {
    std::uint32_t ray_base, result_base, table_base, code;
  };
  const std::vector<Case> cases = {
      {kBankWords - 90 + 1, 0, 0, reg::kWindowOverrun},
      {0, static_cast<std::uint32_t>(kBankWords - result_words + 1), 0, reg::kWindowOverrun},
      {0, 0, kBankWords - 1 + 1, reg::kWindowOverrun},
      {kBankWords - 90, static_cast<std::uint32_t>(kBankWords - result_words), kBankWords - 1, reg::kOk},
  };
  ASSERT_EQ(L.groups.size(), 1u);
  for (unsigned j = 0; j < 3; ++j) ASSERT_EQ(group_bank_words(L.groups[0], j, 90), 90u);
  fill_sentinel(board, L.result_bank, 4 * kBankWords);
  std::vector<PassRecord> passes;
  board.wrapper().on_pass([&](const PassRecord& r) { passes.push_back(r); });
  std::vector<std::uint32_t> statuses, codes;
  std::vector<std::vector<std::uint8_t>> results;
  ScriptedHost host("host", board, [&](ScriptedHost& h) {
    for (const Case& c : cases) {
      const RaySplit split = send_pass(board, d, c.ray_base <= kBankWords - 90 ? c.ray_base : 0,
                                       c.table_base <= kBankWords - 1 ? c.table_base : 0);
      h.write(reg::kRayBase, {c.ray_base, c.result_base, c.table_base});
      h.write(reg::kRayCount, pass_registers(d));
      h.write(reg::kControl, {reg::kStart | reg::kClear});
      board.irq.wait_raised();
      statuses.push_back(h.read(reg::kStatus));
      codes.push_back(h.read(reg::kErrorCode));
      h.write(reg::kStatus, {reg::kDone | reg::kError});
      if (c.code != reg::kOk) {
        expect_sentinel(board, L.result_bank, 0, 4 * kBankWords, "after a refused pass");
        results.emplace_back();
      } else {
        expect_sentinel(board, L.result_bank, 0, 4 * c.result_base, "before the last result window");
        results.push_back(results_at(board, split, c.result_base, 90));
      }
    }
  });
  run_until_finished({&host});
  ASSERT_TRUE(host.finished);
  ASSERT_EQ(passes.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const bool ok = cases[i].code == reg::kOk;
    EXPECT_EQ(codes[i], cases[i].code) << "case " << i;
    EXPECT_EQ(statuses[i], ok ? reg::kDone : reg::kDone | reg::kError) << "case " << i;
    EXPECT_EQ(passes[i].cycles, ok ? pass_cycles(1, 90) : 40u) << "case " << i;
    EXPECT_EQ(passes[i].rays, ok ? 90u : 0u) << "case " << i;
  }
  EXPECT_EQ(results.back(), expected_blocked(d, 15));
}

// Two STARTs queued before either pass has begun, the registers rewritten between them: each pass
// runs with the registers as they were at its own START, the second begins on the edge the first
// ends, and a third START while two are queued is dropped with ERROR and code 4 (kStartWhileBusy).
//
// Times by hand. PCI (tlm/pci_bus.h): 64-bit at 15 ns, setup 8, so a burst of w words takes
// (8 + ceil(4 w / 8)) * 15 ns; a register takes effect register_access_cycles (1 device cycle, 20 ns)
// after its access starts on the bus. From 10 us the host issues ahead of simulated time, back to back:
//   START A      1 word   [10.000, 10.135] us, effective 10.020
//   B's windows  3 words  [10.135, 10.285]
//   B's counts   8 words  [10.285, 10.465]
//   START B      1 word   [10.465, 10.600], effective 10.485
//   START C      1 word   [10.600, 10.735]  refused: two are queued
// Pass A (1 face, 100 rays) starts on the edge at 10.020 us and takes 40 + 7 + 100 = 147 cycles,
// 2.94 us: it ends at 12.960 us. Pass B (3 faces, 64 rays), queued since 10.485 us, starts on that
// same edge and takes 40 + 21 + 192 = 253 cycles, 5.06 us: it ends at 18.020 us.
TEST(StartQueue, QueuedStartsRunTheirOwnSnapshotsBackToBackAndAThirdIsRefused) {
  Rc2000 board("rc2000", round_params(1));
  const BankLayout& L = board.layout();
  const PassData a = crossing_pass(100, 15, 1, 21), b = crossing_pass(64, 15, 3, 22);
  constexpr std::uint32_t kHalf = kBankWords / 2, kTableB = 8;
  std::vector<PassRecord> passes;
  board.wrapper().on_pass([&](const PassRecord& r) { passes.push_back(r); });
  RaySplit split_a, split_b;
  std::vector<sc_time> locals;
  std::uint32_t status_queued = 0, code_queued = 0, passes_after_a = 0, passes_after_b = 0, code_after_b = 0;
  ScriptedHost host("host", board, [&](ScriptedHost& h) {
    split_a = send_pass(board, a, 0, 0);
    split_b = send_pass(board, b, kHalf, kTableB);
    h.write(reg::kRayBase, {0, 0, 0});
    h.write(reg::kRayCount, pass_registers(a));
    ASSERT_LT(sc_core::sc_time_stamp(), sc_time(10, SC_US));
    sc_core::wait(sc_time(10, SC_US) - sc_core::sc_time_stamp());
    sc_time local = h.write_ahead(reg::kControl, {reg::kStart | reg::kClear}, sc_core::SC_ZERO_TIME);
    locals.push_back(local);
    local = h.write_ahead(reg::kRayBase, {kHalf, kHalf, kTableB}, local);
    local = h.write_ahead(reg::kRayCount, pass_registers(b), local);
    local = h.write_ahead(reg::kControl, {reg::kStart | reg::kClear}, local);
    locals.push_back(local);
    local = h.write_ahead(reg::kControl, {reg::kStart | reg::kClear}, local);
    locals.push_back(local);
    sc_core::wait(local);  // synced again, pass A running
    status_queued = h.read(reg::kStatus);
    code_queued = h.read(reg::kErrorCode);
    h.write(reg::kStatus, {reg::kError});
    board.irq.wait_raised();
    passes_after_a = h.read(reg::kPasses);
    h.write(reg::kStatus, {reg::kDone});
    board.irq.wait_raised();
    passes_after_b = h.read(reg::kPasses);
    code_after_b = h.read(reg::kErrorCode);
    h.write(reg::kStatus, {reg::kDone});
  });
  run_until_finished({&host});
  ASSERT_TRUE(host.finished);
  EXPECT_EQ(locals, (std::vector<sc_time>{sc_time(135, SC_NS), sc_time(600, SC_NS), sc_time(735, SC_NS)}));
  EXPECT_EQ(status_queued, reg::kBusy | reg::kError);
  EXPECT_EQ(code_queued, reg::kStartWhileBusy);
  EXPECT_EQ(passes_after_a, 1u);
  EXPECT_EQ(passes_after_b, 2u);
  EXPECT_EQ(code_after_b, reg::kOk);
  ASSERT_EQ(passes.size(), 2u) << "the third START must not run";
  EXPECT_EQ(passes[0].start, sc_time(10020, SC_NS));
  EXPECT_EQ(passes[0].end, sc_time(12960, SC_NS));
  EXPECT_EQ(passes[1].start, passes[0].end);
  EXPECT_EQ(passes[1].end, sc_time(18020, SC_NS));
  EXPECT_EQ(passes[0].rays, 100u);
  EXPECT_EQ(passes[0].faces, 1u);
  EXPECT_EQ(passes[1].rays, 64u);
  EXPECT_EQ(passes[1].faces, 3u);
  // Each pass's answer in its own result window: A's snapshot (windows 0), B's (the upper halves).
  EXPECT_EQ(results_at(board, split_a, 0, a.ends.size()), expected_blocked(a, 15));
  EXPECT_EQ(results_at(board, split_b, kHalf, b.ends.size()), expected_blocked(b, 15));
  EXPECT_EQ(L.bank_words, kBankWords);
}

}  // namespace
}  // namespace rc::board::test
