// A plain address router (no arbitration, no bus timing): decodes each transaction by its window,
// forwards it to out[port] with the window-relative address, and adds a fixed latency. The board
// puts one behind the PCI bridge to reach the control/status registers and the six banks; it is
// also the place an FPGA-side master would go through to reach several banks with one socket.
//
//   delay += latency_cycles * clock_period     (on every decoded transaction, before the target's)
//   unmapped or straddling address -> TLM_ADDRESS_ERROR_RESPONSE, no time, counted and warned
//   read or write of 0 bytes       -> TLM_BURST_ERROR_RESPONSE, no time, not routed (address_map.h)
//
// Loosely and approximately timed alike. b_transport is forwarded and the initiator's address
// restored on return. nb_transport (base protocol, BEGIN_REQ -> END_REQ -> BEGIN_RESP -> END_RESP)
// is forwarded phase by phase, BEGIN_REQ with the latency added to its delay, the backward phases
// (END_REQ, BEGIN_RESP) to the `in` port the request came from, END_RESP to the target that
// responded. The payload carries the window-relative address from the BEGIN_REQ the target gets
// until its response reaches the initiator (a target may read it at any time until it responds);
// the initiator's address is back in place before the initiator sees the response. Return values
// and delays pass through unchanged when nothing competes. The router keeps the exclusion rules on
// every hop, which several initiators sharing a target (or one initiator waiting for responses
// from several targets) would otherwise break:
//   - one open request per target (BEGIN_REQ until its END_REQ, or the BEGIN_RESP or TLM_COMPLETED
//     that implies it): a BEGIN_REQ for a busy target is answered TLM_ACCEPTED and held; it goes to
//     the target, in arrival order, at max(its request time + latency, the END_REQ time of the
//     previous one), and what the target answers reaches the initiator on the backward path;
//   - one open response per initiator (BEGIN_RESP until its END_RESP): a response due while the
//     initiator still holds another is held (the target is answered TLM_ACCEPTED, or, if it
//     responded through a return value, the initiator gets TLM_UPDATED with END_REQ instead) and
//     delivered at max(its time, the END_RESP time of the previous one); the target gets its
//     END_RESP when the initiator gives it.
// An initiator may answer END_REQ TLM_COMPLETED (it wants no response, IEEE 1666-2011 15.2): the
// router then sends it nothing more and ends the target's response itself (TLM_COMPLETED to the
// target's BEGIN_RESP), as the PciBus does. A payload with a memory manager is acquired from
// BEGIN_REQ to its end at the router. An unmapped
// or zero-length BEGIN_REQ is completed at once (TLM_COMPLETED with its error, no time). Targets may be AT or
// LT-only (simple_target_socket converts; it answers BEGIN_REQ with TLM_ACCEPTED and no END_REQ
// before its BEGIN_RESP, so requests to it are serialised). Byte enables and streaming width pass
// untouched.
//
// DMI passes through: the target's answer, grant or refusal, is translated back to the initiator's
// addresses and clipped to the window (a refusal grants DMI_ACCESS_NONE); an address no window holds
// is refused over the unmapped gap around it. Invalidations from a target are translated and
// clipped for every window that maps to it and forwarded to every initiator. Debug transport
// passes through, clipped to the window.
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

struct RouterConfig {
  sc_core::sc_time clock_period = sc_core::sc_time(10, sc_core::SC_NS);
  unsigned latency_cycles = 0;  // decode/forward cost per transaction
  bool report_at_end = true;    // SC_REPORT_INFO the summary at end of simulation
};

struct RouterReport {
  std::uint64_t transactions = 0;    // decoded and forwarded transactions (b_transport calls and BEGIN_REQs)
  std::uint64_t address_errors = 0;  // transactions that decoded to no window
};

class Router : public sc_core::sc_module {
 public:
  tlm_utils::multi_passthrough_target_socket<Router> in;
  tlm_utils::multi_passthrough_initiator_socket<Router> out;  // port = binding order

  Router(const sc_core::sc_module_name& name, const RouterConfig& config = {});

  const RouterConfig& config() const { return m_config; }

  // Maps [base, base + size) to out[port]; the target sees base as address 0. Throws
  // std::invalid_argument on overlap. Call during elaboration.
  void map(std::uint64_t base, std::uint64_t size, unsigned port, const std::string& name = "");
  const AddressMap& address_map() const { return m_map; }

  RouterReport report() const { return m_report; }
  std::string summary() const;

 private:
  // An AT transaction at the router.
  struct Flight {
    int in_port;
    int out_port;
    std::uint64_t address;  // the initiator's
    std::uint64_t offset;   // the target's (window-relative)
    sc_core::sc_time due;   // while held: when its BEGIN_REQ (or BEGIN_RESP) was due
    bool held_request = false;  // answered TLM_ACCEPTED and held: the target's answers go back as calls
    bool target_waits = false;  // the target has responded and waits for END_RESP on the forward path
    bool initiator_done = false;  // the initiator answered END_REQ TLM_COMPLETED: no response goes to it
  };
  // Exclusion-rule state of one side of the router: the open phase (request towards a target,
  // response towards an initiator), when the last one ended, and the transactions held behind it.
  struct Hop {
    tlm::tlm_generic_payload* open = nullptr;
    sc_core::sc_time free_at = sc_core::SC_ZERO_TIME;
    std::deque<tlm::tlm_generic_payload*> held;
  };

  void b_transport(int port, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  tlm::tlm_sync_enum nb_transport_fw(int port, tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay);
  tlm::tlm_sync_enum nb_transport_bw(int port, tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay);
  tlm::tlm_sync_enum begin_request(int port, tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                   sc_core::sc_time& delay);
  tlm::tlm_sync_enum end_response(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  tlm::tlm_sync_enum answered_directly(tlm::tlm_generic_payload& trans, tlm::tlm_sync_enum answer,
                                       tlm::tlm_phase& phase, sc_core::sc_time& delay);
  tlm::tlm_sync_enum begin_response(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase, sc_core::sc_time& delay);
  void send_held_request(tlm::tlm_generic_payload& trans);
  void send_end_request(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase, sc_core::sc_time& delay);
  void respond_later(tlm::tlm_generic_payload& trans, const sc_core::sc_time& delay);
  void send_response(tlm::tlm_generic_payload& trans, sc_core::sc_time delay);
  void request_ended(tlm::tlm_generic_payload& trans, const sc_core::sc_time& at);
  void response_ended(tlm::tlm_generic_payload& trans, const sc_core::sc_time& at);
  void end_target_response(tlm::tlm_generic_payload& trans, sc_core::sc_time delay);
  void release(tlm::tlm_generic_payload& trans);
  void deliver(tlm::tlm_generic_payload& trans, const tlm::tlm_phase& phase);  // m_peq callback
  Flight* flight_of(const tlm::tlm_generic_payload& trans, const char* call);  // reports if none
  Hop& target_hop(int port);
  Hop& initiator_hop(int port);
  unsigned int transport_dbg(int port, tlm::tlm_generic_payload& trans);
  bool get_direct_mem_ptr(int port, tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi);
  void invalidate_direct_mem_ptr(int port, sc_dt::uint64 start, sc_dt::uint64 end);
  void end_of_elaboration() override;
  void end_of_simulation() override;

  void unmapped(tlm::tlm_generic_payload& trans);

  RouterConfig m_config;
  sc_core::sc_time m_latency;  // latency_cycles * clock_period, added to every decoded transaction
  AddressMap m_map;
  RouterReport m_report;
  std::unordered_map<const tlm::tlm_generic_payload*, Flight> m_flights;  // AT transactions at the router
  std::vector<Hop> m_targets;     // by `out` port
  std::vector<Hop> m_initiators;  // by `in` port
  tlm_utils::peq_with_cb_and_phase<Router> m_peq;  // held BEGIN_REQs and BEGIN_RESPs, at their times
};

}  // namespace rc::tlmx
