// The three faults an outside base-protocol checker found (issue 30), each reproduced by the exact
// sequence, with a HopChecker (hop_checker.h) on every hop:
//   - a target behind the PciBus that waits inside b_transport (an AT-only target behind its
//     socket's b-to-nb adapter) made the bus hand later transactions wrapped-around delays;
//   - an initiator answering END_REQ TLM_COMPLETED: the Router reported an error and still sent it
//     the target's BEGIN_RESP; now every interconnect finishes the target's side itself;
//   - streaming bursts decoded by their data length instead of the bytes they touch.
// Times are worked out by hand from pci_bus.h and router.h.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tests/tlm/hop_checker.h"
#include "tests/tlm/protocol_checker.h"
#include "tests/tlm/tlm_test_support.h"
#include "tlm/pci_bus.h"
#include "tlm/router.h"
#include "tlm/sram_bank.h"

namespace rc::tlmx::test {
namespace {

using Violations = std::vector<std::string>;

std::uint64_t reports(sc_core::sc_severity severity) { return sc_core::sc_report_handler::get_count(severity); }

SramBankConfig small_bank() {
  SramBankConfig c;
  c.capacity_bytes = 64 * 1024;  // 10 ns clock, latency 2, 1 cycle per 4-byte word
  return c;
}

// The PciBus (32 bit, 30 ns, setup 8: 4 B take 9 cycles = 270 ns) with an AT-only target at
// 0x1000'0000 (END_REQ after 10 ns, BEGIN_RESP after 1 us) and a bank at 0x2000'0000, a checker on
// every hop. Initiator A issues a read of the AT-only target at 0 (END_REQ at 0: the bus takes it;
// the adapter then waits inside b_transport until 1 us), then a read of the bank requested at 0;
// initiator L calls b_transport at 5 ns for the bank. Before the fix the bus took the first
// transaction's occupancy as 270 ns, started the second at 270 ns while simulated time was 1 us,
// and handed the bank start - now = 2^64 - 730 ns. Now the bus is held until the AT-only target
// responds at 1000 ns; the second starts at 1000 (bank asked to act at 1000, ends 1270), L's at
// 1270 (bank at 1270, ends 1540); no delay anywhere is wrapped.
TEST(PciBusAtOnlyTarget, ServedWithTheBusHeldAndNoDelayWraps) {
  PciBus bus("bus");
  AtTarget at_only("at_only", AtTarget::Style::accepted, sc_time(10, SC_NS), sc_time(1, SC_US));
  SramBank bank("bank", small_bank());
  HopChecker a_hop("a_hop"), l_hop("l_hop"), at_hop("at_hop"), bank_hop("bank_hop");
  std::array<std::uint8_t, 4> first{}, second{}, third{};
  Outcome o1, o2, o3;
  AtInitiator a("a", [&](AtInitiator& self) {
    const AtInitiator::Ticket t1 = self.issue(read_request(0x1000'0000, first.data(), 4));
    const AtInitiator::Ticket t2 = self.issue(read_request(0x2000'0000, second.data(), 4));
    o1 = self.finish(t1);
    o2 = self.finish(t2);
  });
  LtInitiator l("l", [&](LtInitiator& self) {
    sc_core::wait(sc_time(5, SC_NS));
    o3 = self.transport(read_request(0x2000'0040, third.data(), 4));
  });
  a.out.bind(a_hop.in);
  a_hop.out.bind(bus.in);
  l.out.bind(l_hop.in);
  l_hop.out.bind(bus.in);
  bus.out.bind(at_hop.in);
  at_hop.out.bind(at_only.in);
  bus.out.bind(bank_hop.in);
  bank_hop.out.bind(bank.in);
  bus.map(0x1000'0000, 0x1000, 0, "at_only");
  bus.map(0x2000'0000, bank.capacity(), 1, "bank");
  sc_core::sc_start();

  for (const HopChecker* h : {&a_hop, &l_hop, &at_hop, &bank_hop}) {
    EXPECT_EQ(h->violations(), Violations{}) << h->name();
    EXPECT_EQ(h->unfinished(), Violations{}) << h->name();
  }
  EXPECT_EQ(a.violations(), Violations{});
  EXPECT_EQ(l.violations(), Violations{});
  EXPECT_TRUE(at_only.idle());
  EXPECT_EQ(o1.end_request, sc_time(0, SC_NS));
  EXPECT_EQ(o1.response, sc_time(1000, SC_NS));
  EXPECT_EQ(o1.status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(first, (std::array<std::uint8_t, 4>{0x5A, 0x5A, 0x5A, 0x5A}));
  EXPECT_EQ(o2.end_request, sc_time(1000, SC_NS));
  EXPECT_EQ(o2.response, sc_time(1270, SC_NS));
  EXPECT_EQ(o3.request, sc_time(5, SC_NS));
  EXPECT_EQ(o3.response, sc_time(1540, SC_NS));
  EXPECT_EQ(at_only.request_times, std::vector<sc_time>{SC_ZERO_TIME});
  EXPECT_EQ(bank_hop.b_transport_starts(), (std::vector<sc_time>{sc_time(1000, SC_NS), sc_time(1270, SC_NS)}));
  const PciBusReport r = bus.report();
  EXPECT_EQ(r.total.busy, sc_time(1540, SC_NS));
  EXPECT_EQ(r.total.wait, sc_time(1000 + 1265, SC_NS));
  EXPECT_EQ(r.bus_free_at, sc_time(1540, SC_NS));
}

// An initiator that answers END_REQ TLM_COMPLETED wants no response. Behind a Router, two nested
// Routers and a PciBus, each with a checker on every hop: the initiator gets END_REQ, nothing
// after it, no report is made, the target's response is ended by the interconnect, every payload
// is given back, and the next transaction on the same path runs normally.
struct EndReqCase {
  std::vector<Outcome> outcomes;
  std::array<std::uint8_t, 8> data{};
  static std::function<void(AtInitiator&)> script(EndReqCase& c) {
    return [&c](AtInitiator& self) {
      c.outcomes.push_back(self.transport(read_request(0x100, c.data.data(), 4), EndResponse::at_end_request));
      sc_core::wait(sc_time(200, SC_NS));
      c.outcomes.push_back(self.transport(read_request(0x100, c.data.data() + 4, 4)));
    };
  }
};

void expect_clean(const std::vector<const HopChecker*>& hops) {
  for (const HopChecker* h : hops) {
    EXPECT_EQ(h->violations(), Violations{}) << h->name();
    EXPECT_EQ(h->unfinished(), Violations{}) << h->name();
  }
}

TEST(EndReqCompleted, RouterFinishesTheTargetsSideItself) {
  const std::uint64_t errors = reports(sc_core::SC_ERROR), warnings = reports(sc_core::SC_WARNING);
  EndReqCase c;
  AtInitiator cpu("cpu", EndReqCase::script(c));
  Router router("router", RouterConfig{sc_time(10, SC_NS), 1});
  AtTarget target("target", AtTarget::Style::accepted, sc_time(10, SC_NS), sc_time(50, SC_NS));
  HopChecker in_hop("in_hop"), out_hop("out_hop");
  cpu.out.bind(in_hop.in);
  in_hop.out.bind(router.in);
  router.out.bind(out_hop.in);
  out_hop.out.bind(target.in);
  router.map(0, 0x1000, 0, "target");
  sc_core::sc_start();

  expect_clean({&in_hop, &out_hop});
  EXPECT_EQ(cpu.violations(), Violations{});
  EXPECT_EQ(cpu.payloads_in_use(), 0u);
  EXPECT_EQ(reports(sc_core::SC_ERROR), errors);
  EXPECT_EQ(reports(sc_core::SC_WARNING), warnings);
  EXPECT_TRUE(target.idle());
  EXPECT_EQ(target.responses_ended, 2u);
  ASSERT_EQ(c.outcomes.size(), 2u);
  EXPECT_EQ(c.outcomes[0].end_request, sc_time(20, SC_NS));        // latency 10 ns + accept 10 ns
  EXPECT_EQ(c.outcomes[0].status, tlm::TLM_INCOMPLETE_RESPONSE);  // no response reached it
  EXPECT_EQ(in_hop.counts().completed_at_end_req, 1u);
  EXPECT_EQ(out_hop.counts().responses, 2u);  // the target's first response ended at the router
  EXPECT_EQ(in_hop.counts().responses, 1u);
  EXPECT_EQ(c.outcomes[1].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(c.outcomes[1].response, sc_time(20 + 200 + 60, SC_NS));
}

TEST(EndReqCompleted, NestedRoutersFinishTheTargetsSideThemselves) {
  const std::uint64_t errors = reports(sc_core::SC_ERROR), warnings = reports(sc_core::SC_WARNING);
  EndReqCase c;
  AtInitiator cpu("cpu", EndReqCase::script(c));
  Router outer("outer"), inner("inner");
  AtTarget target("target", AtTarget::Style::accepted, sc_time(10, SC_NS), sc_time(50, SC_NS));
  HopChecker h1("h1"), h2("h2"), h3("h3");
  cpu.out.bind(h1.in);
  h1.out.bind(outer.in);
  outer.out.bind(h2.in);
  h2.out.bind(inner.in);
  inner.out.bind(h3.in);
  h3.out.bind(target.in);
  outer.map(0, 0x1000, 0, "inner");
  inner.map(0, 0x1000, 0, "target");
  sc_core::sc_start();

  expect_clean({&h1, &h2, &h3});
  EXPECT_EQ(cpu.violations(), Violations{});
  EXPECT_EQ(cpu.payloads_in_use(), 0u);
  EXPECT_EQ(reports(sc_core::SC_ERROR), errors);
  EXPECT_EQ(reports(sc_core::SC_WARNING), warnings);
  EXPECT_TRUE(target.idle());
  ASSERT_EQ(c.outcomes.size(), 2u);
  EXPECT_EQ(c.outcomes[0].end_request, sc_time(10, SC_NS));
  EXPECT_EQ(h1.counts().completed_at_end_req, 1u);
  EXPECT_EQ(h3.counts().responses, 2u);
  EXPECT_EQ(h2.counts().responses, 2u);  // the outer router ended the first response
  EXPECT_EQ(h1.counts().responses, 1u);
  EXPECT_EQ(c.outcomes[1].status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(c.outcomes[1].response, sc_time(10 + 200 + 50, SC_NS));
}

TEST(EndReqCompleted, PciBusSendsNoResponse) {
  const std::uint64_t errors = reports(sc_core::SC_ERROR), warnings = reports(sc_core::SC_WARNING);
  EndReqCase c;
  AtInitiator cpu("cpu", EndReqCase::script(c));
  PciBus bus("bus");
  SramBank bank("bank", small_bank());
  HopChecker in_hop("in_hop"), out_hop("out_hop");
  cpu.out.bind(in_hop.in);
  in_hop.out.bind(bus.in);
  bus.out.bind(out_hop.in);
  out_hop.out.bind(bank.in);
  bus.map(0, bank.capacity(), 0, "bank");
  sc_core::sc_start();

  expect_clean({&in_hop, &out_hop});
  EXPECT_EQ(cpu.violations(), Violations{});
  EXPECT_EQ(cpu.payloads_in_use(), 0u);
  EXPECT_EQ(reports(sc_core::SC_ERROR), errors);
  EXPECT_EQ(reports(sc_core::SC_WARNING), warnings);
  ASSERT_EQ(c.outcomes.size(), 2u);
  EXPECT_EQ(c.outcomes[0].end_request, SC_ZERO_TIME);
  EXPECT_EQ(in_hop.counts().completed_at_end_req, 1u);
  EXPECT_EQ(in_hop.counts().responses, 1u);
  EXPECT_EQ(out_hop.counts().b_transport, 2u);  // the read still reached the bank
  // The second read is requested at 200 ns; the bus is free from 270 ns: END_REQ 270, 4 B 270 ns.
  EXPECT_EQ(c.outcomes[1].end_request, sc_time(270, SC_NS));
  EXPECT_EQ(c.outcomes[1].response, sc_time(540, SC_NS));
}

// A READ of 51 bytes with streaming width 4 at 0x23fd2 touches [0x23fd2, 0x23fd6), inside a window
// that ends at 0x24000: routed. The same burst 2 bytes before the end touches 2 bytes outside it,
// and the burst without streaming spans past the end: address errors. Behind a Router and a PciBus
// a streaming RAM answers OK (its bytes repeated); a SramBank, which does not stream, answers
// TLM_BURST_ERROR_RESPONSE, never an address error, directly and behind either interconnect.
TEST(StreamingWidth, BurstsAreDecodedByTheBytesTheyTouch) {
  Router router("router");
  PciBus bus("bus");
  AtTarget ram_r("ram_r", AtTarget::Style::completed, SC_ZERO_TIME, sc_time(10, SC_NS));
  AtTarget ram_p("ram_p", AtTarget::Style::completed, SC_ZERO_TIME, sc_time(10, SC_NS));
  SramBankConfig top = small_bank();
  top.capacity_bytes = 0x4000;  // a bank whose end is the window's
  SramBank bank_r("bank_r", top), bank_p("bank_p", top), bank("bank", top);
  for (AtTarget* ram : {&ram_r, &ram_p}) {
    ram->memory.resize(0x4000);
    for (std::size_t i = 0; i < ram->memory.size(); ++i) ram->memory[i] = static_cast<std::uint8_t>(i * 7);
  }
  router.out.bind(ram_r.in);
  router.out.bind(bank_r.in);
  bus.out.bind(ram_p.in);
  bus.out.bind(bank_p.in);
  router.map(0x20000, 0x4000, 0, "ram");
  router.map(0x30000, 0x4000, 1, "bank");
  bus.map(0x20000, 0x4000, 0, "ram");
  bus.map(0x30000, 0x4000, 1, "bank");
  struct Case { std::uint64_t offset; unsigned width; };  // into a 0x4000-byte window
  const std::array<Case, 3> cases{Case{0x3fd2, 4}, Case{0x3ffe, 4}, Case{0x3fd2, 51}};
  using Statuses = std::vector<tlm::tlm_response_status>;
  Statuses via_router, via_bus, direct;
  std::array<std::uint8_t, 51> back{};
  std::vector<std::uint8_t> ram_bytes;
  auto request = [&](std::uint64_t address, unsigned width) {
    Request r = read_request(address, back.data(), 51);
    r.streaming_width = width;
    return r;
  };
  auto through = [&](LtInitiator& self, Statuses& got) {
    for (const Case& k : cases) {
      got.push_back(self.transport(request(0x20000 + k.offset, k.width)).status);
      if (got.size() == 1) ram_bytes.assign(back.begin(), back.end());
      got.push_back(self.transport(request(0x30000 + k.offset, k.width)).status);
    }
  };
  LtInitiator r_cpu("r_cpu", [&](LtInitiator& self) { through(self, via_router); });
  LtInitiator p_cpu("p_cpu", [&](LtInitiator& self) { through(self, via_bus); });
  LtInitiator d_cpu("d_cpu", [&](LtInitiator& self) {
    for (const Case& k : cases) direct.push_back(self.transport(request(k.offset, k.width)).status);
  });
  HopChecker r_hop("r_hop"), p_hop("p_hop"), d_hop("d_hop");
  r_cpu.out.bind(r_hop.in);
  r_hop.out.bind(router.in);
  p_cpu.out.bind(p_hop.in);
  p_hop.out.bind(bus.in);
  d_cpu.out.bind(d_hop.in);
  d_hop.out.bind(bank.in);
  sc_core::sc_start();

  expect_clean({&r_hop, &p_hop, &d_hop});
  const Statuses expected{tlm::TLM_OK_RESPONSE,            tlm::TLM_BURST_ERROR_RESPONSE,
                          tlm::TLM_ADDRESS_ERROR_RESPONSE, tlm::TLM_ADDRESS_ERROR_RESPONSE,
                          tlm::TLM_ADDRESS_ERROR_RESPONSE, tlm::TLM_ADDRESS_ERROR_RESPONSE};
  EXPECT_EQ(via_router, expected);
  EXPECT_EQ(via_bus, expected);
  EXPECT_EQ(direct, (Statuses{tlm::TLM_BURST_ERROR_RESPONSE, tlm::TLM_ADDRESS_ERROR_RESPONSE,
                              tlm::TLM_ADDRESS_ERROR_RESPONSE}));
  ASSERT_EQ(ram_bytes.size(), 51u);
  for (std::size_t i = 0; i < 51; ++i) EXPECT_EQ(ram_bytes[i], static_cast<std::uint8_t>((0x3fd2 + i % 4) * 7)) << i;
  EXPECT_EQ(bank.report().address_errors, 2u);
  EXPECT_EQ(bank_r.report().rejected + bank_p.report().rejected + bank.report().rejected, 3u);
  EXPECT_EQ(router.report().address_errors, 4u);
  EXPECT_EQ(bus.report().total.address_errors, 4u);
}

}  // namespace
}  // namespace rc::tlmx::test
