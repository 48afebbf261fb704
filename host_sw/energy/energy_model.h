// Energy of one run, the Accelergy way: for every component, the count of each action the model
// already keeps times the energy of one action (a profile figure), plus static power times the
// simulated time (docs/energy.md). Every term keeps its counter, its count and the figure it used,
// so every joule in a report traces to a profile value, its source and a counter.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host_sw/energy/energy_table.h"

namespace rc::energy {

// What the model counted in one run (host_sw/platform/ fills it from its RunReport).
struct Activity {
  double seconds = 0;       // simulated time
  std::uint64_t steps = 0;  // shooting steps
  std::uint64_t intersections = 0;
  // Host: CPU-seconds of work on the processors the run uses, and how many it uses.
  double host_busy_cpu_seconds = 0;
  unsigned host_cpus = 1;
  // Board runs (cards == 0: a software run, nothing below applies).
  unsigned cards = 0;
  unsigned lanes = 0;             // per card
  double device_clock_hz = 0;
  double slices_per_lane = 0, multipliers_per_lane = 0;  // the design's, its wrapper's share included
  std::uint64_t lane_active_cycles = 0;  // one per ray-face test, over every lane and card
  unsigned banks = 0;                    // per card
  std::uint64_t bank_word_reads = 0, bank_word_writes = 0;
  std::uint64_t pci_data_phases = 0, pci_transactions = 0;
};

// One line of the sum: `count` actions (or seconds) of `counter` at `figure` each (per second for
// static terms).
struct EnergyTerm {
  std::string component;  // "fpga", "sram", "pci", "host"
  std::string counter;    // what was counted, in words ("lane-cycles with a ray x slices per lane")
  double count = 0;
  Figure figure;
  bool is_static = false;  // power x time rather than actions x energy
  double joules = 0;
};

struct ComponentEnergy {
  std::string name;
  double static_joules = 0, dynamic_joules = 0;
  double joules() const { return static_joules + dynamic_joules; }
  double average_watts = 0;  // over the simulated time
};

struct EnergyReport {
  std::vector<EnergyTerm> terms;
  std::vector<ComponentEnergy> components;  // fpga, sram, pci (board runs), host
  double joules = 0, seconds = 0, average_watts = 0;
  double joules_per_step = 0, joules_per_intersection = 0;  // 0 when there were none
  double energy_delay_product = 0;                          // joules x seconds
  std::string device_table, host_table;                     // files the figures came from
};

// Throws std::invalid_argument if a table the activity needs is absent (a board activity without
// the device table) or the activity is inconsistent (more active lane-cycles than the lanes had).
EnergyReport estimate(const EnergyTables& tables, const Activity& activity);

}  // namespace rc::energy
