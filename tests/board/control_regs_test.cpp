// ControlRegs as a TLM target, driven by the base-protocol checking initiators
// (tests/tlm/protocol_checker.h), loosely and approximately timed: every kind of request gets the
// answer control_regs.h lists, with exact times, and nothing moves on an error.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "board/control_regs.h"
#include "board/register_map.h"
#include "tests/tlm/protocol_checker.h"

namespace rc::board::test {
namespace {

using rc::tlmx::test::AtInitiator;
using rc::tlmx::test::EndResponse;
using rc::tlmx::test::LtInitiator;
using rc::tlmx::test::Outcome;
using rc::tlmx::test::read_request;
using rc::tlmx::test::Request;
using rc::tlmx::test::write_request;
using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_ZERO_TIME;
using Violations = std::vector<std::string>;

const sc_time kAccess(10, SC_NS);  // the registers' access time in these tests

std::uint32_t word(const std::array<std::uint8_t, 64>& bytes, std::uint64_t offset) {
  return static_cast<std::uint32_t>(bytes[offset]) | static_cast<std::uint32_t>(bytes[offset + 1]) << 8 |
         static_cast<std::uint32_t>(bytes[offset + 2]) << 16 | static_cast<std::uint32_t>(bytes[offset + 3]) << 24;
}

// Whole-register reads and writes are OK after the access time; the errors (a read or write of 0
// bytes among them, wherever it points) take no time, count no access and change nothing; a
// TLM_IGNORE_COMMAND is OK with no effect and no time.
TEST(ControlRegs, AnswersEveryKindOfRequestLooselyTimed) {
  ControlRegs regs("regs", kAccess, 0x01020304);
  std::array<std::uint32_t, 8> params{7, 8, 9, 10, 11, 12, 13, 14};
  std::array<std::uint8_t, 64> all{};
  std::array<std::uint8_t, 8> scratch{0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
  std::array<std::uint8_t, 4> enables{0xFF, 0xFF, 0xFF, 0xFF}, beyond{};
  std::uint32_t start = reg::kStart;
  std::vector<Outcome> o;
  LtInitiator host("host", [&](LtInitiator& self) {
    o.push_back(self.transport(write_request(reg::kRayCount, params.data(), 32)));          // 0
    o.push_back(self.transport(read_request(0, all.data(), 64, sc_time(5, SC_NS))));        // 1
    o.push_back(self.transport(read_request(reg::kSize, beyond.data(), 4)));                // 2
    Request masked = write_request(reg::kRayCount, scratch.data(), 4);
    masked.byte_enable = enables.data();
    masked.byte_enable_length = 4;
    o.push_back(self.transport(masked));                                                    // 3
    o.push_back(self.transport(write_request(reg::kRayCount + 2, scratch.data(), 4)));     // 4
    o.push_back(self.transport(read_request(reg::kBarSize - 4, scratch.data(), 8)));       // 5
    o.push_back(self.transport(read_request(reg::kBarSize, scratch.data(), 4)));           // 6
    o.push_back(self.transport(write_request(reg::kRayCount, scratch.data(), 6)));         // 7
    Request streaming = write_request(reg::kRayCount, scratch.data(), 8);
    streaming.streaming_width = 4;
    o.push_back(self.transport(streaming));                                                 // 8
    o.push_back(self.transport(write_request(reg::kControl, &start, 0)));                  // 9
    o.push_back(self.transport(write_request(0x5000, &start, 0)));                         // 10
    Request ignore = write_request(reg::kControl, &start, 4);
    ignore.command = tlm::TLM_IGNORE_COMMAND;
    o.push_back(self.transport(ignore));                                                    // 11
  });
  host.out.bind(regs.in);
  sc_core::sc_start();

  ASSERT_TRUE(host.finished());
  EXPECT_EQ(host.violations(), Violations{});
  ASSERT_EQ(o.size(), 12u);
  EXPECT_EQ(o[0].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(o[0].response, kAccess);
  EXPECT_EQ(regs.value(reg::kRayCount), 7u);
  EXPECT_EQ(regs.value(reg::kMaskStart), 14u);
  EXPECT_EQ(o[1].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(o[1].response, sc_time(15, SC_NS));
  EXPECT_EQ(word(all, reg::kId), reg::kIdValue);
  EXPECT_EQ(word(all, reg::kConfig), 0x01020304u);
  EXPECT_EQ(word(all, reg::kStartX), 11u);
  EXPECT_EQ(o[2].status, tlm::TLM_OK_RESPONSE);  // in the BAR, past the register file: reads 0
  EXPECT_EQ(beyond, (std::array<std::uint8_t, 4>{}));
  EXPECT_EQ(o[3].status, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
  EXPECT_EQ(o[4].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);  // not aligned
  EXPECT_EQ(o[5].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);  // runs past the BAR
  EXPECT_EQ(o[6].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);  // outside the BAR
  EXPECT_EQ(o[7].status, tlm::TLM_BURST_ERROR_RESPONSE);    // not whole registers
  EXPECT_EQ(o[8].status, tlm::TLM_BURST_ERROR_RESPONSE);    // streaming
  EXPECT_EQ(o[9].status, tlm::TLM_BURST_ERROR_RESPONSE);   // 0 bytes
  EXPECT_EQ(o[10].status, tlm::TLM_BURST_ERROR_RESPONSE);  // 0 bytes, outside the BAR: the length first
  EXPECT_EQ(o[11].status, tlm::TLM_OK_RESPONSE);           // IGNORE
  for (std::size_t i = 3; i <= 11; ++i) EXPECT_EQ(o[i].response, SC_ZERO_TIME) << i;
  EXPECT_EQ(regs.value(reg::kRayCount), 7u);  // no error wrote anything
  EXPECT_FALSE(regs.start_pending());         // neither the zero-length write nor the IGNORE started a pass
  EXPECT_EQ(regs.accesses(), 3u);
}

// Through the socket's nb-to-b conversion: BEGIN_RESP after the access time, a START written by an
// AT request at 50 ns takes effect at 60 ns exactly as an LT write at that local time would, and
// errors answer at the request time.
TEST(ControlRegs, ApproximatelyTimedRequestsActAtTheirTime) {
  ControlRegs regs("regs", kAccess, 0);
  std::uint32_t start = reg::kStart | reg::kClear, id = 0, scratch = 0;
  std::array<std::uint8_t, 4> enables{0xFF, 0, 0, 0};
  std::vector<Outcome> o;
  sc_time start_seen_at;
  AtInitiator host("host", [&](AtInitiator& self) {
    o.push_back(self.transport(write_request(reg::kControl, &start, 4, sc_time(50, SC_NS)), EndResponse::accepted,
                               sc_time(3, SC_NS)));
    start_seen_at = regs.start_time();
    o.push_back(self.transport(read_request(reg::kId, &id, 4), EndResponse::updated));
    Request masked = read_request(reg::kId, &scratch, 4);
    masked.byte_enable = enables.data();
    masked.byte_enable_length = 4;
    o.push_back(self.transport(masked));
    o.push_back(self.transport(read_request(reg::kStatus, &scratch, 0)));
  });
  host.out.bind(regs.in);
  sc_core::sc_start();

  EXPECT_EQ(host.violations(), Violations{});
  EXPECT_EQ(host.payloads_in_use(), 0u);
  ASSERT_EQ(o.size(), 4u);
  EXPECT_EQ(o[0].request, sc_time(50, SC_NS));
  EXPECT_EQ(o[0].response, sc_time(60, SC_NS));
  EXPECT_EQ(o[0].end_response, sc_time(63, SC_NS));
  EXPECT_EQ(start_seen_at, sc_time(60, SC_NS));
  EXPECT_TRUE(regs.start_pending());
  EXPECT_EQ(regs.take_start(), reg::kStart | reg::kClear);
  EXPECT_EQ(o[1].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(o[1].response, sc_time(73, SC_NS));
  EXPECT_EQ(id, reg::kIdValue);
  EXPECT_EQ(o[2].status, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
  EXPECT_EQ(o[2].response, sc_time(73, SC_NS));
  EXPECT_EQ(o[3].status, tlm::TLM_BURST_ERROR_RESPONSE);  // 0 bytes
  EXPECT_EQ(o[3].response, sc_time(73, SC_NS));
  EXPECT_EQ(regs.accesses(), 2u);
}

// Registers have side effects: DMI is refused, with no access, over the whole address space.
TEST(ControlRegs, RefusesDmiEverywhere) {
  ControlRegs regs("regs", kAccess, 0);
  bool granted = true;
  tlm::tlm_dmi dmi;
  LtInitiator host("host", [&](LtInitiator& self) {
    tlm::tlm_generic_payload trans;
    trans.set_command(tlm::TLM_READ_COMMAND);
    trans.set_address(reg::kStatus);
    granted = self.out->get_direct_mem_ptr(trans, dmi);
  });
  host.out.bind(regs.in);
  sc_core::sc_start();

  EXPECT_FALSE(granted);
  EXPECT_TRUE(dmi.is_none_allowed());
  EXPECT_EQ(dmi.get_dmi_ptr(), nullptr);
  EXPECT_EQ(dmi.get_start_address(), 0u);
  EXPECT_EQ(dmi.get_end_address(), ~sc_dt::uint64{0});
}

}  // namespace
}  // namespace rc::board::test
