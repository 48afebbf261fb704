// SramBank: data round trip, exact annotated delay, sparse storage, DMI per page and its accounting,
// refusals, byte enables, error responses.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "tests/tlm/tlm_test_support.h"
#include "tlm/sram_bank.h"

namespace rc::tlmx::test {
namespace {

// Default bank: 10 ns clock, read and write latency 2 cycles, 4-byte words, 1 cycle per word.
TEST(SramBank, WriteReadRoundTripWithExactDelay) {
  SramBank bank("bank");
  std::array<std::uint8_t, 16> written{};
  std::iota(written.begin(), written.end(), 1);
  std::array<std::uint8_t, 16> readback{};
  sc_time write_delay, read_delay, unaligned_delay;
  tlm::tlm_response_status write_status{}, read_status{}, unaligned_status{};
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    write_status = self.write(0x100, written.data(), 16, write_delay);
    read_status = self.read(0x100, readback.data(), 16, read_delay);
    std::uint32_t word = 0;
    unaligned_status = self.read(0x102, &word, 4, unaligned_delay);  // touches two words
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  ASSERT_TRUE(cpu.finished);
  EXPECT_EQ(write_status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(read_status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(unaligned_status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(readback, written);
  EXPECT_EQ(bank.debug_bytes(0x100, 1)[0], 1);
  EXPECT_EQ(write_delay, sc_time(60, SC_NS));      // (2 + 16/4) * 10 ns
  EXPECT_EQ(read_delay, sc_time(60, SC_NS));       // (2 + 4) * 10 ns
  EXPECT_EQ(unaligned_delay, sc_time(40, SC_NS));  // (2 + 2 words) * 10 ns
  const SramBankReport r = bank.report();
  EXPECT_EQ(r.reads, 2u);
  EXPECT_EQ(r.writes, 1u);
  EXPECT_EQ(r.bytes_read, 20u);
  EXPECT_EQ(r.bytes_written, 16u);
  EXPECT_EQ(r.busy, sc_time(160, SC_NS));
  EXPECT_EQ(r.address_errors, 0u);
}

// Every parameter enters the formula: delay = (L + words * C) * P.
TEST(SramBank, DelayFollowsConfiguredParameters) {
  SramBankConfig config;
  config.capacity_bytes = 1024;
  config.word_bytes = 8;
  config.clock_period = sc_time(7, SC_NS);
  config.read_latency_cycles = 3;
  config.write_latency_cycles = 1;
  config.cycles_per_word = 2;
  SramBank bank("bank", config);
  std::array<std::uint8_t, 20> buffer{};
  sc_time write_delay, read_delay;
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    self.write(0, buffer.data(), 20, write_delay);
    self.read(0, buffer.data(), 20, read_delay);
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  EXPECT_EQ(write_delay, sc_time(49, SC_NS));  // (1 + 3 words * 2) * 7 ns
  EXPECT_EQ(read_delay, sc_time(63, SC_NS));   // (3 + 3 * 2) * 7 ns
  EXPECT_EQ(bank.access_time(tlm::TLM_READ_COMMAND, 0, 20), sc_time(63, SC_NS));
}

// The grant is the 64 KiB page holding the address: pointer to its first byte, [0x10000, 0x1FFFF],
// and the latency of one word's access, (L + C) * P = (2 + 1) * 10 ns.
TEST(SramBank, DmiGrantsThePageHoldingTheAddressAndCountsReportedAccesses) {
  SramBank bank("bank");
  tlm::tlm_dmi dmi;
  bool granted = false;
  std::uint32_t seen = 0;
  ScriptedInitiator fpga("fpga", [&](ScriptedInitiator& self) {
    tlm::tlm_generic_payload trans;
    trans.set_address(0x1'2344);
    trans.set_command(tlm::TLM_READ_COMMAND);
    granted = self.out->get_direct_mem_ptr(trans, dmi);
    const std::uint32_t value = 0xCAFEF00D;
    std::memcpy(dmi.get_dmi_ptr() + 0x2344, &value, 4);  // stream through the pointer...
    bank.record_dmi_access(DmiActivity{0, 1, 0, 4, sc_time(10, SC_NS)});  // ...and account for it
    sc_time delay;
    self.read(0x1'2344, &seen, 4, delay);  // transport sees what DMI wrote
  });
  fpga.out.bind(bank.in);
  sc_core::sc_start();

  ASSERT_TRUE(granted);
  EXPECT_EQ(dmi.get_dmi_ptr(), bank.storage().find_page(0x1'0000));
  EXPECT_EQ(dmi.get_start_address(), 0x1'0000u);
  EXPECT_EQ(dmi.get_end_address(), 0x1'FFFFu);
  EXPECT_TRUE(dmi.is_read_write_allowed());
  EXPECT_EQ(dmi.get_read_latency(), sc_time(30, SC_NS));
  EXPECT_EQ(dmi.get_write_latency(), sc_time(30, SC_NS));
  EXPECT_EQ(seen, 0xCAFEF00Du);
  EXPECT_EQ(bank.pages_allocated(), 1u);  // the grant allocated the page
  const SramBankReport r = bank.report();
  EXPECT_EQ(r.dmi_grants, 1u);
  EXPECT_EQ(r.writes, 1u);
  EXPECT_EQ(r.dmi_writes, 1u);
  EXPECT_EQ(r.bytes_written, 4u);
  EXPECT_EQ(r.reads, 1u);
  EXPECT_EQ(r.dmi_reads, 0u);
  EXPECT_EQ(r.busy, sc_time(10 + 30, SC_NS));  // reported DMI busy + (2 + 1) * 10 ns read
}

// Per access, read and write apart: (3 + 2) * 7 ns and (1 + 2) * 7 ns, whatever the word width (the
// old per-byte rate would have been 2 * 7 / 8 ns). The last page is cut at the capacity.
TEST(SramBank, DmiLatencyIsOneAccessAndTheLastPageEndsAtTheCapacity) {
  SramBankConfig config;
  config.capacity_bytes = 100'000;
  config.word_bytes = 8;
  config.clock_period = sc_time(7, SC_NS);
  config.read_latency_cycles = 3;
  config.write_latency_cycles = 1;
  config.cycles_per_word = 2;
  config.page_bytes = 4096;
  SramBank bank("bank", config);
  tlm::tlm_dmi dmi;
  bool granted = false;
  ScriptedInitiator fpga("fpga", [&](ScriptedInitiator& self) {
    tlm::tlm_generic_payload trans;
    trans.set_address(99'999);
    trans.set_command(tlm::TLM_WRITE_COMMAND);
    granted = self.out->get_direct_mem_ptr(trans, dmi);
  });
  fpga.out.bind(bank.in);
  sc_core::sc_start();

  ASSERT_TRUE(granted);
  EXPECT_EQ(dmi.get_start_address(), 98'304u);  // 24 * 4096
  EXPECT_EQ(dmi.get_end_address(), 99'999u);
  EXPECT_EQ(dmi.get_read_latency(), sc_time(35, SC_NS));
  EXPECT_EQ(dmi.get_write_latency(), sc_time(21, SC_NS));
  EXPECT_EQ(bank.dmi_latency(tlm::TLM_READ_COMMAND), bank.access_time(tlm::TLM_READ_COMMAND, 0, 8));
}

// Outside the bank: refused, no access, no pointer, and the refusal holds from the capacity to the
// top of the address space (IEEE 1666-2011 11.2.8: the range must say where the answer applies).
TEST(SramBank, DmiOutsideTheBankIsRefusedOverTheRangeBeyondIt) {
  SramBankConfig config;
  config.capacity_bytes = 4096;
  SramBank bank("bank", config);
  std::vector<bool> granted;
  std::vector<tlm::tlm_dmi> answers;
  ScriptedInitiator fpga("fpga", [&](ScriptedInitiator& self) {
    for (std::uint64_t a : {std::uint64_t{4096}, ~std::uint64_t{0}}) {
      tlm::tlm_generic_payload trans;
      trans.set_address(a);
      trans.set_command(tlm::TLM_READ_COMMAND);
      tlm::tlm_dmi dmi;
      dmi.allow_read_write();  // whatever an interconnect left there, a refusal grants nothing
      granted.push_back(self.out->get_direct_mem_ptr(trans, dmi));
      answers.push_back(dmi);
    }
  });
  fpga.out.bind(bank.in);
  sc_core::sc_start();

  ASSERT_EQ(answers.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_FALSE(granted[i]);
    EXPECT_TRUE(answers[i].is_none_allowed());
    EXPECT_EQ(answers[i].get_dmi_ptr(), nullptr);
    EXPECT_EQ(answers[i].get_start_address(), 4096u);
    EXPECT_EQ(answers[i].get_end_address(), ~std::uint64_t{0});
  }
  EXPECT_EQ(bank.report().dmi_refusals, 2u);
  EXPECT_EQ(bank.report().dmi_grants, 0u);
  EXPECT_EQ(bank.pages_allocated(), 0u);
}

// Resident memory of this process, in bytes (/proc/self/statm: size, resident, ... in pages).
std::uint64_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

// A 2^40-byte bank (a terabyte) elaborates and works at its top address while the process grows by
// one page of storage, not by the capacity.
TEST(SramBank, TerabyteBankCostsOnlyThePagesTouched) {
  const std::uint64_t before = resident_bytes();
  SramBankConfig config;
  config.capacity_bytes = std::uint64_t{1} << 40;
  SramBank bank("bank", config);
  const std::uint64_t top = config.capacity_bytes - 8;
  std::uint64_t written = 0x0123'4567'89AB'CDEF, back = 0, untouched = 1;
  tlm::tlm_response_status write_status{}, read_status{};
  sc_time write_delay, read_delay;
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    write_status = self.write(top, &written, 8, write_delay);
    read_status = self.read(top, &back, 8, read_delay);
    sc_time delay;
    self.read(config.capacity_bytes / 2, &untouched, 8, delay);
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  EXPECT_EQ(write_status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(read_status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(back, written);
  EXPECT_EQ(untouched, 0u);
  EXPECT_EQ(write_delay, sc_time(40, SC_NS));  // (2 + 2 words) * 10 ns
  EXPECT_EQ(read_delay, sc_time(40, SC_NS));
  EXPECT_EQ(bank.pages_allocated(), 1u);
  EXPECT_LT(resident_bytes() - before, std::uint64_t{64} << 20);
}

// Reading memory nobody wrote gives zeros, through every path, and allocates nothing.
TEST(SramBank, UntouchedMemoryReadsZeroWithoutAllocating) {
  SramBank bank("bank");
  std::array<std::uint8_t, 256> transported, debugged;
  transported.fill(0xEE);
  debugged.fill(0xEE);
  tlm::tlm_response_status status{};
  unsigned int copied = 0;
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    sc_time delay;
    status = self.read(0xFFC0, transported.data(), 256, delay);  // across a page boundary
    tlm::tlm_generic_payload trans;
    trans.set_command(tlm::TLM_READ_COMMAND);
    trans.set_address(0x20'0000);
    trans.set_data_ptr(debugged.data());
    trans.set_data_length(256);
    copied = self.out->transport_dbg(trans);
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  EXPECT_EQ(status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(copied, 256u);
  for (std::size_t i = 0; i < 256; ++i) {
    ASSERT_EQ(transported[i], 0) << i;
    ASSERT_EQ(debugged[i], 0) << i;
  }
  EXPECT_EQ(bank.debug_bytes(0x3F'FF00, 256), std::vector<std::uint8_t>(256, 0));
  EXPECT_EQ(bank.pages_allocated(), 0u);
  EXPECT_THROW(bank.debug_bytes(0x3F'FF00, 257), std::out_of_range);
}

TEST(SramBank, OutOfRangeGivesAddressErrorAndIsCounted) {
  SramBankConfig config;
  config.capacity_bytes = 4096;
  SramBank bank("bank", config);
  tlm::tlm_response_status straddle{}, beyond{}, wrapping{};
  sc_time delay;
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    std::array<std::uint8_t, 32> buffer{};
    straddle = self.read(4094, buffer.data(), 4, delay);  // last two bytes exist, the rest do not
    beyond = self.write(4096, buffer.data(), 4, delay);
    wrapping = self.read(~std::uint64_t{0} - 7, buffer.data(), 32, delay);  // address + length wraps
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  EXPECT_EQ(straddle, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(beyond, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(wrapping, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  EXPECT_EQ(delay, SC_ZERO_TIME);
  EXPECT_EQ(bank.report().address_errors, 3u);
  EXPECT_EQ(bank.report().reads + bank.report().writes, 0u);
  EXPECT_EQ(sc_core::sc_report_handler::get_count(sc_core::SC_WARNING), 3);
}

// Byte i moves only when element i % byte_enable_length is 0xFF: a 2-element pattern over 8 bytes
// writes bytes 0, 2, 4, 6; a read with a 3-element pattern fills only bytes 1, 4 and 7 of its data
// array and leaves the others as they were. The timing is the access's, enables or not.
TEST(SramBank, ByteEnablesMoveOnlyTheEnabledBytesWithTheirPatternRepeated) {
  SramBank bank("bank");
  std::array<std::uint8_t, 8> ones{}, back{};
  ones.fill(0x11);
  back.fill(0xEE);
  unsigned char every_other[2] = {0xFF, 0x00};
  unsigned char one_in_three[3] = {0x00, 0xFF, 0x00};
  tlm::tlm_response_status write_status{}, read_status{};
  sc_time write_delay, read_delay;
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    std::array<std::uint8_t, 8> base;
    base.fill(0xAA);
    sc_time delay;
    self.write(0x100, base.data(), 8, delay);
    write_status = self.access(tlm::TLM_WRITE_COMMAND, 0x100, ones.data(), 8, write_delay, every_other, 2);
    read_status = self.access(tlm::TLM_READ_COMMAND, 0x100, back.data(), 8, read_delay, one_in_three, 3);
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  EXPECT_EQ(write_status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(read_status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(bank.debug_bytes(0x100, 8), (std::vector<std::uint8_t>{0x11, 0xAA, 0x11, 0xAA, 0x11, 0xAA, 0x11, 0xAA}));
  EXPECT_EQ(back, (std::array<std::uint8_t, 8>{0xEE, 0xAA, 0xEE, 0xEE, 0x11, 0xEE, 0xEE, 0xAA}));
  EXPECT_EQ(write_delay, sc_time(40, SC_NS));  // (2 + 2 words) * 10 ns
  EXPECT_EQ(read_delay, sc_time(40, SC_NS));
  EXPECT_EQ(bank.report().rejected, 0u);
}

// Byte enables across a page boundary (4-byte pages): the enabled bytes land on both pages; a
// masked read of a page nobody wrote gives zeros for its enabled bytes.
TEST(SramBank, ByteEnablesAcrossPagesAndOnUntouchedPages) {
  SramBankConfig config;
  config.page_bytes = 4;
  SramBank bank("bank", config);
  std::array<std::uint8_t, 6> data{1, 2, 3, 4, 5, 6}, fresh{};
  fresh.fill(0xEE);
  unsigned char enables[6] = {0xFF, 0x00, 0xFF, 0xFF, 0x00, 0xFF};
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    sc_time delay;
    self.access(tlm::TLM_WRITE_COMMAND, 2, data.data(), 6, delay, enables, 6);  // bytes 2..7: pages 0 and 1
    self.access(tlm::TLM_READ_COMMAND, 0x100, fresh.data(), 6, delay, enables, 6);
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  EXPECT_EQ(bank.debug_bytes(0, 8), (std::vector<std::uint8_t>{0, 0, 1, 0, 3, 4, 0, 6}));
  EXPECT_EQ(fresh, (std::array<std::uint8_t, 6>{0, 0xEE, 0, 0, 0xEE, 0}));
  EXPECT_EQ(bank.pages_allocated(), 2u);
}

// Malformed byte enables (no length, or an element other than 0x00 / 0xFF, whose meaning the LRM
// leaves undefined) get TLM_BYTE_ENABLE_ERROR_RESPONSE; a streaming width below the length
// TLM_BURST_ERROR_RESPONSE. Nothing is written, no time is taken.
TEST(SramBank, RejectsMalformedByteEnablesAndStreaming) {
  SramBank bank("bank");
  tlm::tlm_response_status no_length{}, undefined{}, streaming{};
  sc_time delay;
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    std::uint32_t value = 0xFFFFFFFF;
    unsigned char byte_enable[4] = {0xFF, 0, 0x0F, 0};
    no_length = self.access(tlm::TLM_WRITE_COMMAND, 0, &value, 4, delay, byte_enable, 0);
    undefined = self.access(tlm::TLM_WRITE_COMMAND, 0, &value, 4, delay, byte_enable, 4);
    tlm::tlm_generic_payload trans;
    trans.set_command(tlm::TLM_WRITE_COMMAND);
    trans.set_address(0);
    trans.set_data_ptr(reinterpret_cast<unsigned char*>(&value));
    trans.set_data_length(4);
    trans.set_streaming_width(2);  // a FIFO-style access: not offered
    self.out->b_transport(trans, delay);
    streaming = trans.get_response_status();
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  EXPECT_EQ(no_length, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
  EXPECT_EQ(undefined, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
  EXPECT_EQ(streaming, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(delay, SC_ZERO_TIME);
  EXPECT_EQ(bank.pages_allocated(), 0u);  // nothing written
  EXPECT_EQ(bank.report().rejected, 3u);
  EXPECT_EQ(bank.report().writes, 0u);
}

// A read or write of zero bytes breaks the base protocol (IEEE 1666-2011 14.12: zero bytes are moved
// with TLM_IGNORE_COMMAND): TLM_BURST_ERROR_RESPONSE, whatever the address, no time, no access
// counted. TLM_IGNORE_COMMAND of any length is OK and does nothing.
TEST(SramBank, ZeroLengthTransfersAreBurstErrorsAndIgnoreIsOk) {
  SramBankConfig config;
  config.capacity_bytes = 4096;
  SramBank bank("bank", config);
  tlm::tlm_response_status read_inside{}, write_beyond{}, ignore{};
  sc_time delay;
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    std::uint32_t value = 0;
    read_inside = self.read(0x10, &value, 0, delay);
    write_beyond = self.write(8192, &value, 0, delay);
    ignore = self.access(tlm::TLM_IGNORE_COMMAND, 0x10, &value, 0, delay);
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  EXPECT_EQ(read_inside, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(write_beyond, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(ignore, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(delay, SC_ZERO_TIME);
  EXPECT_EQ(bank.report().rejected, 2u);
  EXPECT_EQ(bank.report().address_errors, 0u);
  EXPECT_EQ(bank.report().reads + bank.report().writes, 0u);
}

TEST(SramBank, DebugTransportMovesDataWithoutTimeOrCounters) {
  SramBankConfig config;
  config.capacity_bytes = 64;
  SramBank bank("bank", config);
  unsigned int copied = 0;
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    std::array<std::uint8_t, 16> buffer{};
    buffer.fill(0xAB);
    tlm::tlm_generic_payload trans;
    trans.set_command(tlm::TLM_WRITE_COMMAND);
    trans.set_address(56);
    trans.set_data_ptr(buffer.data());
    trans.set_data_length(16);
    copied = self.out->transport_dbg(trans);  // clipped at the end of the array
  });
  cpu.out.bind(bank.in);
  sc_core::sc_start();

  EXPECT_EQ(copied, 8u);
  EXPECT_EQ(bank.debug_bytes(63, 1)[0], 0xAB);
  EXPECT_EQ(bank.report().writes, 0u);
  EXPECT_EQ(sc_core::sc_time_stamp(), SC_ZERO_TIME);
}

// The summary goes out through SC_REPORT_INFO when the simulation ends (sc_stop), once per bank.
TEST(SramBank, ReportsSummaryAtEndOfSimulation) {
  SramBank bank("bank");
  SramBankConfig quiet_config;
  quiet_config.report_at_end = false;
  SramBank quiet("quiet", quiet_config);
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    std::uint32_t value = 7;
    sc_time delay;
    self.write(0, &value, 4, delay);
    sc_core::sc_stop();
  });
  ScriptedInitiator idle("idle");
  cpu.out.bind(bank.in);
  idle.out.bind(quiet.in);
  sc_core::sc_start();

  EXPECT_EQ(sc_core::sc_report_handler::get_count("rc/tlmx/SramBank"), 1);
  EXPECT_NE(bank.summary().find("writes 1 (4 B)"), std::string::npos) << bank.summary();
}

}  // namespace
}  // namespace rc::tlmx::test
