// Approximately-timed transport through the interconnects: the PciBus times an AT transaction
// exactly as a b_transport of the same payload at the same request time, keeps the response
// exclusion rule per initiator port and the arrival order between AT and LT requests; the Router
// forwards phase by phase with its latency, routes the backward path to the right initiator and
// keeps both exclusion rules when initiators or targets compete. Times are worked out by hand
// from pci_bus.h and router.h.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tests/tlm/protocol_checker.h"
#include "tests/tlm/tlm_test_support.h"
#include "tlm/pci_bus.h"
#include "tlm/router.h"
#include "tlm/sram_bank.h"

namespace rc::tlmx::test {
namespace {

using Violations = std::vector<std::string>;
constexpr std::uint64_t kBar = 0x8000'0000;

SramBankConfig fast_bank() {
  SramBankConfig config;
  config.capacity_bytes = 64 * 1024;
  config.clock_period = sc_time(1, SC_NS);  // the bus dominates every transfer
  return config;
}

// The delay that puts a request at absolute time t, from the caller's present.
sc_time until(sc_time t) { return t - sc_core::sc_time_stamp(); }

// The same requests at the same request times, b_transport on one bus and nb_transport on an
// identical other: 4096 B at 100 ns (bus free: 1032 cycles, [100, 31060] ns); 8 B requested at
// 200 ns, which waits for the first (30 860 ns) and takes 10 cycles ([31060, 31360]); a master
// abort at 40 us (6 cycles); a TLM_IGNORE_COMMAND at 50 us (8 setup cycles, no data). AT: END_REQ
// at each start, BEGIN_RESP at each end, the LT completion times; the buses' counters are equal.
TEST(AtTransport, PciBusTimesAtExactlyAsLt) {
  struct Rig {
    PciBus bus;
    SramBank bank;
    Rig(const std::string& name) : bus((name + "_bus").c_str()), bank((name + "_bank").c_str(), fast_bank()) {
      bus.out.bind(bank.in);
      bus.map(kBar, bank.capacity(), 0, "bank");
    }
  };
  Rig lt_rig("lt"), at_rig("at");
  static std::array<std::uint8_t, 4096> block{}, lt_back{}, at_back{};
  auto requests = [](std::array<std::uint8_t, 4096>& back) {
    std::vector<Request> r;
    r.push_back(write_request(kBar, block.data(), 4096, sc_time(100, SC_NS)));
    r.push_back(read_request(kBar + 0x40, back.data(), 8, sc_time(200, SC_NS)));
    r.push_back(read_request(0x9000'0000, back.data(), 4, sc_time(40, SC_US)));
    Request ignore = read_request(kBar, back.data(), 4, sc_time(50, SC_US));
    ignore.command = tlm::TLM_IGNORE_COMMAND;
    r.push_back(ignore);
    return r;  // delays hold absolute request times; each initiator turns them into offsets
  };
  std::vector<Outcome> lt, at;
  LtInitiator lt_host("lt_host", [&](LtInitiator& self) {
    for (Request r : requests(lt_back)) {
      r.delay = until(r.delay);
      lt.push_back(self.transport(r));
    }
  });
  AtInitiator at_host("at_host", [&](AtInitiator& self) {
    std::vector<AtInitiator::Ticket> tickets;
    for (Request r : requests(at_back)) {
      r.delay = until(r.delay);
      tickets.push_back(self.issue(r));
    }
    for (AtInitiator::Ticket t : tickets) at.push_back(self.finish(t));
  });
  lt_host.out.bind(lt_rig.bus.in);
  at_host.out.bind(at_rig.bus.in);
  sc_core::sc_start();

  EXPECT_EQ(lt_host.violations(), Violations{});
  EXPECT_EQ(at_host.violations(), Violations{});
  EXPECT_EQ(at_host.payloads_in_use(), 0u);
  ASSERT_EQ(lt.size(), 4u);
  ASSERT_EQ(at.size(), 4u);
  const std::array<sc_time, 4> starts{sc_time(100, SC_NS), sc_time(31060, SC_NS), sc_time(40, SC_US), sc_time(50, SC_US)};
  const std::array<sc_time, 4> ends{sc_time(31060, SC_NS), sc_time(31360, SC_NS), sc_time(40180, SC_NS),
                                    sc_time(50240, SC_NS)};
  for (std::size_t i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(at[i].request, lt[i].request);
    EXPECT_EQ(at[i].end_request, starts[i]);
    EXPECT_EQ(lt[i].response, ends[i]);
    EXPECT_EQ(at[i].response, ends[i]);
    EXPECT_EQ(at[i].end_response, ends[i]);
    EXPECT_EQ(at[i].status, lt[i].status);
  }
  EXPECT_EQ(lt[2].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(lt[3].status, tlm::TLM_OK_RESPONSE);
  const PciBusReport l = lt_rig.bus.report(), a = at_rig.bus.report();
  EXPECT_EQ(a.total.transactions, l.total.transactions);
  EXPECT_EQ(a.total.bytes_written, l.total.bytes_written);
  EXPECT_EQ(a.total.bytes_read, l.total.bytes_read);
  EXPECT_EQ(a.total.busy, l.total.busy);
  EXPECT_EQ(a.total.wait, l.total.wait);
  EXPECT_EQ(a.total.address_errors, l.total.address_errors);
  EXPECT_EQ(a.bus_free_at, l.bus_free_at);
  EXPECT_EQ(a.total.wait, sc_time(30860, SC_NS));
  EXPECT_EQ(a.total.bytes_read, 8u);
  EXPECT_EQ(at_back, lt_back);
}

// Response exclusion on one `in` port: A (4 B at 0: [0, 270] ns) is held by the initiator for
// 1 us after its BEGIN_RESP; B (4 B requested at 0, after A's END_REQ: [270, 540]) is due at
// 540 ns but gets its BEGIN_RESP only at A's END_RESP, 1270 ns.
TEST(AtTransport, PciBusHoldsAResponseUntilThePreviousEndResp) {
  PciBus bus("bus");
  SramBank bank("bank", fast_bank());
  std::array<std::uint8_t, 4> a_data{1, 2, 3, 4}, b_data{5, 6, 7, 8};
  Outcome a, b;
  AtInitiator host("host", [&](AtInitiator& self) {
    const AtInitiator::Ticket first = self.issue(write_request(kBar, a_data.data(), 4), EndResponse::accepted,
                                                 sc_time(1, SC_US));
    const AtInitiator::Ticket second = self.issue(write_request(kBar + 4, b_data.data(), 4, until(SC_ZERO_TIME)));
    a = self.finish(first);
    b = self.finish(second);
  });
  host.out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(kBar, bank.capacity(), 0, "bank");
  sc_core::sc_start();

  EXPECT_EQ(host.violations(), Violations{});
  EXPECT_EQ(host.payloads_in_use(), 0u);
  EXPECT_EQ(a.end_request, SC_ZERO_TIME);
  EXPECT_EQ(a.response, sc_time(270, SC_NS));
  EXPECT_EQ(a.end_response, sc_time(1270, SC_NS));
  EXPECT_EQ(b.request, SC_ZERO_TIME);
  EXPECT_EQ(b.end_request, sc_time(270, SC_NS));
  EXPECT_EQ(b.response, sc_time(1270, SC_NS));
  EXPECT_EQ(b.status, tlm::TLM_OK_RESPONSE);
  const PciBusReport r = bus.report();
  EXPECT_EQ(r.total.wait, sc_time(270, SC_NS));
  EXPECT_EQ(r.total.busy, sc_time(540, SC_NS));
  EXPECT_EQ(r.bus_free_at, sc_time(540, SC_NS));
}

// An initiator with two sockets on the bus sends a BEGIN_REQ (4096 B) and, in the same evaluation
// phase before the bus's thread has run, a b_transport (4 B): the AT request arrived first, so it
// takes the bus first ([0, 30960] ns) and the b_transport waits behind it ([30960, 31230]).
class TwoSocketHost : public sc_core::sc_module {
 public:
  tlm::tlm_initiator_socket<> at_out, lt_out;
  sc_time lt_done, end_req, begin_resp;

  explicit TwoSocketHost(const sc_core::sc_module_name& name)
      : sc_core::sc_module(name), at_out("at_out"), lt_out("lt_out"), m_at_bw(*this) {
    at_out.bind(m_at_bw);
    lt_out.bind(m_lt_bw);
    SC_HAS_PROCESS(TwoSocketHost);
    SC_THREAD(run);
  }

 private:
  // The AT socket's backward path records when END_REQ and BEGIN_RESP take effect.
  struct AtBackward : tlm::tlm_bw_transport_if<> {
    TwoSocketHost& host;
    explicit AtBackward(TwoSocketHost& h) : host(h) {}
    tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload&, tlm::tlm_phase& phase, sc_time& delay) override {
      if (phase == tlm::END_REQ) host.end_req = sc_core::sc_time_stamp() + delay;
      if (phase != tlm::BEGIN_RESP) return tlm::TLM_ACCEPTED;
      host.begin_resp = sc_core::sc_time_stamp() + delay;
      return tlm::TLM_COMPLETED;
    }
    void invalidate_direct_mem_ptr(sc_dt::uint64, sc_dt::uint64) override {}
  };
  // The LT socket needs a backward path to bind; nothing comes on it.
  struct LtBackward : tlm::tlm_bw_transport_if<> {
    tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload&, tlm::tlm_phase&, sc_time&) override {
      return tlm::TLM_COMPLETED;
    }
    void invalidate_direct_mem_ptr(sc_dt::uint64, sc_dt::uint64) override {}
  };

  void run() {
    static std::array<std::uint8_t, 4096> block{};
    PayloadPool pool;
    tlm::tlm_generic_payload* at = pool.take();
    fill(*at, write_request(kBar, block.data(), 4096));
    tlm::tlm_phase phase = tlm::BEGIN_REQ;
    sc_time delay = SC_ZERO_TIME;
    at_out->nb_transport_fw(*at, phase, delay);
    tlm::tlm_generic_payload lt;
    fill(lt, write_request(kBar + 0x2000, block.data(), 4));
    sc_time lt_delay = SC_ZERO_TIME;
    lt_out->b_transport(lt, lt_delay);
    lt_done = sc_core::sc_time_stamp() + lt_delay;
    sc_core::wait(sc_time(40, SC_US));
    at->release();
  }

  AtBackward m_at_bw;
  LtBackward m_lt_bw;
};

TEST(AtTransport, PciBusCarriesAnAtRequestBeforeALaterBTransport) {
  PciBus bus("bus");
  SramBank bank("bank", fast_bank());
  TwoSocketHost host("host");
  host.at_out.bind(bus.in);
  host.lt_out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(kBar, bank.capacity(), 0, "bank");
  sc_core::sc_start();

  EXPECT_EQ(host.end_req, SC_ZERO_TIME);
  EXPECT_EQ(host.begin_resp, sc_time(30960, SC_NS));
  EXPECT_EQ(host.lt_done, sc_time(31230, SC_NS));
  EXPECT_EQ(bus.report().initiators.at(1).wait, sc_time(30960, SC_NS));
}

// Two AT initiators, one AT target behind the router (latency 0; the target: TLM_ACCEPTED, END_REQ
// after 10 ns, BEGIN_RESP after 50 ns). A requests at 0: END_REQ 10, BEGIN_RESP 50. B requests at
// 5 ns while A's request phase is open: the router holds it (TLM_ACCEPTED) and sends it at 10 ns,
// A's END_REQ: END_REQ 20, BEGIN_RESP 60. Each initiator gets its own phases at its own address.
TEST(AtTransport, RouterSerialisesRequestsToOneTarget) {
  Router router("router");
  AtTarget target("target", AtTarget::Style::accepted, sc_time(10, SC_NS), sc_time(50, SC_NS));
  std::array<std::uint8_t, 4> a_back{}, b_back{};
  Outcome a, b;
  AtInitiator first("first", [&](AtInitiator& self) { a = self.transport(read_request(0x8010, a_back.data(), 4)); });
  AtInitiator second("second", [&](AtInitiator& self) {
    b = self.transport(read_request(0x8020, b_back.data(), 4, sc_time(5, SC_NS)));
  });
  first.out.bind(router.in);
  second.out.bind(router.in);
  router.out.bind(target.in);
  router.map(0x8000, 0x2000, 0, "target");
  sc_core::sc_start();

  EXPECT_EQ(first.violations(), Violations{});
  EXPECT_EQ(second.violations(), Violations{});
  EXPECT_EQ(target.violations, Violations{});
  EXPECT_EQ(a.end_request, sc_time(10, SC_NS));
  EXPECT_EQ(a.response, sc_time(50, SC_NS));
  EXPECT_EQ(b.request, sc_time(5, SC_NS));
  EXPECT_EQ(b.end_request, sc_time(20, SC_NS));
  EXPECT_EQ(b.response, sc_time(60, SC_NS));
  EXPECT_EQ(target.request_times, (std::vector<sc_time>{SC_ZERO_TIME, sc_time(10, SC_NS)}));
  EXPECT_EQ(target.addresses, (std::vector<std::uint64_t>{0x10, 0x20}));
  EXPECT_EQ(a_back, (std::array<std::uint8_t, 4>{0x5A, 0x5A, 0x5A, 0x5A}));
  EXPECT_EQ(b_back, a_back);
}

// One AT initiator, two targets: A to `slow` (END_REQ after 10 ns, BEGIN_RESP after 20 ns),
// answered TLM_ACCEPTED and held by the initiator for 100 ns (END_RESP at 120). B goes to `quick`
// at 25 ns, which answers TLM_COMPLETED 20 ns later (45 ns) while A's response is still open: the
// router answers B with TLM_UPDATED / END_REQ at 45 ns and delivers B's BEGIN_RESP at 120 ns.
TEST(AtTransport, RouterHoldsAResponseFromACompletingTarget) {
  RouterConfig config;
  Router router("router", config);
  AtTarget slow("slow", AtTarget::Style::accepted, sc_time(10, SC_NS), sc_time(20, SC_NS));
  AtTarget quick("quick", AtTarget::Style::completed, SC_ZERO_TIME, sc_time(20, SC_NS));
  std::array<std::uint8_t, 4> a_back{}, b_back{};
  Outcome a, b;
  AtInitiator host("host", [&](AtInitiator& self) {
    const AtInitiator::Ticket ta = self.issue(read_request(0x1000, a_back.data(), 4), EndResponse::accepted,
                                              sc_time(100, SC_NS));
    sc_core::wait(sc_time(15, SC_NS));  // A's response (20 ns) is in and held
    const AtInitiator::Ticket tb = self.issue(read_request(0x2000, b_back.data(), 4));
    a = self.finish(ta);
    b = self.finish(tb);
  });
  host.out.bind(router.in);
  router.out.bind(slow.in);
  router.out.bind(quick.in);
  router.map(0x1000, 0x1000, 0, "slow");
  router.map(0x2000, 0x1000, 1, "quick");
  sc_core::sc_start();

  EXPECT_EQ(host.violations(), Violations{});
  EXPECT_EQ(host.payloads_in_use(), 0u);
  EXPECT_EQ(a.end_request, sc_time(10, SC_NS));
  EXPECT_EQ(a.response, sc_time(20, SC_NS));
  EXPECT_EQ(a.end_response, sc_time(120, SC_NS));
  EXPECT_EQ(b.request, sc_time(25, SC_NS));
  EXPECT_EQ(b.end_request, sc_time(45, SC_NS));
  EXPECT_EQ(b.response, sc_time(120, SC_NS));
  EXPECT_EQ(b.status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(quick.addresses, (std::vector<std::uint64_t>{0}));
}

// As above, but `quick` answers on the backward path (TLM_ACCEPTED, END_REQ after 5 ns, BEGIN_RESP
// after 25 ns): END_REQ reaches the initiator at 30 ns; the BEGIN_RESP (50 ns) is held, the target
// answered TLM_ACCEPTED, and it gets END_RESP when the initiator completes B at 120 ns. A third
// request to `quick` then goes through as usual.
TEST(AtTransport, RouterHoldsAResponseFromABackwardPathTarget) {
  Router router("router");
  AtTarget slow("slow", AtTarget::Style::accepted, sc_time(10, SC_NS), sc_time(20, SC_NS));
  AtTarget quick("quick", AtTarget::Style::accepted, sc_time(5, SC_NS), sc_time(25, SC_NS));
  std::array<std::uint8_t, 4> a_back{}, b_back{};
  Outcome a, b, c;
  AtInitiator host("host", [&](AtInitiator& self) {
    const AtInitiator::Ticket ta = self.issue(read_request(0x1000, a_back.data(), 4), EndResponse::accepted,
                                              sc_time(100, SC_NS));
    sc_core::wait(sc_time(15, SC_NS));
    const AtInitiator::Ticket tb = self.issue(read_request(0x2000, b_back.data(), 4));
    a = self.finish(ta);
    b = self.finish(tb);
    c = self.transport(read_request(0x2004, b_back.data(), 4));  // `quick` takes requests again
  });
  host.out.bind(router.in);
  router.out.bind(slow.in);
  router.out.bind(quick.in);
  router.map(0x1000, 0x1000, 0, "slow");
  router.map(0x2000, 0x1000, 1, "quick");
  sc_core::sc_start();

  EXPECT_EQ(host.violations(), Violations{});
  EXPECT_EQ(quick.violations, Violations{});
  EXPECT_EQ(host.payloads_in_use(), 0u);
  EXPECT_EQ(a.end_response, sc_time(120, SC_NS));
  EXPECT_EQ(b.end_request, sc_time(30, SC_NS));
  EXPECT_EQ(b.response, sc_time(120, SC_NS));
  EXPECT_EQ(c.request, sc_time(120, SC_NS));
  EXPECT_EQ(c.end_request, sc_time(125, SC_NS));
  EXPECT_EQ(c.response, sc_time(145, SC_NS));
  EXPECT_EQ(quick.addresses, (std::vector<std::uint64_t>{0, 4}));
}

// Targets that answer with TLM_UPDATED: END_REQ by return (then BEGIN_RESP on the backward path),
// and BEGIN_RESP by return (then END_RESP from the initiator on the forward path), through a
// router with 2 cycles of 10 ns.
TEST(AtTransport, RouterPassesUpdatedAnswersThrough) {
  RouterConfig config;
  config.latency_cycles = 2;
  Router router("router", config);
  AtTarget end_req("end_req", AtTarget::Style::end_req, sc_time(3, SC_NS), sc_time(9, SC_NS));
  AtTarget begin_resp("begin_resp", AtTarget::Style::begin_resp, SC_ZERO_TIME, sc_time(11, SC_NS));
  std::array<std::uint8_t, 4> back{};
  Outcome a, b;
  AtInitiator host("host", [&](AtInitiator& self) {
    a = self.transport(read_request(0x100, back.data(), 4));
    b = self.transport(read_request(0x200, back.data(), 4), EndResponse::accepted, sc_time(4, SC_NS));
  });
  host.out.bind(router.in);
  router.out.bind(end_req.in);
  router.out.bind(begin_resp.in);
  router.map(0x100, 0x100, 0, "end_req");
  router.map(0x200, 0x100, 1, "begin_resp");
  sc_core::sc_start();

  EXPECT_EQ(host.violations(), Violations{});
  EXPECT_EQ(host.payloads_in_use(), 0u);
  EXPECT_EQ(a.end_request, sc_time(23, SC_NS));  // 20 ns router + 3
  EXPECT_EQ(a.response, sc_time(29, SC_NS));
  EXPECT_EQ(b.request, sc_time(29, SC_NS));
  EXPECT_FALSE(b.end_request.has_value());
  EXPECT_EQ(b.response, sc_time(29 + 20 + 11, SC_NS));
  EXPECT_EQ(b.end_response, sc_time(64, SC_NS));
  EXPECT_EQ(end_req.addresses, (std::vector<std::uint64_t>{0}));
  EXPECT_EQ(begin_resp.addresses, (std::vector<std::uint64_t>{0}));
}

}  // namespace
}  // namespace rc::tlmx::test
