// The timing test kit's pass helpers (rc2000tlm::testkit): one pass's data, its CPU answer, loading
// it into a board's banks through the backdoor (no simulated time, no counters, so that only the pass
// is timed) and running it through the registers from a ScriptedHost.
#pragma once

#include <cstdint>
#include <vector>

#include "board/rc2000.h"
#include "board/word_format.h"
#include "pipeline/fixed_mt.h"
#include "testkit/scripted_host.h"

namespace rc::testkit {

// One pass's data: faces, a start point, end points grouped by end face.
struct PassData {
  std::vector<pipeline::FaceRecord> faces;
  pipeline::FixedVec3 start{0, 0, 0};
  std::vector<pipeline::FixedVec3> ends;
  std::vector<int> end_faces;  // non-decreasing; -1: on no face of the set
  int source_face = -1;
};

// The CPU answer for a pass (pipeline/fixed_mt.h), with the own-face rule.
std::vector<std::uint8_t> expected_blocked(const PassData& d, int bits);

// Loads faces, own-face table and rays into the banks (backdoor: no time, no counters).
board::RaySplit load_pass(board::Rc2000& b, const PassData& d);

// Runs one pass through the registers (PCI): loads it (load_pass), writes the pass registers and
// START (with CLEAR when `clear`), waits for the interrupt, checks STATUS is DONE without ERROR
// (a gtest failure otherwise) and acknowledges it; returns the blocked flags read from the result
// bank (backdoor).
std::vector<std::uint8_t> run_pass(ScriptedHost& host, const PassData& d, bool clear = true);

}  // namespace rc::testkit
