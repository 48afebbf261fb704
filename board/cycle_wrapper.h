// The cycle-level wrapper model, for tests only (small batches): an SC_METHOD on an sc_clock at the
// device clock runs the wrapper's state machine one cycle per rising edge, with real bank reads per
// cycle, a 37-stage pipeline holding valid bits and the stage values of every lane (pipeline's
// stage1/stage2/stage3 called at their stage positions) and the result bank's read-modify-writes as
// results leave the pipeline. Its purpose is to show that pass_timing.h, which the fast model
// charges, is what the clocked design does: same completion time, same result bits.
//
// Bank bandwidth: within a phase (a face's record fetch, a face's stream) a bank of period Pb gives
// floor(t * Pd / Pb) accesses by the end of the phase's t-th device cycle. A group issues a packet in
// a cycle when its rate allows (floor(t * k / 3) packets by cycle t) and every bank it needs has the
// budget: its ray banks for the packet's words and the result bank for the packet's result
// accesses, reserved at issue because the pipeline's fixed latency moves the whole pattern 37 cycles
// later. Groups are served in index order (fixed priority).
//
// Results on chip (layout.results == on_chip): a packet's bits are ORed into a block RAM image of the
// pass's result words as it leaves the pipeline (no result-bank access, no result-bank budget at
// issue); once the last packet has left, a drain phase writes the words to the result bank in order,
// each when the bank's budget of the phase covers its accesses (a write, or a read and a write when
// a pass that does not clear ORs onto a word shared by lanes), then DONE follows `finish` cycles later.
//
// Float lanes (layout.float_format set): the coordinate fields, start registers and face records are
// decoded from their bit patterns (word_format.h) and the lanes run float_mt's stages at the same
// stage positions; timing is the same machine on the float layout (docs/board.md, "Float lanes").
//
// Plugged-in lanes (`lanes` given, e.g. the RTL lanes: board/clocked_lanes.h): the same machine, but the
// lanes' arithmetic is theirs. A packet issued in cycle c is presented at their input ports and sampled
// at the next edge (c + 1); every edge of a running pass clocks them (idle lanes: valid low), and the
// packet's hit bits are read from their output ports at edge c + L, when the C++ lanes write back. A lane
// whose out_valid is not high then (a latency other than L) is an error naming the lane and cycle.
//
// Stage positions (assumption: the paper gives only the total, 37): the direction end - start is
// formed in the input cycle (age 0); stage 1 completes at age 12, stage 2 at age 24, stage 3 (and the
// decision) at age 36, and the result is written at age 37, i.e. ages (L-1)/3, 2(L-1)/3, L-1, L.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "board/clocked_lanes.h"
#include "board/wrapper_base.h"
#include "pipeline/fixed_mt.h"
#include "pipeline/float_mt.h"

namespace rc::board {

class CycleWrapper : public WrapperBase {
 public:
  sc_core::sc_clock clock;

  CycleWrapper(const sc_core::sc_module_name& name, const BankLayout& layout, const WrapperTiming& timing,
               ControlRegs& regs, tlmx::IrqLine& irq, std::vector<tlmx::DmiActivitySink*> bank_sinks,
               std::vector<std::uint64_t> bank_addresses, WrapperSignals signals = {},
               std::unique_ptr<ClockedLanes> lanes = nullptr);

 private:
  enum class Phase { Start, NextFace, Setup, Fetch, Stream, Drain, Tail };

  struct Lane {  // one slot of a packet, i.e. one lane's pipeline register contents
    bool valid = false, masked = false;
    std::uint64_t ray = 0;
    pipeline::FixedVec3 direction{0, 0, 0};
    pipeline::Stage1Result s1{};
    pipeline::Stage2Result s2{};
    pipeline::Stage3Result s3{};
    // Float lanes (layout.float_format): the same registers in the format (pipeline/float_mt.h).
    pipeline::FloatVec3 fdirection{0, 0, 0};
    pipeline::FloatStage1Result fs1{};
    pipeline::FloatStage2Result fs2{};
    pipeline::FloatStage3Result fs3{};
  };
  struct Packet {  // what one group puts into its lanes in one cycle
    std::uint64_t issued = 0;  // cycle
    unsigned group = 0;
    std::uint64_t index = 0;   // packet index within the group
    bool clearing = false;
    pipeline::FaceRecord face{};
    pipeline::FloatFaceRecord float_face{};  // float lanes
    std::vector<Lane> lanes;
  };

  void on_edge();
  void begin();
  void controller();
  bool try_issue(unsigned g);
  void advance_pipeline();
  void write_back(const Packet& p);
  bool drain();  // one drain cycle; true when every result word has been written
  void finish();
  void clock_plugged_lanes();  // plugged-in lanes: one edge with the inputs staged last cycle
  std::uint64_t allowed(std::uint64_t t) const;  // bank accesses by the end of phase cycle t

  bool m_running = false;
  PassInputs m_in;
  PassRecord m_record;
  std::vector<BankTraffic> m_traffic;
  std::uint64_t m_cycle = 0, m_done_cycle = 0;
  Phase m_phase = Phase::Start;
  std::uint64_t m_left = 0;         // cycles left in Start / Setup
  std::uint64_t m_phase_cycle = 0;  // t: cycles elapsed in Fetch / Stream, this one included
  std::uint64_t m_face = 0;
  OwnSurfaceRange m_own{0};  // the rays masked for the current face (its sheet's)
  pipeline::FaceRecord m_face_record{};
  pipeline::FloatFaceRecord m_float_face{};  // float lanes
  pipeline::FloatVec3 m_float_start{0, 0, 0};
  std::vector<std::uint64_t> m_issued;  // packets issued this face, per group
  std::uint64_t m_result_used = 0;      // result-bank accesses reserved this face
  std::deque<Packet> m_pipe;
  std::string m_limit;
  // Results on chip: the block RAM's result words of the pass, and the drain's progress.
  std::vector<std::uint64_t> m_store;
  std::uint64_t m_drain_first = 0;  // cycle of the drain's first cycle (the pipeline is empty by then)
  std::uint64_t m_drain_word = 0, m_drain_used = 0;  // next word to write, bank accesses so far
  std::vector<unsigned> m_word_group;  // group of each result word
  // Plugged-in lanes: the lanes, the inputs staged this cycle for the next edge.
  std::unique_ptr<ClockedLanes> m_plugged;
  std::vector<ClockedLaneInput> m_staged;
};

}  // namespace rc::board
