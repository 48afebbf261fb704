// The fast wrapper model: one pass is one SC_THREAD activation and one timed wait. At the START
// event it reads the pass's data from the banks through DMI and computes every result with
// pipeline::occlude_face (face-outer, ray-inner, as the hardware streams, sec 4.1; float lanes: the
// float pipeline's occlude_face on the decoded bit patterns), then waits
// until the pass's completion time from pass_timing.h (first device clock edge at or after START,
// plus the pass's cycles), writes the result words, sets DONE and raises the interrupt. The result
// words are the same whether the results accumulate in the bank or on chip (docs/board.md, "Results
// on chip"); only the pass's time and the result bank's traffic differ, and both come from
// pass_timing.h.
#pragma once

#include <cstdint>
#include <vector>

#include "board/wrapper_base.h"

namespace rc::board {

class FastWrapper : public WrapperBase {
 public:
  FastWrapper(const sc_core::sc_module_name& name, const BankLayout& layout, const WrapperTiming& timing,
              ControlRegs& regs, tlmx::IrqLine& irq, std::vector<tlmx::DmiActivitySink*> bank_sinks,
              std::vector<std::uint64_t> bank_addresses, WrapperSignals signals = {});

 private:
  struct TimedPass {
    std::uint64_t rays = 0, faces = 0;
    bool clear = false;
    PassTiming timing;
    std::vector<std::uint64_t> lane_rays;  // over all faces of the pass
    std::vector<tlmx::DmiActivity> activity;  // timing.banks as the banks' sinks take it
  };
  static constexpr std::size_t kTimedPasses = 4;

  void run();
  const TimedPass& timed_pass(const PassInputs& in);
  void compute(const PassInputs& in);
  void compute_float(const PassInputs& in);  // float lanes (layout.float_format): float_mt's occlude_face
  void write_results(const PassInputs& in);
  // The result words' read-modify-writes, with load(word) / store(word, value) on the result bank.
  template <class Load, class Store>
  void or_results(const PassInputs& in, Load&& load, Store&& store);

  // Scratch kept between passes: end points in pass order and the blocked flags.
  PassInputs m_in;       // the current pass's, reused from pass to pass
  PassRecord m_record;
  std::vector<TimedPass> m_timed;  // the last kTimedPasses pass shapes and their timing
  std::vector<std::int64_t> m_x, m_y, m_z;
  std::vector<double> m_fx, m_fy, m_fz;  // float lanes: the end points decoded
  std::vector<std::uint8_t> m_blocked;
  std::vector<const std::uint8_t*> m_ray_words;  // per bank: its ray words in place, when one region holds them
};

// Rays each lane streams per face for a split (lane = group's first lane + slot).
std::vector<std::uint64_t> lane_rays_per_face(const BankLayout& layout, const RaySplit& split);

}  // namespace rc::board
