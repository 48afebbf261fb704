// Fuzz-style random benches (random_traffic.h), fixed seeds, a few thousand transactions per part:
// two LT and two AT checking initiators drive a SramBank, a PciBus, a Router and two nested Routers,
// with a HopChecker on every hop behind them; every answer and every byte read is checked against
// the oracle's shadow, every checker stays clean, and the traffic covers every answer.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tests/tlm/hop_checker.h"
#include "tests/tlm/random_traffic.h"
#include "tests/tlm/tlm_test_support.h"
#include "tlm/pci_bus.h"
#include "tlm/router.h"
#include "tlm/sram_bank.h"

namespace rc::tlmx::test {
namespace {

using Violations = std::vector<std::string>;
constexpr unsigned kPerInitiator = 800;  // four initiators: 3200 transactions per part
constexpr std::uint64_t kWindow = 0x4000;
constexpr std::uint64_t kOwned = 0x800;  // initiator k owns [k * kOwned, (k + 1) * kOwned) of each window

HopCheckerConfig target_side() {
  HopCheckerConfig c;
  c.malformed_requests_expected = true;  // byte-enable length 0 passes the interconnects to the targets
  return c;
}

SramBankConfig bank_config() {
  SramBankConfig c;
  c.capacity_bytes = kWindow;
  c.page_bytes = 0x1000;
  return c;
}

// Four checking initiators with their oracles over one Space, and the checkers behind the part.
struct Bench {
  Space space;
  std::vector<std::unique_ptr<TrafficOracle>> oracles;
  std::vector<std::string> errors;
  std::unique_ptr<LtInitiator> lt0, lt1;
  std::unique_ptr<AtInitiator> at0, at1;
  std::vector<std::unique_ptr<HopChecker>> hops;

  // lt_only / at_only: one initiator of that kind (a target socket that takes one binding).
  enum class Initiators { four, lt_only, at_only };
  Bench(std::vector<ShadowWindow> windows, bool routed, unsigned seed, Initiators kinds = Initiators::four) {
    sc_core::sc_report_handler::set_actions(sc_core::SC_WARNING, sc_core::SC_DO_NOTHING);  // an address error warns
    space.windows = std::move(windows);
    space.routed = routed;
    for (ShadowWindow& w : space.windows) w.bytes.assign(w.size, 0);
    for (unsigned k = 0; k < 4; ++k) {
      std::vector<Region> owned;
      for (const ShadowWindow& w : space.windows) owned.push_back({w.base + k * kOwned, kOwned});
      oracles.push_back(std::make_unique<TrafficOracle>(space, owned, seed * 10 + k));
    }
    const unsigned alone = 4 * kPerInitiator;
    if (kinds != Initiators::at_only)
      lt0 = std::make_unique<LtInitiator>("lt0", lt_traffic(*oracles[0], kinds == Initiators::four ? kPerInitiator : alone, errors));
    if (kinds != Initiators::lt_only)
      at0 = std::make_unique<AtInitiator>("at0", at_traffic(*oracles[2], kinds == Initiators::four ? kPerInitiator : alone, errors));
    if (kinds != Initiators::four) return;
    lt1 = std::make_unique<LtInitiator>("lt1", lt_traffic(*oracles[1], kPerInitiator, errors));
    at1 = std::make_unique<AtInitiator>("at1", at_traffic(*oracles[3], kPerInitiator, errors));
  }
  template <class Socket>
  void bind_initiators(Socket& socket) {
    for (LtInitiator* i : {lt0.get(), lt1.get()})
      if (i != nullptr) i->out.bind(socket);
    for (AtInitiator* i : {at0.get(), at1.get()})
      if (i != nullptr) i->out.bind(socket);
  }
  // A checker between an interconnect's `out` and a target.
  template <class From, class To>
  void checked(From& from, To& to) {
    hops.push_back(std::make_unique<HopChecker>(("hop" + std::to_string(hops.size())).c_str(), target_side()));
    from.bind(hops.back()->in);
    hops.back()->out.bind(to);
  }

  void run_and_check() {
    sc_core::sc_start();
    EXPECT_EQ(errors, Violations{});
    for (const LtInitiator* i : {lt0.get(), lt1.get()}) {
      if (i == nullptr) continue;
      EXPECT_TRUE(i->finished()) << i->name();
      EXPECT_EQ(i->violations(), Violations{}) << i->name();
    }
    for (const AtInitiator* i : {at0.get(), at1.get()}) {
      if (i == nullptr) continue;
      EXPECT_TRUE(i->finished()) << i->name();
      EXPECT_EQ(i->violations(), Violations{}) << i->name();
      EXPECT_EQ(i->payloads_in_use(), 0u) << i->name();
    }
    for (const auto& h : hops) {
      EXPECT_EQ(h->violations(), Violations{}) << h->name();
      EXPECT_EQ(h->unfinished(), Violations{}) << h->name();
    }
    StatusCounts all;
    for (const auto& o : oracles)
      for (const auto& [status, n] : o->statuses()) all[status] += n;
    EXPECT_GT(all[tlm::TLM_OK_RESPONSE], 1000u);
    EXPECT_GT(all[tlm::TLM_ADDRESS_ERROR_RESPONSE], 100u);
    EXPECT_GT(all[tlm::TLM_BURST_ERROR_RESPONSE], 10u);
    EXPECT_GT(all[tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE], 10u);
  }
};

ShadowWindow window(std::uint64_t base, TargetKind kind) { return ShadowWindow{base, kWindow, kind, {}}; }

// A bank's socket takes one initiator: 3200 transactions from an LT one, then from an AT one.
TEST(TlmFuzz, SramBankLooselyTimed) {
  Bench bench({window(0, TargetKind::bank)}, false, 1, Bench::Initiators::lt_only);
  SramBank bank("bank", bank_config());
  bench.bind_initiators(bank.in);
  bench.run_and_check();
}

TEST(TlmFuzz, SramBankApproximatelyTimed) {
  Bench bench({window(0, TargetKind::bank)}, false, 5, Bench::Initiators::at_only);
  SramBank bank("bank", bank_config());
  bench.bind_initiators(bank.in);
  bench.run_and_check();
}

// A bank and an AT-only RAM (served through its socket's b-to-nb adapter, so it waits inside
// b_transport), with a gap between their windows.
TEST(TlmFuzz, PciBus) {
  Bench bench({window(0x1000'0000, TargetKind::bank), window(0x1001'0000, TargetKind::ram)}, true, 2);
  PciBus bus("bus");
  SramBank bank("bank", bank_config());
  AtTarget ram("ram", AtTarget::Style::accepted, sc_time(5, SC_NS), sc_time(45, SC_NS));
  ram.memory.assign(kWindow, 0);
  bench.bind_initiators(bus.in);
  bench.checked(bus.out, bank.in);
  bench.checked(bus.out, ram.in);
  bus.map(0x1000'0000, kWindow, 0, "bank");
  bus.map(0x1001'0000, kWindow, 1, "ram");
  bench.run_and_check();
  EXPECT_TRUE(ram.idle());
}

// Two banks and a RAM of every AT answering style behind one Router.
TEST(TlmFuzz, Router) {
  std::vector<ShadowWindow> windows{window(0, TargetKind::bank), window(0x8000, TargetKind::bank)};
  for (unsigned i = 0; i < 4; ++i) windows.push_back(window(0x20000 + i * 0x8000, TargetKind::ram));
  Bench bench(windows, true, 3);
  Router router("router", RouterConfig{sc_time(10, SC_NS), 1});
  SramBank bank0("bank0", bank_config()), bank1("bank1", bank_config());
  using S = AtTarget::Style;
  AtTarget ram0("ram0", S::accepted, sc_time(3, SC_NS), sc_time(20, SC_NS));
  AtTarget ram1("ram1", S::end_req, sc_time(2, SC_NS), sc_time(15, SC_NS));
  AtTarget ram2("ram2", S::begin_resp, SC_ZERO_TIME, sc_time(12, SC_NS));
  AtTarget ram3("ram3", S::completed, SC_ZERO_TIME, sc_time(7, SC_NS));
  bench.bind_initiators(router.in);
  bench.checked(router.out, bank0.in);
  bench.checked(router.out, bank1.in);
  unsigned port = 2;
  for (AtTarget* ram : {&ram0, &ram1, &ram2, &ram3}) {
    ram->memory.assign(kWindow, 0);
    bench.checked(router.out, ram->in);
    router.map(0x20000 + (port - 2) * 0x8000, kWindow, port, ram->name());
    ++port;
  }
  router.map(0, kWindow, 0, "bank0");
  router.map(0x8000, kWindow, 1, "bank1");
  bench.run_and_check();
  for (AtTarget* ram : {&ram0, &ram1, &ram2, &ram3}) EXPECT_TRUE(ram->idle()) << ram->name();
}

// An outer Router whose upper window is an inner Router holding a bank and an AT RAM.
TEST(TlmFuzz, NestedRouters) {
  Bench bench({window(0, TargetKind::bank), window(0x10000, TargetKind::bank), window(0x18000, TargetKind::ram)}, true, 4);
  Router outer("outer", RouterConfig{sc_time(10, SC_NS), 1}), inner("inner", RouterConfig{sc_time(5, SC_NS), 2});
  SramBank near("near", bank_config()), far("far", bank_config());
  AtTarget ram("ram", AtTarget::Style::accepted, sc_time(4, SC_NS), sc_time(30, SC_NS));
  ram.memory.assign(kWindow, 0);
  bench.bind_initiators(outer.in);
  bench.checked(outer.out, near.in);
  bench.checked(outer.out, inner.in);
  bench.checked(inner.out, far.in);
  bench.checked(inner.out, ram.in);
  outer.map(0, kWindow, 0, "near");
  outer.map(0x10000, 0x10000, 1, "inner");
  inner.map(0, kWindow, 0, "far");
  inner.map(0x8000, kWindow, 1, "ram");
  bench.run_and_check();
  EXPECT_TRUE(ram.idle());
}

}  // namespace
}  // namespace rc::tlmx::test
