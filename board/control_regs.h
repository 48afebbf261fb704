// The wrapper's control/status registers as a TLM target (PCI BAR0). The host reaches them through
// the PCI bus; the wrapper (same FPGA) reads and updates them directly through the device-side API.
//
// Timing: every access annotates register_access_cycles device cycles. A write takes effect at
// t_call + delay (the delay handed in: the bus's start offset and the bridge latency, plus this
// module's): START is sampled by the wrapper from then (start_time()), and an acknowledge (DONE
// cleared) lowers the interrupt then, so a temporally decoupled host gets the same times as a
// synced one.
//
// Transactions (b_transport; an AT initiator is served through the socket's nb-to-b conversion),
// answered in this order:
//   TLM_IGNORE_COMMAND                                          TLM_OK_RESPONSE, nothing touched
//   a read or write of 0 bytes (outside the base protocol,
//   IEEE 1666-2011 14.12; as every part answers it)             TLM_BURST_ERROR_RESPONSE
//   address not 4-byte aligned, or [a, a + t) not in the BAR    TLM_ADDRESS_ERROR_RESPONSE
//   (t: the bytes the addresses span, n or a smaller streaming width, tlm/address_map.h)
//   byte enables (any)                                          TLM_BYTE_ENABLE_ERROR_RESPONSE
//   length not a multiple of 4, or streaming width < length     TLM_BURST_ERROR_RESPONSE
//   otherwise: whole registers in address order, TLM_OK_RESPONSE; offsets past the register
//   file (up to the BAR size) read 0 and ignore writes.
// Only the last takes time (the access time) or touches a register; the others count no access.
// Byte enables are refused rather than handled: a partial write of START or of the write-1-to-clear
// STATUS bits has no sensible meaning here, and the driver never uses them.
// DMI is refused over the whole address space (reads and writes have side effects).
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "board/register_map.h"

namespace rc::board {

class ControlRegs : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<ControlRegs> in;

  ControlRegs(const sc_core::sc_module_name& name, sc_core::sc_time access_time, std::uint32_t config_value);

  // ---- device side ----
  std::uint32_t value(std::uint64_t offset) const { return m_regs[offset / 4]; }
  // A START takes a snapshot of the registers as they are when it is written and joins a queue of
  // at most kStartQueue (a START beyond it is dropped and sets ERROR with kStartWhileBusy): a host
  // running ahead of simulated time may write the next pass's registers and START before this pass
  // has begun, and each pass still reads its own (the pipelined driver, docs/board.md).
  static constexpr std::size_t kStartQueue = 2;
  const sc_core::sc_event& start_event() const { return m_start_event; }  // notified at each START's time
  bool start_pending() const { return m_start_count != 0; }
  sc_core::sc_time start_time() const { return m_starts[m_start_head].time; }  // the oldest queued START's
  std::uint32_t take_start();  // dequeues the oldest START, returns its CONTROL bits
  std::uint32_t pass_value(std::uint64_t offset) const { return m_pass[offset / 4]; }  // the taken START's snapshot
  void set_busy(bool busy);
  void finish_pass(std::uint64_t cycles, std::uint32_t error);  // DONE (and ERROR), counters
  void on_acknowledge(std::function<void()> callback) { m_acknowledge = std::move(callback); }

  std::uint64_t accesses() const { return m_accesses; }

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  unsigned int transport_dbg(tlm::tlm_generic_payload& trans);
  bool get_direct_mem_ptr(tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi);
  static tlm::tlm_response_status check(const tlm::tlm_generic_payload& trans);
  void write(std::uint64_t offset, std::uint32_t value, const sc_core::sc_time& effective);
  void acknowledge_now();  // an acknowledge written ahead of simulated time, at its time

  sc_core::sc_time m_access_time;
  std::array<std::uint32_t, reg::kSize / 4> m_regs{};
  struct StartCommand {
    sc_core::sc_time time;
    std::uint32_t bits = 0;
    std::array<std::uint32_t, reg::kSize / 4> regs{};
  };
  // The queued STARTs, oldest at m_start_head: a ring of kStartQueue (a deque allocated every few passes).
  std::array<StartCommand, kStartQueue> m_starts{};
  std::size_t m_start_head = 0, m_start_count = 0;
  std::array<std::uint32_t, reg::kSize / 4> m_pass{};
  sc_core::sc_event m_start_event;
  std::function<void()> m_acknowledge;
  sc_core::sc_event m_acknowledge_event;
  std::uint64_t m_accesses = 0;
};

}  // namespace rc::board
