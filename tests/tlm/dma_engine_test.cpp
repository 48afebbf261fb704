// DmaEngine through a PciBus into an SramBank: real data movement and exact transfer times from the
// formula in pci_bus.h, serialisation of two engines, error handling.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tests/tlm/tlm_test_support.h"
#include "tlm/dma_engine.h"
#include "tlm/pci_bus.h"
#include "tlm/sram_bank.h"

namespace rc::tlmx::test {
namespace {

constexpr std::uint64_t kBar = 0x1000'0000;
constexpr std::uint64_t kMiB = 1u << 20;

std::vector<std::uint8_t> pattern(std::size_t bytes, unsigned seed) {
  std::vector<std::uint8_t> data(bytes);
  for (std::size_t i = 0; i < bytes; ++i) data[i] = static_cast<std::uint8_t>(i * 31 + seed + (i >> 8));
  return data;
}

// Host thread, DMA engine, bus, one 4 MiB bank at kBar.
struct Rig {
  ScriptedInitiator host_unused{"host_unused"};  // keeps in[0] for a driver, as on a real board
  DmaEngine dma;
  PciBus bus;
  SramBank bank;

  Rig(const PciBusConfig& bus_config, const SramBankConfig& bank_config, std::uint64_t burst_bytes)
      : dma("dma", DmaConfig{burst_bytes, true}), bus("bus", bus_config), bank("bank", bank_config) {
    host_unused.out.bind(bus.in);
    dma.out.bind(bus.in);
    bus.out.bind(bank.in);
    bus.map(kBar, bank.capacity(), 0, "bank");
  }
};

SramBankConfig fast_bank() {
  SramBankConfig config;
  config.clock_period = sc_time(1, SC_NS);  // the bus dominates: occupancy = transfer_time
  return config;
}

struct Timed {
  sc_time to_device_4, to_device_4k, to_device_1m, to_host_1m;
};

// Runs 4 B, 4096 B and 1 MiB to the device, then 1 MiB back, one after the other.
Timed run_sizes(Rig& rig, std::vector<std::uint8_t>& readback, bool& all_ok) {
  Timed t;
  const std::vector<std::uint8_t> data = pattern(kMiB, 7);
  std::vector<std::uint8_t> source = data;
  ScriptedInitiator driver("driver", [&](ScriptedInitiator&) {
    const sc_time begin = sc_core::sc_time_stamp();
    DmaResult a = rig.dma.transfer(DmaDirection::to_device, source.data(), kBar + 0x100, 4);
    EXPECT_EQ(a.start, begin);
    EXPECT_EQ(a.end, sc_core::sc_time_stamp());  // transfer() returns synchronised
    DmaResult b = rig.dma.transfer(DmaDirection::to_device, source.data(), kBar + 0x1000, 4096);
    DmaResult c = rig.dma.transfer(DmaDirection::to_device, source.data(), kBar + 2 * kMiB, kMiB);
    DmaResult d = rig.dma.transfer(DmaDirection::to_host, readback.data(), kBar + 2 * kMiB, kMiB);
    all_ok = a.ok() && b.ok() && c.ok() && d.ok() && d.bytes_done == kMiB;
    t = {a.duration(), b.duration(), c.duration(), d.duration()};
  });
  driver.out.bind(rig.bus.in);  // a third initiator, idle on the bus
  sc_core::sc_start();
  EXPECT_TRUE(driver.finished);
  EXPECT_EQ(readback, data);
  EXPECT_EQ(rig.bank.debug_bytes(0x100, 4),
            std::vector<std::uint8_t>(data.begin(), data.begin() + 4));
  EXPECT_EQ(rig.bank.debug_bytes(0x1000, 0x1000),
            std::vector<std::uint8_t>(data.begin(), data.begin() + 4096));
  return t;
}

// 32-bit, 33 MHz (30 ns), efficiency 1, setup 8, bursts of 4096 B.
TEST(DmaEngine, KnownSizesAt32Bit33MHz) {
  Rig rig(PciBusConfig{}, fast_bank(), 4096);
  std::vector<std::uint8_t> readback(kMiB);
  bool ok = false;
  const Timed t = run_sizes(rig, readback, ok);

  EXPECT_TRUE(ok);
  EXPECT_EQ(t.to_device_4, sc_time(9 * 30, SC_NS));              // 8 + 1
  EXPECT_EQ(t.to_device_4k, sc_time(1032 * 30, SC_NS));          // 8 + 1024
  EXPECT_EQ(t.to_device_1m, sc_time(256 * 1032 * 30, SC_NS));    // 256 bursts
  EXPECT_EQ(t.to_host_1m, sc_time(256 * 1032 * 30, SC_NS));
  const DmaReport d = rig.dma.report();
  EXPECT_EQ(d.transfers, 4u);
  EXPECT_EQ(d.bursts, 1u + 1u + 256u + 256u);
  EXPECT_EQ(d.bytes_to_device, 4u + 4096u + kMiB);
  EXPECT_EQ(d.bytes_to_host, kMiB);
  EXPECT_EQ(d.busy, t.to_device_4 + t.to_device_4k + t.to_device_1m + t.to_host_1m);
  const PciInitiatorReport dma_port = rig.bus.report().initiators.at(1);
  EXPECT_EQ(dma_port.transactions, d.bursts);
  EXPECT_EQ(dma_port.bytes_written, d.bytes_to_device);
  EXPECT_EQ(dma_port.bytes_read, kMiB);
  EXPECT_EQ(dma_port.busy, d.busy);
  EXPECT_EQ(dma_port.wait, SC_ZERO_TIME);
  EXPECT_EQ(rig.bank.report().bytes_written, d.bytes_to_device);
}

// 64-bit, 66 MHz (15 ns), efficiency 0.8, setup 4, bursts of 4096 B.
TEST(DmaEngine, KnownSizesAt64Bit66MHz) {
  PciBusConfig config;
  config.width_bits = 64;
  config.clock_period = sc_time(15, SC_NS);
  config.burst_efficiency = 0.8;
  config.setup_cycles = 4;
  Rig rig(config, fast_bank(), 4096);
  std::vector<std::uint8_t> readback(kMiB);
  bool ok = false;
  const Timed t = run_sizes(rig, readback, ok);

  EXPECT_TRUE(ok);
  EXPECT_EQ(t.to_device_4, sc_time(6 * 15, SC_NS));              // 4 + ceil(1 / 0.8) = 4 + 2
  EXPECT_EQ(t.to_device_4k, sc_time(644 * 15, SC_NS));           // 4 + 512 / 0.8 = 4 + 640
  EXPECT_EQ(t.to_device_1m, sc_time(256 * 644 * 15, SC_NS));
  EXPECT_EQ(t.to_host_1m, sc_time(256 * 644 * 15, SC_NS));
}

// A DMA burst size below the bus's maximum: each DMA burst is its own bus burst, with its setup.
TEST(DmaEngine, SmallerDmaBurstsPaySetupEach) {
  Rig rig(PciBusConfig{}, fast_bank(), 1024);
  std::vector<std::uint8_t> source = pattern(4096, 3);
  sc_time duration;
  ScriptedInitiator driver("driver", [&](ScriptedInitiator&) {
    duration = rig.dma.transfer(DmaDirection::to_device, source.data(), kBar, 4096).duration();
  });
  driver.out.bind(rig.bus.in);
  sc_core::sc_start();
  EXPECT_EQ(duration, sc_time(4 * (8 + 256) * 30, SC_NS));
  EXPECT_EQ(rig.dma.report().bursts, 4u);
}

// When the bank is slower than the bus (64-bit 66 MHz PCI against a 32-bit 100 MHz bank), its wait
// states set the occupancy: max(bus, bank) per burst.
TEST(DmaEngine, SlowTargetSetsOccupancy) {
  PciBusConfig config;
  config.width_bits = 64;
  config.clock_period = sc_time(15, SC_NS);
  Rig rig(config, SramBankConfig{}, 4096);  // bank: (2 + 1024) * 10 ns = 10260 ns per 4 KiB write
  std::vector<std::uint8_t> source = pattern(8192, 5);
  sc_time duration;
  ScriptedInitiator driver("driver", [&](ScriptedInitiator&) {
    duration = rig.dma.transfer(DmaDirection::to_device, source.data(), kBar, 8192).duration();
  });
  driver.out.bind(rig.bus.in);
  sc_core::sc_start();
  ASSERT_LT(rig.bus.transfer_time(4096), sc_time(10260, SC_NS));  // bus alone: (8 + 512) * 15 = 7800 ns
  EXPECT_EQ(duration, sc_time(2 * 10260, SC_NS));
}

// Two engines share the bus: first come first served per burst, in order of request.
//   A: 3 bursts from t = 0; B: 2 bursts queued with start() at t = 100 ns. One burst = 30960 ns.
//   A1 [0, 30960]; B1 requested at 100, waits 30860 -> [30960, 61920];
//   A2 requested at 30960 -> [61920, 92880]; B2 requested at 61920 -> [92880, 123840];
//   A3 requested at 92880 -> [123840, 154800].
TEST(DmaEngine, TwoEnginesAreSerialisedBurstByBurst) {
  PciBus bus("bus");
  SramBank bank("bank", fast_bank());
  DmaEngine dma_a("dma_a");
  DmaEngine dma_b("dma_b");
  std::vector<std::uint8_t> data_a = pattern(3 * 4096, 1);
  std::vector<std::uint8_t> data_b = pattern(2 * 4096, 2);
  DmaResult result_a;
  sc_time b_done_seen;
  ScriptedInitiator host_a("host_a", [&](ScriptedInitiator&) {
    result_a = dma_a.transfer(DmaDirection::to_device, data_a.data(), kBar, data_a.size());
  });
  ScriptedInitiator host_b("host_b", [&](ScriptedInitiator&) {
    wait(sc_time(100, SC_NS));
    dma_b.start(DmaRequest{DmaDirection::to_device, data_b.data(), kBar + kMiB, data_b.size()});
    EXPECT_FALSE(dma_b.idle());
    wait(dma_b.done_event());
    b_done_seen = sc_core::sc_time_stamp();
  });
  dma_a.out.bind(bus.in);
  dma_b.out.bind(bus.in);
  host_a.out.bind(bus.in);  // the scripted hosts only drive the engines; their sockets stay idle
  host_b.out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(kBar, bank.capacity(), 0);
  sc_core::sc_start();

  const sc_time burst(30960, SC_NS);
  EXPECT_EQ(result_a.start, SC_ZERO_TIME);
  EXPECT_EQ(result_a.end, 5.0 * burst);
  EXPECT_EQ(dma_b.last_result().start, sc_time(100, SC_NS));
  EXPECT_EQ(dma_b.last_result().end, 4.0 * burst);
  EXPECT_EQ(b_done_seen, 4.0 * burst);
  EXPECT_TRUE(dma_b.idle());
  const PciBusReport r = bus.report();
  EXPECT_EQ(r.initiators.at(0).wait, 2.0 * burst);
  EXPECT_EQ(r.initiators.at(1).wait, sc_time(30860, SC_NS) + burst);
  EXPECT_EQ(r.initiators.at(0).busy, 3.0 * burst);
  EXPECT_EQ(r.initiators.at(1).busy, 2.0 * burst);
  EXPECT_EQ(r.total.busy, 5.0 * burst);
  EXPECT_EQ(r.bus_free_at, 5.0 * burst);
  EXPECT_EQ(bank.debug_bytes(0, data_a.size()), data_a);
  EXPECT_EQ(bank.debug_bytes(kMiB, data_b.size()), data_b);
}

TEST(DmaEngine, StopsAtFailingBurstAndReportsError) {
  Rig rig(PciBusConfig{}, fast_bank(), 4096);
  std::vector<std::uint8_t> source = pattern(3 * 4096, 9);
  DmaResult result;
  ScriptedInitiator driver("driver", [&](ScriptedInitiator&) {
    // Starts one burst before the end of the 4 MiB window: the second burst is a master abort.
    result = rig.dma.transfer(DmaDirection::to_device, source.data(), kBar + 4 * kMiB - 4096, source.size());
  });
  driver.out.bind(rig.bus.in);
  sc_core::sc_start();
  EXPECT_EQ(result.status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(result.bytes_done, 4096u);
  EXPECT_EQ(result.duration(), sc_time((1032 + 6) * 30, SC_NS));  // one burst + master abort
  EXPECT_EQ(rig.dma.report().errors, 1u);
  EXPECT_EQ(rig.dma.report().bytes_to_device, 4096u);
  EXPECT_EQ(rig.dma.report().bursts, 2u);
}

}  // namespace
}  // namespace rc::tlmx::test

namespace rc::tlmx::test {
namespace {

// A no-data request (timing replay of blank buffers) takes exactly the time of a real one and is
// counted the same by engine, bus and bank, but moves no byte either way.
TEST(DmaEngine, NoDataTransfersAreTimedAndCountedButMoveNothing) {
  Rig rig(PciBusConfig{}, fast_bank(), 4096);
  const std::vector<std::uint8_t> data = pattern(3 * 4096 + 100, 3);
  std::vector<std::uint8_t> readback(data.size(), 0xAB);
  DmaResult real, blank_write, blank_read;
  ScriptedInitiator driver("driver", [&](ScriptedInitiator&) {
    real = rig.dma.transfer(DmaDirection::to_device, const_cast<std::uint8_t*>(data.data()), kBar, data.size());
    std::vector<std::uint8_t> zeros(data.size(), 0);
    blank_write = rig.dma.transfer({DmaDirection::to_device, zeros.data(), kBar, zeros.size(), true});
    blank_read = rig.dma.transfer({DmaDirection::to_host, readback.data(), kBar, readback.size(), true});
  });
  driver.out.bind(rig.bus.in);
  sc_core::sc_start();
  ASSERT_TRUE(driver.finished);
  EXPECT_TRUE(real.ok() && blank_write.ok() && blank_read.ok());
  EXPECT_EQ(blank_write.duration(), real.duration());
  EXPECT_EQ(blank_read.duration(), real.duration());
  EXPECT_EQ(rig.bank.debug_bytes(0, data.size()), data);  // not overwritten
  EXPECT_EQ(readback, std::vector<std::uint8_t>(data.size(), 0xAB));                          // not read
  EXPECT_EQ(rig.bank.report().bytes_written, 2 * data.size());
  EXPECT_EQ(rig.bank.report().bytes_read, data.size());
  EXPECT_EQ(rig.dma.report().bursts, 3u * 4u);
}

}  // namespace
}  // namespace rc::tlmx::test

namespace rc::tlmx::test {
namespace {

// A temporally decoupled transfer issued at a local offset gives the times a synced one gives at
// that moment, and waits for nothing.
TEST(DmaEngine, DecoupledTransferTimesEqualSyncedOnes) {
  Rig rig(PciBusConfig{}, fast_bank(), 4096);
  std::vector<std::uint8_t> data = pattern(2 * 4096 + 12, 5);
  const sc_time offset(1234, SC_NS);
  DmaResult synced, decoupled;
  sc_time local_after, now_after;
  ScriptedInitiator driver("driver", [&](ScriptedInitiator&) {
    sc_core::wait(offset);
    synced = rig.dma.transfer(DmaDirection::to_device, data.data(), kBar, data.size());
    const sc_time base = sc_core::sc_time_stamp();
    sc_time local = offset;
    decoupled = rig.dma.transfer({DmaDirection::to_device, data.data(), kBar + 0x10000, data.size()}, local);
    local_after = local;
    now_after = sc_core::sc_time_stamp() - base;
  });
  driver.out.bind(rig.bus.in);
  sc_core::sc_start();
  ASSERT_TRUE(driver.finished);
  EXPECT_EQ(synced.start, offset);
  EXPECT_EQ(decoupled.start, synced.end + offset);
  EXPECT_EQ(decoupled.duration(), synced.duration());
  EXPECT_EQ(local_after, offset + synced.duration());
  EXPECT_EQ(now_after, SC_ZERO_TIME);  // no wait
  EXPECT_EQ(rig.bank.debug_bytes(0x10000, data.size()), data);
}

}  // namespace
}  // namespace rc::tlmx::test
