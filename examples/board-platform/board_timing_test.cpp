// A user's own exact timing assertion with the installed timing test kit (rc2000tlm::testkit): the
// board from the installed xc2v6000 profile, the kit's scripted host, and the time of a register read
// and of a 1 KiB DMA stated as sc_time. Each TEST runs in its own process (the kit's main, with
// gtest_discover_tests through rc2000tlm_add_timing_test).
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "board/board_params.h"
#include "board/device_profile.h"
#include "board/rc2000.h"
#include "board/register_map.h"
#include "testkit/scripted_host.h"

using namespace rc;
using sc_core::sc_time;
using sc_core::SC_NS;

namespace {

board::BoardParams xc2v6000() {
  board::BoardChoices choices;
  choices.lanes = 1;
  return board::make_board_params(board::find_device_profile("xc2v6000"), choices);
}

// One 4-byte read on the board's PCI bus: setup cycles plus one data phase, nothing else.
TEST(MyPlatform, IdRegisterReadTakesOneBusAccess) {
  const board::BoardParams params = xc2v6000();
  board::Rc2000 rc2000("rc2000", params);
  sc_time at;
  testkit::ScriptedHost host("host", rc2000, [&](testkit::ScriptedHost& h) {
    EXPECT_EQ(h.read(board::reg::kId), board::reg::kIdValue);
    at = sc_core::sc_time_stamp();
  });
  testkit::run_until_finished({&host});
  EXPECT_EQ(at, params.pci.clock_period * static_cast<double>(params.pci.setup_cycles + 1));
}

// A 1 KiB DMA each way holds the bus for max(bus time, bridge + bank time) (tlm/pci_bus.h,
// "occupancy"; the bank one word per cycle after its latency), with the profile's own numbers.
TEST(MyPlatform, DmaTakesTheLongerOfBusAndBankTime) {
  const board::BoardParams p = xc2v6000();
  board::Rc2000 rc2000("rc2000", p);
  std::vector<std::uint8_t> data(1024), back(1024);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 29 + 3);
  sc_time in, out;
  testkit::ScriptedHost host("host", rc2000, [&](testkit::ScriptedHost& h) {
    h.dma(tlmx::DmaDirection::to_device, data.data(), 1, data.size());
    in = sc_core::sc_time_stamp();
    h.dma(tlmx::DmaDirection::to_host, back.data(), 1, back.size());
    out = sc_core::sc_time_stamp() - in;
  });
  testkit::run_until_finished({&host});
  const double words = 1024.0 / (p.word_bits / 8);
  const sc_time bridge = p.pci.clock_period * static_cast<double>(p.bridge_latency_cycles);
  const sc_time bus = rc2000.pci.transfer_time(1024);
  EXPECT_EQ(in, std::max(bus, bridge + p.timing.bank_period * (p.bank_write_latency + words)));
  EXPECT_EQ(out, std::max(bus, bridge + p.timing.bank_period * (p.timing.bank_read_latency + words)));
  EXPECT_EQ(back, data);
}

}  // namespace
