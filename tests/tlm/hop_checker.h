// A base-protocol checker that sits ON a hop (an interposer, tlm/hop_interposer.h): the initiator
// side binds to `in`, `out` binds to the target, and every call passes through unchanged in value
// and time, both directions: b_transport, nb_transport_fw/bw, get_direct_mem_ptr,
// invalidate_direct_mem_ptr, transport_dbg. On the way it records each breach of the TLM-2.0 rules
// (IEEE 1666-2011) it can see on its hop, with the clause:
//   - a payload as an initiator must start it (14.5 memory manager and reference count for
//     nb_transport, 14.8 option, 14.11 data pointer, 14.12 length, 14.14 byte-enable length,
//     14.15 streaming width, 14.16 DMI hint clear, 14.17 status incomplete);
//   - phase sequences per transaction (15.2.4), only forward phases forward and backward phases
//     backward (15.2.3), b_transport never inside an nb_transport sequence (15.2.10), the END_REQ
//     of an initiator that answered it TLM_COMPLETED followed by nothing (15.2);
//   - both exclusion rules on the hop (15.2.6: one open request, one open response);
//   - timing annotations never decreasing per transaction, a b_transport completing no earlier than
//     it was issued, and no annotation beyond `implausible_delay` (a wrapped-around negative
//     offset is about 2^64 ps) (15.2.7, 11.1.3);
//   - at the response: status set (14.17), the attributes nobody beyond the hop may change
//     unchanged (command, address, data pointer, length, byte-enable pointer, length and array,
//     streaming width, a write's data) (14.7), the response path the reverse of the request path
//     across all checkers and no interconnect turning an error into TLM_OK_RESPONSE (15.2.11, 14.7),
//     and a DMI hint that holds (14.16: get_direct_mem_ptr grants the address for the command);
//   - DMI: a descriptor handed in as initialised (11.2.5), a grant with a pointer and access over a
//     range holding the address, a refusal with no pointer and no access over a range holding the
//     address (the refusal says where it holds, docs/tlm.md), invalidations with start <= end;
//   - debug transport returning no more bytes than the data length (11.3.4).
// violations() lists them; unfinished() lists transactions still open on the hop (at the end of a
// test, a payload nobody finished). counts() says what passed, so a test can show it was not idle.
#pragma once

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <systemc>
#include <tlm>

#include "tlm/hop_interposer.h"

namespace rc::tlmx::test {

// The attributes an initiator sets and nobody else may change.
struct Attributes {
  tlm::tlm_command command = tlm::TLM_IGNORE_COMMAND;
  std::uint64_t address = 0;
  unsigned char* data = nullptr;
  unsigned int length = 0;
  unsigned char* byte_enable = nullptr;
  unsigned int byte_enable_length = 0;
  unsigned int streaming_width = 0;

  static Attributes of(const tlm::tlm_generic_payload& t) {
    return {t.get_command(),         t.get_address(),     t.get_data_ptr(),       t.get_data_length(),
            t.get_byte_enable_ptr(), t.get_byte_enable_length(), t.get_streaming_width()};
  }
  // The names of the attributes that differ in `now`, comma separated ("" if none).
  std::string changed_in(const Attributes& now) const {
    std::string names;
    auto note = [&](bool differs, const char* name) {
      if (differs) names += names.empty() ? name : std::string(", ") + name;
    };
    note(now.command != command, "command");
    note(now.address != address, "address");
    note(now.data != data, "data pointer");
    note(now.length != length, "data length");
    note(now.byte_enable != byte_enable, "byte-enable pointer");
    note(now.byte_enable_length != byte_enable_length, "byte-enable length");
    note(now.streaming_width != streaming_width, "streaming width");
    return names;
  }
};

struct HopCheckerConfig {
  // The bench sends malformed payloads on purpose (reads and writes of 0 bytes, byte-enable length 0,
  // streaming width 0) to check the answers: then those are not breaches of the initiator's.
  bool malformed_requests_expected = false;
  bool probe_dmi_hints = true;  // ask get_direct_mem_ptr where a response's DMI hint is set
  sc_core::sc_time implausible_delay = sc_core::sc_time(3600, sc_core::SC_SEC);
};

struct HopCounts {
  std::uint64_t b_transport = 0, nb_requests = 0, responses = 0, completed_at_end_req = 0;
  std::uint64_t dmi_requests = 0, dmi_grants = 0, invalidations = 0, debug = 0;
};

class HopChecker : public sc_core::sc_module,
                   public HopInterposer,
                   public tlm::tlm_fw_transport_if<>,
                   public tlm::tlm_bw_transport_if<> {
 public:
  tlm::tlm_target_socket<> in;
  tlm::tlm_initiator_socket<> out;

  explicit HopChecker(const sc_core::sc_module_name& name, const HopCheckerConfig& config = {})
      : sc_core::sc_module(name), in("in"), out("out"), m_config(config) {
    in.bind(*this);
    out.bind(*this);
  }

  tlm::tlm_target_socket<>& hop_in() override { return in; }
  tlm::tlm_initiator_socket<>& hop_out() override { return out; }

  const std::vector<std::string>& violations() const { return m_violations; }
  const HopCounts& counts() const { return m_counts; }
  // When each b_transport through the hop asked its target to act: sc_time_stamp() + delay.
  const std::vector<sc_core::sc_time>& b_transport_starts() const { return m_b_starts; }
  std::vector<std::string> unfinished() const {
    std::vector<std::string> open;
    for (const auto& [trans, state] : m_states)
      open.push_back(std::string(name()) + ": transaction at 0x" + hex(state.sent.address) + " still open");
    return open;
  }

  // ---- forward path ----
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) override {
    ++m_counts.b_transport;
    State& s = m_states[&trans];
    if (s.phase != Phase::none) breach(trans, "15.2.10 c", "b_transport inside an nb_transport sequence");
    check_initial(trans, "b_transport", false);
    ++s.b_calls;
    remember(trans, s);
    check_delay(trans, delay, "b_transport called");
    m_b_starts.push_back(sc_core::sc_time_stamp() + delay);
    const sc_core::sc_time issued = sc_core::sc_time_stamp() + delay;
    out->b_transport(trans, delay);
    check_delay(trans, delay, "b_transport returned");
    if (sc_core::sc_time_stamp() + delay < issued)
      breach(trans, "11.1.3", "b_transport completes at " + (sc_core::sc_time_stamp() + delay).to_string() +
                                  ", before it was issued at " + issued.to_string());
    State& after = m_states[&trans];
    check_response(trans, after, "b_transport");
    if (--after.b_calls == 0 && after.phase == Phase::none) m_states.erase(&trans);
  }

  tlm::tlm_sync_enum nb_transport_fw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay) override {
    const tlm::tlm_phase sent = phase;
    if (sent == tlm::BEGIN_REQ) {
      begin_request(trans, delay);
    } else if (sent == tlm::END_RESP) {
      State& s = m_states[&trans];
      if (s.phase != Phase::begin_resp) breach(trans, "15.2.4", "END_RESP without BEGIN_RESP");
      advance(trans, s, delay, "END_RESP");
      if (m_response_open == &trans) m_response_open = nullptr;
    } else {
      breach(trans, "15.2.3 c", "phase " + phase_name(sent) + " on the forward path");
    }
    const tlm::tlm_sync_enum answer = out->nb_transport_fw(trans, phase, delay);
    if (sent == tlm::END_RESP) {
      if (answer == tlm::TLM_UPDATED) breach(trans, "15.2.4", "END_RESP answered TLM_UPDATED");
      over(trans);
    } else if (sent == tlm::BEGIN_REQ) {
      forward_answer(trans, answer, phase, delay);
    }
    return answer;
  }

  bool get_direct_mem_ptr(tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi) override {
    ++m_counts.dmi_requests;
    if (dmi.get_dmi_ptr() != nullptr || !dmi.is_none_allowed() || dmi.get_start_address() != 0 ||
        dmi.get_end_address() != ~sc_dt::uint64{0} || dmi.get_read_latency() != sc_core::SC_ZERO_TIME ||
        dmi.get_write_latency() != sc_core::SC_ZERO_TIME)
      breach(trans, "11.2.5", "DMI descriptor handed in not initialised");
    const std::uint64_t address = trans.get_address();
    const bool granted = out->get_direct_mem_ptr(trans, dmi);
    if (trans.get_address() != address) breach(trans, "11.2.5", "DMI request's address not restored");
    const bool holds = dmi.get_start_address() <= address && address <= dmi.get_end_address();
    if (granted) {
      ++m_counts.dmi_grants;
      if (dmi.get_dmi_ptr() == nullptr || dmi.is_none_allowed() || !holds)
        breach(trans, "11.2.5", "DMI grant without a pointer, without access, or not holding the address");
    } else if (dmi.get_dmi_ptr() != nullptr || !dmi.is_none_allowed() || !holds) {
      breach(trans, "11.2.5", "DMI refusal with a pointer or an access, or whose range does not hold the address");
    }
    return granted;
  }

  unsigned int transport_dbg(tlm::tlm_generic_payload& trans) override {
    ++m_counts.debug;
    const unsigned int done = out->transport_dbg(trans);
    if (done > trans.get_data_length()) breach(trans, "11.3.4", "transport_dbg returned more bytes than the length");
    return done;
  }

  // ---- backward path ----
  tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay) override {
    const tlm::tlm_phase sent = phase;
    State& s = m_states[&trans];
    if (sent == tlm::END_REQ) {
      if (s.phase != Phase::begin_req) breach(trans, "15.2.4", "END_REQ out of sequence");
      advance(trans, s, delay, "END_REQ");
      s.phase = Phase::end_req;
      if (m_request_open == &trans) m_request_open = nullptr;
    } else if (sent == tlm::BEGIN_RESP) {
      if (s.phase != Phase::begin_req && s.phase != Phase::end_req)
        breach(trans, "15.2.4", m_done_at_end_req.count(&trans) != 0 ? "BEGIN_RESP after the initiator completed at END_REQ"
                                                                     : "BEGIN_RESP out of sequence");
      advance(trans, s, delay, "BEGIN_RESP");
      begin_response(trans, s);
    } else {
      breach(trans, "15.2.3 c", "phase " + phase_name(sent) + " on the backward path");
    }
    const tlm::tlm_sync_enum answer = in->nb_transport_bw(trans, phase, delay);
    if (answer == tlm::TLM_ACCEPTED) return answer;
    if (sent == tlm::END_REQ && answer == tlm::TLM_COMPLETED) {
      ++m_counts.completed_at_end_req;
      leave_path(trans, false);
      over(trans);
      m_done_at_end_req.insert(&trans);
      return answer;
    }
    if (sent != tlm::BEGIN_RESP || (answer == tlm::TLM_UPDATED && phase != tlm::END_RESP)) {
      breach(trans, "15.2.4", "answer " + std::to_string(answer) + " with phase " + phase_name(phase) + " to " +
                                  phase_name(sent) + " on the backward path");
    }
    if (answer == tlm::TLM_UPDATED) check_delay(trans, delay, "END_RESP returned");
    over(trans);
    return answer;
  }

  void invalidate_direct_mem_ptr(sc_dt::uint64 start, sc_dt::uint64 end) override {
    ++m_counts.invalidations;
    if (start > end) breach_text("11.2.5", "invalidate_direct_mem_ptr with start > end");
    in->invalidate_direct_mem_ptr(start, end);
  }

 private:
  enum class Phase { none, begin_req, end_req, begin_resp };
  struct State {
    Phase phase = Phase::none;
    unsigned b_calls = 0;
    sc_core::sc_time last = sc_core::SC_ZERO_TIME;
    Attributes sent;
    std::vector<unsigned char> data, enables;  // a write's data and the byte enables, as sent
  };
  // The checkers a payload passed on its way to the target, across all checkers (15.2.11).
  struct Path {
    std::vector<const HopChecker*> hops;
    bool answered = false, answered_ok = false;  // what the innermost hop answered so far
  };
  static std::unordered_map<const tlm::tlm_generic_payload*, Path>& paths() {
    static std::unordered_map<const tlm::tlm_generic_payload*, Path> all;
    return all;
  }

  static std::string hex(std::uint64_t v) {
    std::ostringstream s;
    s << std::hex << v;
    return s.str();
  }
  static std::string phase_name(const tlm::tlm_phase& p) {
    std::ostringstream s;
    s << p;
    return s.str();
  }

  void breach_text(const char* clause, const std::string& what) {
    m_violations.push_back(std::string(name()) + " at " + sc_core::sc_time_stamp().to_string() + ": " + what +
                           " (IEEE 1666-2011 " + clause + ")");
  }
  void breach(const tlm::tlm_generic_payload& trans, const char* clause, const std::string& what) {
    breach_text(clause, what + " [address 0x" + hex(trans.get_address()) + ", " +
                            std::to_string(trans.get_data_length()) + " bytes]");
  }

  void check_initial(tlm::tlm_generic_payload& trans, const char* call, bool non_blocking) {
    const bool data_command = trans.get_command() != tlm::TLM_IGNORE_COMMAND;
    if (non_blocking && !trans.has_mm()) breach(trans, "14.5 i", std::string(call) + " without a memory manager");
    if (non_blocking && trans.get_ref_count() == 0) breach(trans, "14.5 t", std::string(call) + " with reference count 0");
    if (trans.get_gp_option() != tlm::TLM_MIN_PAYLOAD) breach(trans, "14.8", "gp_option not TLM_MIN_PAYLOAD");
    if (data_command && trans.get_data_ptr() == nullptr) breach(trans, "14.11", "no data pointer");
    if (!m_config.malformed_requests_expected) {
      if (data_command && trans.get_data_length() == 0) breach(trans, "14.12", "read or write of 0 bytes");
      if (trans.get_byte_enable_ptr() != nullptr && trans.get_byte_enable_length() == 0)
        breach(trans, "14.14", "byte-enable pointer with length 0");
      if (trans.get_streaming_width() == 0) breach(trans, "14.15", "streaming width 0");
    }
    if (trans.is_dmi_allowed()) breach(trans, "14.16", "DMI hint set by the initiator");
    if (trans.get_response_status() != tlm::TLM_INCOMPLETE_RESPONSE)
      breach(trans, "14.17", "response status not TLM_INCOMPLETE_RESPONSE at the request");
  }

  void remember(tlm::tlm_generic_payload& trans, State& s) {
    m_done_at_end_req.erase(&trans);
    s.sent = Attributes::of(trans);
    s.last = sc_core::sc_time_stamp();
    const bool has_data = trans.is_write() && trans.get_data_ptr() != nullptr;
    s.data.assign(has_data ? trans.get_data_ptr() : nullptr, has_data ? trans.get_data_ptr() + trans.get_data_length() : nullptr);
    const unsigned char* be = trans.get_byte_enable_ptr();
    s.enables.assign(be, be == nullptr ? nullptr : be + trans.get_byte_enable_length());
    Path& p = paths()[&trans];
    if (p.hops.empty()) p = Path{};
    p.hops.push_back(this);
  }

  void check_delay(const tlm::tlm_generic_payload& trans, const sc_core::sc_time& delay, const char* where) {
    if (delay > m_config.implausible_delay)
      breach(trans, "15.2.7", std::string(where) + " with a delay of " + delay.to_string() +
                                  ": beyond any plausible annotation (a negative offset wrapped around?)");
  }

  void advance(const tlm::tlm_generic_payload& trans, State& s, const sc_core::sc_time& delay, const char* phase) {
    check_delay(trans, delay, phase);
    const sc_core::sc_time at = sc_core::sc_time_stamp() + delay;
    if (at < s.last) breach(trans, "15.2.7 c", std::string(phase) + " at " + at.to_string() +
                                               ", before the previous phase at " + s.last.to_string());
    s.last = std::max(s.last, at);
  }

  void begin_request(tlm::tlm_generic_payload& trans, const sc_core::sc_time& delay) {
    ++m_counts.nb_requests;
    State& s = m_states[&trans];
    if (s.phase != Phase::none || s.b_calls != 0) breach(trans, "15.2.4", "BEGIN_REQ while the payload is in a transaction");
    check_initial(trans, "nb_transport_fw", true);
    if (m_request_open != nullptr) breach(trans, "15.2.6 e", "BEGIN_REQ while another request on the hop is open");
    m_request_open = &trans;
    remember(trans, s);
    advance(trans, s, delay, "BEGIN_REQ");
    s.phase = Phase::begin_req;
  }

  // What the target side returned to a BEGIN_REQ.
  void forward_answer(tlm::tlm_generic_payload& trans, tlm::tlm_sync_enum answer, const tlm::tlm_phase& phase,
                      const sc_core::sc_time& delay) {
    if (answer == tlm::TLM_ACCEPTED) {
      if (phase != tlm::BEGIN_REQ) breach(trans, "15.2.4", "TLM_ACCEPTED with a changed phase");
      return;
    }
    State& s = m_states[&trans];
    if (answer == tlm::TLM_COMPLETED) {
      advance(trans, s, delay, "TLM_COMPLETED");
      if (m_request_open == &trans) m_request_open = nullptr;
      check_response(trans, s, "TLM_COMPLETED to BEGIN_REQ");
      return over(trans);
    }
    advance(trans, s, delay, "the returned phase");
    if (phase == tlm::END_REQ) {
      if (s.phase != Phase::begin_req) breach(trans, "15.2.4", "END_REQ returned out of sequence");
      s.phase = Phase::end_req;
      if (m_request_open == &trans) m_request_open = nullptr;
    } else if (phase == tlm::BEGIN_RESP) {
      begin_response(trans, s);
    } else {
      breach(trans, "15.2.4", "BEGIN_REQ answered TLM_UPDATED with phase " + phase_name(phase));
    }
  }

  void begin_response(tlm::tlm_generic_payload& trans, State& s) {
    if (m_request_open == &trans) m_request_open = nullptr;
    if (m_response_open != nullptr && m_response_open != &trans)
      breach(trans, "15.2.6 f", "BEGIN_RESP while another response on the hop is open");
    m_response_open = &trans;
    s.phase = Phase::begin_resp;
    check_response(trans, s, "BEGIN_RESP");
  }

  void check_response(tlm::tlm_generic_payload& trans, const State& s, const char* where) {
    ++m_counts.responses;
    if (trans.get_response_status() == tlm::TLM_INCOMPLETE_RESPONSE)
      breach(trans, "14.17", std::string(where) + ": response status left TLM_INCOMPLETE_RESPONSE");
    std::string changed = s.sent.changed_in(Attributes::of(trans));
    const bool data_changed = trans.is_write() && !s.data.empty() &&
                              !std::equal(s.data.begin(), s.data.end(), trans.get_data_ptr());
    const bool enables_changed = !s.enables.empty() && trans.get_byte_enable_ptr() != nullptr &&
                                 !std::equal(s.enables.begin(), s.enables.end(), trans.get_byte_enable_ptr());
    if (data_changed) changed += changed.empty() ? "write data" : ", write data";
    if (enables_changed) changed += changed.empty() ? "byte enables" : ", byte enables";
    if (!changed.empty()) breach(trans, "14.7", std::string(where) + ": attributes changed beyond the hop: " + changed);
    leave_path(trans, true);
    if (trans.is_dmi_allowed() && m_config.probe_dmi_hints) probe_dmi_hint(trans);
  }

  // The response passes this hop: it must be the innermost one still on the payload's path.
  void leave_path(const tlm::tlm_generic_payload& trans, bool responding) {
    auto it = paths().find(&trans);
    if (it == paths().end()) return;
    Path& p = it->second;
    if (responding && (p.hops.empty() || p.hops.back() != this))
      breach(trans, "15.2.11 a", "the response path is not the reverse of the request path");
    for (auto h = p.hops.begin(); h != p.hops.end(); ++h)
      if (*h == this) {
        p.hops.erase(h);
        break;
      }
    if (responding) {
      if (p.answered && !p.answered_ok && trans.is_response_ok())
        breach(trans, "14.7", "an interconnect turned an error response into TLM_OK_RESPONSE");
      p.answered = true;
      p.answered_ok = trans.is_response_ok();
    }
    if (p.hops.empty()) paths().erase(it);
  }

  void probe_dmi_hint(const tlm::tlm_generic_payload& trans) {
    tlm::tlm_generic_payload probe;
    probe.set_command(trans.get_command());
    probe.set_address(trans.get_address());
    tlm::tlm_dmi dmi;
    const bool granted = out->get_direct_mem_ptr(probe, dmi);
    const bool allowed = trans.is_write() ? dmi.is_write_allowed() : dmi.is_read_allowed();
    if (!granted || !allowed || dmi.get_start_address() > trans.get_address() || dmi.get_end_address() < trans.get_address())
      breach(trans, "14.16", "DMI hint set, but get_direct_mem_ptr does not grant the address for the command");
  }

  void over(const tlm::tlm_generic_payload& trans) {
    if (m_request_open == &trans) m_request_open = nullptr;
    if (m_response_open == &trans) m_response_open = nullptr;
    auto it = m_states.find(&trans);
    if (it != m_states.end() && it->second.b_calls == 0) m_states.erase(it);
  }

  HopCheckerConfig m_config;
  std::unordered_map<const tlm::tlm_generic_payload*, State> m_states;
  const tlm::tlm_generic_payload* m_request_open = nullptr;
  const tlm::tlm_generic_payload* m_response_open = nullptr;
  std::unordered_set<const tlm::tlm_generic_payload*> m_done_at_end_req;  // until the payload's next request
  std::vector<std::string> m_violations;
  HopCounts m_counts;
  std::vector<sc_core::sc_time> m_b_starts;
};

}  // namespace rc::tlmx::test
