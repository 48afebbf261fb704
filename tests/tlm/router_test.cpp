// Router and AddressMap: decoding by window, relative addresses, latency, DMI translation.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "tests/tlm/tlm_test_support.h"
#include "tlm/address_map.h"
#include "tlm/router.h"
#include "tlm/sram_bank.h"

namespace rc::tlmx::test {
namespace {

TEST(AddressMap, DecodesWithinWindowsAndRejectsOverlapsAndStraddles) {
  AddressMap map;
  map.add({0x1000, 0x1000, 0, "a"});
  map.add({0x2000, 0x100, 1, "b"});
  EXPECT_THROW(map.add({0x1F00, 0x200, 2, "overlaps a and b"}), std::invalid_argument);
  EXPECT_THROW(map.add({0x3000, 0, 2, "empty"}), std::invalid_argument);
  EXPECT_THROW(map.add({~std::uint64_t{0}, 2, 2, "wraps"}), std::invalid_argument);

  const auto hit = map.decode(0x2010, 0x10);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->window->port, 1u);
  EXPECT_EQ(hit->offset, 0x10u);
  EXPECT_TRUE(map.decode(0x1FFC, 4).has_value());   // last word of a
  EXPECT_FALSE(map.decode(0x1FFC, 8).has_value());  // straddles a and b
  EXPECT_FALSE(map.decode(0x0FFF, 1).has_value());
  EXPECT_FALSE(map.decode(0x2100, 1).has_value());
}

SramBankConfig small_bank() {
  SramBankConfig config;
  config.capacity_bytes = 0x1000;
  return config;
}

TEST(Router, RoutesWithRelativeAddressesAndLatency) {
  RouterConfig config;
  config.latency_cycles = 3;  // at 10 ns
  Router router("router", config);
  SramBank regs("regs", small_bank());
  SramBank bank("bank", small_bank());
  sc_time delay, error_delay;
  tlm::tlm_response_status status{}, error{};
  std::uint64_t address_after = 0;
  ScriptedInitiator bridge("bridge", [&](ScriptedInitiator& self) {
    std::uint32_t value = 0xA5A5A5A5;
    status = self.write(0x10'0010, &value, 4, delay);
    address_after = self.last_address_seen;
    error = self.write(0x20'0000, &value, 4, error_delay);
  });
  bridge.out.bind(router.in);
  router.out.bind(regs.in);
  router.out.bind(bank.in);
  router.map(0x00'0000, regs.capacity(), 0, "regs");
  router.map(0x10'0000, bank.capacity(), 1, "bank");
  sc_core::sc_start();

  EXPECT_EQ(status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(address_after, 0x10'0010u);
  EXPECT_EQ(bank.debug_bytes(0x10, 1)[0], 0xA5);
  EXPECT_EQ(regs.report().writes, 0u);
  EXPECT_EQ(delay, sc_time(30 + 30, SC_NS));  // router 3 cycles + bank (2 + 1) * 10 ns
  EXPECT_EQ(error, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(error_delay, SC_ZERO_TIME);
  EXPECT_EQ(router.report().transactions, 1u);
  EXPECT_EQ(router.report().address_errors, 1u);
}

TEST(Router, DmiIsTranslatedToTheInitiatorsView) {
  Router router("router");
  SramBank bank0("bank0", small_bank());
  SramBank bank1("bank1", small_bank());
  tlm::tlm_dmi dmi;
  bool granted = false;
  ScriptedInitiator fpga("fpga", [&](ScriptedInitiator& self) {
    tlm::tlm_generic_payload trans;
    trans.set_command(tlm::TLM_READ_COMMAND);
    trans.set_address(0x40'0800);
    granted = self.out->get_direct_mem_ptr(trans, dmi);
  });
  fpga.out.bind(router.in);
  router.out.bind(bank0.in);
  router.out.bind(bank1.in);
  router.map(0x00'0000, bank0.capacity(), 0);
  router.map(0x40'0000, bank1.capacity(), 1);
  sc_core::sc_start();

  ASSERT_TRUE(granted);
  EXPECT_EQ(dmi.get_dmi_ptr(), bank1.storage().find_page(0));  // the bank's one page
  EXPECT_EQ(dmi.get_start_address(), 0x40'0000u);
  EXPECT_EQ(dmi.get_end_address(), 0x40'0FFFu);
  EXPECT_EQ(bank1.report().dmi_grants, 1u);
}

// A target that revokes all DMI it may have granted, at 10 ns.
class RevokingTarget : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<RevokingTarget> in;
  explicit RevokingTarget(const sc_core::sc_module_name& name) : sc_core::sc_module(name), in("in") {
    in.register_b_transport(this, &RevokingTarget::b_transport);
    SC_HAS_PROCESS(RevokingTarget);
    SC_THREAD(revoke);
  }

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_time&) { trans.set_response_status(tlm::TLM_OK_RESPONSE); }
  void revoke() {
    wait(sc_time(10, SC_NS));
    in->invalidate_direct_mem_ptr(0, ~sc_dt::uint64{0});
  }
};

// Records the invalidations it receives.
class DmiUser : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<DmiUser> out;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> invalidated;
  explicit DmiUser(const sc_core::sc_module_name& name) : sc_core::sc_module(name), out("out") {
    out.register_invalidate_direct_mem_ptr(this, &DmiUser::invalidate);
  }

 private:
  void invalidate(sc_dt::uint64 start, sc_dt::uint64 end) { invalidated.emplace_back(start, end); }
};

TEST(Router, InvalidationIsTranslatedAndClippedToTheWindow) {
  Router router("router");
  SramBank bank("bank", small_bank());
  RevokingTarget target("target");
  DmiUser user("user");
  user.out.bind(router.in);
  router.out.bind(bank.in);
  router.out.bind(target.in);
  router.map(0x0000, 0x1000, 0, "bank");
  router.map(0x8000, 0x2000, 1, "target");
  sc_core::sc_start();

  ASSERT_EQ(user.invalidated.size(), 1u);
  EXPECT_EQ(user.invalidated[0].first, 0x8000u);
  EXPECT_EQ(user.invalidated[0].second, 0x9FFFu);
}

}  // namespace
}  // namespace rc::tlmx::test
