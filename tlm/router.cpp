#include "tlm/router.h"

#include <algorithm>
#include <sstream>

#include "tlm/timing.h"

namespace rc::tlmx {

namespace {
constexpr const char* kMsgType = "rc/tlmx/Router";
}

Router::Router(const sc_core::sc_module_name& name, const RouterConfig& config)
    : sc_core::sc_module(name), in("in"), out("out"), m_config(config) {
  in.register_b_transport(this, &Router::b_transport);
  in.register_transport_dbg(this, &Router::transport_dbg);
  in.register_get_direct_mem_ptr(this, &Router::get_direct_mem_ptr);
  out.register_invalidate_direct_mem_ptr(this, &Router::invalidate_direct_mem_ptr);
}

void Router::map(std::uint64_t base, std::uint64_t size, unsigned port, const std::string& name) {
  m_map.add(AddressWindow{base, size, port, name.empty() ? "port " + std::to_string(port) : name});
}

void Router::unmapped(tlm::tlm_generic_payload& trans) {
  ++m_report.address_errors;
  std::ostringstream msg;
  msg << name() << ": no window holds address 0x" << std::hex << trans.get_address() << " + 0x"
      << trans.get_data_length() << " bytes";
  SC_REPORT_WARNING(kMsgType, msg.str().c_str());
  trans.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
}

void Router::b_transport(int, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  const std::uint64_t address = trans.get_address();
  const std::optional<Decoded> hit = m_map.decode(address, trans.get_data_length());
  if (!hit) return unmapped(trans);
  ++m_report.transactions;
  delay += cycles(m_config.latency_cycles, m_config.clock_period);
  trans.set_address(hit->offset);
  out[static_cast<int>(hit->window->port)]->b_transport(trans, delay);
  trans.set_address(address);  // the initiator gets its own view back
}

unsigned int Router::transport_dbg(int, tlm::tlm_generic_payload& trans) {
  const std::uint64_t address = trans.get_address();
  const std::optional<Decoded> hit = m_map.decode(address, 1);
  if (!hit) return 0;
  const unsigned int length = trans.get_data_length();
  trans.set_address(hit->offset);
  trans.set_data_length(static_cast<unsigned int>(std::min<std::uint64_t>(length, hit->window->size - hit->offset)));
  const unsigned int done = out[static_cast<int>(hit->window->port)]->transport_dbg(trans);
  trans.set_address(address);
  trans.set_data_length(length);
  return done;
}

// The target answers in its own addresses; the initiator must get a region in its own addresses
// that does not leak outside the window (the neighbouring window belongs to another target).
bool Router::get_direct_mem_ptr(int, tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi) {
  const std::uint64_t address = trans.get_address();
  const std::optional<Decoded> hit = m_map.decode(address, 1);
  if (!hit) return false;
  const AddressWindow& w = *hit->window;
  trans.set_address(hit->offset);
  const bool granted = out[static_cast<int>(w.port)]->get_direct_mem_ptr(trans, dmi);
  trans.set_address(address);
  // Granted or not, the range describes where the answer holds; translate it either way. The
  // pointer addresses the start byte, which does not move, so it stays as the target set it.
  const std::uint64_t first = std::min<std::uint64_t>(dmi.get_start_address(), w.size - 1);
  const std::uint64_t last = std::min<std::uint64_t>(dmi.get_end_address(), w.size - 1);
  dmi.set_start_address(w.base + first);
  dmi.set_end_address(w.base + last);
  return granted;
}

void Router::invalidate_direct_mem_ptr(int port, sc_dt::uint64 start, sc_dt::uint64 end) {
  for (const AddressWindow& w : m_map.windows()) {
    if (w.port != static_cast<unsigned>(port) || start > w.size - 1) continue;
    const std::uint64_t last = std::min<std::uint64_t>(end, w.size - 1);
    for (unsigned int i = 0; i < in.size(); ++i)
      in[static_cast<int>(i)]->invalidate_direct_mem_ptr(w.base + start, w.base + last);
  }
}

void Router::end_of_elaboration() {
  for (const AddressWindow& w : m_map.windows()) {
    if (w.port >= out.size()) {
      const std::string msg = std::string(name()) + ": window '" + w.name + "' maps to out[" +
                              std::to_string(w.port) + "], which is not bound";
      SC_REPORT_ERROR(kMsgType, msg.c_str());
    }
  }
}

std::string Router::summary() const {
  std::ostringstream text;
  text << name() << ": " << m_report.transactions << " transactions routed, " << m_report.address_errors
      << " address errors";
  return text.str();
}

void Router::end_of_simulation() {
  if (m_config.report_at_end) SC_REPORT_INFO(kMsgType, summary().c_str());
}

}  // namespace rc::tlmx
