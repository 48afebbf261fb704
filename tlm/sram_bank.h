// One synchronous SRAM bank as a loosely-timed TLM-2.0 target (the RC2000 has six of them, 4 MB of
// 32-bit words each). It stores real data in sparse pages (tlm/sparse_memory.h: a page is allocated,
// zeroed, the first time a write, a debug write or a DMI grant touches it, so any capacity up to
// 2^64 - 1 bytes costs memory only where data is), annotates the time an access takes at the bank's
// own clock, grants DMI one page at a time, and counts its activity, including accesses that
// initiators made through DMI and reported back (see DmiActivitySink).
//
// Timing of a b_transport of n bytes starting at address a (L = read or write latency in cycles,
// W = word bytes, C = cycles per word, P = clock period):
//   words = floor((a + n - 1) / W) - floor(a / W) + 1   (words touched; ceil(n / W) when a is word aligned)
//   delay = (L + words * C) * P
// Byte enables do not change it (the bank still cycles through the words). The bank is not a
// contended resource: concurrent accesses each pay their own delay; sharing is modelled by the bus
// in front of it (PciBus) or by the initiator.
//
// Responses, in this order (IEEE 1666-2011 ch. 14 for the generic payload's rules):
//   TLM_IGNORE_COMMAND                              OK, nothing done, no time
//   data_length 0 (forbidden by 14.12 for a read or write; zero bytes are moved with IGNORE)
//                                                   TLM_BURST_ERROR_RESPONSE, counted as rejected
//   [a, a + t) not inside [0, capacity)             TLM_ADDRESS_ERROR_RESPONSE, warned, counted
//     (t: the bytes the addresses span, n, or the streaming width w when w < n: address_map.h)
//   byte enables of length 0, or an element other than 0x00 / 0xFF (undefined by 14.14)
//                                                   TLM_BYTE_ENABLE_ERROR_RESPONSE, counted as rejected
//   streaming width < data length                   TLM_BURST_ERROR_RESPONSE, counted as rejected
//   otherwise                                       OK; data moved, byte i only when element
//                                                   i % byte_enable_length is 0xFF (a read leaves the
//                                                   disabled bytes of the data array as they were)
// Errors take no time and move no byte.
//
// DMI (IEEE 1666-2011 sec. 11.2): only a page is contiguous host memory, so get_direct_mem_ptr grants
// read/write access to the page holding the address, [page start, page last] (the last page cut at
// the capacity), allocating it if untouched; the pointer addresses the page's first byte. The
// latencies are those of one access through the pointer, a single word as b_transport would time it:
//   read latency  = (read_latency_cycles  + cycles_per_word) * P
//   write latency = (write_latency_cycles + cycles_per_word) * P
// An address at or beyond the capacity is refused: access none, no pointer, and the range the
// refusal holds for, [capacity, 2^64 - 1]. Pages never move, so the bank never invalidates DMI.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "tlm/dmi_activity.h"
#include "tlm/sparse_memory.h"

namespace rc::tlmx {

struct SramBankConfig {
  std::uint64_t capacity_bytes = 4u << 20;                         // 4 MiB, as on the RC2000
  unsigned word_bytes = 4;                                         // 32-bit words
  sc_core::sc_time clock_period = sc_core::sc_time(10, sc_core::SC_NS);  // 100 MHz, the paper's peak memory clock
  unsigned read_latency_cycles = 2;                                // address to first data (pipelined SSRAM)
  unsigned write_latency_cycles = 2;
  unsigned cycles_per_word = 1;                                    // burst rate after the first word
  // Storage page: the unit of allocation and of a DMI grant (a power of two). 64 KiB: the wrapper
  // streams face records (9 words), ray packets (3 words over 1..3 banks) and result words
  // sequentially through DMI, so with 64 KiB pages it changes region once every 16 Ki 32-bit words
  // and asks for DMI at most 64 times for a 4 MiB bank; a bank touched at one word costs 64 KiB.
  std::uint64_t page_bytes = std::uint64_t{64} << 10;
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
  std::uint64_t dmi_grants = 0;      // successful get_direct_mem_ptr calls (one page each)
  std::uint64_t dmi_refusals = 0;    // get_direct_mem_ptr calls outside the bank
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
  // The latency of one access through a DMI pointer: a single word's access_time.
  sc_core::sc_time dmi_latency(tlm::tlm_command command) const;

  // Backdoor to the storage, for loading and inspecting contents without simulated time or
  // counters. [address, address + bytes) must lie in the bank (std::out_of_range otherwise).
  // debug_read gives zeros where nothing was written and allocates nothing.
  void debug_read(std::uint64_t address, void* out, std::uint64_t bytes) const;
  std::vector<std::uint8_t> debug_bytes(std::uint64_t address, std::uint64_t bytes) const;
  void debug_write(std::uint64_t address, const void* data, std::uint64_t bytes);

  const SparseMemory& storage() const { return m_memory; }
  std::uint64_t pages_allocated() const { return m_memory.pages_allocated(); }

  void record_dmi_access(const DmiActivity& activity) override;

  SramBankReport report() const { return m_report; }
  std::string summary() const;  // one line, printable

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  unsigned int transport_dbg(tlm::tlm_generic_payload& trans);
  bool get_direct_mem_ptr(tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi);
  void end_of_simulation() override;

  bool in_range(std::uint64_t address, std::uint64_t bytes) const;
  void check_range(std::uint64_t address, std::uint64_t bytes, const char* what) const;  // throws
  tlm::tlm_response_status check(const tlm::tlm_generic_payload& trans);
  void copy(tlm::tlm_generic_payload& trans);
  void copy_enabled(tlm::tlm_generic_payload& trans);  // byte enables
  void count(const tlm::tlm_generic_payload& trans, const sc_core::sc_time& delay);

  SramBankConfig m_config;
  SparseMemory m_memory;
  SramBankReport m_report;
};

}  // namespace rc::tlmx
