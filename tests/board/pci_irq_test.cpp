// The board's PCI side: DMA of known sizes into and out of a bank through the bus and the bridge,
// register accesses, the interrupt's latency to the host, and errors the wrapper reports.
#include <gtest/gtest.h>

#include <vector>

#include "tests/board/board_test_support.h"
#include "tlm/dma_engine.h"

namespace rc::board::test {
namespace {

// 64-bit PCI at 15 ns, setup 8, 4 KiB bursts; bridge 2 PCI cycles (30 ns); bank 10 ns, latency 2.
// Each burst occupies the bus for max(bus time, bridge + bank time):
//   4 B:     max(( 8 +   1) * 15 =   135 ns, 30 + (2 +    1) * 10 =    60 ns) =    135 ns
//   1 KiB:   max(( 8 + 128) * 15 =  2040 ns, 30 + (2 +  256) * 10 =  2610 ns) =   2610 ns
//   4 KiB:   max(( 8 + 512) * 15 =  7800 ns, 30 + (2 + 1024) * 10 = 10290 ns) =  10290 ns
//   64 KiB:  16 bursts of 4 KiB                                                = 164640 ns
TEST(BoardPci, DmaOfKnownSizesThroughTheBridge) {
  Rc2000 board("rc2000", round_params(1));
  std::vector<std::uint8_t> data(65536), back(65536);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 7 + (i >> 9));
  std::vector<sc_time> took;
  ScriptedHost host("host", board, [&](ScriptedHost&) {
    for (std::uint64_t n : {4u, 1024u, 4096u, 65536u}) {
      const tlmx::DmaResult r = board.dma.transfer(tlmx::DmaDirection::to_device, data.data(), board.bank_pci_address(3), n);
      EXPECT_TRUE(r.ok());
      took.push_back(r.duration());
    }
    const tlmx::DmaResult r = board.dma.transfer(tlmx::DmaDirection::to_host, back.data(), board.bank_pci_address(3), 4096);
    took.push_back(r.duration());
    const sc_time before = sc_core::sc_time_stamp();
    EXPECT_EQ(host.read(reg::kId), reg::kIdValue);
    took.push_back(sc_core::sc_time_stamp() - before);  // register read: (8 + 1) * 15 ns
  });
  sc_core::sc_start();
  ASSERT_TRUE(host.finished);
  EXPECT_EQ(took, (std::vector<sc_time>{sc_time(135, SC_NS), sc_time(2610, SC_NS), sc_time(10290, SC_NS),
                                        sc_time(164640, SC_NS), sc_time(10290, SC_NS), sc_time(135, SC_NS)}));
  EXPECT_EQ(board.bank(3).debug_bytes(0, data.size()), data);
  EXPECT_TRUE(std::equal(back.begin(), back.begin() + 4096, data.begin()));
  EXPECT_EQ(board.bank(3).report().bytes_written, 4u + 1024 + 4096 + 65536);
  EXPECT_EQ(board.pci.report().total.bytes_read, 4096u + 4);
}

// The host sees the interrupt exactly irq_latency after the wrapper raises it at the end of the
// pass, and clearing DONE lowers it so that the next pass interrupts again.
TEST(BoardPci, InterruptReachesTheHostAfterItsLatency) {
  BoardParams params = round_params(1);
  params.irq_latency = sc_time(4700, SC_NS);
  Rc2000 board("rc2000", params);
  std::vector<PassRecord> passes;
  std::vector<sc_time> seen;
  board.wrapper().on_pass([&](const PassRecord& r) { passes.push_back(r); });
  ScriptedHost host("host", board, [&](ScriptedHost& h) {
    for (int i = 0; i < 2; ++i) {
      const PassData d = crossing_pass(10, 15, 1, 5 + i);
      load_pass(board, d);
      h.write(reg::kRayCount, {10, 1, 0, reg::kNoFace, static_cast<std::uint32_t>(d.start.x),
                               static_cast<std::uint32_t>(d.start.y), static_cast<std::uint32_t>(d.start.z), 10});
      h.write(reg::kControl, {reg::kStart | reg::kClear});
      EXPECT_TRUE(h.read(reg::kStatus) & reg::kBusy);
      board.irq.wait_raised();
      seen.push_back(sc_core::sc_time_stamp());
      EXPECT_EQ(h.read(reg::kStatus), reg::kDone);
      EXPECT_EQ(h.read(reg::kPassCyclesLo), 47u + 10);
      h.write(reg::kStatus, {reg::kDone});
      EXPECT_FALSE(board.irq.raised());
      EXPECT_EQ(h.read(reg::kStatus), 0u);
    }
  });
  sc_core::sc_start();
  ASSERT_TRUE(host.finished);
  ASSERT_EQ(passes.size(), 2u);
  for (int i = 0; i < 2; ++i) EXPECT_EQ(seen[i], passes[i].end + sc_time(4700, SC_NS));
  EXPECT_EQ(board.irq.report().delivered, 2u);
}

// A host running ahead of simulated time (the driver does) writes START and the acknowledge at a
// local offset: the pass starts, and the interrupt drops, when those writes reach the registers,
// exactly as for a host that first waited out the offset.
TEST(BoardPci, RegistersWrittenAheadOfTimeActAtTheirAccessTime) {
  Rc2000 board("rc2000", round_params(1));
  std::vector<PassRecord> passes;
  std::vector<sc_time> issued;
  board.wrapper().on_pass([&](const PassRecord& r) { passes.push_back(r); });
  const sc_time ahead(3210, SC_NS);
  ScriptedHost host("host", board, [&](ScriptedHost& h) {
    const PassData d = crossing_pass(10, 15, 1, 5);
    load_pass(board, d);
    const std::vector<std::uint32_t> pass_registers = {10, 1, 0, reg::kNoFace, static_cast<std::uint32_t>(d.start.x),
                                                       static_cast<std::uint32_t>(d.start.y),
                                                       static_cast<std::uint32_t>(d.start.z), 10};
    // Synced: wait until 10 us, then write. (Both hosts issue on a device clock edge, so the pass
    // starts the same time after.)
    sc_core::wait(sc_time(10, SC_US) - sc_core::sc_time_stamp());
    issued.push_back(sc_core::sc_time_stamp());
    h.write(reg::kRayCount, pass_registers);
    h.write(reg::kControl, {reg::kStart | reg::kClear});
    board.irq.wait_raised();
    h.write(reg::kStatus, {reg::kDone});
    EXPECT_FALSE(board.irq.raised());
    // Decoupled: the same writes issued at 20 us from an earlier simulated time, without waiting.
    ASSERT_LT(sc_core::sc_time_stamp(), sc_time(20, SC_US));
    issued.push_back(sc_time(20, SC_US));
    sc_time local = h.write_ahead(reg::kRayCount, pass_registers, sc_time(20, SC_US) - sc_core::sc_time_stamp());
    local = h.write_ahead(reg::kControl, {reg::kStart | reg::kClear}, local);
    board.irq.wait_raised();
    const sc_time raised_at = sc_core::sc_time_stamp();
    local = h.write_ahead(reg::kStatus, {reg::kDone}, ahead);
    EXPECT_TRUE(board.irq.raised()) << "the acknowledge has not reached the register yet";
    sc_core::wait(ahead);  // the write starts on the bus; bridge and register access still to go
    EXPECT_TRUE(board.irq.raised());
    sc_core::wait(local - ahead);  // the write has completed
    EXPECT_FALSE(board.irq.raised());
    EXPECT_EQ(sc_core::sc_time_stamp() - raised_at, local);
  });
  sc_core::sc_start();
  ASSERT_TRUE(host.finished);
  ASSERT_EQ(passes.size(), 2u);
  EXPECT_EQ(passes[1].start - issued[1], passes[0].start - issued[0]);
  EXPECT_EQ(passes[1].end - passes[1].start, passes[0].end - passes[0].start);
}

// A pass beyond the banks' capacity, or with an own-face table that claims more rays than the pass
// has, completes at once with ERROR and an error code.
TEST(BoardPci, WrapperReportsBadPassesAsErrors) {
  BoardParams params = round_params(1);
  params.bank_capacity_bytes = 4096;  // 1024 words: at most 1024 rays, 1024 / 9 = 113 faces
  Rc2000 board("rc2000", params);
  std::vector<std::uint32_t> codes;
  ScriptedHost host("host", board, [&](ScriptedHost& h) {
    const std::vector<std::vector<std::uint32_t>> bad = {
        {1025, 1, 0, reg::kNoFace, 0, 0, 0, 0},  // too many rays
        {10, 114, 0, reg::kNoFace, 0, 0, 0, 0},  // too many faces
        {10, 1, 0, reg::kNoFace, 0, 0, 0, 11},   // mask start beyond the rays
        {10, 1, 0, reg::kNoFace, 1u << 15, 0, 0, 0}};  // start point not a 0.15 code
    for (const auto& regs : bad) {
      h.write(reg::kRayCount, regs);
      h.write(reg::kControl, {reg::kStart});
      board.irq.wait_raised();
      EXPECT_EQ(h.read(reg::kStatus), reg::kDone | reg::kError);
      codes.push_back(h.read(reg::kErrorCode));
      h.write(reg::kStatus, {reg::kDone | reg::kError});
    }
  });
  sc_core::sc_start();
  ASSERT_TRUE(host.finished);
  EXPECT_EQ(codes, (std::vector<std::uint32_t>{reg::kTooManyRays, reg::kTooManyFaces, reg::kMaskOverrun,
                                               reg::kBadStartPoint}));
}

}  // namespace
}  // namespace rc::board::test
