// SramBank: data round trip, exact annotated delay, DMI and its accounting, error responses.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <numeric>

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
  EXPECT_EQ(bank.data()[0x100], 1);
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

TEST(SramBank, DmiGrantsWholeArrayAndCountsReportedAccesses) {
  SramBank bank("bank");
  tlm::tlm_dmi dmi;
  bool granted = false;
  std::uint32_t seen = 0;
  ScriptedInitiator fpga("fpga", [&](ScriptedInitiator& self) {
    tlm::tlm_generic_payload trans;
    trans.set_address(0x40);
    trans.set_command(tlm::TLM_READ_COMMAND);
    granted = self.out->get_direct_mem_ptr(trans, dmi);
    const std::uint32_t value = 0xCAFEF00D;
    std::memcpy(dmi.get_dmi_ptr() + 0x40, &value, 4);  // stream through the pointer...
    bank.record_dmi_access(DmiActivity{0, 1, 0, 4, sc_time(10, SC_NS)});  // ...and account for it
    sc_time delay;
    self.read(0x40, &seen, 4, delay);  // transport sees what DMI wrote
  });
  fpga.out.bind(bank.in);
  sc_core::sc_start();

  ASSERT_TRUE(granted);
  EXPECT_EQ(dmi.get_dmi_ptr(), bank.data());
  EXPECT_EQ(dmi.get_start_address(), 0u);
  EXPECT_EQ(dmi.get_end_address(), bank.capacity() - 1);
  EXPECT_TRUE(dmi.is_read_write_allowed());
  EXPECT_EQ(dmi.get_read_latency(), sc_time(2500, SC_PS));  // 10 ns per 4-byte word
  EXPECT_EQ(dmi.get_write_latency(), sc_time(2500, SC_PS));
  EXPECT_EQ(seen, 0xCAFEF00Du);
  const SramBankReport r = bank.report();
  EXPECT_EQ(r.dmi_grants, 1u);
  EXPECT_EQ(r.writes, 1u);
  EXPECT_EQ(r.dmi_writes, 1u);
  EXPECT_EQ(r.bytes_written, 4u);
  EXPECT_EQ(r.reads, 1u);
  EXPECT_EQ(r.dmi_reads, 0u);
  EXPECT_EQ(r.busy, sc_time(10 + 30, SC_NS));  // reported DMI busy + (2 + 1) * 10 ns read
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

TEST(SramBank, RejectsByteEnablesAndStreaming) {
  SramBank bank("bank");
  tlm::tlm_response_status enables{}, streaming{};
  ScriptedInitiator cpu("cpu", [&](ScriptedInitiator& self) {
    std::uint32_t value = 0xFFFFFFFF;
    unsigned char byte_enable[4] = {0xFF, 0, 0xFF, 0};
    sc_time delay;
    enables = self.access(tlm::TLM_WRITE_COMMAND, 0, &value, 4, delay, byte_enable, 4);
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

  EXPECT_EQ(enables, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
  EXPECT_EQ(streaming, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(bank.data()[0], 0);  // nothing written
  EXPECT_EQ(bank.report().rejected, 2u);
  EXPECT_EQ(bank.report().writes, 0u);
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
  EXPECT_EQ(bank.data()[63], 0xAB);
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
