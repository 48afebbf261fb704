// One synchronous SRAM bank as a loosely-timed TLM-2.0 target (the RC2000 has six of them, 4 MB of
// 32-bit words each). It stores real data, annotates the time an access takes at the bank's own
// clock, grants DMI over the whole array, and counts its activity, including accesses that
// initiators made through DMI and reported back (see DmiActivitySink).
//
// Timing of a b_transport of n bytes starting at address a (L = read or write latency in cycles,
// W = word bytes, C = cycles per word, P = clock period):
//   words = n == 0 ? 0 : floor((a + n - 1) / W) - floor(a / W) + 1   (words touched; ceil(n / W) when a is word aligned)
//   delay = (L + words * C) * P
// The bank is not a contended resource: concurrent accesses each pay their own delay; sharing is
// modelled by the bus in front of it (PciBus) or by the initiator.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "tlm/dmi_activity.h"

namespace rc::tlmx {

struct SramBankConfig {
  std::uint64_t capacity_bytes = 4u << 20;                         // 4 MiB, as on the RC2000
  unsigned word_bytes = 4;                                         // 32-bit words
  sc_core::sc_time clock_period = sc_core::sc_time(10, sc_core::SC_NS);  // 100 MHz, the paper's peak memory clock
  unsigned read_latency_cycles = 2;                                // address to first data (pipelined SSRAM)
  unsigned write_latency_cycles = 2;
  unsigned cycles_per_word = 1;                                    // burst rate after the first word
  bool report_at_end = true;                                       // SC_REPORT_INFO the summary at end of simulation
};

// Activity since construction. Transport and DMI accesses are both included in reads/writes/bytes.
struct SramBankReport {
  std::uint64_t reads = 0;           // read transactions (b_transport) plus reported DMI reads
  std::uint64_t writes = 0;
  std::uint64_t bytes_read = 0;
  std::uint64_t bytes_written = 0;
  sc_core::sc_time busy = sc_core::SC_ZERO_TIME;  // sum of annotated delays plus reported DMI busy time
  std::uint64_t address_errors = 0;  // accesses outside [0, capacity)
  std::uint64_t rejected = 0;        // byte-enable and streaming-width (burst) errors
  std::uint64_t dmi_grants = 0;      // successful get_direct_mem_ptr calls
  std::uint64_t dmi_reads = 0;       // the part of reads/writes reported through record_dmi_access
  std::uint64_t dmi_writes = 0;
};

class SramBank : public sc_core::sc_module, public DmiActivitySink {
 public:
  tlm_utils::simple_target_socket<SramBank> in;

  SramBank(const sc_core::sc_module_name& name, const SramBankConfig& config = {});

  const SramBankConfig& config() const { return m_config; }
  std::uint64_t capacity() const { return m_config.capacity_bytes; }

  // The delay b_transport annotates for an in-range access (formula in the header comment).
  sc_core::sc_time access_time(tlm::tlm_command command, std::uint64_t address, std::uint64_t bytes) const;

  // Backdoor to the storage, for loading and inspecting contents without simulated time or counters.
  std::uint8_t* data() { return m_data.get(); }
  const std::uint8_t* data() const { return m_data.get(); }

  void record_dmi_access(const DmiActivity& activity) override;

  SramBankReport report() const { return m_report; }
  std::string summary() const;  // one line, printable

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  unsigned int transport_dbg(tlm::tlm_generic_payload& trans);
  bool get_direct_mem_ptr(tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi);
  void end_of_simulation() override;

  bool in_range(std::uint64_t address, std::uint64_t bytes) const;
  tlm::tlm_response_status check(const tlm::tlm_generic_payload& trans);
  void copy(tlm::tlm_generic_payload& trans);
  void count(const tlm::tlm_generic_payload& trans, const sc_core::sc_time& delay);

  SramBankConfig m_config;
  // Zeroed by calloc: large blocks come straight from the kernel's zero pages, so a bank costs
  // memory only where it is written (a study elaborates dozens of boards of six 4 MiB banks).
  struct FreeBytes {
    void operator()(std::uint8_t* p) const { std::free(p); }
  };
  std::unique_ptr<std::uint8_t, FreeBytes> m_data;
  SramBankReport m_report;
};

}  // namespace rc::tlmx
