// The test kit's generic initiator (testkit/tlm/scripted_initiator.h) against one SRAM bank: the
// script runs from time 0, each access returns the bank's response and its annotated delay
// (tlm/sram_bank.h: (latency + words) * period), and `finished` is set when the script ends.
#include <gtest/gtest.h>

#include <cstdint>

#include "testkit/tlm/scripted_initiator.h"
#include "tlm/sram_bank.h"

namespace rc::testkit {
namespace {

using sc_core::sc_time;
using sc_core::SC_NS;

TEST(TestkitInitiator, AccessesReturnTheBanksResponseAndDelay) {
  tlmx::SramBankConfig config;  // 4-byte words, 10 ns, latency 2
  config.report_at_end = false;
  tlmx::SramBank bank("bank", config);
  std::uint32_t words[2] = {0x11223344u, 0x55667788u}, back[2] = {};
  sc_time write_delay, read_delay, started;
  tlm::tlm_response_status outside = tlm::TLM_OK_RESPONSE;
  ScriptedInitiator host("host", [&](ScriptedInitiator& h) {
    started = sc_core::sc_time_stamp();
    EXPECT_EQ(h.write(0x40, words, 8, write_delay), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(h.read(0x40, back, 8, read_delay), tlm::TLM_OK_RESPONSE);
    sc_time ignored;
    outside = h.read(bank.capacity(), back, 4, ignored);
  });
  host.out.bind(bank.in);
  sc_core::sc_start();
  EXPECT_TRUE(host.finished);
  EXPECT_EQ(started, sc_core::SC_ZERO_TIME);
  EXPECT_EQ(write_delay, sc_time(40, SC_NS));  // (2 + 2 words) * 10 ns
  EXPECT_EQ(read_delay, sc_time(40, SC_NS));
  EXPECT_EQ(back[0], words[0]);
  EXPECT_EQ(back[1], words[1]);
  EXPECT_EQ(outside, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(host.last_address_seen, bank.capacity());
}

}  // namespace
}  // namespace rc::testkit
