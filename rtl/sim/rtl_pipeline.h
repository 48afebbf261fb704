// The Verilated RTL pipeline (rtl/mt_pipeline.v) behind a plain C++ face: one model per lane, one call
// per rising clock edge. No SystemC here; the board's RTL lanes (host_sw/platform/rtl_lanes.h) and the
// co-simulation tests (tests/rtl/) clock it. A build without Verilator has no models:
// `rtl_models_built()` is false and `make_rtl_pipeline` throws saying so.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "pipeline/fixed_format.h"

namespace rc::rtl {

// What one lane's input ports carry for one test (docs/pipeline.md: positions unsigned 0.N, the face
// record's edges signed 1.N).
struct RtlInputs {
  bool valid = false;
  pipeline::FixedVec3 start{0, 0, 0}, end{0, 0, 0};
  pipeline::FaceRecord face{};
  // The t_guard port (8 bits, 0..pipeline::kMaxTGuard): a static input, held while tests are in flight.
  int t_guard = 0;
};

class RtlPipeline {
 public:
  virtual ~RtlPipeline() = default;
  virtual int bits() const = 0;
  // Holds rst high over one rising edge: the valid chain empties (data registers keep their values).
  virtual void reset() = 0;
  // Presents `in` at the input ports and applies one rising edge of clk.
  virtual void clock(const RtlInputs& in) = 0;
  // The output ports after the last edge.
  virtual bool out_valid() const = 0;
  virtual bool out_hit() const = 0;
};

// The register stages from input to output that rtl/mt_pipeline.v promises (and the tests check).
constexpr unsigned kRtlLatency = 37;

// Whether this build has Verilated models, and of which fractional widths (RC_RTL_WIDTHS at configure
// time; empty without Verilator).
bool rtl_models_built();
std::vector<int> rtl_widths();
// Which multipliers a model uses: "block" (Verilog `*`, SOFT_MULTS = 0) or "array" (SOFT_MULTS = 1).
// Array models are built at the widths RC_RTL_ARRAY_WIDTHS.
std::vector<int> rtl_array_widths();

// A new model of the pipeline at `bits`, reset. Throws std::invalid_argument naming the widths built
// (or that the build has no Verilator).
std::unique_ptr<RtlPipeline> make_rtl_pipeline(int bits, bool array_multipliers = false);

// Why RTL models cannot be made, or "" if they can at `bits`.
std::string rtl_unavailable_reason(int bits, bool array_multipliers = false);

}  // namespace rc::rtl
