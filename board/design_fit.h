// Does a design of L pipeline lanes at N fractional bits fit a device, and how fast does it run?
// Resources per lane and for the wrapper come from pipeline/'s resource model (the paper's
// synthesis results, or with ResourceSource::synthesis the synthesizer's counts for the device's
// family, pipeline/synthesis_resources.h); the device's slices, block multipliers and wrapper-limited clock from its
// profile (configs/devices/). docs/board.md, "Lanes that fit".
#pragma once

#include <string>

#include "board/device_profile.h"
#include "board/lane_count.h"
#include "pipeline/resource_model.h"

namespace rc::board {

struct DesignFit {
  std::string device;
  int bits = 0;
  int lanes = 0;
  // Lanes built with 18x18 block multipliers, and with multipliers made of slices (paper sec 5.3
  // gives both implementations). Block-multiplier lanes are far smaller, so they come first.
  int hard_lanes = 0;
  int soft_lanes = 0;
  int slices = 0;             // needed: wrapper + every lane
  int block_multipliers = 0;  // needed
  int slices_available = 0;
  int block_multipliers_available = 0;
  // Block RAM: the design's own use (lanes and wrapper, results on chip excluded) and the device's.
  // pipeline/resource_model has no block RAM figure: the paper's synthesis results (table 1, sec 5.4,
  // 5.5) list slices and block multipliers only, and the pipeline (System Generator adders,
  // multipliers, registers) and the Handel-C wrapper (counters, registers) hold no memories, so the
  // design is taken to use none (assumption). What is left holds results on chip (bank_layout.h).
  std::uint64_t block_ram_bits = 0;
  std::uint64_t block_ram_bits_available = 0;
  double pipeline_clock_mhz = 0;  // the slowest lane implementation used, at this width
  double clock_mhz = 0;           // min(the profile's design clock for this lane count, pipeline clock)
  bool modelled = false;          // any resource figure interpolated or extrapolated (not synthesised)
  pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit;  // where slices and blocks came from
  bool fits = false;

  std::string describe() const;  // one line, e.g. for errors and reports
};

// The smallest implementation of `lanes` lanes on the device: as many block-multiplier lanes as
// its multipliers allow, the rest with slice multipliers. Throws std::invalid_argument for
// (LaneCount and FracBits are valid by construction.)
DesignFit fit_design(const DeviceProfile& device, const pipeline::ResourceModel& resources, LaneCount lanes, pipeline::FracBits bits);

// The largest lane count that fits (0 if not even one does).
int max_lanes(const DeviceProfile& device, const pipeline::ResourceModel& resources, pipeline::FracBits bits);

// The most lanes that fit under each source of resources (pipeline/resource_source.h), side by side:
// `paper` and `synthesis` are the fits of those lane counts (of one lane, not fitting, when none fits).
// Throws what ResourceModel::load_default(synthesis) throws (the synthesis file missing or broken).
struct LanesBySource {
  std::string device;
  int bits = 0;
  int paper_lanes = 0, synthesis_lanes = 0;
  DesignFit paper, synthesis;
};
LanesBySource lanes_by_source(const DeviceProfile& device, pipeline::FracBits bits);

// The same for lanes of the floating-point pipeline in `format` (pipeline::ResourceModel::float_pipeline,
// an ESTIMATE throughout: `modelled` is always true). The device's family comes from its part
// (XC2V, XC4V, XC3S); lanes are built as for fixed point: block-multiplier lanes while the blocks
// last, the rest with slice multipliers; the same Handel-C wrapper; the clock is min(the profile's
// clock for this lane count, the float lane's clock). `bits` holds the word width 1+E+M.
struct FloatDesignFit : DesignFit {
  pipeline::FloatFormat format{8, 23};
  std::string family;            // "Virtex-II", ...
  std::string block_multiplier;  // "MULT18X18" or "DSP48"
};
FloatDesignFit fit_float_design(const DeviceProfile& device, const pipeline::ResourceModel& resources, LaneCount lanes,
                                pipeline::FloatFormat format);
int max_float_lanes(const DeviceProfile& device, const pipeline::ResourceModel& resources, pipeline::FloatFormat format);

}  // namespace rc::board
