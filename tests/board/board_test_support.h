// Scaffolding for the board tests: round-number board parameters whose timing can be worked out by
// hand, a scripted host that talks to a board over PCI, and single-pass helpers that load a pass's
// data into the banks through the backdoor (no simulated time) so that only the pass is timed.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>

#include "board/rc2000.h"
#include "board/register_map.h"
#include "board/word_format.h"
#include "pipeline/fixed_mt.h"

namespace rc::board::test {

using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_PS;
using sc_core::SC_US;

// Device 50 MHz (20 ns), banks 100 MHz (10 ns, read latency 2), PCI 64-bit 66 MHz (15 ns, setup 8,
// 4 KiB bursts, bridge 2 cycles), wrapper start 2, face setup 1, finish 1, latency 37.
inline BoardParams round_params(unsigned lanes, int bits = 15, unsigned banks = 6,
                                WrapperModel model = WrapperModel::fast) {
  BoardParams p;
  p.device = "test";
  p.lanes = lanes;
  p.bits = bits;
  p.banks = banks;
  p.bank_capacity_bytes = 1u << 20;
  p.timing.device_period = sc_time(20, SC_NS);
  p.timing.bank_period = sc_time(10, SC_NS);
  p.timing.bank_read_latency = 2;
  p.timing.pass_start = 2;
  p.timing.face_setup = 1;
  p.timing.pass_finish = 1;
  p.timing.pipeline_latency = 37;
  p.register_access_cycles = 1;
  p.pci.width_bits = 64;
  p.pci.clock_period = sc_time(15, SC_NS);
  p.pci.setup_cycles = 8;
  p.pci.max_burst_bytes = 4096;
  p.bridge_latency_cycles = 2;
  p.model = model;
  return p;
}

// A host thread with a PCI master socket bound to a board.
class ScriptedHost : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<ScriptedHost> out;
  std::function<void(ScriptedHost&)> script;
  bool finished = false;

  ScriptedHost(const sc_core::sc_module_name& name, Rc2000& board, std::function<void(ScriptedHost&)> body)
      : sc_core::sc_module(name), out("out"), script(std::move(body)), m_board(board) {
    out.bind(board.pci.in);
    SC_HAS_PROCESS(ScriptedHost);
    SC_THREAD(run);
  }

  Rc2000& board() { return m_board; }

  // Register access through PCI BAR0; waits for the bus's completion time.
  void write(std::uint64_t offset, std::vector<std::uint32_t> values) { access(tlm::TLM_WRITE_COMMAND, offset, values); }
  std::uint32_t read(std::uint64_t offset) {
    std::vector<std::uint32_t> v(1);
    access(tlm::TLM_READ_COMMAND, offset, v);
    return v[0];
  }
  // Temporally decoupled write: issued at local offset `local`, returns the completion's offset
  // without waiting.
  sc_time write_ahead(std::uint64_t offset, std::vector<std::uint32_t> values, sc_time local) {
    tlm::tlm_generic_payload t;
    const auto n = static_cast<unsigned>(values.size() * 4);
    t.set_command(tlm::TLM_WRITE_COMMAND);
    t.set_address(Rc2000::kBar0 + offset);
    t.set_data_ptr(reinterpret_cast<unsigned char*>(values.data()));
    t.set_data_length(n);
    t.set_streaming_width(n);
    t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    out->b_transport(t, local);
    EXPECT_TRUE(t.is_response_ok());
    return local;
  }

 private:
  void access(tlm::tlm_command cmd, std::uint64_t offset, std::vector<std::uint32_t>& values) {
    tlm::tlm_generic_payload t;
    const auto n = static_cast<unsigned>(values.size() * 4);
    t.set_command(cmd);
    t.set_address(Rc2000::kBar0 + offset);
    t.set_data_ptr(reinterpret_cast<unsigned char*>(values.data()));
    t.set_data_length(n);
    t.set_streaming_width(n);
    t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_time delay = sc_core::SC_ZERO_TIME;
    out->b_transport(t, delay);
    ASSERT_TRUE(t.is_response_ok());
    sc_core::wait(delay);
  }
  void run() {
    script(*this);
    finished = true;
  }
  Rc2000& m_board;
};

// Runs the simulation until every host's script has finished, then stops it.
inline void run_until_finished(const std::vector<const ScriptedHost*>& hosts) {
  auto all = [&] {
    for (const ScriptedHost* h : hosts)
      if (!h->finished) return false;
    return true;
  };
  while (!all()) sc_core::sc_start(sc_core::sc_time(10, sc_core::SC_US));
  sc_core::sc_stop();
}

// The hosts of test benches that hold one (`bench->host`), for run_until_finished.
template <class Bench>
std::vector<const ScriptedHost*> hosts_of(const std::vector<Bench*>& benches) {
  std::vector<const ScriptedHost*> hosts;
  for (const Bench* b : benches) hosts.push_back(b->host.get());
  return hosts;
}

// One pass's data: faces, a start point, end points grouped by end face.
struct PassData {
  std::vector<pipeline::FaceRecord> faces;
  pipeline::FixedVec3 start{0, 0, 0};
  std::vector<pipeline::FixedVec3> ends;
  std::vector<int> end_faces;  // non-decreasing; -1: on no face of the set
  int source_face = -1;
};

// A face across the middle of the unit cube (z = 0.5), a start below it and `rays` end points above,
// so that roughly half of the segments cross the face. Extra faces are smaller copies elsewhere.
inline PassData crossing_pass(std::uint64_t rays, int bits, unsigned faces = 1, unsigned seed = 1) {
  PassData d;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.02, 0.98);
  for (unsigned f = 0; f < faces; ++f) {
    const double z = 0.5 + 0.05 * f, s = 0.9 / (f + 1);
    d.faces.push_back(pipeline::make_face_record({{0.05, 0.05, z}, {0.05 + s, 0.1, z}, {0.1, 0.05 + s, z}}, bits));
  }
  d.start = pipeline::quantize_point({0.3, 0.3, 0.1}, bits);
  for (std::uint64_t r = 0; r < rays; ++r) {
    d.ends.push_back(pipeline::quantize_point({u(rng), u(rng), 0.95}, bits));
    // Rays end on faces in face order: the first quarter on face 0, the next on face 1, ...
    d.end_faces.push_back(faces > 1 ? static_cast<int>(r * faces / (rays + 1)) : -1);
  }
  return d;
}

// The CPU answer for a pass, with the own-face rule.
inline std::vector<std::uint8_t> expected_blocked(const PassData& d, int bits) {
  std::vector<std::uint8_t> blocked(d.ends.size(), 0);
  for (std::size_t r = 0; r < d.ends.size(); ++r)
    for (std::size_t f = 0; f < d.faces.size(); ++f)
      if (static_cast<int>(f) != d.source_face && static_cast<int>(f) != d.end_faces[r])
        blocked[r] |= pipeline::segment_hits(d.faces[f], d.start, d.ends[r], bits);
  return blocked;
}

// Loads faces, own-face table and rays into the banks (backdoor: no time, no counters).
inline RaySplit load_pass(Rc2000& b, const PassData& d) {
  const BankLayout& L = b.layout();
  const unsigned wb = L.word_bits / 8;
  auto put = [&](unsigned bank, std::uint64_t word, std::uint64_t value) {
    std::uint8_t bytes[8];
    store_word(bytes, 0, wb, value);
    b.bank(bank).debug_write(word * wb, bytes, wb);
  };
  std::uint64_t words[9];
  for (std::size_t f = 0; f < d.faces.size(); ++f) {
    face_record_words(d.faces[f], words);
    for (unsigned i = 0; i < 9; ++i) put(L.face_bank, f * 9 + i, words[i]);
  }
  const unsigned mask_bank = L.mask_bank ? *L.mask_bank : L.face_bank;
  const std::uint64_t mask_first = L.mask_bank ? 0 : d.faces.size() * 9;
  for (std::size_t f = 0; f < d.faces.size(); ++f) {
    std::uint64_t n = 0;
    for (int e : d.end_faces) n += e == static_cast<int>(f);
    put(mask_bank, mask_first + f, n);
  }
  std::vector<std::int64_t> x, y, z;
  for (const auto& e : d.ends) x.push_back(e.x), y.push_back(e.y), z.push_back(e.z);
  const RaySplit split = split_rays(L, d.ends.size());
  std::vector<std::vector<std::uint8_t>> images;
  pack_rays(L, split, x.data(), y.data(), z.data(), images);
  for (unsigned bank = 0; bank < images.size(); ++bank)
    if (!images[bank].empty()) b.bank(bank).debug_write(0, images[bank].data(), images[bank].size());
  return split;
}

// Runs one pass through the registers (PCI), waits for the interrupt and acknowledges it; returns
// the blocked flags read from the result bank (backdoor).
inline std::vector<std::uint8_t> run_pass(ScriptedHost& host, const PassData& d, bool clear = true) {
  Rc2000& b = host.board();
  const RaySplit split = load_pass(b, d);
  std::uint32_t before = 0;
  for (int e : d.end_faces) before += e < 0 ? 1 : 0;  // rays "ending" before face 0
  host.write(reg::kRayCount, {static_cast<std::uint32_t>(d.ends.size()), static_cast<std::uint32_t>(d.faces.size()), 0,
                              d.source_face < 0 ? reg::kNoFace : static_cast<std::uint32_t>(d.source_face),
                              static_cast<std::uint32_t>(d.start.x), static_cast<std::uint32_t>(d.start.y),
                              static_cast<std::uint32_t>(d.start.z), before});
  host.write(reg::kControl, {reg::kStart | (clear ? reg::kClear : 0u)});
  b.irq.wait_raised();
  EXPECT_EQ(host.read(reg::kStatus) & (reg::kDone | reg::kError), reg::kDone);
  host.write(reg::kStatus, {reg::kDone});
  std::vector<std::uint8_t> blocked(d.ends.size(), 0);
  const std::vector<std::uint8_t> words =
      b.bank(b.layout().result_bank).debug_bytes(0, split.result_words * (b.layout().word_bits / 8));
  unpack_results(b.layout(), split, words.data(), blocked.data());
  return blocked;
}

}  // namespace rc::board::test
