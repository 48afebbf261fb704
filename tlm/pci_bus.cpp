#include "tlm/pci_bus.h"

#include <algorithm>
#include <sstream>

#include "tlm/programmed_io_extension.h"
#include "tlm/timing.h"

namespace rc::tlmx {

namespace {
constexpr const char* kPciBusMsgType = "rc/tlmx/PciBus";
}

PciBus::PciBus(const sc_core::sc_module_name& name, const PciBusConfig& config)
    : sc_core::sc_module(name), in("in"), out("out"), m_config(config), m_peq("responses", this, &PciBus::deliver) {
  if (m_config.width_bits == 0 || m_config.width_bits % 8 != 0)
    SC_REPORT_ERROR(kPciBusMsgType, "width_bits must be a positive multiple of 8 (PCI: 32 or 64)");
  if (!(m_config.burst_efficiency > 0.0 && m_config.burst_efficiency <= 1.0))
    SC_REPORT_ERROR(kPciBusMsgType, "burst_efficiency must be in (0, 1]");
  if (m_config.max_burst_bytes == 0) SC_REPORT_ERROR(kPciBusMsgType, "max_burst_bytes must be positive");
  in.register_b_transport(this, &PciBus::b_transport);
  in.register_nb_transport_fw(this, &PciBus::nb_transport_fw);
  in.register_transport_dbg(this, &PciBus::transport_dbg);
  in.register_get_direct_mem_ptr(this, &PciBus::get_direct_mem_ptr);
  out.register_invalidate_direct_mem_ptr(this, &PciBus::invalidate_direct_mem_ptr);
  SC_HAS_PROCESS(PciBus);
  SC_THREAD(carry_requests_thread);
}

void PciBus::map(std::uint64_t base, std::uint64_t size, unsigned port, const std::string& name) {
  m_map.add(AddressWindow{base, size, port, name.empty() ? "port " + std::to_string(port) : name});
}

std::uint64_t PciBus::burst_cycles(std::uint64_t bytes) const {
  const std::uint64_t beats = ceil_div(bytes, m_config.width_bits / 8);
  return m_config.setup_cycles + ceil_over_efficiency(beats, m_config.burst_efficiency);
}

sc_core::sc_time PciBus::transfer_time(std::uint64_t bytes) const {
  const std::uint64_t max = m_config.max_burst_bytes;
  std::uint64_t total = (bytes / max) * burst_cycles(max);
  const std::uint64_t rest = bytes % max;
  if (rest != 0 || bytes == 0) total += burst_cycles(rest);
  return cycles(total, m_config.clock_period);
}

sc_core::sc_time PciBus::programmed_io_time(std::uint64_t bytes, unsigned access_bytes, bool read,
                                            const sc_core::sc_time& read_round_trip) const {
  if (access_bytes == 0) SC_REPORT_ERROR(kPciBusMsgType, "programmed I/O needs access_bytes > 0");
  const std::uint64_t accesses = ceil_div(bytes, access_bytes);
  // In time units: one access is its burst's cycles plus a read's round trip (what cycles() and
  // sc_time's + compute, one conversion instead of three on every programmed I/O transaction).
  const sc_core::sc_time::value_type one =
      m_config.clock_period.value() * burst_cycles(access_bytes) + (read ? read_round_trip.value() : 0);
  return sc_core::sc_time::from_value(one * accesses);
}

// The target sees the window-relative address and, as its delay, the offset at which the
// transaction starts on the bus (zero if that is already past: an offset is never negative). It
// returns its own delay D_t added, possibly after waiting inside b_transport (an AT-only target
// behind its socket's b-to-nb adapter), so the completion is taken after the call: the time then
// plus the returned delay. The initiator gets its own address back.
sc_core::sc_time PciBus::forward(tlm::tlm_generic_payload& trans, const Decoded& hit, const sc_core::sc_time& start) {
  const std::uint64_t address = trans.get_address();
  const sc_core::sc_time now = sc_core::sc_time_stamp();
  sc_core::sc_time target_delay = start > now ? start - now : sc_core::SC_ZERO_TIME;
  trans.set_address(hit.offset);
  out[static_cast<int>(hit.window->port)]->b_transport(trans, target_delay);
  trans.set_address(address);
  trans.set_dmi_allowed(false);  // the target may offer DMI, but not through this bus
  return sc_core::sc_time_stamp() + target_delay;
}

// No window claims the address: nobody asserts DEVSEL, the initiator times out.
sc_core::sc_time PciBus::master_abort(tlm::tlm_generic_payload& trans) {
  std::ostringstream msg;
  msg << name() << ": no BAR window holds address 0x" << std::hex << trans.get_address() << " + 0x"
      << bytes_touched(trans) << " bytes (master abort)";
  SC_REPORT_WARNING(kPciBusMsgType, msg.str().c_str());
  trans.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
  return cycles(m_config.master_abort_cycles, m_config.clock_period);
}

// The bus's own time for the payload, before the target's wait states.
sc_core::sc_time PciBus::bus_time(const tlm::tlm_generic_payload& trans) const {
  const std::uint64_t bytes = trans.get_command() == tlm::TLM_IGNORE_COMMAND ? 0 : trans.get_data_length();
  const ProgrammedIoExtension* pio = trans.get_extension<ProgrammedIoExtension>();
  return pio != nullptr ? programmed_io_time(bytes, pio->access_bytes, trans.is_read(), pio->read_round_trip)
                        : transfer_time(bytes);
}

// One transaction, LT or AT alike, in its turn: arbitration at `request`, the target's call, the
// counters; then the next turn.
PciBus::Carried PciBus::carry(int port, tlm::tlm_generic_payload& trans, const sc_core::sc_time& request) {
  const std::optional<Decoded> hit = m_map.decode(trans.get_address(), bytes_touched(trans));
  PciBus& arbiter = *m_arbiter;
  const sc_core::sc_time start = start_for(request);
  const sc_core::sc_time end = hit ? std::max(start + bus_time(trans), forward(trans, *hit, start))
                                   : start + master_abort(trans);
  arbiter.m_bus_free_at = end;
  PciInitiatorReport& c = counters(port);
  count(c, trans, end - start, start - request);
  if (!hit) ++c.address_errors;
  ++arbiter.m_serving;
  arbiter.m_turn_changed.notify();
  return {start, end};
}

// Returns when it is `ticket`'s turn on the bus: at once, unless a target is waiting inside
// b_transport for an earlier transaction. AT requests of this bus whose turn comes first are
// carried from here (so none is overtaken); those of a bus sharing the arbitration by its own thread.
// When a transaction requested at `request` starts, in its turn: when the bus is free.
sc_core::sc_time PciBus::start_for(const sc_core::sc_time& request) const {
  return std::max(request, m_arbiter->m_bus_free_at);
}

void PciBus::wait_for_turn(std::uint64_t ticket) {
  for (;;) {
    carry_queued_requests();
    if (m_arbiter->m_serving == ticket) return;
    sc_core::wait(m_arbiter->m_turn_changed);
  }
}

void PciBus::b_transport(int port, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  if (zero_length_transfer(trans)) return trans.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
  const sc_core::sc_time request = sc_core::sc_time_stamp() + delay;  // the call's local time
  wait_for_turn(m_arbiter->m_tickets++);
  const Carried carried = carry(port, trans, request);
  // Time may have moved (a target waited, or this call waited for one): never a negative offset.
  const sc_core::sc_time now = sc_core::sc_time_stamp();
  delay = carried.end > now ? carried.end - now : sc_core::SC_ZERO_TIME;
}

// ---- approximately timed ----

PciBus::AtPort& PciBus::at_port(int port) {
  if (static_cast<std::size_t>(port) >= m_at_ports.size()) m_at_ports.resize(port + 1);
  return m_at_ports[port];
}

void PciBus::protocol_error(int port, const std::string& what) const {
  const std::string msg = std::string(name()) + ": in[" + std::to_string(port) + "]: " + what;
  SC_REPORT_ERROR(kPciBusMsgType, msg.c_str());
}

tlm::tlm_sync_enum PciBus::nb_transport_fw(int port, tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                           sc_core::sc_time& delay) {
  if (phase == tlm::BEGIN_REQ && zero_length_transfer(trans)) {
    trans.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return tlm::TLM_COMPLETED;  // at once, as for b_transport
  }
  if (phase == tlm::BEGIN_REQ) {
    AtPort& p = at_port(port);
    if (p.request_open) protocol_error(port, "BEGIN_REQ before the END_REQ of the previous request (exclusion rule)");
    p.request_open = true;
    if (trans.has_mm()) trans.acquire();
    m_at_port_of[&trans] = port;
    m_requests.push_back({port, &trans, sc_core::sc_time_stamp() + delay, m_arbiter->m_tickets++});
    m_request_arrived.notify();  // immediate: carried in this evaluation phase, before time moves
    return tlm::TLM_ACCEPTED;
  }
  if (phase == tlm::END_RESP) {
    if (at_port(port).responding != &trans) protocol_error(port, "END_RESP for a transaction without an open response");
    end_response_at(port, trans, delay);
    return tlm::TLM_COMPLETED;
  }
  std::ostringstream what;
  what << "phase " << phase << " is not a forward phase of the base protocol";
  protocol_error(port, what.str());
  return tlm::TLM_COMPLETED;
}

// With no AT request queued, a turn on the bus concerns this thread not at all: it then waits for a
// request alone, so the loosely-timed traffic (every b_transport ends a turn) does not wake it.
void PciBus::carry_requests_thread() {
  for (;;) {
    carry_queued_requests();  // first: requests may arrive before this thread first runs
    if (m_requests.empty()) {
      sc_core::wait(m_request_arrived);
    } else {
      sc_core::wait(m_request_arrived | m_arbiter->m_turn_changed);
    }
  }
}

// Carries the queued AT requests whose turn it is, in arrival order (always from a thread: targets
// get b_transport), sends END_REQ at each one's start and schedules its BEGIN_RESP at its end. An
// initiator may end the transaction at END_REQ (TLM_COMPLETED, 15.2): it gets no response; the
// target's side is over already (its b_transport has returned).
void PciBus::carry_queued_requests() {
  while (!m_requests.empty() && m_requests.front().ticket == m_arbiter->m_serving) {
    const AtRequest r = m_requests.front();
    m_requests.pop_front();
    const bool respond = end_request(r.port, *r.trans, start_for(r.request));
    const Carried carried = carry(r.port, *r.trans, r.request);
    if (!respond) {  // the initiator ended the transaction at END_REQ: no response
      m_at_port_of.erase(r.trans);
      if (r.trans->has_mm()) r.trans->release();
      continue;
    }
    const sc_core::sc_time now = sc_core::sc_time_stamp();
    m_peq.notify(*r.trans, tlm::BEGIN_RESP, carried.end > now ? carried.end - now : sc_core::SC_ZERO_TIME);
  }
}

// END_REQ at `start`, when the bus takes the transaction (before the target's call, which may
// wait); false if the initiator answers TLM_COMPLETED and wants no response.
bool PciBus::end_request(int port, tlm::tlm_generic_payload& trans, const sc_core::sc_time& start) {
  at_port(port).request_open = false;
  const sc_core::sc_time now = sc_core::sc_time_stamp();
  tlm::tlm_phase phase = tlm::END_REQ;
  sc_core::sc_time delay = start > now ? start - now : sc_core::SC_ZERO_TIME;
  const tlm::tlm_sync_enum answer = in[port]->nb_transport_bw(trans, phase, delay);
  if (answer == tlm::TLM_COMPLETED) return false;
  if (answer != tlm::TLM_ACCEPTED) protocol_error(port, "END_REQ must be answered TLM_ACCEPTED or TLM_COMPLETED");
  return true;
}

void PciBus::deliver(tlm::tlm_generic_payload& trans, const tlm::tlm_phase& phase) {
  const int port = m_at_port_of.at(&trans);
  if (phase == tlm::END_RESP) return response_ended(port, trans);
  AtPort& p = at_port(port);
  if (p.responding != nullptr) {
    p.due.push_back(&trans);  // BEGIN_RESP exclusion: after the open response's END_RESP
  } else {
    send_response(port, trans);
  }
}

void PciBus::send_response(int port, tlm::tlm_generic_payload& trans) {
  at_port(port).responding = &trans;
  tlm::tlm_phase phase = tlm::BEGIN_RESP;
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  const tlm::tlm_sync_enum answer = in[port]->nb_transport_bw(trans, phase, delay);
  if (answer == tlm::TLM_ACCEPTED) return;  // END_RESP comes on the forward path
  if (answer == tlm::TLM_UPDATED && phase != tlm::END_RESP) protocol_error(port, "BEGIN_RESP updated to a phase other than END_RESP");
  end_response_at(port, trans, delay);
}

// END_RESP at sc_time_stamp() + delay: the port's next response may go from then on.
void PciBus::end_response_at(int port, tlm::tlm_generic_payload& trans, const sc_core::sc_time& delay) {
  if (delay == sc_core::SC_ZERO_TIME) return response_ended(port, trans);
  m_peq.notify(trans, tlm::END_RESP, delay);
}

void PciBus::response_ended(int port, tlm::tlm_generic_payload& trans) {
  AtPort& p = at_port(port);
  p.responding = nullptr;
  m_at_port_of.erase(&trans);
  if (trans.has_mm()) trans.release();  // may free the payload: not touched after this
  if (p.due.empty()) return;
  tlm::tlm_generic_payload* next = p.due.front();
  p.due.pop_front();
  send_response(port, *next);
}

unsigned int PciBus::transport_dbg(int, tlm::tlm_generic_payload& trans) {
  const std::optional<Decoded> hit = m_map.decode(trans.get_address(), 1);
  if (!hit) return 0;
  const std::uint64_t address = trans.get_address();
  const std::uint64_t room = hit->window->size - hit->offset;
  const unsigned int length = trans.get_data_length();
  trans.set_address(hit->offset);
  trans.set_data_length(static_cast<unsigned int>(std::min<std::uint64_t>(length, room)));
  const unsigned int done = out[static_cast<int>(hit->window->port)]->transport_dbg(trans);
  trans.set_address(address);
  trans.set_data_length(length);
  return done;
}

// Refused everywhere: every PCI access must be arbitrated and timed. The descriptor states the
// range the refusal holds for, the whole address space, with no access granted.
bool PciBus::get_direct_mem_ptr(int, tlm::tlm_generic_payload&, tlm::tlm_dmi& dmi) {
  dmi.set_dmi_ptr(nullptr);
  dmi.allow_none();
  dmi.set_start_address(0);
  dmi.set_end_address(~sc_dt::uint64{0});
  return false;
}

// The bus never passes a DMI grant to its initiators, so a target's invalidation concerns nobody.
void PciBus::invalidate_direct_mem_ptr(int, sc_dt::uint64, sc_dt::uint64) {}

void PciBus::share_arbitration_with(PciBus& owner) {
  if (sc_core::sc_get_status() != sc_core::SC_ELABORATION && sc_core::sc_get_status() != sc_core::SC_BEFORE_END_OF_ELABORATION) {
    SC_REPORT_ERROR(kPciBusMsgType, (std::string(name()) + ": share_arbitration_with must be called during elaboration").c_str());
  }
  PciBus* root = owner.m_arbiter;  // a chain of sharing ends at the bus that owns the arbitration
  if (root == this) SC_REPORT_ERROR(kPciBusMsgType, (std::string(name()) + ": cannot share arbitration with itself").c_str());
  if (m_sharers != 0) {
    SC_REPORT_ERROR(kPciBusMsgType, (std::string(name()) + ": other buses already share this bus's arbitration").c_str());
  }
  if (m_arbiter != this) --m_arbiter->m_sharers;
  m_arbiter = root;
  ++root->m_sharers;
}

PciInitiatorReport& PciBus::counters(int port) {
  if (static_cast<std::size_t>(port) >= m_initiators.size()) m_initiators.resize(port + 1);
  return m_initiators[port];
}

void PciBus::count(PciInitiatorReport& c, const tlm::tlm_generic_payload& trans, const sc_core::sc_time& occupancy,
                   const sc_core::sc_time& wait) {
  ++c.transactions;
  c.busy += occupancy;
  c.wait += wait;
  if (!trans.is_response_ok()) return;
  if (trans.is_write()) c.bytes_written += trans.get_data_length();
  if (trans.is_read()) c.bytes_read += trans.get_data_length();
}

void PciBus::end_of_elaboration() {
  m_initiators.resize(std::max<std::size_t>(m_initiators.size(), in.size()));
  for (const AddressWindow& w : m_map.windows()) {
    if (w.port >= out.size()) {
      const std::string msg = std::string(name()) + ": window '" + w.name + "' maps to out[" +
                              std::to_string(w.port) + "], which is not bound";
      SC_REPORT_ERROR(kPciBusMsgType, msg.c_str());
    }
  }
}

PciBusReport PciBus::report() const {
  PciBusReport r;
  r.initiators = m_initiators;
  r.bus_free_at = m_arbiter->m_bus_free_at;
  for (const PciInitiatorReport& c : m_initiators) {
    r.total.transactions += c.transactions;
    r.total.bytes_written += c.bytes_written;
    r.total.bytes_read += c.bytes_read;
    r.total.busy += c.busy;
    r.total.wait += c.wait;
    r.total.address_errors += c.address_errors;
  }
  return r;
}

std::string PciBus::summary() const {
  const PciBusReport r = report();
  std::ostringstream text;
  text << name() << ": " << r.total.transactions << " transactions, " << r.total.bytes_written << " B written, "
      << r.total.bytes_read << " B read, busy " << r.total.busy << ", arbitration wait " << r.total.wait
      << ", master aborts " << r.total.address_errors;
  for (std::size_t i = 0; i < r.initiators.size(); ++i) {
    const PciInitiatorReport& c = r.initiators[i];
    text << "\n  in[" << i << "]: " << c.transactions << " transactions, " << c.bytes_written << " B written, "
        << c.bytes_read << " B read, busy " << c.busy << ", wait " << c.wait << ", master aborts "
        << c.address_errors;
  }
  return text.str();
}

void PciBus::end_of_simulation() {
  if (m_config.report_at_end) SC_REPORT_INFO(kPciBusMsgType, summary().c_str());
}

}  // namespace rc::tlmx
