// Scaffolding for the board tests: round-number board parameters whose timing can be worked out by
// hand and a pass across a face; the scripted host that talks to a board over PCI and the single-pass
// helpers (backdoor loading, so that only the pass is timed) come from the timing test kit.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include <systemc>

#include "board/rc2000.h"
#include "board/register_map.h"
#include "board/word_format.h"
#include "pipeline/fixed_mt.h"
#include "testkit/pass_script.h"
#include "testkit/scripted_host.h"

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

// The scripted host, run-until-finished and the pass helpers are the timing test kit's (testkit/).
using testkit::expected_blocked;
using testkit::hosts_of;
using testkit::load_pass;
using testkit::PassData;
using testkit::run_pass;
using testkit::run_until_finished;
using testkit::ScriptedHost;

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

}  // namespace rc::board::test
