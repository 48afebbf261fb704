// A level-sensitive interrupt line from a device to the host, with an interrupt-to-host latency.
//
// Semantics, exactly:
//   raise(offset)  device side; ignored if the line is already raised. The host sees the line high
//                  at sc_time_stamp() + offset + latency (offset: the caller's local time, for
//                  temporally decoupled devices).
//   lower()        takes effect at once on both sides (the host acknowledges and the device drops its
//                  request) and cancels a raise still on its way to the host, so a host that lowers
//                  and then waits again never wakes on the interrupt it has just handled.
//   wait_raised()  host side, from an SC_THREAD: returns at once if the host sees the line high,
//                  otherwise blocks until it does, i.e. exactly `latency` after the raise.
//   wait_raised_ahead(ahead)  host side, for a thread running `ahead` of simulated time (temporally
//                  decoupled): returns when wait(ahead) followed by wait_raised() would, and counts a
//                  host wait when that wait_raised() would block. When the line is low with no raise on
//                  its way, it waits for the rise first (then, if the rise came before the host's time,
//                  for that time, and looks again), so a rise after the host's time costs the thread one
//                  wake instead of two. A rise exactly at the host's time counts no wait (the synced
//                  host's count there depends on the order of processes within that time step).
#pragma once

#include <cstdint>
#include <string>

#include <systemc>

namespace rc::tlmx {

struct IrqLineConfig {
  sc_core::sc_time latency = sc_core::SC_ZERO_TIME;  // device raise -> host sees it
  bool report_at_end = true;                         // SC_REPORT_INFO the summary at end of simulation
};

struct IrqLineReport {
  std::uint64_t raises = 0;      // low -> high transitions driven by the device
  std::uint64_t lowers = 0;      // high -> low transitions
  std::uint64_t delivered = 0;   // raises that reached the host (not cancelled by lower())
  std::uint64_t host_waits = 0;  // wait_raised() calls that had to block
};

class IrqLine : public sc_core::sc_module {
 public:
  IrqLine(const sc_core::sc_module_name& name, const IrqLineConfig& config = {});

  const IrqLineConfig& config() const { return m_config; }

  void raise(const sc_core::sc_time& offset = sc_core::SC_ZERO_TIME);
  void lower();

  bool driven() const { return m_device_level; }  // the level the device drives
  bool raised() const { return m_host_level; }    // the level the host sees now

  void wait_raised();
  void wait_raised_ahead(const sc_core::sc_time& ahead);
  const sc_core::sc_event& raised_event() const { return m_host_raised; }  // host-visible rising edge

  IrqLineReport report() const { return m_report; }
  std::string summary() const;

 private:
  void deliver();
  void end_of_simulation() override;

  IrqLineConfig m_config;
  bool m_device_level = false;
  bool m_host_level = false;
  sc_core::sc_event m_in_flight;    // a raise travelling to the host (at most one: raises while high are ignored)
  sc_core::sc_event m_host_raised;
  IrqLineReport m_report;
};

}  // namespace rc::tlmx
