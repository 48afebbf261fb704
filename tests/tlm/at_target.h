// An approximately-timed target for the interconnects' tests (the target half of the scripted AT
// pair; the initiators are in protocol_checker.h). It answers every BEGIN_REQ in one style, with
// END_REQ `accept` and BEGIN_RESP `respond` after the request (respond >= accept). It keeps the
// exclusion rules of its own socket as a target must (one response open at a time) and records what
// it saw. Without memory it answers TLM_OK_RESPONSE and fills reads with `fill_byte`; with
// `memory` set it is a small RAM with every payload feature (serve_from_memory below), so random
// traffic can be checked against a shadow copy. Bound on a simple_target_socket with only
// nb_transport registered, it is also an AT-only target: a b_transport call reaches it through the
// socket's b-to-nb adapter, which waits inside b_transport until the response.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/peq_with_cb_and_phase.h>
#include <tlm_utils/simple_target_socket.h>

namespace rc::tlmx::test {

// A RAM's answer to a payload, every feature of IEEE 1666-2011 clause 14 honoured, in this order:
// TLM_IGNORE_COMMAND OK; a read or write of 0 bytes TLM_BURST_ERROR_RESPONSE; the bytes the
// addresses span (the streaming width when below the length) not inside the memory
// TLM_ADDRESS_ERROR_RESPONSE; a byte-enable pointer with length 0 or an element the data uses that is
// neither 0x00 nor 0xFF TLM_BYTE_ENABLE_ERROR_RESPONSE; a streaming width of 0 TLM_BURST_ERROR_RESPONSE;
// otherwise byte i moves to / from address + i % streaming_width when element i % byte_enable_length
// is 0xFF (or there are no byte enables), TLM_OK_RESPONSE.
inline tlm::tlm_response_status serve_from_memory(std::vector<std::uint8_t>& memory, tlm::tlm_generic_payload& t) {
  if (t.get_command() == tlm::TLM_IGNORE_COMMAND) return tlm::TLM_OK_RESPONSE;
  const std::uint64_t length = t.get_data_length(), width = t.get_streaming_width();
  if (length == 0) return tlm::TLM_BURST_ERROR_RESPONSE;
  const std::uint64_t span = width != 0 && width < length ? width : length;
  if (t.get_address() > memory.size() || span > memory.size() - t.get_address()) return tlm::TLM_ADDRESS_ERROR_RESPONSE;
  const unsigned char* enables = t.get_byte_enable_ptr();
  const unsigned pattern = t.get_byte_enable_length();
  if (enables != nullptr) {
    if (pattern == 0) return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
    for (unsigned i = 0; i < std::min<std::uint64_t>(pattern, length); ++i)
      if (enables[i] != TLM_BYTE_ENABLED && enables[i] != TLM_BYTE_DISABLED) return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
  }
  if (width == 0) return tlm::TLM_BURST_ERROR_RESPONSE;
  unsigned char* data = t.get_data_ptr();
  for (std::uint64_t i = 0; i < length; ++i) {
    if (enables != nullptr && enables[i % pattern] != TLM_BYTE_ENABLED) continue;
    std::uint8_t& cell = memory[t.get_address() + i % width];
    if (t.is_read()) data[i] = cell; else cell = data[i];
  }
  return tlm::TLM_OK_RESPONSE;
}

class AtTarget : public sc_core::sc_module {
 public:
  // accepted: TLM_ACCEPTED, then END_REQ and BEGIN_RESP on the backward path;
  // end_req: TLM_UPDATED with END_REQ, then BEGIN_RESP on the backward path;
  // begin_resp: TLM_UPDATED with BEGIN_RESP (delay `respond`), END_RESP expected on the forward path;
  // completed: TLM_COMPLETED (delay `respond`).
  enum class Style { accepted, end_req, begin_resp, completed };

  tlm_utils::simple_target_socket<AtTarget> in;
  Style style;
  sc_core::sc_time accept, respond;
  unsigned char fill_byte = 0x5A;
  std::vector<std::uint8_t> memory;             // empty: no storage (reads give fill_byte)
  std::vector<std::uint64_t> addresses;        // address of each BEGIN_REQ as received
  std::vector<sc_core::sc_time> request_times;  // when each BEGIN_REQ took effect
  std::vector<std::string> violations;          // requests while a request phase was open
  std::uint64_t responses_ended = 0;            // transactions whose response is over (any way)

  AtTarget(const sc_core::sc_module_name& name, Style how, sc_core::sc_time accept_after,
           sc_core::sc_time respond_after)
      : sc_core::sc_module(name),
        in("in"),
        style(how),
        accept(accept_after),
        respond(respond_after),
        m_peq("phases", this, &AtTarget::send) {
    in.register_nb_transport_fw(this, &AtTarget::nb_transport_fw);
  }

  // Every request answered and every response ended.
  bool idle() const { return !m_request_open && m_response_open == nullptr && m_due.empty() && m_pending == 0; }

 private:
  tlm::tlm_sync_enum nb_transport_fw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase, sc_core::sc_time& delay) {
    if (phase == tlm::END_RESP) {
      if (m_response_open != &trans) violations.push_back(std::string(name()) + ": END_RESP without an open response");
      response_over();
      if (!m_due.empty()) {
        tlm::tlm_generic_payload* next = m_due.front();
        m_due.pop_front();
        m_peq.notify(*next, tlm::BEGIN_RESP, delay);
      }
      return tlm::TLM_COMPLETED;
    }
    addresses.push_back(trans.get_address());
    request_times.push_back(sc_core::sc_time_stamp() + delay);
    if (m_request_open) violations.push_back(std::string(name()) + ": BEGIN_REQ while a request phase is open");
    execute(trans);
    switch (style) {
      case Style::accepted:
        m_request_open = true;
        ++m_pending;
        m_peq.notify(trans, tlm::END_REQ, delay + accept);
        m_peq.notify(trans, tlm::BEGIN_RESP, delay + respond);
        return tlm::TLM_ACCEPTED;
      case Style::begin_resp:
        if (m_response_open == nullptr) {
          ++m_pending;
          m_response_open = &trans;
          phase = tlm::BEGIN_RESP;
          delay += respond;
          return tlm::TLM_UPDATED;
        }
        [[fallthrough]];  // a response is open (exclusion rule): END_REQ now, BEGIN_RESP after its END_RESP
      case Style::end_req:
        ++m_pending;
        m_peq.notify(trans, tlm::BEGIN_RESP, delay + respond);
        phase = tlm::END_REQ;
        delay += accept;
        return tlm::TLM_UPDATED;
      case Style::completed:
        ++responses_ended;
        delay += respond;
        return tlm::TLM_COMPLETED;
    }
    return tlm::TLM_COMPLETED;
  }

  void execute(tlm::tlm_generic_payload& trans) {
    if (!memory.empty()) return trans.set_response_status(serve_from_memory(memory, trans));
    if (trans.is_read()) std::fill_n(trans.get_data_ptr(), trans.get_data_length(), fill_byte);
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
  }

  void response_over() {
    m_response_open = nullptr;
    --m_pending;
    ++responses_ended;
  }

  void send(tlm::tlm_generic_payload& trans, const tlm::tlm_phase& phase) {
    if (phase == tlm::BEGIN_RESP && m_response_open != nullptr) {
      m_due.push_back(&trans);  // after the open response's END_RESP
      return;
    }
    tlm::tlm_phase p = phase;
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    if (phase == tlm::END_REQ) m_request_open = false;
    if (phase == tlm::BEGIN_RESP) {
      m_request_open = false;
      m_response_open = &trans;
    }
    const tlm::tlm_sync_enum answer = in->nb_transport_bw(trans, p, delay);
    if (phase != tlm::BEGIN_RESP || answer == tlm::TLM_ACCEPTED) return;
    response_over();  // TLM_COMPLETED, or TLM_UPDATED with END_RESP
    if (!m_due.empty()) {
      tlm::tlm_generic_payload* next = m_due.front();
      m_due.pop_front();
      m_peq.notify(*next, tlm::BEGIN_RESP, delay);
    }
  }

  bool m_request_open = false;
  tlm::tlm_generic_payload* m_response_open = nullptr;
  std::deque<tlm::tlm_generic_payload*> m_due;
  std::uint64_t m_pending = 0;  // requests taken whose response is not over
  tlm_utils::peq_with_cb_and_phase<AtTarget> m_peq;
};

}  // namespace rc::tlmx::test
