// The concrete parameters of one RC2000 instance: a device profile plus the run's choices (lanes,
// banks, width, capacity override, wrapper model). Tests may fill BoardParams directly.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <systemc>

#include "board/clocked_lanes.h"
#include "board/design_fit.h"
#include "board/device_profile.h"
#include "board/pass_timing.h"
#include "tlm/pci_bus.h"

namespace rc::board {

enum class WrapperModel { fast, cycle };

struct BoardParams {
  std::string device = "custom";
  LaneCount lanes = 1;
  unsigned banks = 6;
  pipeline::FracBits bits = 15;        // fixed-point lanes: fractional bits
  std::optional<pipeline::FloatFormat> float_format;  // set: float lanes in this format, `bits` unused
  std::uint64_t bank_capacity_bytes = 4u << 20;
  unsigned word_bits = 32;
  unsigned bank_write_latency = 2;     // bank cycles (read latency: timing.bank_read_latency)
  WrapperTiming timing;                // device and bank clocks, wrapper cycle costs, pipeline latency
  unsigned register_access_cycles = 1; // device cycles per register access
  tlmx::PciBusConfig pci;
  unsigned bridge_latency_cycles = 2;  // PCI cycles through the bridge to the local bus
  sc_core::sc_time irq_latency = sc_core::SC_ZERO_TIME;  // device raises -> host thread runs
  WrapperModel model = WrapperModel::fast;
  // Set: the cycle-level wrapper's lanes are these (the RTL lanes), not the C++ stage functions
  // (docs/board.md, "RTL lanes"). Needs model == cycle and fixed-point lanes.
  ClockedLanesFactory clocked_lanes;
  ResultStore results = ResultStore::bank;  // where a pass's blocked bits accumulate (bank_layout.h)
  std::uint64_t result_store_bits = 0;  // on chip: block RAM bits left for them (device's minus the design's)
  // How a pass's rays are divided over the ray groups (bank_layout.h, docs/board.md "Ray split"):
  // by what limits each group's stream (default), or by the nominal lane rates (the paper's).
  RaySplitRule ray_split = RaySplitRule::limit;
  bool report_at_end = false;          // print the tlm parts' summaries at sc_stop()
  DesignFit fit;                       // resources and clock of the design (make_board_params)
};

struct BoardChoices {
  LaneCount lanes = 1;
  unsigned banks = 0;                    // 0: the profile's count
  pipeline::FracBits bits = 15;
  std::optional<pipeline::FloatFormat> float_format;  // set: float lanes (docs/board.md, "Float lanes")
  std::uint64_t bank_capacity_bytes = 0; // 0: the profile's
  WrapperModel model = WrapperModel::fast;
  ClockedLanesFactory clocked_lanes;     // set: lanes plugged in (BoardParams::clocked_lanes)
  // Where the fixed-point lanes' slices and block multipliers come from (pipeline/resource_source.h);
  // float lanes have counting-rule estimates only, so they take the paper fit.
  pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit;
  sc_core::sc_time irq_latency = sc_core::SC_ZERO_TIME;
  RaySplitRule ray_split = RaySplitRule::limit;  // BoardParams::ray_split
};

// Throws std::invalid_argument if the lanes do not fit the device (design_fit.h), the profile
// has no clock for the lane count, or results on chip find no block RAM left, or plugged-in lanes are
// asked for with the fast wrapper or float lanes. Float lanes: the
// design's resources and clock are fit_float_design's ESTIMATE; the pipeline latency stays the
// profile's (the float operators' latencies are not sourced; docs/board.md, "Float lanes").
BoardParams make_board_params(const DeviceProfile& profile, const BoardChoices& choices);

// The bank layout of a board with these parameters, results placed and rays split as they say
// (bank_layout.h; the split at the design's device and bank clocks).
BankLayout make_bank_layout(const BoardParams& params);

}  // namespace rc::board
