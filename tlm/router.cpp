#include "tlm/router.h"

#include <algorithm>
#include <sstream>

#include "tlm/timing.h"

namespace rc::tlmx {

namespace {
constexpr const char* kRouterMsgType = "rc/tlmx/Router";
}

Router::Router(const sc_core::sc_module_name& name, const RouterConfig& config)
    : sc_core::sc_module(name), in("in"), out("out"), m_config(config),
      m_latency(cycles(config.latency_cycles, config.clock_period)),
      m_peq("held", this, &Router::deliver) {
  in.register_b_transport(this, &Router::b_transport);
  in.register_nb_transport_fw(this, &Router::nb_transport_fw);
  in.register_transport_dbg(this, &Router::transport_dbg);
  in.register_get_direct_mem_ptr(this, &Router::get_direct_mem_ptr);
  out.register_nb_transport_bw(this, &Router::nb_transport_bw);
  out.register_invalidate_direct_mem_ptr(this, &Router::invalidate_direct_mem_ptr);
}

void Router::map(std::uint64_t base, std::uint64_t size, unsigned port, const std::string& name) {
  m_map.add(AddressWindow{base, size, port, name.empty() ? "port " + std::to_string(port) : name});
}

void Router::unmapped(tlm::tlm_generic_payload& trans) {
  ++m_report.address_errors;
  std::ostringstream msg;
  msg << name() << ": no window holds address 0x" << std::hex << trans.get_address() << " + 0x"
      << bytes_touched(trans) << " bytes";
  SC_REPORT_WARNING(kRouterMsgType, msg.str().c_str());
  trans.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
}

void Router::b_transport(int, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  if (zero_length_transfer(trans)) return trans.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
  const std::uint64_t address = trans.get_address();
  const std::optional<Decoded> hit = m_map.decode(address, bytes_touched(trans));
  if (!hit) return unmapped(trans);
  ++m_report.transactions;
  delay += m_latency;
  trans.set_address(hit->offset);
  out[static_cast<int>(hit->window->port)]->b_transport(trans, delay);
  trans.set_address(address);  // the initiator gets its own view back
}

// ---- approximately timed (router.h: forwarding, exclusion rules, addresses) ----

namespace {
sc_core::sc_time now() { return sc_core::sc_time_stamp(); }
}  // namespace

Router::Hop& Router::target_hop(int port) {
  if (static_cast<std::size_t>(port) >= m_targets.size()) m_targets.resize(port + 1);
  return m_targets[port];
}

Router::Hop& Router::initiator_hop(int port) {
  if (static_cast<std::size_t>(port) >= m_initiators.size()) m_initiators.resize(port + 1);
  return m_initiators[port];
}

Router::Flight* Router::flight_of(const tlm::tlm_generic_payload& trans, const char* call) {
  const auto it = m_flights.find(&trans);
  if (it != m_flights.end()) return &it->second;
  const std::string msg = std::string(name()) + ": " + call + " for a transaction this router is not carrying";
  SC_REPORT_ERROR(kRouterMsgType, msg.c_str());
  return nullptr;
}

void Router::release(tlm::tlm_generic_payload& trans) {
  m_flights.erase(&trans);
  if (trans.has_mm()) trans.release();  // may free the payload: not touched after this
}

tlm::tlm_sync_enum Router::nb_transport_fw(int port, tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                           sc_core::sc_time& delay) {
  if (phase == tlm::BEGIN_REQ) return begin_request(port, trans, phase, delay);
  if (phase == tlm::END_RESP) return end_response(trans, delay);
  std::ostringstream msg;
  msg << name() << ": in[" << port << "]: phase " << phase << " is not a forward phase of the base protocol";
  SC_REPORT_ERROR(kRouterMsgType, msg.str().c_str());
  return tlm::TLM_COMPLETED;
}

tlm::tlm_sync_enum Router::begin_request(int port, tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                         sc_core::sc_time& delay) {
  if (zero_length_transfer(trans)) {
    trans.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return tlm::TLM_COMPLETED;  // no time, as for b_transport
  }
  const std::uint64_t address = trans.get_address();
  const std::optional<Decoded> hit = m_map.decode(address, bytes_touched(trans));
  if (!hit) {
    unmapped(trans);
    return tlm::TLM_COMPLETED;  // no time, as for b_transport
  }
  ++m_report.transactions;
  delay += m_latency;
  if (trans.has_mm()) trans.acquire();
  const Flight f{port, static_cast<int>(hit->window->port), address, hit->offset, now() + delay};
  m_flights[&trans] = f;
  Hop& target = target_hop(f.out_port);
  if (target.open != nullptr) {  // the target's request phase is taken: wait for its END_REQ
    m_flights[&trans].held_request = true;
    target.held.push_back(&trans);
    return tlm::TLM_ACCEPTED;
  }
  target.open = &trans;
  if (target.free_at > now() + delay) delay = target.free_at - now();
  trans.set_address(f.offset);
  const tlm::tlm_sync_enum answer = out[f.out_port]->nb_transport_fw(trans, phase, delay);
  return answered_directly(trans, answer, phase, delay);
}

// The target's answer to a BEGIN_REQ whose initiator is still in its call: passed back as the
// return value, unless the initiator holds another response (then END_REQ now, the response later).
tlm::tlm_sync_enum Router::answered_directly(tlm::tlm_generic_payload& trans, tlm::tlm_sync_enum answer,
                                             tlm::tlm_phase& phase, sc_core::sc_time& delay) {
  if (answer == tlm::TLM_ACCEPTED) return answer;
  request_ended(trans, now() + delay);  // END_REQ, or implied by BEGIN_RESP / TLM_COMPLETED
  if (answer == tlm::TLM_UPDATED && phase == tlm::END_REQ) return answer;
  Flight& f = m_flights.at(&trans);
  f.target_waits = answer == tlm::TLM_UPDATED;  // it responded with BEGIN_RESP: END_RESP goes to it
  Hop& initiator = initiator_hop(f.in_port);
  if (initiator.open != nullptr) {
    respond_later(trans, delay);
    phase = tlm::END_REQ;
    return tlm::TLM_UPDATED;
  }
  if (initiator.free_at > now() + delay) delay = initiator.free_at - now();
  trans.set_address(f.address);
  if (answer == tlm::TLM_UPDATED) {
    initiator.open = &trans;  // BEGIN_RESP by return: the initiator sends END_RESP on the forward path
    return answer;
  }
  initiator.free_at = now() + delay;
  release(trans);
  return answer;
}

// END_REQ and BEGIN_RESP from a target: to the initiator the request came from.
tlm::tlm_sync_enum Router::nb_transport_bw(int port, tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                           sc_core::sc_time& delay) {
  Flight* f = flight_of(trans, "nb_transport_bw");
  if (f == nullptr) return tlm::TLM_COMPLETED;
  if (phase == tlm::BEGIN_RESP) return begin_response(trans, phase, delay);
  if (phase != tlm::END_REQ) {
    std::ostringstream msg;
    msg << name() << ": out[" << port << "]: phase " << phase << " is not a backward phase of the base protocol";
    SC_REPORT_ERROR(kRouterMsgType, msg.str().c_str());
    return tlm::TLM_COMPLETED;
  }
  request_ended(trans, now() + delay);
  send_end_request(trans, phase, delay);
  return tlm::TLM_ACCEPTED;
}

// END_REQ to the initiator on the backward path. The initiator may end the transaction there
// (TLM_COMPLETED, IEEE 1666-2011 15.2): it gets no response, and the router finishes the target's
// side itself when the target's BEGIN_RESP comes (begin_response).
void Router::send_end_request(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase, sc_core::sc_time& delay) {
  Flight& f = m_flights.at(&trans);  // a reference into the map stays valid across the call
  const tlm::tlm_sync_enum answer = in[f.in_port]->nb_transport_bw(trans, phase, delay);
  if (answer == tlm::TLM_COMPLETED) {
    f.initiator_done = true;
  } else if (answer != tlm::TLM_ACCEPTED) {
    const std::string msg = std::string(name()) + ": in[" + std::to_string(f.in_port) +
                            "]: END_REQ must be answered TLM_ACCEPTED or TLM_COMPLETED";
    SC_REPORT_ERROR(kRouterMsgType, msg.c_str());
  }
}

// BEGIN_RESP from a target waiting for the answer: passed to a free initiator and its answer back.
tlm::tlm_sync_enum Router::begin_response(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                          sc_core::sc_time& delay) {
  request_ended(trans, now() + delay);  // implied END_REQ, if none came
  Flight& f = m_flights.at(&trans);
  if (f.initiator_done) {  // the initiator ended the transaction at END_REQ: the response ends here
    trans.set_address(f.address);
    release(trans);
    return tlm::TLM_COMPLETED;
  }
  Hop& initiator = initiator_hop(f.in_port);
  if (initiator.open != nullptr) {
    f.target_waits = true;
    respond_later(trans, delay);
    return tlm::TLM_ACCEPTED;
  }
  initiator.open = &trans;
  if (initiator.free_at > now() + delay) delay = initiator.free_at - now();
  trans.set_address(f.address);
  const tlm::tlm_sync_enum answer = in[f.in_port]->nb_transport_bw(trans, phase, delay);
  if (answer == tlm::TLM_ACCEPTED) {
    f.target_waits = true;
    return answer;
  }
  response_ended(trans, now() + delay);
  release(trans);
  return answer;  // TLM_UPDATED with END_RESP, or TLM_COMPLETED: the target's side ends with it
}

// END_RESP from the initiator: its response hop is free, and the target gets END_RESP if it waits.
tlm::tlm_sync_enum Router::end_response(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  Flight* f = flight_of(trans, "END_RESP");
  if (f == nullptr) return tlm::TLM_COMPLETED;
  if (initiator_hop(f->in_port).open != &trans) {
    SC_REPORT_ERROR(kRouterMsgType, (std::string(name()) + ": END_RESP for a transaction without an open response").c_str());
  }
  response_ended(trans, now() + delay);
  end_target_response(trans, delay);
  return tlm::TLM_COMPLETED;
}

// A held BEGIN_REQ whose turn has come (its target hop is reserved for it); the initiator was
// answered TLM_ACCEPTED, so the target's answer goes back as backward calls.
void Router::send_held_request(tlm::tlm_generic_payload& trans) {
  Flight& f = m_flights.at(&trans);
  trans.set_address(f.offset);
  tlm::tlm_phase phase = tlm::BEGIN_REQ;
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  const tlm::tlm_sync_enum answer = out[f.out_port]->nb_transport_fw(trans, phase, delay);
  if (answer == tlm::TLM_ACCEPTED) return;
  request_ended(trans, now() + delay);
  if (answer == tlm::TLM_UPDATED && phase == tlm::END_REQ) return send_end_request(trans, phase, delay);
  f.target_waits = answer == tlm::TLM_UPDATED;
  respond_later(trans, delay);
}

// A response for an initiator that is not in a call with the router: now if its hop is free, else
// held until the open response ends.
void Router::respond_later(tlm::tlm_generic_payload& trans, const sc_core::sc_time& delay) {
  Flight& f = m_flights.at(&trans);
  Hop& initiator = initiator_hop(f.in_port);
  f.due = now() + delay;
  if (initiator.open != nullptr) {
    initiator.held.push_back(&trans);
    return;
  }
  initiator.open = &trans;
  send_response(trans, delay);
}

// BEGIN_RESP on the backward path; the initiator's hop is reserved for this transaction.
void Router::send_response(tlm::tlm_generic_payload& trans, sc_core::sc_time delay) {
  const Flight& f = m_flights.at(&trans);
  const Hop& initiator = initiator_hop(f.in_port);
  if (initiator.free_at > now() + delay) delay = initiator.free_at - now();
  trans.set_address(f.address);
  tlm::tlm_phase phase = tlm::BEGIN_RESP;
  const tlm::tlm_sync_enum answer = in[f.in_port]->nb_transport_bw(trans, phase, delay);
  if (answer == tlm::TLM_ACCEPTED) return;  // END_RESP comes on the forward path
  response_ended(trans, now() + delay);
  end_target_response(trans, delay);
}

// The target's request phase is over at `at`: the next held request may go from then on.
void Router::request_ended(tlm::tlm_generic_payload& trans, const sc_core::sc_time& at) {
  Hop& target = target_hop(m_flights.at(&trans).out_port);
  if (target.open != &trans) return;  // already ended (END_REQ before BEGIN_RESP)
  target.open = nullptr;
  target.free_at = std::max(target.free_at, at);
  if (target.held.empty()) return;
  tlm::tlm_generic_payload* next = target.held.front();
  target.held.pop_front();
  target.open = next;  // reserved until its END_REQ
  m_peq.notify(*next, tlm::BEGIN_REQ, std::max(m_flights.at(next).due, target.free_at) - now());
}

// The initiator has ended a response at `at`: the next held response may go from then on.
void Router::response_ended(tlm::tlm_generic_payload& trans, const sc_core::sc_time& at) {
  Hop& initiator = initiator_hop(m_flights.at(&trans).in_port);
  if (initiator.open == &trans) initiator.open = nullptr;
  initiator.free_at = std::max(initiator.free_at, at);
  if (initiator.open != nullptr || initiator.held.empty()) return;
  tlm::tlm_generic_payload* next = initiator.held.front();
  initiator.held.pop_front();
  initiator.open = next;
  m_peq.notify(*next, tlm::BEGIN_RESP, std::max(m_flights.at(next).due, initiator.free_at) - now());
}

// The target's side ends: END_RESP if it waits for one (in its addresses), then the router lets go.
void Router::end_target_response(tlm::tlm_generic_payload& trans, sc_core::sc_time delay) {
  const Flight f = m_flights.at(&trans);
  if (f.target_waits) {
    trans.set_address(f.offset);
    tlm::tlm_phase phase = tlm::END_RESP;
    out[f.out_port]->nb_transport_fw(trans, phase, delay);
    trans.set_address(f.address);
  }
  release(trans);
}

void Router::deliver(tlm::tlm_generic_payload& trans, const tlm::tlm_phase& phase) {
  if (phase == tlm::BEGIN_REQ) {
    send_held_request(trans);
  } else {
    send_response(trans, sc_core::SC_ZERO_TIME);
  }
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
// Granted or refused, the range says where the answer holds, so it is translated either way; the
// pointer addresses the start byte, which does not move, so it stays as the target set it.
bool Router::get_direct_mem_ptr(int, tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi) {
  const std::uint64_t address = trans.get_address();
  const std::optional<Decoded> hit = m_map.decode(address, 1);
  if (!hit) {
    const AddressMap::Gap gap = *m_map.gap(address);  // no window holds it: refused over the gap
    dmi.set_dmi_ptr(nullptr);
    dmi.allow_none();
    dmi.set_start_address(gap.first);
    dmi.set_end_address(gap.last);
    return false;
  }
  const AddressWindow& w = *hit->window;
  trans.set_address(hit->offset);
  const bool granted = out[static_cast<int>(w.port)]->get_direct_mem_ptr(trans, dmi);
  trans.set_address(address);
  const std::uint64_t first = dmi.get_start_address();
  const std::uint64_t last = std::min<std::uint64_t>(dmi.get_end_address(), w.size - 1);
  if (first > hit->offset || last < hit->offset) {
    std::ostringstream msg;
    msg << name() << ": window '" << w.name << "': the target's DMI answer for 0x" << std::hex << hit->offset
        << " covers [0x" << dmi.get_start_address() << ", 0x" << dmi.get_end_address()
        << "], which does not hold that address";
    SC_REPORT_ERROR(kRouterMsgType, msg.str().c_str());
  }
  dmi.set_start_address(w.base + first);
  dmi.set_end_address(w.base + last);
  if (!granted) {
    dmi.set_dmi_ptr(nullptr);
    dmi.allow_none();  // a refusal grants nothing, whatever access the target left set
  }
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
      SC_REPORT_ERROR(kRouterMsgType, msg.c_str());
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
  if (m_config.report_at_end) SC_REPORT_INFO(kRouterMsgType, summary().c_str());
}

}  // namespace rc::tlmx
