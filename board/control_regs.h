// The wrapper's control/status registers as a TLM target (PCI BAR0). The host reaches them through
// the PCI bus; the wrapper (same FPGA) reads and updates them directly through the device-side API.
//
// Timing: every access annotates register_access_cycles device cycles. A write takes effect at
// t_call + delay (the delay handed in: the bus's start offset and the bridge latency, plus this
// module's): START is sampled by the wrapper from then (start_time()), and an acknowledge (DONE
// cleared) lowers the interrupt then, so a temporally decoupled host gets the same times as a
// synced one.
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
  const sc_core::sc_event& start_event() const { return m_start_event; }  // notified at start_time()
  bool start_pending() const { return m_start_pending; }
  sc_core::sc_time start_time() const { return m_start_time; }
  std::uint32_t take_start();  // clears the pending START, returns the CONTROL bits written with it
  void set_busy(bool busy);
  void finish_pass(std::uint64_t cycles, std::uint32_t error);  // DONE (and ERROR), counters
  void on_acknowledge(std::function<void()> callback) { m_acknowledge = std::move(callback); }

  std::uint64_t accesses() const { return m_accesses; }

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  unsigned int transport_dbg(tlm::tlm_generic_payload& trans);
  void write(std::uint64_t offset, std::uint32_t value, const sc_core::sc_time& effective);
  void acknowledge_now();  // an acknowledge written ahead of simulated time, at its time

  sc_core::sc_time m_access_time;
  std::array<std::uint32_t, reg::kSize / 4> m_regs{};
  bool m_start_pending = false;
  std::uint32_t m_start_bits = 0;
  sc_core::sc_time m_start_time = sc_core::SC_ZERO_TIME;
  sc_core::sc_event m_start_event;
  std::function<void()> m_acknowledge;
  sc_core::sc_event m_acknowledge_event;
  std::uint64_t m_accesses = 0;
};

}  // namespace rc::board
