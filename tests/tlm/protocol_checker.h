// Base-protocol checking initiators for the TLM parts' tests: an LT initiator (b_transport) and an
// AT initiator (nb_transport, BEGIN_REQ -> END_REQ -> BEGIN_RESP -> END_RESP) that drive any target
// or interconnect and record every breach of the TLM-2.0 base protocol rules (IEEE 1666-2011) they
// can see from the initiator's side:
//   - phases in order on the hop, and only the phases of the base protocol on each path;
//   - the exclusion rules: no BEGIN_RESP while another response on the socket is open;
//   - timing annotations that never decrease (each phase takes effect no earlier than the last);
//   - a response status set by the target (never left TLM_INCOMPLETE_RESPONSE);
//   - the attributes a target and the interconnects must leave alone as the initiator sees them
//     when the response reaches it: command, address, data pointer, data length, byte-enable
//     pointer and length, streaming width;
//   - a DMI hint that holds: dmi_allowed set means get_direct_mem_ptr grants the address for the
//     command;
//   - every payload given back to the memory manager once the transaction is over (AT).
// Each breach is a line in violations(); a test asserts it is empty. The outcome of each transaction
// (status, and the time each phase took effect) is returned for the test's exact timing checks.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/peq_with_cb_and_phase.h>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "tests/tlm/at_target.h"
#include "tests/tlm/hop_checker.h"

namespace rc::tlmx::test {

// One transaction as an initiator asks for it.
struct Request {
  tlm::tlm_command command = tlm::TLM_READ_COMMAND;
  std::uint64_t address = 0;
  unsigned char* data = nullptr;
  unsigned int length = 0;
  unsigned int streaming_width = 0;  // 0: equal to the length (no streaming)
  unsigned char* byte_enable = nullptr;
  unsigned int byte_enable_length = 0;
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;  // local time offset at which it is issued
};

inline Request read_request(std::uint64_t address, void* data, unsigned int length,
                            sc_core::sc_time delay = sc_core::SC_ZERO_TIME) {
  Request r;
  r.command = tlm::TLM_READ_COMMAND;
  r.address = address;
  r.data = static_cast<unsigned char*>(data);
  r.length = length;
  r.delay = delay;
  return r;
}

inline Request write_request(std::uint64_t address, void* data, unsigned int length,
                             sc_core::sc_time delay = sc_core::SC_ZERO_TIME) {
  Request r = read_request(address, data, length, delay);
  r.command = tlm::TLM_WRITE_COMMAND;
  return r;
}

// What came back, with the simulated time at which each phase took effect (sc_time_stamp() +
// annotated delay). For b_transport: request = the call's local time, response = the returned one.
struct Outcome {
  tlm::tlm_response_status status = tlm::TLM_INCOMPLETE_RESPONSE;
  bool dmi_hint = false;
  sc_core::sc_time request;                     // BEGIN_REQ
  std::optional<sc_core::sc_time> end_request;  // END_REQ received as such (AT)
  sc_core::sc_time response;                    // BEGIN_RESP, or TLM_COMPLETED
  sc_core::sc_time end_response;                // END_RESP (AT; equal to response when completed at once)
};

inline void fill(tlm::tlm_generic_payload& trans, const Request& r) {
  trans.set_command(r.command);
  trans.set_address(r.address);
  trans.set_data_ptr(r.data);
  trans.set_data_length(r.length);
  trans.set_streaming_width(r.streaming_width == 0 ? r.length : r.streaming_width);
  trans.set_byte_enable_ptr(r.byte_enable);
  trans.set_byte_enable_length(r.byte_enable_length);
  trans.set_dmi_allowed(false);
  trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
}

// Violations, each a line naming the initiator, the transaction and the rule.
class ViolationLog {
 public:
  explicit ViolationLog(std::string who) : m_who(std::move(who)) {}
  void add(const Request& r, const std::string& what) {
    std::ostringstream line;
    line << m_who << ": " << (r.command == tlm::TLM_READ_COMMAND ? "read" : r.command == tlm::TLM_WRITE_COMMAND ? "write" : "ignore")
         << " 0x" << std::hex << r.address << std::dec << " + " << r.length << " at "
         << sc_core::sc_time_stamp() << ": " << what;
    m_lines.push_back(line.str());
  }
  const std::vector<std::string>& lines() const { return m_lines; }

 private:
  std::string m_who;
  std::vector<std::string> m_lines;
};

// The checks made when a response reaches the initiator, LT or AT.
inline void check_response(tlm::tlm_generic_payload& trans, const Request& r, const Attributes& sent,
                           tlm::tlm_fw_transport_if<>& path, ViolationLog& log) {
  if (trans.get_response_status() == tlm::TLM_INCOMPLETE_RESPONSE)
    log.add(r, "response status left TLM_INCOMPLETE_RESPONSE");
  const std::string changed = sent.changed_in(Attributes::of(trans));
  if (!changed.empty()) log.add(r, "attributes changed on the way: " + changed);
  if (!trans.is_dmi_allowed()) return;
  // The hint says DMI would be granted here: ask, with a fresh payload and descriptor.
  tlm::tlm_generic_payload probe;
  probe.set_command(r.command);
  probe.set_address(r.address);
  tlm::tlm_dmi dmi;
  const bool granted = path.get_direct_mem_ptr(probe, dmi);
  const bool allowed = r.command == tlm::TLM_WRITE_COMMAND ? dmi.is_write_allowed() : dmi.is_read_allowed();
  if (!granted || !allowed || dmi.get_start_address() > r.address || dmi.get_end_address() < r.address)
    log.add(r, "DMI hint set, but get_direct_mem_ptr does not grant the address for the command");
}

// Owns the AT payloads; counts those not yet given back.
class PayloadPool : public tlm::tlm_mm_interface {
 public:
  tlm::tlm_generic_payload* take() {
    if (m_free.empty()) {
      m_all.push_back(std::make_unique<tlm::tlm_generic_payload>(this));
      m_free.push_back(m_all.back().get());
    }
    tlm::tlm_generic_payload* trans = m_free.back();
    m_free.pop_back();
    trans->acquire();
    return trans;
  }
  void free(tlm::tlm_generic_payload* trans) override {
    trans->reset();
    m_free.push_back(trans);
  }
  std::size_t in_use() const { return m_all.size() - m_free.size(); }

 private:
  std::vector<std::unique_ptr<tlm::tlm_generic_payload>> m_all;
  std::vector<tlm::tlm_generic_payload*> m_free;
};

// The socket of a checking initiator as a test sees it: the initiator's own socket is bound to a
// HopChecker inside it, so every call it makes (and every call a test makes through `->`) passes the
// checker; bind() binds the checker's far side to the target.
template <class Owner>
class CheckedSocket {
 public:
  CheckedSocket(const char* name, HopChecker& hop) : m_socket(name), m_hop(hop) { m_socket.bind(hop.in); }
  template <class Target>
  void bind(Target& target) { m_hop.out.bind(target); }
  tlm::tlm_fw_transport_if<>* operator->() { return m_socket.operator->(); }
  tlm_utils::simple_initiator_socket<Owner>& socket() { return m_socket; }

 private:
  tlm_utils::simple_initiator_socket<Owner> m_socket;
  HopChecker& m_hop;
};

// The checking initiators send malformed payloads on purpose (tests of the answers to them).
inline HopCheckerConfig initiator_hop_config() {
  HopCheckerConfig c;
  c.malformed_requests_expected = true;
  return c;
}

// The initiator's own breaches list, then its hop checker's, then transactions left open on the hop.
inline std::vector<std::string> all_violations(const ViolationLog& log, const HopChecker& hop) {
  std::vector<std::string> all = log.lines();
  all.insert(all.end(), hop.violations().begin(), hop.violations().end());
  const std::vector<std::string> open = hop.unfinished();
  all.insert(all.end(), open.begin(), open.end());
  return all;
}

// A loosely-timed initiator running `script` in its thread.
class LtInitiator : public sc_core::sc_module {
 public:
  HopChecker hop;
  CheckedSocket<LtInitiator> out;

  LtInitiator(const sc_core::sc_module_name& name, std::function<void(LtInitiator&)> script)
      : sc_core::sc_module(name),
        hop("hop", initiator_hop_config()),
        out("out", hop),
        m_script(std::move(script)),
        m_log(this->name()) {
    SC_HAS_PROCESS(LtInitiator);
    SC_THREAD(run);
  }

  // One b_transport at local offset r.delay; returns without waiting (the caller owns local time).
  Outcome transport(const Request& r) {
    tlm::tlm_generic_payload trans;
    fill(trans, r);
    const Attributes sent = Attributes::of(trans);
    sc_core::sc_time delay = r.delay;
    const sc_core::sc_time requested = sc_core::sc_time_stamp() + r.delay;  // the call may wait
    out->b_transport(trans, delay);
    if (sc_core::sc_time_stamp() + delay < requested) m_log.add(r, "b_transport completes before it was issued");
    check_response(trans, r, sent, *out.operator->(), m_log);
    Outcome o;
    o.status = trans.get_response_status();
    o.dmi_hint = trans.is_dmi_allowed();
    o.request = requested;
    o.response = o.end_response = sc_core::sc_time_stamp() + delay;
    return o;
  }

  std::vector<std::string> violations() const { return all_violations(m_log, hop); }
  bool finished() const { return m_finished; }

 private:
  void run() {
    m_script(*this);
    m_finished = true;
  }

  std::function<void(LtInitiator&)> m_script;
  ViolationLog m_log;
  bool m_finished = false;
};

// How the AT initiator answers a BEGIN_RESP: TLM_COMPLETED, TLM_UPDATED with END_RESP, or
// TLM_ACCEPTED followed by END_RESP on the forward path `hold` later. at_end_request: it answers an
// END_REQ on the backward path TLM_COMPLETED, ending the transaction there without a response (the
// base protocol allows it, 15.2); a BEGIN_RESP arriving later is a violation.
enum class EndResponse { completed, updated, accepted, at_end_request };

// An approximately-timed initiator running `script` in its thread. issue() sends BEGIN_REQ and
// returns at the end of the request phase (the next BEGIN_REQ may follow); finish() returns when
// the transaction is over, at its END_RESP time.
class AtInitiator : public sc_core::sc_module {
 public:
  HopChecker hop;
  CheckedSocket<AtInitiator> out;

  AtInitiator(const sc_core::sc_module_name& name, std::function<void(AtInitiator&)> script)
      : sc_core::sc_module(name),
        hop("hop", initiator_hop_config()),
        out("out", hop),
        m_script(std::move(script)),
        m_log(this->name()),
        m_end_responses("end_responses", this, &AtInitiator::send_end_response) {
    out.socket().register_nb_transport_bw(this, &AtInitiator::nb_transport_bw);
    SC_HAS_PROCESS(AtInitiator);
    SC_THREAD(run);
  }

  using Ticket = std::size_t;

  Ticket issue(const Request& r, EndResponse answer = EndResponse::completed,
               sc_core::sc_time hold = sc_core::SC_ZERO_TIME) {
    m_records.emplace_back();
    const Ticket ticket = m_records.size() - 1;
    Record& rec = m_records.back();
    rec.request = r;
    rec.answer = answer;
    rec.hold = hold;
    rec.trans = m_pool.take();
    fill(*rec.trans, r);
    rec.sent = Attributes::of(*rec.trans);
    rec.outcome.request = rec.last = sc_core::sc_time_stamp() + r.delay;
    m_active[rec.trans] = &rec;
    tlm::tlm_phase phase = tlm::BEGIN_REQ;
    sc_core::sc_time delay = r.delay;
    const tlm::tlm_sync_enum status = out->nb_transport_fw(*rec.trans, phase, delay);
    if (status == tlm::TLM_ACCEPTED && phase != tlm::BEGIN_REQ) m_log.add(r, "TLM_ACCEPTED with a changed phase");
    if (status == tlm::TLM_UPDATED) returned_phase(rec, phase, delay);
    if (status == tlm::TLM_COMPLETED) completed(rec, delay);
    while (!rec.request_over) sc_core::wait(rec.request_over_event);
    sync_to(rec.request_end);
    return ticket;
  }

  Outcome finish(Ticket ticket) {
    Record& rec = m_records.at(ticket);
    while (!rec.over) sc_core::wait(rec.over_event);
    sync_to(rec.outcome.end_response);
    return rec.outcome;
  }

  Outcome transport(const Request& r, EndResponse answer = EndResponse::completed,
                    sc_core::sc_time hold = sc_core::SC_ZERO_TIME) {
    return finish(issue(r, answer, hold));
  }

  std::vector<std::string> violations() const { return all_violations(m_log, hop); }
  std::size_t payloads_in_use() const { return m_pool.in_use(); }
  bool finished() const { return m_finished; }

 private:
  enum class Phase { begin_req, end_req, begin_resp, over };
  struct Record {
    Request request;
    EndResponse answer = EndResponse::completed;
    sc_core::sc_time hold;
    tlm::tlm_generic_payload* trans = nullptr;
    Attributes sent;
    Phase phase = Phase::begin_req;
    sc_core::sc_time last;         // when the last phase took effect
    sc_core::sc_time request_end;  // END_REQ, or what implied it
    Outcome outcome;
    bool request_over = false;
    bool over = false;
    sc_core::sc_event request_over_event, over_event;
  };

  void run() {
    m_script(*this);
    m_finished = true;
  }

  static void sync_to(const sc_core::sc_time& t) {
    if (t > sc_core::sc_time_stamp()) sc_core::wait(t - sc_core::sc_time_stamp());
  }

  // A phase taking effect at `at`: annotations must not go back in time.
  void advance(Record& rec, const sc_core::sc_time& at, const char* phase) {
    if (at < rec.last) {
      std::ostringstream what;
      what << phase << " at " << at << ", before the previous phase at " << rec.last << " (decreasing timing annotation)";
      m_log.add(rec.request, what.str());
    }
    rec.last = at;
  }

  void end_request(Record& rec, const sc_core::sc_time& at) {
    rec.request_end = at;
    rec.request_over = true;
    rec.request_over_event.notify();
  }

  void got_end_req(Record& rec, const sc_core::sc_time& at) {
    advance(rec, at, "END_REQ");
    if (rec.phase != Phase::begin_req) m_log.add(rec.request, "END_REQ out of order");
    rec.phase = Phase::end_req;
    rec.outcome.end_request = at;
    end_request(rec, at);
  }

  // A response: a BEGIN_RESP phase, or (phase false) TLM_COMPLETED returned to BEGIN_REQ, which is no
  // response phase: the exclusion rules (15.2.6) are about phases and do not apply to it.
  void got_begin_resp(Record& rec, const sc_core::sc_time& at, bool phase = true) {
    advance(rec, at, "BEGIN_RESP");
    if (rec.phase != Phase::begin_req && rec.phase != Phase::end_req) m_log.add(rec.request, "BEGIN_RESP out of order");
    if (phase && m_open_response != nullptr)
      m_log.add(rec.request, "BEGIN_RESP while another response on the socket is open (exclusion rule)");
    if (phase && at < m_responses_free_at)
      m_log.add(rec.request, "BEGIN_RESP before the END_RESP of the previous response (exclusion rule)");
    if (!rec.request_over) end_request(rec, at);
    rec.phase = Phase::begin_resp;
    rec.outcome.response = at;
    check_response(*rec.trans, rec.request, rec.sent, *out.operator->(), m_log);
    rec.outcome.status = rec.trans->get_response_status();
    rec.outcome.dmi_hint = rec.trans->is_dmi_allowed();
  }

  void over(Record& rec, const sc_core::sc_time& at, bool response_phase = true) {
    rec.outcome.end_response = at;
    if (m_open_response == &rec) m_open_response = nullptr;
    if (response_phase && rec.phase == Phase::begin_resp) m_responses_free_at = std::max(m_responses_free_at, at);
    rec.phase = Phase::over;
    m_active.erase(rec.trans);
    rec.trans->release();
    rec.trans = nullptr;
    rec.over = true;
    rec.over_event.notify();
  }

  // TLM_COMPLETED from the target side: request, response and its end all at `at`.
  void completed(Record& rec, const sc_core::sc_time& delay) {
    const sc_core::sc_time at = sc_core::sc_time_stamp() + delay;
    got_begin_resp(rec, at, false);
    over(rec, at, false);
  }

  // TLM_UPDATED returned to BEGIN_REQ: END_REQ, or BEGIN_RESP (after which END_RESP is ours to send).
  void returned_phase(Record& rec, const tlm::tlm_phase& phase, const sc_core::sc_time& delay) {
    const sc_core::sc_time at = sc_core::sc_time_stamp() + delay;
    if (phase == tlm::END_REQ) return got_end_req(rec, at);
    if (phase != tlm::BEGIN_RESP) return m_log.add(rec.request, "TLM_UPDATED to a phase other than END_REQ or BEGIN_RESP");
    got_begin_resp(rec, at);
    m_open_response = &rec;
    m_end_responses.notify(*rec.trans, tlm::END_RESP, delay + rec.hold);
  }

  tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase, sc_core::sc_time& delay) {
    const auto it = m_active.find(&trans);
    if (it == m_active.end()) {
      m_log.add(Request{}, "nb_transport_bw for a transaction not in flight");
      return tlm::TLM_COMPLETED;
    }
    Record& rec = *it->second;
    const sc_core::sc_time at = sc_core::sc_time_stamp() + delay;
    if (phase == tlm::END_REQ) {
      got_end_req(rec, at);
      if (rec.answer != EndResponse::at_end_request) return tlm::TLM_ACCEPTED;
      over(rec, at);  // no response: status and response time stay as they were
      return tlm::TLM_COMPLETED;
    }
    if (phase != tlm::BEGIN_RESP) {
      m_log.add(rec.request, "a phase other than END_REQ or BEGIN_RESP on the backward path");
      return tlm::TLM_COMPLETED;
    }
    got_begin_resp(rec, at);
    switch (rec.answer) {
      case EndResponse::at_end_request:  // the response implied END_REQ: too late to decline it
      case EndResponse::completed:
        over(rec, at);
        return tlm::TLM_COMPLETED;
      case EndResponse::updated:
        over(rec, at);
        phase = tlm::END_RESP;
        return tlm::TLM_UPDATED;
      case EndResponse::accepted:
        break;
    }
    m_open_response = &rec;
    m_end_responses.notify(trans, tlm::END_RESP, delay + rec.hold);
    return tlm::TLM_ACCEPTED;
  }

  void send_end_response(tlm::tlm_generic_payload& trans, const tlm::tlm_phase&) {
    Record& rec = *m_active.at(&trans);
    const sc_core::sc_time at = sc_core::sc_time_stamp();
    advance(rec, at, "END_RESP");
    // Given with the call: the target side may send the next BEGIN_RESP from inside it.
    m_open_response = nullptr;
    m_responses_free_at = std::max(m_responses_free_at, at);
    tlm::tlm_phase phase = tlm::END_RESP;
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    const tlm::tlm_sync_enum status = out->nb_transport_fw(trans, phase, delay);
    if (status == tlm::TLM_UPDATED) m_log.add(rec.request, "END_RESP answered TLM_UPDATED");
    over(rec, at);
  }

  std::function<void(AtInitiator&)> m_script;
  ViolationLog m_log;
  PayloadPool m_pool;
  std::deque<Record> m_records;  // stable addresses
  std::unordered_map<const tlm::tlm_generic_payload*, Record*> m_active;
  Record* m_open_response = nullptr;  // BEGIN_RESP received, END_RESP not yet sent
  sc_core::sc_time m_responses_free_at = sc_core::SC_ZERO_TIME;
  tlm_utils::peq_with_cb_and_phase<AtInitiator> m_end_responses;
  bool m_finished = false;
};

}  // namespace rc::tlmx::test
