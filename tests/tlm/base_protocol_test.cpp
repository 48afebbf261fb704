// Every TLM part driven by the base-protocol checking initiators (protocol_checker.h), loosely and
// approximately timed: reads, writes and the error cases, with exact statuses and times. The
// interconnects' own AT timing (arbitration, exclusion rules) is in at_transport_test.cpp.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <tlm_utils/simple_target_socket.h>

#include "tests/tlm/protocol_checker.h"
#include "tests/tlm/tlm_test_support.h"
#include "tlm/pci_bus.h"
#include "tlm/router.h"
#include "tlm/sram_bank.h"

namespace rc::tlmx::test {
namespace {

using Violations = std::vector<std::string>;

SramBankConfig bank_config() {
  SramBankConfig config;
  config.capacity_bytes = 64 * 1024;  // 10 ns clock, latency 2, 1 cycle per 4-byte word
  return config;
}

// An LT target that answers OK after `delay` and records the attributes of what it received, so
// the interconnects' pass-through of byte enables, streaming width and length can be checked.
class RecordingTarget : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<RecordingTarget> in;
  std::vector<Attributes> received;
  sc_time delay;

  RecordingTarget(const sc_core::sc_module_name& name, sc_time answer_after)
      : sc_core::sc_module(name), in("in"), delay(answer_after) {
    in.register_b_transport(this, &RecordingTarget::b_transport);
  }

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_time& t) {
    received.push_back(Attributes::of(trans));
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
    t += delay;
  }
};

// Reads, writes and the bank's stable error answers, LT: exact delays from sram_bank.h.
TEST(BaseProtocol, SramBankLooselyTimed) {
  SramBank bank("bank", bank_config());
  std::array<std::uint8_t, 16> out{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}, back{};
  std::array<std::uint8_t, 8> scratch{};
  std::vector<Outcome> o;
  LtInitiator cpu("cpu", [&](LtInitiator& self) {
    o.push_back(self.transport(write_request(0x100, out.data(), 16)));
    o.push_back(self.transport(read_request(0x100, back.data(), 16, sc_time(5, SC_NS))));
    o.push_back(self.transport(read_request(0x10000 - 4, scratch.data(), 8)));  // past the end
    Request streaming = read_request(0x200, scratch.data(), 8);
    streaming.streaming_width = 4;
    o.push_back(self.transport(streaming));
    Request ignore = read_request(0x200, scratch.data(), 8);
    ignore.command = tlm::TLM_IGNORE_COMMAND;
    o.push_back(self.transport(ignore));
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  ASSERT_TRUE(cpu.finished());
  EXPECT_EQ(cpu.violations(), Violations{});
  ASSERT_EQ(o.size(), 5u);
  EXPECT_EQ(o[0].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(o[0].response, sc_time(60, SC_NS));  // (2 + 4 words) * 10 ns
  EXPECT_TRUE(o[0].dmi_hint);
  EXPECT_EQ(o[1].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(o[1].response, sc_time(65, SC_NS));
  EXPECT_EQ(back, out);
  EXPECT_EQ(o[2].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(o[2].response, SC_ZERO_TIME);
  EXPECT_EQ(o[3].status, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(o[3].response, SC_ZERO_TIME);
  EXPECT_EQ(o[4].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(o[4].response, SC_ZERO_TIME);
}

// The same through the bank's socket, approximately timed: simple_target_socket runs b_transport
// at the request time and sends BEGIN_RESP (no END_REQ before it) when its delay has passed.
TEST(BaseProtocol, SramBankApproximatelyTimed) {
  SramBank bank("bank", bank_config());
  std::array<std::uint8_t, 16> out{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}, back{};
  std::array<std::uint8_t, 8> scratch{};
  std::vector<Outcome> o;
  AtInitiator cpu("cpu", [&](AtInitiator& self) {
    o.push_back(self.transport(write_request(0x100, out.data(), 16)));
    o.push_back(self.transport(read_request(0x100, back.data(), 16, sc_time(5, SC_NS)), EndResponse::updated));
    o.push_back(self.transport(read_request(0x10000 - 4, scratch.data(), 8), EndResponse::accepted, sc_time(7, SC_NS)));
    Request streaming = read_request(0x200, scratch.data(), 8);
    streaming.streaming_width = 4;
    o.push_back(self.transport(streaming));
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  ASSERT_TRUE(cpu.finished());
  EXPECT_EQ(cpu.violations(), Violations{});
  EXPECT_EQ(cpu.payloads_in_use(), 0u);
  ASSERT_EQ(o.size(), 4u);
  EXPECT_EQ(o[0].status, tlm::TLM_OK_RESPONSE);
  EXPECT_FALSE(o[0].end_request.has_value());  // implied by BEGIN_RESP
  EXPECT_EQ(o[0].request, SC_ZERO_TIME);
  EXPECT_EQ(o[0].response, sc_time(60, SC_NS));
  EXPECT_EQ(o[1].request, sc_time(65, SC_NS));   // issued at 60 with 5 ns of local time
  EXPECT_EQ(o[1].response, sc_time(125, SC_NS));
  EXPECT_EQ(back, out);
  EXPECT_EQ(o[2].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(o[2].response, sc_time(125, SC_NS));      // no time
  EXPECT_EQ(o[2].end_response, sc_time(132, SC_NS));  // held 7 ns by the initiator
  EXPECT_EQ(o[3].status, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(o[3].response, sc_time(132, SC_NS));
  EXPECT_EQ(bank.report().writes, 1u);
  EXPECT_EQ(bank.report().reads, 1u);
}

// Bank behind a PciBus (32 bit, 30 ns, setup 8), LT and AT side by side on one bus at different
// times, plus a master abort and a straddling access.
TEST(BaseProtocol, PciBusLooselyAndApproximatelyTimed) {
  constexpr std::uint64_t kBar = 0x8000'0000;
  PciBus bus("bus");
  SramBankConfig fast = bank_config();
  fast.clock_period = sc_time(1, SC_NS);  // the bus dominates
  SramBank bank("bank", fast);
  std::array<std::uint8_t, 8> data{1, 2, 3, 4, 5, 6, 7, 8}, back{};
  std::vector<Outcome> lt, at;
  LtInitiator driver("driver", [&](LtInitiator& self) {
    lt.push_back(self.transport(write_request(kBar + 0x10, data.data(), 8)));
    lt.push_back(self.transport(read_request(0x9000'0000, back.data(), 4, sc_time(1, SC_US))));
    lt.push_back(self.transport(read_request(kBar + 0x10000 - 4, back.data(), 8, sc_time(2, SC_US))));
  });
  AtInitiator dma("dma", [&](AtInitiator& self) {
    sc_core::wait(sc_time(10, SC_US));
    at.push_back(self.transport(read_request(kBar + 0x10, back.data(), 8)));
    at.push_back(self.transport(read_request(0x9000'0000, back.data(), 4, sc_time(1, SC_US)), EndResponse::accepted,
                                sc_time(100, SC_NS)));
  });
  driver.out.bind(bus.in);
  dma.out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(kBar, bank.capacity(), 0, "bank");
  sc_core::sc_start();

  EXPECT_EQ(driver.violations(), Violations{});
  EXPECT_EQ(dma.violations(), Violations{});
  EXPECT_EQ(dma.payloads_in_use(), 0u);
  ASSERT_EQ(lt.size(), 3u);
  ASSERT_EQ(at.size(), 2u);
  EXPECT_EQ(lt[0].status, tlm::TLM_OK_RESPONSE);
  EXPECT_FALSE(lt[0].dmi_hint);                      // the bus clears it: no DMI through PCI
  EXPECT_EQ(lt[0].response, sc_time(10 * 30, SC_NS));  // 8 + 2 cycles
  EXPECT_EQ(lt[1].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(lt[1].response, sc_time(1000 + 6 * 30, SC_NS));  // master abort
  EXPECT_EQ(lt[2].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);  // straddles the window's end
  EXPECT_EQ(lt[2].response, sc_time(2000 + 6 * 30, SC_NS));
  EXPECT_EQ(at[0].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(at[0].end_request, sc_time(10, SC_US));  // the bus is free: END_REQ at the request
  EXPECT_EQ(at[0].response, sc_time(10000 + 300, SC_NS));
  EXPECT_EQ(back, data);
  EXPECT_EQ(at[1].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(at[1].end_request, sc_time(11300, SC_NS));
  EXPECT_EQ(at[1].response, sc_time(11300 + 180, SC_NS));
  EXPECT_EQ(at[1].end_response, sc_time(11300 + 180 + 100, SC_NS));
  const PciBusReport r = bus.report();
  EXPECT_EQ(r.total.transactions, 5u);
  EXPECT_EQ(r.total.address_errors, 3u);
  EXPECT_EQ(r.initiators.at(1).bytes_read, 8u);
  EXPECT_EQ(r.initiators.at(0).bytes_written, 8u);
}

// The bus passes byte enables, streaming width and length to the target untouched; a
// TLM_IGNORE_COMMAND moves no data and takes one burst's setup (8 cycles); a read or write of 0
// bytes is refused at once (burst error, no time, not forwarded, not counted), LT and AT alike.
TEST(BaseProtocol, PciBusPassesAttributesThroughAndTimesTransfersWithoutData) {
  PciBus bus("bus");
  RecordingTarget target("target", sc_time(1, SC_NS));
  std::array<std::uint8_t, 8> data{}, enables{0xFF, 0, 0xFF, 0, 0xFF, 0, 0xFF, 0};
  std::vector<Outcome> o;
  Outcome at_empty;
  LtInitiator driver("driver", [&](LtInitiator& self) {
    Request masked = write_request(0x100, data.data(), 8);
    masked.byte_enable = enables.data();
    masked.byte_enable_length = 4;
    masked.streaming_width = 4;
    o.push_back(self.transport(masked));
    o.push_back(self.transport(write_request(0x100, data.data(), 0, sc_time(1, SC_US))));
    Request ignore = read_request(0x100, data.data(), 8, sc_time(2, SC_US));
    ignore.command = tlm::TLM_IGNORE_COMMAND;
    o.push_back(self.transport(ignore));
  });
  AtInitiator dma("dma", [&](AtInitiator& self) {
    sc_core::wait(sc_time(5, SC_US));
    at_empty = self.transport(read_request(0x100, data.data(), 0));
  });
  driver.out.bind(bus.in);
  dma.out.bind(bus.in);
  bus.out.bind(target.in);
  bus.map(0, 0x1000, 0, "target");
  sc_core::sc_start();

  EXPECT_EQ(driver.violations(), Violations{});
  EXPECT_EQ(dma.violations(), Violations{});
  ASSERT_EQ(target.received.size(), 2u);
  EXPECT_EQ(target.received[0].byte_enable, enables.data());
  EXPECT_EQ(target.received[0].byte_enable_length, 4u);
  EXPECT_EQ(target.received[0].streaming_width, 4u);
  EXPECT_EQ(target.received[0].length, 8u);
  EXPECT_EQ(target.received[0].address, 0x100u);
  ASSERT_EQ(o.size(), 3u);
  EXPECT_EQ(o[0].response, sc_time(10 * 30, SC_NS));
  EXPECT_EQ(o[1].status, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(o[1].response, sc_time(1000, SC_NS));
  EXPECT_EQ(o[2].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(o[2].response, sc_time(2000 + 8 * 30, SC_NS));
  EXPECT_EQ(target.received[1].command, tlm::TLM_IGNORE_COMMAND);
  EXPECT_EQ(at_empty.status, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(at_empty.response, sc_time(5, SC_US));
  EXPECT_EQ(bus.report().total.transactions, 2u);
  EXPECT_EQ(bus.report().total.bytes_written, 8u);
  EXPECT_EQ(bus.report().total.bytes_read, 0u);
  EXPECT_EQ(bus.report().bus_free_at, sc_time(2000 + 8 * 30, SC_NS));
}

// Router (3 cycles of 10 ns) in front of a bank and a recording target: LT and AT reads and writes
// with the latency, unmapped and straddling addresses (address error, no time), zero-length reads
// (burst error, no time, not routed), attributes passed through untouched.
TEST(BaseProtocol, RouterLooselyAndApproximatelyTimed) {
  RouterConfig config;
  config.latency_cycles = 3;
  Router router("router", config);
  SramBank bank("bank", bank_config());
  RecordingTarget target("target", sc_time(7, SC_NS));
  std::array<std::uint8_t, 8> data{9, 8, 7, 6, 5, 4, 3, 2}, back{}, enables{0xFF, 0, 0xFF, 0};
  std::vector<Outcome> lt, at;
  LtInitiator cpu("cpu", [&](LtInitiator& self) {
    lt.push_back(self.transport(write_request(0x10'0010, data.data(), 8)));
    lt.push_back(self.transport(read_request(0x30'0000, back.data(), 4)));            // unmapped
    lt.push_back(self.transport(read_request(0x10'FFFC, back.data(), 8)));            // straddles
    Request masked = write_request(0x20'0040, data.data(), 8, sc_time(1, SC_US));
    masked.byte_enable = enables.data();
    masked.byte_enable_length = 4;
    lt.push_back(self.transport(masked));
    lt.push_back(self.transport(read_request(0x20'0040, back.data(), 0, sc_time(2, SC_US))));
  });
  AtInitiator fpga("fpga", [&](AtInitiator& self) {
    sc_core::wait(sc_time(5, SC_US));
    at.push_back(self.transport(read_request(0x10'0010, back.data(), 8)));
    at.push_back(self.transport(read_request(0x30'0000, back.data(), 4), EndResponse::updated));
    Request masked = write_request(0x20'0040, data.data(), 8);
    masked.byte_enable = enables.data();
    masked.byte_enable_length = 4;
    masked.streaming_width = 8;
    at.push_back(self.transport(masked, EndResponse::accepted, sc_time(5, SC_NS)));
    at.push_back(self.transport(read_request(0x20'0040, back.data(), 0)));
  });
  cpu.out.bind(router.in);
  fpga.out.bind(router.in);
  router.out.bind(bank.in);
  router.out.bind(target.in);
  router.map(0x10'0000, bank.capacity(), 0, "bank");
  router.map(0x20'0000, 0x1000, 1, "target");
  sc_core::sc_start();

  EXPECT_EQ(cpu.violations(), Violations{});
  EXPECT_EQ(fpga.violations(), Violations{});
  EXPECT_EQ(fpga.payloads_in_use(), 0u);
  ASSERT_EQ(lt.size(), 5u);
  ASSERT_EQ(at.size(), 4u);
  EXPECT_EQ(lt[0].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(lt[0].response, sc_time(30 + 40, SC_NS));  // router 30 ns + bank (2 + 2 words) * 10 ns
  EXPECT_TRUE(lt[0].dmi_hint);                        // the bank's hint passes (and DMI is granted)
  EXPECT_EQ(lt[1].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(lt[1].response, SC_ZERO_TIME);
  EXPECT_EQ(lt[2].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(lt[3].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(lt[3].response, sc_time(1000 + 30 + 7, SC_NS));
  EXPECT_EQ(at[0].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(at[0].response, sc_time(5000 + 70, SC_NS));  // the same as LT
  EXPECT_EQ(back, data);
  EXPECT_EQ(at[1].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(at[1].response, sc_time(5070, SC_NS));  // completed at once
  EXPECT_EQ(at[2].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(at[2].response, sc_time(5070 + 37, SC_NS));
  EXPECT_EQ(at[2].end_response, sc_time(5070 + 42, SC_NS));
  EXPECT_EQ(lt[4].status, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(lt[4].response, sc_time(2, SC_US));
  EXPECT_EQ(at[3].status, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(at[3].response, sc_time(5112, SC_NS));
  ASSERT_EQ(target.received.size(), 2u);
  for (const Attributes& a : target.received) {
    EXPECT_EQ(a.address, 0x40u);  // window-relative
    EXPECT_EQ(a.byte_enable, enables.data());
    EXPECT_EQ(a.byte_enable_length, 4u);
    EXPECT_EQ(a.streaming_width, 8u);
  }
  EXPECT_EQ(router.report().transactions, 4u);
  EXPECT_EQ(router.report().address_errors, 3u);
}

}  // namespace
}  // namespace rc::tlmx::test
