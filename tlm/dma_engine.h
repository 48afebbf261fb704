// A host-side DMA engine: moves a host buffer to or from a device address through its initiator
// socket (bound to a PciBus) in bursts, with real data movement. It adds no time of its own: every
// burst takes what the interconnect annotates (bus occupancy plus arbitration wait), so
//   transfer duration = completion of the last burst - call time
// and, on an idle PciBus with burst_bytes equal to the bus's max_burst_bytes (or any multiple of
// it), exactly PciBus::transfer_time(bytes) when the bus dominates the target's own delay.
//
// Two ways to use it, both from SC_THREADs:
//   transfer(...)  blocks the calling thread until the data has moved (it returns synchronised:
//                  sc_time_stamp() is the completion time). Call it with no pending local time
//                  offset (sync your own quantum keeper first).
//   start(...)     queues the request for the engine's own thread and returns at once; done_event()
//                  is notified when each queued request completes, last_result() tells how it went.
// Between bursts the engine syncs whenever its tlm_quantumkeeper says so; with the default global
// quantum of zero that is before every burst, so other initiators interleave at burst granularity
// (see the arbitration policy in pci_bus.h).
#pragma once

#include <cstdint>
#include <deque>
#include <string>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "tlm/no_data_extension.h"

namespace rc::tlmx {

enum class DmaDirection { to_device, to_host };

struct DmaConfig {
  std::uint64_t burst_bytes = 4096;  // bytes per bus transaction; match PciBusConfig::max_burst_bytes
  bool report_at_end = true;         // SC_REPORT_INFO the summary at end of simulation
};

struct DmaRequest {
  DmaDirection direction = DmaDirection::to_device;
  void* host = nullptr;              // host buffer: read for to_device, written for to_host
  std::uint64_t device_address = 0;  // address on the bus (e.g. BAR base + offset)
  std::uint64_t bytes = 0;
  bool no_data = false;              // timed and counted, bytes not moved (NoDataExtension)
};

struct DmaResult {
  tlm::tlm_response_status status = tlm::TLM_INCOMPLETE_RESPONSE;  // OK, or the failing burst's status
  std::uint64_t bytes_done = 0;  // bytes of the bursts that succeeded
  sc_core::sc_time start = sc_core::SC_ZERO_TIME;
  sc_core::sc_time end = sc_core::SC_ZERO_TIME;
  bool ok() const { return status == tlm::TLM_OK_RESPONSE; }
  sc_core::sc_time duration() const { return end - start; }
};

struct DmaReport {
  std::uint64_t transfers = 0;        // transfer() calls and completed start() requests
  std::uint64_t bursts = 0;           // bus transactions issued
  std::uint64_t bytes_to_device = 0;  // successfully moved
  std::uint64_t bytes_to_host = 0;
  sc_core::sc_time busy = sc_core::SC_ZERO_TIME;  // sum of transfer durations (overlapping calls add up)
  std::uint64_t errors = 0;           // transfers that ended with an error response
};

class DmaEngine : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<DmaEngine> out;

  DmaEngine(const sc_core::sc_module_name& name, const DmaConfig& config = {});

  const DmaConfig& config() const { return m_config; }

  DmaResult transfer(DmaDirection direction, void* host, std::uint64_t device_address, std::uint64_t bytes);
  DmaResult transfer(const DmaRequest& request);
  // Temporally decoupled: the first burst is issued at the caller's local time offset `local`,
  // the rest back to back, and `local` comes back as the completion's offset; nothing waits. The
  // same times as transfer() called after syncing `local`, without the two context switches. The
  // caller owns the local time (its quantum keeper) and syncs when it must.
  DmaResult transfer(const DmaRequest& request, sc_core::sc_time& local);

  void start(const DmaRequest& request);
  const sc_core::sc_event& done_event() const { return m_done; }
  bool idle() const { return m_queue.empty() && !m_worker_busy; }
  DmaResult last_result() const { return m_last; }

  DmaReport report() const { return m_report; }
  std::string summary() const;

 private:
  void worker();
  tlm::tlm_response_status burst(tlm::tlm_generic_payload& trans, const DmaRequest& request, std::uint64_t done,
                                 sc_core::sc_time& local);
  // The bursts, from local time `local`; `sync` is called between bursts when a quantum keeper asks.
  template <class Sync>
  DmaResult run_bursts(tlm::tlm_generic_payload& trans, const DmaRequest& request, sc_core::sc_time& local,
                       Sync&& sync);
  void count(const DmaRequest& request, const DmaResult& result);
  void end_of_simulation() override;

  DmaConfig m_config;
  tlm::tlm_generic_payload m_decoupled_trans;
  NoDataExtension m_no_data;  // attached to the bursts of no_data requests, never owned by a payload
  std::deque<DmaRequest> m_queue;
  bool m_worker_busy = false;
  sc_core::sc_event m_kick;
  sc_core::sc_event m_done;
  DmaResult m_last;
  DmaReport m_report;
};

}  // namespace rc::tlmx
