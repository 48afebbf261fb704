// A shared PCI bus as a TLM-2.0 interconnect for loosely-timed (b_transport) and approximately-timed
// (nb_transport, base protocol) initiators: any number of initiators (host driver, DMA engines,
// other cards) bind to `in`; BAR windows route each transaction to one of the targets bound to
// `out`; the bus is one shared resource, so transfers are serialised and timed.
//
// Timing (W = width_bits / 8 bytes per data phase, E = burst_efficiency in (0, 1], S = setup_cycles,
// M = max_burst_bytes, P = clock_period). A transaction of n bytes is carried as
// bursts = n == 0 ? 1 : ceil(n / M) bursts of M bytes, the last one holding the remainder (a
// transaction without data is one burst of 0 bytes), and
//   burst_cycles(b)  = S + ceil(ceil(b / W) / E)
//   transfer_time(n) = (sum of burst_cycles over the bursts) * P
// ceil(x / E) takes x / E within a relative 1e-9 of an integer as that integer (see timing.h).
// A TLM_IGNORE_COMMAND moves no data whatever its length: it is timed as n = 0. A read or write of
// 0 bytes is outside the base protocol: TLM_BURST_ERROR_RESPONSE at once, not arbitrated, no time,
// not counted (address_map.h, zero_length_transfer).
// The target behind the window is called with the transaction's start on the bus as its delay
// (start - sc_time_stamp(), see Arbitration), so a target with side effects (registers) can time
// them at the access; it adds its own delay D_t, wait states that overlap the bus data phases, so
// the bus is occupied for
//   occupancy = max(transfer_time(n), D_t)
// A payload with a ProgrammedIoExtension (programmed_io_extension.h) is n single-word accesses:
//   transfer_time = n * (burst_cycles(access_bytes) * P + (read ? read_round_trip : 0))
// An unmapped address is a master abort: occupancy = master_abort_cycles * P and
// TLM_ADDRESS_ERROR_RESPONSE.
//
// Arbitration: first come, first served in the order transactions reach the bus (b_transport
// calls and BEGIN_REQs), with the bus reserved on arrival. With request = sc_time_stamp() + delay
// (the initiator's local time, so temporal decoupling is honoured) and bus_free_at the end of the
// last reservation:
//   start       = max(request, bus_free_at)
//   wait        = start - request                     (counted per initiator)
//   bus_free_at = start + occupancy
//   delay       = start + occupancy - sc_time_stamp()  (the returned annotation: completion time)
// An initiator that runs ahead of simulated time reserves the bus at its local time when it calls,
// so it can take the bus before another initiator whose request is earlier in simulated time but
// whose call comes later. Initiators that need burst-level fairness must therefore sync (wait for
// their local offset) before each transfer; DmaEngine does whenever its quantum keeper asks, which
// is before every burst with the default global quantum of zero.
//
// Approximately timed (base protocol, BEGIN_REQ -> END_REQ -> BEGIN_RESP -> END_RESP): a BEGIN_REQ
// at sc_time_stamp() + delay is the same request as a b_transport with that delay. The bus answers
// TLM_ACCEPTED and carries it, in arrival order, from its own thread (or from the next b_transport
// caller, whichever runs first, so no later b_transport overtakes it): the same arbitration, the
// same target call, the same occupancy and counters. END_REQ goes back (nb_transport_bw, annotated)
// at `start`, when the bus takes the transaction; BEGIN_RESP at start + occupancy, the time a
// b_transport would have returned. Per `in` port one response is open at a time (response
// exclusion rule): a response that is due while the initiator still holds the previous one
// (TLM_ACCEPTED, END_RESP later) waits for its END_RESP. A second BEGIN_REQ on a port before the
// END_REQ of the first breaks the request exclusion rule (SC_REPORT_ERROR). The bus acquires a
// payload with a memory manager from BEGIN_REQ to the end of its response and releases it then.
// An initiator may answer END_REQ TLM_COMPLETED: the transaction is still carried (the target's
// side ends with its b_transport), and no response is sent.
//
// Targets: the bus always calls b_transport (always from a thread). An AT-only target (a
// simple_target_socket with only nb_transport registered) is served through the socket's
// b-to-nb adapter, which waits inside b_transport until the target's response: conventional PCI
// has no split transactions, so the bus is held from the start until the target completes
//   end = max(start + bus_time, completion)   completion = time after the call + returned delay
// One transaction is on the bus at a time, in arrival order (every b_transport call and BEGIN_REQ
// takes a ticket on arrival; a later one waits for its turn), so a target that waits delays those
// behind it and never overlaps them. The offset a target is handed is start - sc_time_stamp(), or
// zero when simulated time has already passed the start: never negative. Targets that do not wait
// (every part here) see no change: nothing waits, and the times are those of the formulas above.
//
// Shared arbitration (several cards on one bus): each card keeps its own PciBus (its BAR windows,
// its counters), and share_arbitration_with(owner) makes this bus use the owner's bus_free_at, so a
// transfer on any of the buses waits for every other one exactly as the policy above says, as if
// they were one bus. Without it nothing changes.
//
// Decoding is by the bytes a transaction's addresses span (a streaming burst: its streaming width,
// address_map.h, bytes_touched). Byte enables and streaming width pass to the target untouched. transport_dbg is routed (clipped
// to the window, no time). DMI is refused everywhere (every PCI access must be arbitrated and
// timed): get_direct_mem_ptr returns false with DMI_ACCESS_NONE over [0, 2^64 - 1], the whole
// range the refusal holds for, and forwarded transactions come back with the DMI hint cleared.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <unordered_map>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_initiator_socket.h>
#include <tlm_utils/multi_passthrough_target_socket.h>
#include <tlm_utils/peq_with_cb_and_phase.h>

#include "tlm/address_map.h"

namespace rc::tlmx {

struct PciBusConfig {
  unsigned width_bits = 32;                                              // 32 or 64
  sc_core::sc_time clock_period = sc_core::sc_time(30, sc_core::SC_NS);  // PCI "33 MHz" is 33.33 MHz; 66 MHz: 15 ns
  double burst_efficiency = 1.0;     // fraction of data cycles that carry data within a burst, (0, 1]
  unsigned setup_cycles = 8;         // per burst: arbitration, address phase, turnaround, target initial latency
  std::uint64_t max_burst_bytes = 4096;  // longest burst before the bus is released (latency timer)
  unsigned master_abort_cycles = 6;  // unmapped address: address phase + 5 clocks of DEVSEL time-out
  bool report_at_end = true;         // SC_REPORT_INFO the summary at end of simulation
};

// Counters of one initiator port (or of all, in PciBusReport::total).
struct PciInitiatorReport {
  std::uint64_t transactions = 0;    // b_transport calls and AT requests, including failed ones
  std::uint64_t bytes_written = 0;   // initiator -> target (successful writes)
  std::uint64_t bytes_read = 0;      // target -> initiator (successful reads)
  sc_core::sc_time busy = sc_core::SC_ZERO_TIME;  // bus occupancy of this initiator's transfers
  sc_core::sc_time wait = sc_core::SC_ZERO_TIME;  // arbitration wait (start - request)
  std::uint64_t address_errors = 0;  // master aborts (unmapped addresses)
};

struct PciBusReport {
  std::vector<PciInitiatorReport> initiators;  // indexed by `in` binding order
  PciInitiatorReport total;
  sc_core::sc_time bus_free_at = sc_core::SC_ZERO_TIME;
};

class PciBus : public sc_core::sc_module {
 public:
  tlm_utils::multi_passthrough_target_socket<PciBus> in;      // initiators bind here
  tlm_utils::multi_passthrough_initiator_socket<PciBus> out;  // BAR targets, port = binding order

  PciBus(const sc_core::sc_module_name& name, const PciBusConfig& config = {});

  const PciBusConfig& config() const { return m_config; }

  // Maps [base, base + size) to the target bound as out[port]; the target sees base as address 0.
  // Throws std::invalid_argument on overlap. Call during elaboration.
  void map(std::uint64_t base, std::uint64_t size, unsigned port, const std::string& name = "");
  const AddressMap& address_map() const { return m_map; }

  // Bus time of an n-byte transaction, without target wait states or arbitration (formula above).
  sc_core::sc_time transfer_time(std::uint64_t bytes) const;
  // Bus time of n bytes of programmed I/O (formula above).
  sc_core::sc_time programmed_io_time(std::uint64_t bytes, unsigned access_bytes, bool read,
                                      const sc_core::sc_time& read_round_trip) const;

  // From now on this bus arbitrates with `owner` (and every bus sharing with it): one bus_free_at
  // for all of them. Call during elaboration, before any transfer; SC_REPORT_ERROR if called later,
  // with this bus itself, or when other buses already share this one's arbitration.
  void share_arbitration_with(PciBus& owner);
  bool shares_arbitration() const { return m_arbiter != this; }

  PciBusReport report() const;  // bus_free_at: of the shared arbitration when shared
  std::string summary() const;

 private:
  // When a transaction is on the bus: from start (the grant) to end = start + occupancy.
  struct Carried {
    sc_core::sc_time start;
    sc_core::sc_time end;
  };
  // An AT request waiting to be carried, with its request time.
  struct AtRequest {
    int port;
    tlm::tlm_generic_payload* trans;
    sc_core::sc_time request;
    std::uint64_t ticket;  // its turn on the bus (arrival order)
  };
  // The base-protocol state of one `in` port.
  struct AtPort {
    bool request_open = false;                         // BEGIN_REQ received, END_REQ not yet sent
    tlm::tlm_generic_payload* responding = nullptr;    // BEGIN_RESP sent, END_RESP not yet reached
    std::deque<tlm::tlm_generic_payload*> due;         // responses due while another was open
  };

  void b_transport(int port, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  tlm::tlm_sync_enum nb_transport_fw(int port, tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay);
  unsigned int transport_dbg(int port, tlm::tlm_generic_payload& trans);
  bool get_direct_mem_ptr(int port, tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi);
  void invalidate_direct_mem_ptr(int port, sc_dt::uint64 start, sc_dt::uint64 end);
  void end_of_elaboration() override;
  void end_of_simulation() override;

  std::uint64_t burst_cycles(std::uint64_t bytes) const;
  Carried carry(int port, tlm::tlm_generic_payload& trans, const sc_core::sc_time& request);
  sc_core::sc_time bus_time(const tlm::tlm_generic_payload& trans) const;
  sc_core::sc_time forward(tlm::tlm_generic_payload& trans, const Decoded& hit, const sc_core::sc_time& start);
  void wait_for_turn(std::uint64_t ticket);
  sc_core::sc_time start_for(const sc_core::sc_time& request) const;
  sc_core::sc_time master_abort(tlm::tlm_generic_payload& trans);
  PciInitiatorReport& counters(int port);
  void count(PciInitiatorReport& c, const tlm::tlm_generic_payload& trans, const sc_core::sc_time& occupancy,
             const sc_core::sc_time& wait);

  // Approximately timed path.
  void carry_requests_thread();
  void carry_queued_requests();
  bool end_request(int port, tlm::tlm_generic_payload& trans, const sc_core::sc_time& start);
  void deliver(tlm::tlm_generic_payload& trans, const tlm::tlm_phase& phase);  // m_peq callback
  void send_response(int port, tlm::tlm_generic_payload& trans);
  void response_ended(int port, tlm::tlm_generic_payload& trans);
  void end_response_at(int port, tlm::tlm_generic_payload& trans, const sc_core::sc_time& delay);
  AtPort& at_port(int port);
  void protocol_error(int port, const std::string& what) const;

  PciBusConfig m_config;
  AddressMap m_map;
  sc_core::sc_time m_bus_free_at = sc_core::SC_ZERO_TIME;  // of this bus's arbitration when it owns it
  PciBus* m_arbiter = this;  // whose bus_free_at arbitrates this bus (itself unless shared)
  unsigned m_sharers = 0;    // buses arbitrating through this one
  // Turns on the bus, in the arbiter: every transaction (b_transport call or BEGIN_REQ) takes a
  // ticket on arrival and is carried when m_serving reaches it, so one is on the bus at a time even
  // while a target waits inside b_transport.
  std::uint64_t m_tickets = 0;
  std::uint64_t m_serving = 0;
  sc_core::sc_event m_turn_changed;
  std::vector<PciInitiatorReport> m_initiators;

  std::deque<AtRequest> m_requests;  // AT requests not yet carried, in arrival order
  sc_core::sc_event m_request_arrived;
  tlm_utils::peq_with_cb_and_phase<PciBus> m_peq;  // BEGIN_RESP due, annotated END_RESP reached
  std::unordered_map<const tlm::tlm_generic_payload*, int> m_at_port_of;  // AT transactions in flight
  std::vector<AtPort> m_at_ports;
};

}  // namespace rc::tlmx
