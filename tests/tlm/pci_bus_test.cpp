// PciBus: the transfer-time formula, BAR routing, master abort, and the arbitration policy under
// temporal decoupling. Expected times are worked out by hand from the formula in pci_bus.h.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>

#include "tests/tlm/tlm_test_support.h"
#include "tlm/pci_bus.h"
#include "tlm/programmed_io_extension.h"
#include "tlm/sram_bank.h"
#include "tlm/timing.h"

namespace rc::tlmx::test {
namespace {

SramBankConfig small_bank() {
  SramBankConfig config;
  config.capacity_bytes = 64 * 1024;
  config.clock_period = sc_time(1, SC_NS);  // fast enough that the bus always dominates
  return config;
}

// Default bus: 32 bit, 30 ns, efficiency 1, setup 8, bursts of 4096 B.
TEST(PciBus, TransferTimeFormula) {
  PciBusConfig config;
  PciBus bus("bus", config);
  SramBank bank("bank", small_bank());
  ScriptedInitiator host("host");
  host.out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(0, bank.capacity(), 0, "bank");
  sc_core::sc_start();

  EXPECT_EQ(bus.transfer_time(0), sc_time(8 * 30, SC_NS));             // one burst, no data
  EXPECT_EQ(bus.transfer_time(4), sc_time(9 * 30, SC_NS));             // 8 + 1
  EXPECT_EQ(bus.transfer_time(5), sc_time(10 * 30, SC_NS));            // 8 + ceil(5/4)
  EXPECT_EQ(bus.transfer_time(4096), sc_time(1032 * 30, SC_NS));       // 8 + 1024
  EXPECT_EQ(bus.transfer_time(5000), sc_time((1032 + 234) * 30, SC_NS));  // 4096 + 904: 8 + 226
  EXPECT_EQ(bus.transfer_time(1 << 20), sc_time(256 * 1032 * 30, SC_NS));
}

TEST(PciBus, TransferTimeWithEfficiencyAndFrequency) {
  PciBusConfig config;
  config.width_bits = 64;
  config.clock_period = period_from_hz(66e6);  // 15.1515... ns, rounded to 15152 ps
  config.burst_efficiency = 0.75;
  config.setup_cycles = 3;
  config.max_burst_bytes = 256;
  PciBus bus("bus", config);
  SramBank bank("bank", small_bank());
  ScriptedInitiator host("host");
  host.out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(0, bank.capacity(), 0);
  sc_core::sc_start();

  EXPECT_EQ(config.clock_period, sc_time(15152, SC_PS));
  EXPECT_EQ(bus.transfer_time(8), sc_time(5 * 15152, SC_PS));       // 3 + ceil(1 / 0.75) = 3 + 2
  EXPECT_EQ(bus.transfer_time(192), sc_time(35 * 15152, SC_PS));    // 3 + 24 / 0.75 = 3 + 32 exactly
  EXPECT_EQ(bus.transfer_time(256), sc_time(46 * 15152, SC_PS));    // 3 + ceil(32 / 0.75 = 42.67) = 46
  EXPECT_EQ(bus.transfer_time(1024), sc_time(4 * 46 * 15152, SC_PS));
  EXPECT_EQ(ceil_over_efficiency(1024, 0.8), 1280u);  // 0.8 is inexact in binary; still exact here
}

TEST(PciBus, RoutesByBarWindowWithRelativeAddresses) {
  PciBus bus("bus");
  SramBank bank0("bank0", small_bank());
  SramBank bank1("bank1", small_bank());
  std::uint64_t address_after = 0;
  tlm::tlm_response_status status{};
  sc_time delay;
  ScriptedInitiator host("host", [&](ScriptedInitiator& self) {
    std::uint32_t value = 0x12345678;
    status = self.write(0x8001'0010, &value, 4, delay);
    address_after = self.last_address_seen;
  });
  host.out.bind(bus.in);
  bus.out.bind(bank0.in);
  bus.out.bind(bank1.in);
  bus.map(0x8000'0000, 0x1'0000, 0, "bar0");
  bus.map(0x8001'0000, 0x1'0000, 1, "bar1");
  sc_core::sc_start();

  EXPECT_EQ(status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(address_after, 0x8001'0010u);  // the initiator gets its address back
  EXPECT_EQ(bank1.debug_bytes(0x10, 1)[0], 0x78);
  EXPECT_EQ(bank0.report().writes, 0u);
  EXPECT_EQ(bank1.report().writes, 1u);
  EXPECT_EQ(delay, sc_time(9 * 30, SC_NS));
  EXPECT_EQ(bus.report().initiators.at(0).bytes_written, 4u);
}

TEST(PciBus, UnmappedAddressIsMasterAbort) {
  PciBus bus("bus");
  SramBank bank("bank", small_bank());
  tlm::tlm_response_status unmapped{}, straddling{};
  sc_time unmapped_delay, straddling_delay;
  ScriptedInitiator host("host", [&](ScriptedInitiator& self) {
    std::array<std::uint8_t, 8> buffer{};
    unmapped = self.read(0x9000'0000, buffer.data(), 4, unmapped_delay);
    straddling_delay = unmapped_delay;  // loosely timed: carry on from the first access's completion
    straddling = self.read(0x8000'0000 + bank.capacity() - 4, buffer.data(), 8, straddling_delay);
  });
  host.out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(0x8000'0000, bank.capacity(), 0, "bar0");
  sc_core::sc_start();

  EXPECT_EQ(unmapped, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(straddling, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(unmapped_delay, sc_time(6 * 30, SC_NS));  // master_abort_cycles
  EXPECT_EQ(straddling_delay, sc_time(2 * 6 * 30, SC_NS));
  const PciBusReport r = bus.report();
  EXPECT_EQ(r.total.address_errors, 2u);
  EXPECT_EQ(r.total.transactions, 2u);
  EXPECT_EQ(r.total.bytes_read, 0u);
  EXPECT_EQ(r.total.wait, SC_ZERO_TIME);
  EXPECT_EQ(bank.report().reads, 0u);
}

// The bus reserves itself at call time, at the caller's local time (sc_time_stamp() + delay).
TEST(PciBus, ArbitrationUsesLocalTimeAndCallOrder) {
  PciBus bus("bus");
  SramBank bank("bank", small_bank());
  sc_time ahead_delay, behind_delay, later_delay;
  ScriptedInitiator ahead("ahead", [&](ScriptedInitiator& self) {
    std::uint32_t value = 1;
    ahead_delay = sc_time(1000, SC_NS);  // temporally decoupled: 1 us ahead of simulated time
    self.write(0, &value, 4, ahead_delay);
  });
  ScriptedInitiator behind("behind", [&](ScriptedInitiator& self) {
    wait(sc_time(1, SC_NS));  // calls after `ahead`, though its request (1 ns) is earlier in time
    std::uint32_t value = 2;
    behind_delay = SC_ZERO_TIME;
    self.write(4, &value, 4, behind_delay);
    wait(sc_time(2000, SC_NS));  // well after both: the bus is free, no wait
    later_delay = SC_ZERO_TIME;
    self.write(8, &value, 4, later_delay);
  });
  ahead.out.bind(bus.in);
  behind.out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(0, bank.capacity(), 0);
  sc_core::sc_start();

  // ahead: request 1000 ns, bus free -> occupies [1000, 1270].
  EXPECT_EQ(ahead_delay, sc_time(1270, SC_NS));
  // behind: request 1 ns, reserved after ahead -> starts 1270, ends 1540; delay from now (1 ns).
  EXPECT_EQ(behind_delay, sc_time(1539, SC_NS));
  EXPECT_EQ(later_delay, sc_time(270, SC_NS));
  const PciBusReport r = bus.report();
  EXPECT_EQ(r.initiators.at(0).wait, SC_ZERO_TIME);
  EXPECT_EQ(r.initiators.at(1).wait, sc_time(1269, SC_NS));
  EXPECT_EQ(r.initiators.at(1).busy, sc_time(540, SC_NS));
  EXPECT_EQ(r.bus_free_at, sc_time(2001 + 270, SC_NS));
}

// Programmed I/O: a 20-byte payload of 4-byte accesses is 5 single-data-phase transactions
// (8 setup + 1 data cycles of 30 ns each); a read adds its round trip to every access. The data
// really moves, in one call to the target.
TEST(PciBus, ProgrammedIoIsOneTransactionPerWord) {
  PciBus bus("bus");
  SramBank bank("bank", small_bank());
  std::array<std::uint32_t, 5> out{1, 2, 3, 4, 5}, in{};
  sc_time write_done, read_done, read_start;
  ScriptedInitiator host("host", [&](ScriptedInitiator& self) {
    ProgrammedIoExtension pio;
    pio.access_bytes = 4;
    pio.read_round_trip = sc_time(700, SC_NS);
    auto transfer = [&](tlm::tlm_command command, void* data, sc_time& delay) {
      tlm::tlm_generic_payload trans;
      trans.set_command(command);
      trans.set_address(0x40);
      trans.set_data_ptr(static_cast<unsigned char*>(data));
      trans.set_data_length(20);
      trans.set_streaming_width(20);
      trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
      trans.set_extension(&pio);
      self.out->b_transport(trans, delay);
      trans.clear_extension(&pio);
      EXPECT_TRUE(trans.is_response_ok());
    };
    sc_time delay = SC_ZERO_TIME;
    transfer(tlm::TLM_WRITE_COMMAND, out.data(), delay);
    write_done = delay;
    read_start = delay;
    transfer(tlm::TLM_READ_COMMAND, in.data(), delay);
    read_done = delay;
  });
  host.out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(0, bank.capacity(), 0, "bank");
  sc_core::sc_start();

  EXPECT_EQ(write_done, sc_time(5 * 9 * 30, SC_NS));                        // posted writes: bus time only
  EXPECT_EQ(read_done - read_start, sc_time(5 * (9 * 30 + 700), SC_NS));    // non-posted: plus the round trips
  EXPECT_EQ(bus.programmed_io_time(20, 4, false, sc_time(700, SC_NS)), sc_time(1350, SC_NS));
  EXPECT_EQ(bus.programmed_io_time(6, 4, true, sc_time(700, SC_NS)), sc_time(2 * 970, SC_NS));  // ceil(6 / 4) = 2
  EXPECT_EQ(in, out);
  EXPECT_EQ(bus.report().total.transactions, 2u);  // two calls: the target sees each buffer once
}

// Two cards on one bus (share_arbitration_with) or each on its own. Each bus has its own BAR
// window and initiator; `first` writes 4096 B at 0 (8 + 1024 cycles of 30 ns: [0, 30960 ns]),
// `second` 4 B at 100 ns (9 cycles: 270 ns) through the other bus. Separate: no wait, the second
// ends at 370 ns. Shared: it starts when the first ends, 30960 ns, and ends at 31230 ns, having
// waited 30860 ns; both buses report the shared bus_free_at. The counters stay per bus.
TEST(PciBus, SharedArbitrationSerialisesTwoBusesTransfers) {
  struct Pair {
    PciBus a, b;
    SramBank bank_a, bank_b;
    ScriptedInitiator first, second;
    sc_time first_delay, second_delay;
    Pair(const char* name, bool shared)
        : a((std::string(name) + "_a").c_str()),
          b((std::string(name) + "_b").c_str()),
          bank_a((std::string(name) + "_bank_a").c_str(), small_bank()),
          bank_b((std::string(name) + "_bank_b").c_str(), small_bank()),
          first((std::string(name) + "_first").c_str(),
                [this](ScriptedInitiator& self) {
                  static std::array<std::uint8_t, 4096> data{};
                  first_delay = SC_ZERO_TIME;
                  self.write(0, data.data(), 4096, first_delay);
                }),
          second((std::string(name) + "_second").c_str(), [this](ScriptedInitiator& self) {
            wait(sc_time(100, SC_NS));
            std::uint32_t value = 7;
            second_delay = SC_ZERO_TIME;
            self.write(0, &value, 4, second_delay);
          }) {
      first.out.bind(a.in);
      second.out.bind(b.in);
      a.out.bind(bank_a.in);
      b.out.bind(bank_b.in);
      a.map(0, bank_a.capacity(), 0);
      b.map(0, bank_b.capacity(), 0);
      if (shared) b.share_arbitration_with(a);
    }
  };
  Pair separate("separate", false), shared("shared", true);
  sc_core::sc_start();

  EXPECT_FALSE(separate.b.shares_arbitration());
  EXPECT_TRUE(shared.b.shares_arbitration());
  EXPECT_FALSE(shared.a.shares_arbitration());  // the owner
  for (Pair* p : {&separate, &shared}) EXPECT_EQ(p->first_delay, sc_time(1032 * 30, SC_NS));
  EXPECT_EQ(separate.second_delay, sc_time(270, SC_NS));
  EXPECT_EQ(separate.b.report().total.wait, SC_ZERO_TIME);
  EXPECT_EQ(separate.a.report().bus_free_at, sc_time(30960, SC_NS));
  EXPECT_EQ(separate.b.report().bus_free_at, sc_time(370, SC_NS));

  EXPECT_EQ(shared.second_delay, sc_time(31230 - 100, SC_NS));  // from its call at 100 ns
  EXPECT_EQ(shared.b.report().total.wait, sc_time(30860, SC_NS));
  EXPECT_EQ(shared.b.report().total.busy, sc_time(270, SC_NS));    // its own occupancy only
  EXPECT_EQ(shared.a.report().total.busy, sc_time(30960, SC_NS));
  EXPECT_EQ(shared.a.report().total.wait, SC_ZERO_TIME);
  EXPECT_EQ(shared.a.report().bus_free_at, sc_time(31230, SC_NS));
  EXPECT_EQ(shared.b.report().bus_free_at, sc_time(31230, SC_NS));
  EXPECT_EQ(shared.b.report().total.bytes_written, 4u);
}

}  // namespace
}  // namespace rc::tlmx::test
