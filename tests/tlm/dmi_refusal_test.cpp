// DMI answers through the interconnects: the PciBus refuses over the whole address space; the
// Router translates a target's refusal or grant back to the initiator's addresses, clipped to the
// window, refuses an unmapped address over the gap around it, and translates invalidations per
// window that maps the target.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "tests/tlm/tlm_test_support.h"
#include "tlm/address_map.h"
#include "tlm/pci_bus.h"
#include "tlm/router.h"

namespace rc::tlmx::test {
namespace {

constexpr std::uint64_t kTop = ~std::uint64_t{0};

// A target with its own answer to get_direct_mem_ptr: a grant over [0, size) of its array, or a
// refusal over [first, last] that (as the convenience socket's default does) leaves read/write
// access set; and, at 10 ns, an invalidation of [inv_first, inv_last] if asked for.
class DmiTarget : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<DmiTarget> in;
  std::array<unsigned char, 0x2000> storage{};
  bool grant = true;
  std::uint64_t first = 0, last = 0;
  std::vector<std::uint64_t> asked;  // addresses of the requests, as the target saw them
  std::optional<std::pair<std::uint64_t, std::uint64_t>> invalidate;

  explicit DmiTarget(const sc_core::sc_module_name& name) : sc_core::sc_module(name), in("in") {
    in.register_b_transport(this, &DmiTarget::b_transport);
    in.register_get_direct_mem_ptr(this, &DmiTarget::get_direct_mem_ptr);
    SC_HAS_PROCESS(DmiTarget);
    SC_THREAD(revoke);
  }

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_time&) { trans.set_response_status(tlm::TLM_OK_RESPONSE); }
  bool get_direct_mem_ptr(tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi) {
    asked.push_back(trans.get_address());
    dmi.allow_read_write();
    if (!grant) {
      dmi.set_start_address(first);
      dmi.set_end_address(last);
      return false;
    }
    dmi.set_dmi_ptr(storage.data());
    dmi.set_start_address(0);
    dmi.set_end_address(storage.size() - 1);
    return true;
  }
  void revoke() {
    if (!invalidate) return;
    wait(sc_time(10, SC_NS));
    in->invalidate_direct_mem_ptr(invalidate->first, invalidate->second);
  }
};

// Asks for DMI at each address from its thread, and records the invalidations it receives.
class DmiAsker : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<DmiAsker> out;
  std::vector<std::uint64_t> addresses;
  std::vector<bool> granted;
  std::vector<tlm::tlm_dmi> answers;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> invalidated;

  explicit DmiAsker(const sc_core::sc_module_name& name) : sc_core::sc_module(name), out("out") {
    out.register_invalidate_direct_mem_ptr(this, &DmiAsker::invalidate);
    SC_HAS_PROCESS(DmiAsker);
    SC_THREAD(run);
  }

 private:
  void run() {
    for (std::uint64_t a : addresses) {
      tlm::tlm_generic_payload trans;
      trans.set_command(tlm::TLM_READ_COMMAND);
      trans.set_address(a);
      tlm::tlm_dmi dmi;
      granted.push_back(out->get_direct_mem_ptr(trans, dmi));
      answers.push_back(dmi);
      EXPECT_EQ(trans.get_address(), a);  // the initiator's address comes back
    }
  }
  void invalidate(sc_dt::uint64 start, sc_dt::uint64 end) { invalidated.emplace_back(start, end); }
};

TEST(AddressMap, GapIsTheUnmappedRangeAroundAnAddress) {
  AddressMap map;
  map.add({0x1'0000, 0x1000, 0, "a"});
  map.add({0x2'0000, 0x1000, 1, "b"});
  EXPECT_FALSE(map.gap(0x1'0800).has_value());
  const auto between = map.gap(0x1'8000);
  ASSERT_TRUE(between.has_value());
  EXPECT_EQ(between->first, 0x1'1000u);
  EXPECT_EQ(between->last, 0x1'FFFFu);
  EXPECT_EQ(map.gap(0x100)->first, 0u);
  EXPECT_EQ(map.gap(0x100)->last, 0xFFFFu);
  EXPECT_EQ(map.gap(0x3'0000)->first, 0x2'1000u);
  EXPECT_EQ(map.gap(0x3'0000)->last, kTop);
  EXPECT_EQ(AddressMap{}.gap(42)->last, kTop);
}

// The bus refuses at a mapped address as anywhere: no access, over the whole address space.
TEST(DmiRefusal, PciBusRefusesOverTheWholeAddressSpace) {
  PciBus bus("bus");
  DmiTarget target("target");  // would grant, but not through PCI
  DmiAsker host("host");
  host.addresses = {0x8000'0010, 0x10};
  host.out.bind(bus.in);
  bus.out.bind(target.in);
  bus.map(0x8000'0000, 0x2000, 0, "target");
  sc_core::sc_start();

  ASSERT_EQ(host.answers.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_FALSE(host.granted[i]);
    EXPECT_TRUE(host.answers[i].is_none_allowed());
    EXPECT_EQ(host.answers[i].get_dmi_ptr(), nullptr);
    EXPECT_EQ(host.answers[i].get_start_address(), 0u);
    EXPECT_EQ(host.answers[i].get_end_address(), kTop);
  }
  EXPECT_TRUE(target.asked.empty());
}

// Router windows: `refuses` at 0x1'0000 (refusal over its [0x100, 0x2FF]); `sloppy` at 0x2'0000,
// size 0x1000, refusing over [0, 2^64 - 1] with read/write left set; `grants` at 0x4'0000 with a
// window (0x1000) smaller than its 0x2000-byte array. And two unmapped addresses.
TEST(DmiRefusal, RouterTranslatesAndClipsTargetsAnswersAndRefusesGaps) {
  Router router("router");
  DmiTarget refuses("refuses"), sloppy("sloppy"), grants("grants");
  refuses.grant = false;
  refuses.first = 0x100;
  refuses.last = 0x2FF;
  sloppy.grant = false;
  sloppy.first = 0;
  sloppy.last = kTop;
  DmiAsker fpga("fpga");
  fpga.addresses = {0x1'0150, 0x2'0FFF, 0x4'0800, 0x3'0000, 0x50'0000};
  fpga.out.bind(router.in);
  router.out.bind(refuses.in);
  router.out.bind(sloppy.in);
  router.out.bind(grants.in);
  router.map(0x1'0000, 0x1000, 0, "refuses");
  router.map(0x2'0000, 0x1000, 1, "sloppy");
  router.map(0x4'0000, 0x1000, 2, "grants");
  sc_core::sc_start();

  ASSERT_EQ(fpga.answers.size(), 5u);
  EXPECT_EQ(refuses.asked, (std::vector<std::uint64_t>{0x150}));
  EXPECT_FALSE(fpga.granted[0]);
  EXPECT_TRUE(fpga.answers[0].is_none_allowed());
  EXPECT_EQ(fpga.answers[0].get_start_address(), 0x1'0100u);
  EXPECT_EQ(fpga.answers[0].get_end_address(), 0x1'02FFu);

  EXPECT_FALSE(fpga.granted[1]);
  EXPECT_TRUE(fpga.answers[1].is_none_allowed());  // no access, whatever the target left set
  EXPECT_EQ(fpga.answers[1].get_start_address(), 0x2'0000u);
  EXPECT_EQ(fpga.answers[1].get_end_address(), 0x2'0FFFu);  // clipped to the window

  EXPECT_TRUE(fpga.granted[2]);
  EXPECT_TRUE(fpga.answers[2].is_read_write_allowed());
  EXPECT_EQ(fpga.answers[2].get_dmi_ptr(), grants.storage.data());  // addresses the start byte
  EXPECT_EQ(fpga.answers[2].get_start_address(), 0x4'0000u);
  EXPECT_EQ(fpga.answers[2].get_end_address(), 0x4'0FFFu);

  EXPECT_FALSE(fpga.granted[3]);  // between "sloppy" and "grants"
  EXPECT_TRUE(fpga.answers[3].is_none_allowed());
  EXPECT_EQ(fpga.answers[3].get_start_address(), 0x2'1000u);
  EXPECT_EQ(fpga.answers[3].get_end_address(), 0x3'FFFFu);
  EXPECT_FALSE(fpga.granted[4]);  // above every window
  EXPECT_EQ(fpga.answers[4].get_start_address(), 0x4'1000u);
  EXPECT_EQ(fpga.answers[4].get_end_address(), kTop);
}

// One target behind two windows (at 0x1000, 0x100 bytes, and at 0x4000, 0x200 bytes) revokes
// [0x80, 0x17F]: each window forwards its part, translated and clipped; a window the range misses
// (the third, 0x80 bytes at 0x8000) forwards nothing. Every initiator is told.
TEST(DmiRefusal, RouterInvalidatesPerWindowClipped) {
  Router router("router");
  DmiTarget target("target");
  target.invalidate = std::make_pair(std::uint64_t{0x80}, std::uint64_t{0x17F});
  DmiTarget other("other");
  DmiAsker a("a"), b("b");
  a.out.bind(router.in);
  b.out.bind(router.in);
  router.out.bind(target.in);
  router.out.bind(other.in);
  router.map(0x1000, 0x100, 0, "low alias");
  router.map(0x4000, 0x200, 0, "high alias");
  router.map(0x8000, 0x80, 0, "short alias");
  router.map(0x9000, 0x1000, 1, "other");
  sc_core::sc_start();

  const std::vector<std::pair<std::uint64_t, std::uint64_t>> expected{{0x1080, 0x10FF}, {0x4080, 0x417F}};
  EXPECT_EQ(a.invalidated, expected);
  EXPECT_EQ(b.invalidated, expected);
}

}  // namespace
}  // namespace rc::tlmx::test
