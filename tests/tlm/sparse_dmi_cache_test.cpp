// SparseDmiCache: the page regions a sparse bank grants, collected through a router; words that
// straddle pages; invalidation that drops exactly the overlapping regions; refusals reported.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <tlm_utils/simple_initiator_socket.h>

#include "tests/tlm/tlm_test_support.h"
#include "tlm/router.h"
#include "tlm/sparse_dmi_cache.h"
#include "tlm/sram_bank.h"

namespace rc::tlmx::test {
namespace {

constexpr std::uint64_t kBase = 0x10'0000;  // where the router maps the bank

SramBankConfig paged_bank(std::uint64_t page_bytes) {
  SramBankConfig c;
  c.capacity_bytes = 4096;
  c.page_bytes = page_bytes;
  c.report_at_end = false;
  return c;
}

// An initiator that keeps its DMI regions in a SparseDmiCache and hands it invalidations from its
// socket, as the board's wrapper does; runs `script` in a thread.
class CachingInitiator : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<CachingInitiator> out;
  SparseDmiCache cache;
  std::function<void(CachingInitiator&)> script;
  bool finished = false;

  CachingInitiator(const sc_core::sc_module_name& name, std::function<void(CachingInitiator&)> body)
      : sc_core::sc_module(name),
        out("out"),
        cache(this->name(), [this](tlm::tlm_generic_payload& t, tlm::tlm_dmi& d) { return out->get_direct_mem_ptr(t, d); }),
        script(std::move(body)) {
    out.register_invalidate_direct_mem_ptr(this, &CachingInitiator::invalidate);
    SC_HAS_PROCESS(CachingInitiator);
    SC_THREAD(run);
  }

 private:
  void invalidate(sc_dt::uint64 start, sc_dt::uint64 end) { cache.invalidate(start, end); }
  void run() {
    script(*this);
    finished = true;
  }
};

// A caching initiator, a router and one 4 KiB bank at kBase.
struct Rig {
  Router router{"router", RouterConfig{sc_time(10, SC_NS), 0, false}};
  SramBank bank;
  CachingInitiator cpu;
  Rig(std::uint64_t page_bytes, std::function<void(CachingInitiator&)> script)
      : bank("bank", paged_bank(page_bytes)), cpu("cpu", std::move(script)) {
    cpu.out.bind(router.in);
    router.out.bind(bank.in);
    router.map(kBase, bank.capacity(), 0, "bank");
  }
};

// Sequential words in one page: one request; the regions are the bank's pages in the initiator's
// addresses.
TEST(SparseDmiCache, RegionsAreTheBanksPagesInTheInitiatorsAddresses) {
  std::uint32_t sum = 0;
  Rig r(64, [&](CachingInitiator& cpu) {
    for (std::uint64_t w = 0; w < 16; ++w) {  // page 0: bytes 0..63
      const auto v = static_cast<std::uint32_t>(w + 1);
      cpu.cache.write(kBase + 4 * w, &v, 4);
    }
    for (std::uint64_t w = 0; w < 16; ++w) {
      std::uint32_t v = 0;
      cpu.cache.read(kBase + 4 * w, &v, 4);
      sum += v;
    }
    std::uint32_t v = 0;
    cpu.cache.read(kBase + 64 * 10, &v, 4);  // page 10
  });
  sc_core::sc_start();

  ASSERT_TRUE(r.cpu.finished);
  EXPECT_EQ(sum, 136u);
  // One write request for page 0 (it grants read and write, so the reads need none), one read for page 10.
  EXPECT_EQ(r.cpu.cache.report().requests, 2u);
  ASSERT_EQ(r.cpu.cache.regions().size(), 2u);
  EXPECT_EQ(r.cpu.cache.regions()[0].start, kBase);
  EXPECT_EQ(r.cpu.cache.regions()[0].end, kBase + 63);
  EXPECT_EQ(r.cpu.cache.regions()[1].start, kBase + 640);
  EXPECT_EQ(r.cpu.cache.regions()[1].end, kBase + 703);
  EXPECT_EQ(r.bank.report().dmi_grants, 2u);
  EXPECT_EQ(r.bank.pages_allocated(), 2u);
  EXPECT_EQ(r.bank.debug_bytes(60, 4), (std::vector<std::uint8_t>{16, 0, 0, 0}));
}

// With 2-byte pages every 4-byte word lies across two regions, and an unaligned one across three.
TEST(SparseDmiCache, WordsStraddlingRegionsAreSplitBetweenThem) {
  std::uint32_t aligned = 0, unaligned = 0;
  std::uint64_t wide = 0;
  Rig r(2, [&](CachingInitiator& cpu) {
    const std::uint32_t a = 0xA1B2C3D4, b = 0x11223344;
    const std::uint64_t c = 0x0102030405060708;
    cpu.cache.write(kBase + 8, &a, 4);    // pages 4, 5
    cpu.cache.write(kBase + 13, &b, 4);   // pages 6, 7, 8
    cpu.cache.write(kBase + 100, &c, 8);  // pages 50..53
    cpu.cache.read(kBase + 8, &aligned, 4);
    cpu.cache.read(kBase + 13, &unaligned, 4);
    cpu.cache.read(kBase + 100, &wide, 8);
  });
  sc_core::sc_start();

  ASSERT_TRUE(r.cpu.finished);
  EXPECT_EQ(aligned, 0xA1B2C3D4u);
  EXPECT_EQ(unaligned, 0x11223344u);
  EXPECT_EQ(wide, 0x0102030405060708u);
  EXPECT_EQ(r.bank.debug_bytes(8, 4), (std::vector<std::uint8_t>{0xD4, 0xC3, 0xB2, 0xA1}));
  EXPECT_EQ(r.bank.debug_bytes(12, 6), (std::vector<std::uint8_t>{0, 0x44, 0x33, 0x22, 0x11, 0}));
  EXPECT_EQ(r.cpu.cache.regions().size(), 2u + 3u + 4u);
  EXPECT_EQ(r.cpu.cache.report().requests, 9u);  // one per page: the reads find them cached
  EXPECT_EQ(r.bank.pages_allocated(), 9u);
}

// [70, 130] overlaps pages 1 and 2 of 64 bytes and no other: those two are dropped, page 0 and
// page 3 stay, and the next access to page 1 asks again (and gets the same storage back).
TEST(SparseDmiCache, InvalidationDropsExactlyTheOverlappingRegions) {
  std::uint32_t after = 0;
  std::uint64_t requests_before = 0;
  Rig r(64, [&](CachingInitiator& cpu) {
    const std::uint32_t v = 77;
    for (std::uint64_t page = 0; page < 4; ++page) cpu.cache.write(kBase + 64 * page, &v, 4);
    r.bank.in->invalidate_direct_mem_ptr(70, 130);  // the bank's own addresses; the router translates
    requests_before = cpu.cache.report().requests;
    cpu.cache.read(kBase + 64, &after, 4);
  });
  sc_core::sc_start();

  ASSERT_TRUE(r.cpu.finished);
  EXPECT_EQ(requests_before, 4u);
  EXPECT_EQ(r.cpu.cache.report().invalidations, 1u);
  EXPECT_EQ(r.cpu.cache.report().dropped, 2u);
  EXPECT_EQ(r.cpu.cache.report().requests, 5u);  // page 1 again
  EXPECT_EQ(after, 77u);
  ASSERT_EQ(r.cpu.cache.regions().size(), 3u);  // pages 0, 1 (re-acquired) and 3
  EXPECT_EQ(r.cpu.cache.regions()[0].start, kBase);
  EXPECT_EQ(r.cpu.cache.regions()[1].start, kBase + 64);
  EXPECT_EQ(r.cpu.cache.regions()[2].start, kBase + 192);
}

// The cache calls the router only for addresses it maps; a request the bank refuses is an error
// that names the owner and the address.
TEST(SparseDmiCache, RefusedRequestIsAnError) {
  bool threw = false;
  std::string message;
  SramBank bank("bank", paged_bank(64));
  ScriptedInitiator cpu("cpu");
  SparseDmiCache cache("fpga", [&](tlm::tlm_generic_payload& t, tlm::tlm_dmi& d) { return cpu.out->get_direct_mem_ptr(t, d); });
  cpu.script = [&](ScriptedInitiator&) {
    std::uint32_t v = 0;
    try {
      cache.read(4096, &v, 4);  // one past the bank
    } catch (const sc_core::sc_report& e) {
      threw = true;
      message = e.what();
    }
  };
  cpu.out.bind(bank.in);
  sc_core::sc_report_handler::set_actions("rc/tlmx/SparseDmiCache", sc_core::SC_ERROR, sc_core::SC_THROW);
  sc_core::sc_start();

  EXPECT_TRUE(threw);
  EXPECT_NE(message.find("fpga: no DMI read access at 0x1000 (refused)"), std::string::npos) << message;
  EXPECT_EQ(bank.report().dmi_refusals, 1u);
  EXPECT_TRUE(cache.regions().empty());
}

}  // namespace
}  // namespace rc::tlmx::test
