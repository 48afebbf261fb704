// Whole board passes with a base-protocol checker (tests/tlm/hop_checker.h) on every inner hop of the
// Rc2000 (InnerHops, board/rc2000.h): pci.out to the registers and to the local bus, the wrapper to
// the local bus, the local bus to each bank. The host DMAs a pass's faces, own-face table and rays
// into the banks through PCI, writes the parameters, STARTs, waits for the interrupt, acknowledges
// it and DMAs the results back; twice, for both wrapper models. Every checker stays clean, every hop
// carried traffic, and the results are the CPU's.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/board/board_test_support.h"
#include "tests/tlm/hop_checker.h"

namespace rc::board::test {
namespace {

using tlmx::test::HopChecker;
using Violations = std::vector<std::string>;

struct CheckedBoard {
  HopChecker regs{"regs_hop"}, pci_local{"pci_local_hop"}, wrapper_local{"wrapper_local_hop"};
  std::vector<std::unique_ptr<HopChecker>> banks;
  std::unique_ptr<Rc2000> board;

  explicit CheckedBoard(const BoardParams& p) {
    InnerHops hops{&regs, &pci_local, &wrapper_local, {}};
    for (unsigned b = 0; b < p.banks; ++b) {
      banks.push_back(std::make_unique<HopChecker>(("bank" + std::to_string(b) + "_hop").c_str()));
      hops.local_to_bank.push_back(banks.back().get());
    }
    board = std::make_unique<Rc2000>("board", p, tlmx::SramBankConfig{}.page_bytes, hops);
  }
  std::vector<const HopChecker*> all() const {
    std::vector<const HopChecker*> v{&regs, &pci_local, &wrapper_local};
    for (const auto& b : banks) v.push_back(b.get());
    return v;
  }
};

// The bank images of a pass, as load_pass lays them out, for the DMA engine to carry.
std::vector<std::vector<std::uint8_t>> bank_images(const Rc2000& b, const PassData& d, RaySplit& split) {
  const BankLayout& L = b.layout();
  const unsigned wb = L.word_bits / 8;
  std::vector<std::vector<std::uint8_t>> images(b.params().banks);
  auto put = [&](unsigned bank, std::uint64_t word, std::uint64_t value) {
    std::vector<std::uint8_t>& image = images[bank];
    if (image.size() < (word + 1) * wb) image.resize((word + 1) * wb);
    store_word(image.data(), word, wb, value);
  };
  std::uint64_t words[9];
  for (std::size_t f = 0; f < d.faces.size(); ++f) {
    face_record_words(d.faces[f], words);
    for (unsigned i = 0; i < 9; ++i) put(L.face_bank, f * 9 + i, words[i]);
  }
  const unsigned mask_bank = L.mask_bank ? *L.mask_bank : L.face_bank;
  const std::uint64_t mask_first = L.mask_bank ? 0 : d.faces.size() * 9;
  for (std::size_t f = 0; f < d.faces.size(); ++f) {
    std::uint64_t n = 0;
    for (int e : d.end_faces) n += e == static_cast<int>(f);
    put(mask_bank, mask_first + f, n);
  }
  std::vector<std::int64_t> x, y, z;
  for (const auto& e : d.ends) x.push_back(e.x), y.push_back(e.y), z.push_back(e.z);
  split = split_rays(L, d.ends.size());
  std::vector<std::vector<std::uint8_t>> rays;
  pack_rays(L, split, x.data(), y.data(), z.data(), rays);
  for (unsigned bank = 0; bank < rays.size(); ++bank) {
    if (rays[bank].empty()) continue;
    if (!images[bank].empty()) throw std::logic_error("a ray bank holds faces too: the test's layout assumption broke");
    images[bank] = rays[bank];
  }
  return images;
}

// One pass through PCI only: DMA in, registers, START, interrupt, acknowledge, DMA out.
std::vector<std::uint8_t> dma_pass(ScriptedHost& host, const PassData& d) {
  Rc2000& b = host.board();
  RaySplit split;
  std::vector<std::vector<std::uint8_t>> images = bank_images(b, d, split);
  for (unsigned bank = 0; bank < images.size(); ++bank) {
    if (images[bank].empty()) continue;
    const tlmx::DmaResult r = b.dma.transfer(tlmx::DmaDirection::to_device, images[bank].data(),
                                             b.bank_pci_address(bank), images[bank].size());
    EXPECT_TRUE(r.ok()) << "DMA to bank " << bank;
  }
  std::uint32_t before = 0;
  for (int e : d.end_faces) before += e < 0 ? 1 : 0;
  host.write(reg::kRayCount, {static_cast<std::uint32_t>(d.ends.size()), static_cast<std::uint32_t>(d.faces.size()), 0,
                              reg::kNoFace, static_cast<std::uint32_t>(d.start.x), static_cast<std::uint32_t>(d.start.y),
                              static_cast<std::uint32_t>(d.start.z), before});
  host.write(reg::kControl, {reg::kStart | reg::kClear});
  b.irq.wait_raised();
  EXPECT_EQ(host.read(reg::kStatus) & (reg::kDone | reg::kError), reg::kDone);
  host.write(reg::kStatus, {reg::kDone});
  const unsigned wb = b.layout().word_bits / 8;
  std::vector<std::uint8_t> words(split.result_words * wb);
  const tlmx::DmaResult r = b.dma.transfer(tlmx::DmaDirection::to_host, words.data(),
                                           b.bank_pci_address(b.layout().result_bank), words.size());
  EXPECT_TRUE(r.ok()) << "DMA of the results";
  std::vector<std::uint8_t> blocked(d.ends.size(), 0);
  unpack_results(b.layout(), split, words.data(), blocked.data());
  return blocked;
}

void run_checked_passes(WrapperModel model) {
  BoardParams p = round_params(4, 15, 6, model);
  p.report_at_end = false;
  CheckedBoard checked(p);
  const PassData first = crossing_pass(300, p.bits, 3, 1), second = crossing_pass(257, p.bits, 2, 2);
  std::vector<std::uint8_t> got_first, got_second;
  ScriptedHost host("host", *checked.board, [&](ScriptedHost& h) {
    got_first = dma_pass(h, first);
    got_second = dma_pass(h, second);
  });
  run_until_finished({&host});

  EXPECT_EQ(got_first, expected_blocked(first, p.bits));
  EXPECT_EQ(got_second, expected_blocked(second, p.bits));
  for (const HopChecker* h : checked.all()) {
    EXPECT_EQ(h->violations(), Violations{}) << h->name();
    EXPECT_EQ(h->unfinished(), Violations{}) << h->name();
  }
  EXPECT_GE(checked.regs.counts().b_transport, 8u);  // two passes: parameters, START, STATUS read, acknowledge
  EXPECT_GT(checked.pci_local.counts().b_transport, 0u);  // the DMA bursts
  EXPECT_GT(checked.wrapper_local.counts().dmi_requests, 0u);
  const BankLayout& L = checked.board->layout();
  EXPECT_GT(checked.banks[L.face_bank]->counts().b_transport, 0u);
  EXPECT_GT(checked.banks[L.result_bank]->counts().b_transport, 0u);
  EXPECT_GT(checked.banks[L.result_bank]->counts().dmi_requests, 0u);
  EXPECT_EQ(checked.board->regs.value(reg::kPasses), 2u);
}

TEST(Rc2000InnerHops, FastWrapperPassesAreCleanOnEveryHop) { run_checked_passes(WrapperModel::fast); }
TEST(Rc2000InnerHops, CycleWrapperPassesAreCleanOnEveryHop) { run_checked_passes(WrapperModel::cycle); }

// Interposers the board cannot place are refused at construction, naming the option.
TEST(Rc2000InnerHops, RefusesAWrongBankCountOrAnInterposerNamedTwice) {
  const BoardParams p = round_params(4);
  HopChecker a("a"), b("b");
  EXPECT_THROW(Rc2000("two_banks", p, tlmx::SramBankConfig{}.page_bytes, InnerHops{nullptr, nullptr, nullptr, {&a, &b}}),
               std::invalid_argument);
  EXPECT_THROW(Rc2000("twice", p, tlmx::SramBankConfig{}.page_bytes, InnerHops{&a, &a, nullptr, {}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace rc::board::test
