// What a caller chooses for a board run (host_sw/platform/board_run.h): device, lanes, width, driver,
// host, outputs. Every default is the command's, field by field.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "board/board_params.h"
#include "board/device_profile.h"
#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/platform/card_options.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/radiosity/visibility.h"

namespace rc {

// Every default is `rc2000sim run --impl board`'s with no other option (apps/run_command.cpp;
// tests/scripts/library_defaults_test.sh): same device, host, lanes, banks, width and driver.
struct BoardRunOptions {
  std::string device = "xc2v6000";      // configs/devices/NAME.json, or a path to a profile
  std::optional<board::DeviceProfile> device_profile;  // when set, this profile instead of `device` (studies)
  board::LaneCount lanes = 1;           // pipeline instances (1..255, checked when set)
  unsigned banks = 0;                   // 0: the profile's bank count
  pipeline::FracBits bits = 15;         // fractional bits (7..31), checked when set
  // Set: float lanes in this format instead (docs/board.md, "Float lanes"); `bits` is then unused.
  // The oracle, if any, must then be the `float:E,M` software backend of the same format.
  std::optional<pipeline::FloatFormat> float_format;
  bool concurrent = false;              // paper sec 4.3
  // The CPU/FPGA split (host_sw/driver/cpu_split.h; one card only); off: the host profile's
  // (driver_model.cpu_*, usually off). Its answers come from the oracle, if any, else from a host
  // kernel at the lanes' width or float format that the system makes.
  CpuSplit cpu_split;
  // The pipelined driver (host_sw/driver/board_visibility_pipelined.cpp; one card only): rays per
  // chunk; 0: the host profile's (driver_model.chunk_rays, usually absent: the unpipelined driver).
  std::size_t chunk_rays = 0;
  // configs/hosts/NAME.json, or a path. The command's default: the profile fitted to the paper's
  // measurements (docs/calibration.md), so a library call gives `rc2000sim run --impl board`'s times.
  std::string host = "athlon-mp-2600-calibrated";
  std::optional<HostProfile> host_profile;  // when set, this profile instead of `host` (calibration variants)
  // Record a Chrome/Perfetto trace of steps trace_first..trace_last: BoardRunResult::trace_json (the
  // caller writes it, with its other outputs).
  bool trace = false;
  int trace_first_step = 1, trace_last_step = 3;
  // Where SystemC writes a VCD of start/busy/done/irq while the run simulates (empty: none). It is
  // written as the simulation goes, so the run command points it at a temporary file and moves that
  // into place with its other outputs when the run has succeeded.
  std::string vcd_path;
  std::uint64_t bank_capacity_bytes = 0;  // 0: the profile's (tests force batching with small banks)
  bool allow_batching = true;
  board::WrapperModel model = board::WrapperModel::fast;  // cycle: tests on small scenes only
  // Set: lanes plugged into the cycle-level wrapper (model must be cycle), e.g. the RTL lanes that the
  // application wires in (rtl/lanes/rtl_lanes.h; docs/board.md, "RTL lanes"). Empty: the C++ lanes.
  board::ClockedLanesFactory clocked_lanes;
  // Where the lanes' slices and block multipliers come from (pipeline/resource_source.h): the paper fit
  // (default) or the synthesizer's counts; decides whether the lanes fit and the design's cost.
  pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit;
  VisibilityBackend* oracle = nullptr;  // lanes' answer from a bit-identical host model (BoardVisibilityOptions)
  bool print_summaries = false;         // the tlm parts' one-line summaries at the end
  std::function<void(const StepProgress&)> on_progress;  // after every step (host thread)
  AnswersObserver on_answers;  // every step's segments and the board's answers (host thread)
  // Several identical cards (docs/board.md, "Several cards"): how many (1..16, checked when set),
  // how a step is split over them, and whether they share one PCI bus.
  CardCount cards = 1;
  CardSplit card_split = CardSplit::rays;
  CardBus card_bus = CardBus::shared;
  // How a pass's rays are divided over the ray groups (board/bank_layout.h; docs/board.md "Ray split"):
  // by what limits each group's stream (default), or the paper's nominal lane rates.
  board::RaySplitRule ray_split = board::RaySplitRule::limit;
};

}  // namespace rc
