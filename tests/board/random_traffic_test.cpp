// Fuzz-style random benches for the board's parts (tests/tlm/random_traffic.h), fixed seeds: the
// control registers alone (LT, then AT), and the whole Rc2000 driven through pci.in by two LT and
// two AT host initiators while its DMA engine moves data into every bank, with a HopChecker on every
// inner hop (InnerHops). Answers and bytes are checked against the oracle's shadow; afterwards the
// banks hold exactly the shadow's bytes in the initiators' regions and the DMA's data in its own.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "board/control_regs.h"
#include "tests/board/board_test_support.h"
#include "tests/tlm/hop_checker.h"
#include "tests/tlm/random_traffic.h"

namespace rc::board::test {
namespace {

using namespace rc::tlmx::test;
using Violations = std::vector<std::string>;
constexpr unsigned kTransactions = 3200;

tlmx::test::HopCheckerConfig tolerant() {
  tlmx::test::HopCheckerConfig c;
  c.malformed_requests_expected = true;
  return c;
}

Space regs_space(std::uint64_t base) {
  Space s;
  s.windows.push_back(ShadowWindow{base, reg::kBarSize, TargetKind::regs, std::vector<std::uint8_t>(reg::kBarSize, 0)});
  s.regs_size = reg::kSize;  // kRayCount .. kMaskStart (0x10 .. 0x30) are plain registers
  for (unsigned i = 0; i < 4; ++i) s.windows[0].bytes[reg::kSourceFace + i] = 0xFF;  // reset value: kNoFace
  return s;
}

void expect_spread(const StatusCounts& s) {
  EXPECT_GT(s.at(tlm::TLM_OK_RESPONSE), 100u);
  EXPECT_GT(s.at(tlm::TLM_ADDRESS_ERROR_RESPONSE), 100u);
  EXPECT_GT(s.at(tlm::TLM_BURST_ERROR_RESPONSE), 10u);
  EXPECT_GT(s.at(tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE), 10u);
}

template <class Initiator, class Script>
void regs_bench(Script script, unsigned seed) {
  sc_core::sc_report_handler::set_actions(sc_core::SC_WARNING, sc_core::SC_DO_NOTHING);
  Space space = regs_space(0);
  space.routed = false;
  TrafficOracle oracle(space, {Region{0x10, 0x20}}, seed);
  std::vector<std::string> errors;
  ControlRegs regs("regs", sc_time(20, SC_NS), 0x1234);
  Initiator host("host", script(oracle, kTransactions, errors));
  host.out.bind(regs.in);
  sc_core::sc_start();
  EXPECT_TRUE(host.finished());
  EXPECT_EQ(errors, Violations{});
  EXPECT_EQ(host.violations(), Violations{});
  expect_spread(oracle.statuses());
}

TEST(BoardFuzz, ControlRegsLooselyTimed) { regs_bench<LtInitiator>(lt_traffic, 11); }
TEST(BoardFuzz, ControlRegsApproximatelyTimed) { regs_bench<AtInitiator>(at_traffic, 12); }

// Host traffic through pci.in to the registers (BAR0) and the six banks (BAR1, windows of the bank
// capacity on a 16 MiB stride: the gaps are unmapped), while the DMA engine writes 64 KiB into the
// upper half of every bank. Initiator k owns bytes [k * 2 KiB, (k + 1) * 2 KiB) of each bank and
// registers 0x10 + 8k .. 0x17 + 8k.
TEST(BoardFuzz, Rc2000ThroughPciWithDmaRunning) {
  sc_core::sc_report_handler::set_actions(sc_core::SC_WARNING, sc_core::SC_DO_NOTHING);
  BoardParams p = round_params(4);
  p.report_at_end = false;
  HopChecker regs_hop("regs_hop", tolerant()), local_hop("local_hop", tolerant()), wrapper_hop("wrapper_hop", tolerant());
  std::vector<std::unique_ptr<HopChecker>> bank_hops;
  InnerHops hops{&regs_hop, &local_hop, &wrapper_hop, {}};
  for (unsigned b = 0; b < p.banks; ++b) {
    bank_hops.push_back(std::make_unique<HopChecker>(("bank" + std::to_string(b) + "_hop").c_str(), tolerant()));
    hops.local_to_bank.push_back(bank_hops.back().get());
  }
  Rc2000 board("board", p, tlmx::SramBankConfig{}.page_bytes, hops);
  Space space = regs_space(Rc2000::kBar0);
  for (unsigned b = 0; b < p.banks; ++b) {
    space.windows.push_back(ShadowWindow{board.bank_pci_address(b), p.bank_capacity_bytes, TargetKind::bank,
                                         std::vector<std::uint8_t>(p.bank_capacity_bytes, 0)});
  }
  std::vector<std::unique_ptr<TrafficOracle>> oracles;
  for (unsigned k = 0; k < 4; ++k) {
    std::vector<Region> owned{Region{Rc2000::kBar0 + 0x10 + 8 * k, 8}};
    for (unsigned b = 0; b < p.banks; ++b) owned.push_back(Region{board.bank_pci_address(b) + k * 0x800, 0x800});
    oracles.push_back(std::make_unique<TrafficOracle>(space, owned, 20 + k));
  }
  std::vector<std::string> errors;
  constexpr unsigned kEach = kTransactions / 4;
  LtInitiator lt0("lt0", lt_traffic(*oracles[0], kEach, errors)), lt1("lt1", lt_traffic(*oracles[1], kEach, errors));
  AtInitiator at0("at0", at_traffic(*oracles[2], kEach, errors)), at1("at1", at_traffic(*oracles[3], kEach, errors));
  for (LtInitiator* i : {&lt0, &lt1}) i->out.bind(board.pci.in);
  for (AtInitiator* i : {&at0, &at1}) i->out.bind(board.pci.in);
  std::vector<std::uint8_t> dma_data(64 * 1024);
  for (std::size_t i = 0; i < dma_data.size(); ++i) dma_data[i] = static_cast<std::uint8_t>(i * 13 + 5);
  const std::uint64_t dma_offset = p.bank_capacity_bytes / 2;
  LtInitiator starter("starter", [&](LtInitiator&) {
    for (unsigned b = 0; b < p.banks; ++b)
      board.dma.start(tlmx::DmaRequest{tlmx::DmaDirection::to_device, dma_data.data(), board.bank_pci_address(b) + dma_offset,
                                       dma_data.size(), false});
  });
  tlmx::SramBank spare("spare");  // the starter's socket needs a target; it sends nothing
  starter.out.bind(spare.in);
  sc_core::sc_start();

  EXPECT_EQ(errors, Violations{});
  for (const LtInitiator* i : {&lt0, &lt1}) {
    EXPECT_TRUE(i->finished());
    EXPECT_EQ(i->violations(), Violations{}) << i->name();
  }
  for (const AtInitiator* i : {&at0, &at1}) {
    EXPECT_TRUE(i->finished());
    EXPECT_EQ(i->violations(), Violations{}) << i->name();
    EXPECT_EQ(i->payloads_in_use(), 0u);
  }
  std::vector<const HopChecker*> checkers{&regs_hop, &local_hop, &wrapper_hop};
  for (const auto& h : bank_hops) checkers.push_back(h.get());
  for (const HopChecker* h : checkers) {
    EXPECT_EQ(h->violations(), Violations{}) << h->name();
    EXPECT_EQ(h->unfinished(), Violations{}) << h->name();
  }
  EXPECT_TRUE(board.dma.idle());
  EXPECT_EQ(board.dma.report().bytes_to_device, p.banks * dma_data.size());
  for (unsigned b = 0; b < p.banks; ++b) {
    EXPECT_EQ(board.bank(b).debug_bytes(dma_offset, dma_data.size()), dma_data) << "bank " << b;
    const std::vector<std::uint8_t>& shadow = space.windows[1 + b].bytes;
    EXPECT_EQ(board.bank(b).debug_bytes(0, 4 * 0x800), std::vector<std::uint8_t>(shadow.begin(), shadow.begin() + 4 * 0x800))
        << "bank " << b;
  }
  StatusCounts all;
  for (const auto& o : oracles)
    for (const auto& [status, n] : o->statuses()) all[status] += n;
  expect_spread(all);
  EXPECT_GT(local_hop.counts().b_transport, 1000u);
}

}  // namespace
}  // namespace rc::board::test
