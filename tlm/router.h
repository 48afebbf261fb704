// A plain address router (no arbitration, no bus timing): decodes each transaction by its window,
// forwards it to out[port] with the window-relative address, and adds a fixed latency. The board
// puts one behind the PCI bridge to reach the control/status registers and the six banks; it is
// also the place an FPGA-side master would go through to reach several banks with one socket.
//
//   delay += latency_cycles * clock_period     (on every decoded transaction, before the target's)
//   unmapped or straddling address -> TLM_ADDRESS_ERROR_RESPONSE, no time, counted and warned
//
// DMI passes through: a grant from a target is translated back to the initiator's address view and
// clipped to the window; invalidations from a target are translated for every window that maps to
// it and forwarded to every initiator. Debug transport passes through, clipped to the window.
#pragma once

#include <cstdint>
#include <string>

#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_initiator_socket.h>
#include <tlm_utils/multi_passthrough_target_socket.h>

#include "tlm/address_map.h"

namespace rc::tlmx {

struct RouterConfig {
  sc_core::sc_time clock_period = sc_core::sc_time(10, sc_core::SC_NS);
  unsigned latency_cycles = 0;  // decode/forward cost per transaction
  bool report_at_end = true;    // SC_REPORT_INFO the summary at end of simulation
};

struct RouterReport {
  std::uint64_t transactions = 0;    // decoded and forwarded b_transport calls
  std::uint64_t address_errors = 0;  // b_transport calls that decoded to no window
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
  void b_transport(int port, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  unsigned int transport_dbg(int port, tlm::tlm_generic_payload& trans);
  bool get_direct_mem_ptr(int port, tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi);
  void invalidate_direct_mem_ptr(int port, sc_dt::uint64 start, sc_dt::uint64 end);
  void end_of_elaboration() override;
  void end_of_simulation() override;

  void unmapped(tlm::tlm_generic_payload& trans);

  RouterConfig m_config;
  AddressMap m_map;
  RouterReport m_report;
};

}  // namespace rc::tlmx
