// Random traffic for the fuzz-style benches (random_traffic_test.cpp, tests/board): checking
// initiators (protocol_checker.h, each with its HopChecker) issue thousands of random transactions,
// loosely and approximately timed, from fixed seeds: every command, addresses inside the initiator's
// own region, straddling a window's end, in unmapped gaps and far away, lengths 0..64 at any
// alignment, byte enables (some invalid, some of length 0), streaming widths below and above the
// length, random delays and every way an initiator may end a response (END_RESP by return, later,
// or TLM_COMPLETED, and TLM_COMPLETED already at END_REQ).
//
// The oracle is the bench's own statement of the documented answers (docs/tlm.md, board/control_regs.h),
// written independently of the parts: a Space of windows, each a bank (SramBank: no streaming), a
// ram (AtTarget memory: streams) or the registers, with a shadow of their contents. Each initiator
// owns one region per window and writes only there (a write that would succeed elsewhere is turned
// into a read), so the shadow is exact for its own bytes whatever the interleaving; a read is
// checked byte by byte where the initiator owns the address.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tests/tlm/protocol_checker.h"

namespace rc::tlmx::test {

enum class TargetKind { bank, ram, regs };

struct ShadowWindow {
  std::uint64_t base = 0, size = 0;  // in the initiators' addresses
  TargetKind kind = TargetKind::bank;
  std::vector<std::uint8_t> bytes;   // the contents as the bench believes them
};

struct Region {
  std::uint64_t base = 0, size = 0;
};

// The windows the initiators see, and whether an interconnect decodes them (false: one target at 0).
struct Space {
  std::vector<ShadowWindow> windows;
  bool routed = true;
  std::uint64_t regs_plain_first = 0x10, regs_plain_end = 0x30, regs_size = 0x40;  // the registers' shadow (regs only)
};

// One random transaction as the oracle sees it: the request, its buffers, what must come back.
struct Trial {
  Request request;
  std::vector<std::uint8_t> data, enables;
  tlm::tlm_response_status expected = tlm::TLM_OK_RESPONSE;
  std::vector<int> expected_read;  // per byte: the value, or -1 where not checked
  EndResponse answer = EndResponse::completed;
  sc_core::sc_time hold;
};

// Statuses seen, by kind, so a bench can show its traffic was not all of one kind.
using StatusCounts = std::map<tlm::tlm_response_status, std::uint64_t>;

class TrafficOracle {
 public:
  TrafficOracle(Space& space, std::vector<Region> owned, unsigned seed) : m_space(space), m_owned(std::move(owned)), m_rng(seed) {}

  Trial next(bool approximately_timed) {
    Trial t;
    Request& r = t.request;
    const unsigned roll = pick(100);
    r.command = roll < 45 ? tlm::TLM_READ_COMMAND : roll < 92 ? tlm::TLM_WRITE_COMMAND : tlm::TLM_IGNORE_COMMAND;
    r.length = pick(100) < 3 ? 0 : 1 + pick(64);
    r.address = address(r.length);
    r.streaming_width = r.length == 0 ? 1 : pick(100) < 20 ? 1 + pick(r.length + 8) : r.length;
    if (pick(100) < 20) {
      t.enables.resize(pick(100) < 5 ? 0 : 1 + pick(8));
      for (std::uint8_t& e : t.enables) e = pick(100) < 4 ? 0x0F : pick(2) ? TLM_BYTE_ENABLED : TLM_BYTE_DISABLED;
      t.enables.push_back(0);  // storage exists even for a length of 0
      r.byte_enable = t.enables.data();
      r.byte_enable_length = static_cast<unsigned>(t.enables.size() - 1);
    }
    t.data.resize(r.length + 1);
    for (std::uint8_t& b : t.data) b = static_cast<std::uint8_t>(pick(256));
    r.data = t.data.data();
    r.delay = sc_core::sc_time(pick(approximately_timed ? 20 : 50), sc_core::SC_NS);
    const unsigned style = pick(100);
    t.answer = style < 30 ? EndResponse::completed : style < 55 ? EndResponse::updated
                                                    : style < 95 ? EndResponse::accepted : EndResponse::at_end_request;
    t.hold = sc_core::sc_time(pick(30), sc_core::SC_NS);
    expect(t);
    return t;
  }

  // Compares what came back with the oracle; a line per difference.
  void check(const Trial& t, const Outcome& o, std::vector<std::string>& errors) {
    if (t.answer == EndResponse::at_end_request && o.status == tlm::TLM_INCOMPLETE_RESPONSE) return;  // no response asked
    ++m_statuses[o.status];
    if (o.status != t.expected) return note(t, "status " + std::to_string(o.status) + ", expected " + std::to_string(t.expected), errors);
    for (std::size_t i = 0; i < t.expected_read.size(); ++i)
      if (t.expected_read[i] >= 0 && t.data[i] != t.expected_read[i])
        return note(t, "byte " + std::to_string(i) + " read " + std::to_string(t.data[i]) + ", expected " +
                           std::to_string(t.expected_read[i]), errors);
  }

  const StatusCounts& statuses() const { return m_statuses; }

 private:
  unsigned pick(unsigned n) { return std::uniform_int_distribution<unsigned>(0, n - 1)(m_rng); }

  std::uint64_t address(unsigned length) {
    const ShadowWindow& w = m_space.windows[pick(static_cast<unsigned>(m_space.windows.size()))];
    const Region& own = m_owned[&w - m_space.windows.data()];
    const unsigned roll = pick(100);
    if (roll < 75) return own.base + pick(static_cast<unsigned>(own.size));
    if (roll < 88) return w.base + w.size - 1 - pick(std::max(length, 1u) + 4);  // at or over the end
    if (roll < 96) return w.base + w.size + pick(64);                            // past it: a gap or the next window
    return ~std::uint64_t{0} - pick(128);                                       // far away
  }

  const ShadowWindow* decode(std::uint64_t address, std::uint64_t touched) const {
    for (const ShadowWindow& w : m_space.windows)
      if (address >= w.base && address - w.base < w.size && touched <= w.size - (address - w.base)) return &w;
    return nullptr;
  }

  bool owns(const ShadowWindow& w, std::uint64_t offset) const {
    const Region& own = m_owned[&w - m_space.windows.data()];
    return w.base + offset >= own.base && w.base + offset - own.base < own.size;
  }

  static bool enables_invalid(const Trial& t) {
    const Request& r = t.request;
    if (r.byte_enable == nullptr) return false;
    if (r.byte_enable_length == 0) return true;
    for (unsigned i = 0; i < std::min(r.byte_enable_length, r.length); ++i)
      if (r.byte_enable[i] != TLM_BYTE_ENABLED && r.byte_enable[i] != TLM_BYTE_DISABLED) return true;
    return false;
  }

  // The documented answer, in the documented order; an OK write goes into the shadow.
  void expect(Trial& t) {
    Request& r = t.request;
    const bool ignore = r.command == tlm::TLM_IGNORE_COMMAND;
    if (ignore && !m_space.routed) return void(t.expected = tlm::TLM_OK_RESPONSE);
    if (!ignore && r.length == 0) return void(t.expected = tlm::TLM_BURST_ERROR_RESPONSE);
    const std::uint64_t touched = r.streaming_width < r.length ? r.streaming_width : r.length;
    const ShadowWindow* w = decode(r.address, touched);
    if (w == nullptr) return void(t.expected = tlm::TLM_ADDRESS_ERROR_RESPONSE);
    const std::uint64_t offset = r.address - w->base;
    t.expected = ignore ? tlm::TLM_OK_RESPONSE : target_answer(t, *w, offset);
    if (t.expected != tlm::TLM_OK_RESPONSE || ignore) return;
    apply(t, *const_cast<ShadowWindow*>(w), offset);
  }

  tlm::tlm_response_status target_answer(const Trial& t, const ShadowWindow& w, std::uint64_t offset) const {
    const Request& r = t.request;
    if (w.kind == TargetKind::regs) {
      if (offset % 4 != 0) return tlm::TLM_ADDRESS_ERROR_RESPONSE;
      if (r.byte_enable != nullptr) return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
      return r.length % 4 != 0 || r.streaming_width < r.length ? tlm::TLM_BURST_ERROR_RESPONSE : tlm::TLM_OK_RESPONSE;
    }
    if (enables_invalid(t)) return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
    if (w.kind == TargetKind::bank && r.streaming_width < r.length) return tlm::TLM_BURST_ERROR_RESPONSE;
    return tlm::TLM_OK_RESPONSE;
  }

  // The byte offsets the transaction moves (-1: disabled), in data order.
  std::vector<std::int64_t> cells(const Trial& t, const ShadowWindow& w, std::uint64_t offset) const {
    const Request& r = t.request;
    std::vector<std::int64_t> at(r.length, -1);
    for (unsigned i = 0; i < r.length; ++i) {
      if (r.byte_enable != nullptr && r.byte_enable[i % r.byte_enable_length] != TLM_BYTE_ENABLED) continue;
      at[i] = static_cast<std::int64_t>(offset + (w.kind == TargetKind::ram ? i % r.streaming_width : i));
    }
    return at;
  }

  void apply(Trial& t, ShadowWindow& w, std::uint64_t offset) {
    Request& r = t.request;
    const std::vector<std::int64_t> at = cells(t, w, offset);
    const bool write = r.command == tlm::TLM_WRITE_COMMAND;
    bool all_owned = true;
    for (std::int64_t a : at) all_owned = all_owned && (a < 0 || owns(w, static_cast<std::uint64_t>(a)));
    if (write && !all_owned) r.command = tlm::TLM_READ_COMMAND;  // never into another initiator's bytes
    if (r.command == tlm::TLM_WRITE_COMMAND) {
      for (unsigned i = 0; i < r.length; ++i)
        if (at[i] >= 0) store(w, static_cast<std::uint64_t>(at[i]), t.data[i]);
      return;
    }
    t.expected_read.assign(r.length, -1);
    for (unsigned i = 0; i < r.length; ++i) {
      t.data[i] = 0xCD;  // what a disabled byte keeps
      if (at[i] < 0) t.expected_read[i] = 0xCD;
      else if (owns(w, static_cast<std::uint64_t>(at[i]))) t.expected_read[i] = load(w, static_cast<std::uint64_t>(at[i]));
      else if (w.kind == TargetKind::regs && static_cast<std::uint64_t>(at[i]) >= m_space.regs_size) t.expected_read[i] = 0;
    }
  }

  // The registers: plain ones hold what is written, beyond the register file reads 0 and writes vanish.
  void store(ShadowWindow& w, std::uint64_t offset, std::uint8_t v) {
    if (w.kind != TargetKind::regs || (offset >= m_space.regs_plain_first && offset < m_space.regs_plain_end)) w.bytes[offset] = v;
  }
  int load(const ShadowWindow& w, std::uint64_t offset) const {
    if (w.kind != TargetKind::regs) return w.bytes[offset];
    if (offset >= m_space.regs_plain_first && offset < m_space.regs_plain_end) return w.bytes[offset];
    return offset >= m_space.regs_size ? 0 : -1;
  }

  void note(const Trial& t, const std::string& what, std::vector<std::string>& errors) const {
    std::ostringstream line;
    line << (t.request.command == tlm::TLM_READ_COMMAND ? "read" : t.request.command == tlm::TLM_WRITE_COMMAND ? "write" : "ignore")
         << " 0x" << std::hex << t.request.address << std::dec << " + " << t.request.length << " (streaming "
         << t.request.streaming_width << ", byte enables " << t.request.byte_enable_length << "): " << what;
    if (errors.size() < 20) errors.push_back(line.str());
  }

  Space& m_space;
  std::vector<Region> m_owned;
  std::mt19937 m_rng;
  StatusCounts m_statuses;
};

// Trials whose buffers must outlive the scripts (until the process ends).
inline std::vector<std::shared_ptr<std::deque<Trial>>>& kept_trials() {
  static std::vector<std::shared_ptr<std::deque<Trial>>> kept;
  return kept;
}

// Scripts: `count` random transactions, LT one at a time, AT with up to three in flight.
inline std::function<void(LtInitiator&)> lt_traffic(TrafficOracle& oracle, unsigned count, std::vector<std::string>& errors) {
  return [&oracle, count, &errors](LtInitiator& self) {
    for (unsigned i = 0; i < count; ++i) {
      Trial t = oracle.next(false);
      const Outcome o = self.transport(t.request);
      oracle.check(t, o, errors);
      sc_core::wait(o.response - sc_core::sc_time_stamp());  // synced: the next one is issued after this one
    }
  };
}

// Every trial is kept to the end: an initiator that ends a transaction at END_REQ leaves its data
// buffer to the interconnect, which may still carry the transaction.
inline std::function<void(AtInitiator&)> at_traffic(TrafficOracle& oracle, unsigned count, std::vector<std::string>& errors) {
  return [&oracle, count, &errors](AtInitiator& self) {
    auto trials = std::make_shared<std::deque<Trial>>();
    std::deque<std::pair<Trial*, AtInitiator::Ticket>> in_flight;
    for (unsigned i = 0; i < count || !in_flight.empty();) {
      if (i < count && in_flight.size() < 3) {
        trials->push_back(oracle.next(true));
        Trial& t = trials->back();
        t.request.data = t.data.data();
        if (!t.enables.empty()) t.request.byte_enable = t.enables.data();
        in_flight.emplace_back(&t, self.issue(t.request, t.answer, t.hold));
        ++i;
        continue;
      }
      const Outcome o = self.finish(in_flight.front().second);
      oracle.check(*in_flight.front().first, o, errors);
      in_flight.pop_front();
    }
    kept_trials().push_back(trials);
  };
}

}  // namespace rc::tlmx::test
