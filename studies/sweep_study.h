// `rc2000sim sweep` as a study: one scene, every combination of device, width, driver, lanes and
// banks. Each width is solved once (a recording); every combination that can exist replays it
// through its own SystemC system in one timing study; the others get a row with the reason. The
// command (apps/sweep_command.cpp) parses the options into a SweepSpec and writes the rows.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "scenes/prepare.h"
#include "studies/config_sweep.h"
#include "studies/timing_study.h"

namespace rc {

struct SweepSpec {
  SweepAxes axes;
  SceneOptions scene;           // how the scene was made (paper step counts apply to paper scenes only)
  std::string steps = "paper";  // parse_steps: "paper", "converge" or a count
  double convergence = SolverOptions{}.convergence;
  bool paper_faithful = true;
  std::string host = "athlon-mp-2600-calibrated";
  std::string visibility = "fast";
  bool full_banks = false;      // false: banks as small as change no pass (compact_bank_capacity)
  bool quiet = false;
};

// One width's functional answer and the steps every configuration at that width replays.
struct WidthRun {
  RecordedRun functional;
  int steps = 0;
  std::uint64_t max_segments = 0;  // in one step, over the replayed steps
};

struct Planned {
  SweepConfig config;
  ConfigCheck check;
  std::uint64_t bank_capacity = 0;  // 0: the profile's
  std::size_t outcome = 0;          // index into the study's outcomes (ok configurations)
};

struct SweepResult {
  Scene scene;                            // made from SweepSpec::scene
  std::vector<Planned> plan;              // every combination, in enumeration order
  std::size_t valid = 0;                  // combinations that can exist (simulated)
  std::map<int, WidthRun> widths;         // by fractional width
  std::map<int, double> software_seconds; // the software implementation, by width
  std::map<std::string, std::uint64_t> bank_capacities;  // modelled bank size per device (0: the profile's)
  std::vector<SweepRow> rows;
};

// Checks the spec (steps policy, profiles), makes the scene, then runs the whole study (once per
// process: it runs the timing study). `progress` gets one line per phase.
SweepResult run_sweep_study(const SweepSpec& spec, const std::function<void(const std::string&)>& progress);

}  // namespace rc
