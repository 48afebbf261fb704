// The design search (`rc2000sim design`, docs/design.md): for one workload and one device, the fastest
// feasible design over lanes, banks (count and clock), where results accumulate, fractional width,
// block or slice multipliers, cards and driver, under constraints (most banks, least width, an
// energy or power cap), and the Pareto front of time, energy and banks. Every figure it reports is
// simulated by the SystemC model (a timing study, timing_study.h); the only pruning is exact:
//
//   * feasibility: a design whose lanes do not fit the device or whose banks cannot feed them is not
//     a design (ConfigChecker, the check every board run goes through);
//   * spare banks: a board with more banks than the layout uses plus one (the own-face table's bank)
//     leaves the rest spare (board/bank_layout.h); its passes, hence its time, are those of the board
//     with one fewer bank, and it draws more standby energy and has more banks: dominated in all three
//     objectives, never the fastest (ties are broken towards fewer banks). Tests
//     DesignSearch.PrunedSearchEqualsExhaustive* check it against the whole space simulated.
//
// One result bank per group of lanes is not a choice here: the wrapper model has one result bank
// (BankLayout::result_bank, the result-bank term of board/pass_timing.h is one sum over the groups,
// and the driver reads every result word from that bank), so such a design cannot be simulated
// without a new layout, pass-timing term, wrapper and driver read-back (docs/design.md says so).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "board/bank_layout.h"
#include "host_sw/studies/config_checker.h"
#include "host_sw/studies/sweep_config.h"
#include "host_sw/studies/sweep_options.h"
#include "host_sw/studies/sweep_row.h"
#include "host_sw/studies/roofline.h"
#include "host_sw/studies/timing_study.h"
#include "host_sw/studies/workload.h"
#include "host_sw/visibility/visibility_factory.h"
#include "scenes/prepare.h"

namespace rc {

// Block: block multipliers while the device has them, slice multipliers beyond (design_fit.h's
// smallest implementation). Slice: every lane's multipliers in slices (fpga.block_multipliers = 0).
enum class Multipliers { block, slice };
const char* to_string(Multipliers m);  // "block", "slice"
Multipliers parse_multipliers(const std::string& text);  // throws std::invalid_argument naming --multipliers

// The axes searched. Empty lanes: 1 .. the most that fit; empty banks: 5 .. max_banks; empty bank
// clocks: the profile's.
struct DesignSpace {
  std::string device = "xc2v6000";
  std::string host = "athlon-mp-2600-calibrated";
  std::vector<int> lanes;
  std::vector<int> banks;
  std::vector<double> bank_clocks_mhz;
  std::vector<board::ResultStore> results = {board::ResultStore::bank, board::ResultStore::on_chip};
  std::vector<int> bits = {15};
  std::vector<Multipliers> multipliers = {Multipliers::block, Multipliers::slice};
  std::vector<int> cards = {1};
  std::vector<bool> concurrent = {true};
  // The host-side segment fixes (host_sw/radiosity/segment_fixes.h; `run`'s --offset-lsb,
  // --neighbour-rings, --coordinate-bits), 0 meaning off: every combination is a fix, searched at every
  // width (a coordinate width must be below every width searched). Each (width, fix) is solved and
  // measured on its own.
  std::vector<int> offset_lsb = {0};
  std::vector<int> neighbour_rings = {0};
  std::vector<int> coordinate_bits = {0};
  // Not an axis: where the lanes' slices and block multipliers come from (which lane counts fit).
  pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit;
  // Not an axis: how each pass divides its rays over the ray groups (board/bank_layout.h).
  board::RaySplitRule ray_split = board::RaySplitRule::limit;
  // Not an axis: whether each width's picture is measured against one double-precision solve of the
  // workload (WidthFidelity; `--fidelity off` skips that solve, the costliest part of a search on the
  // default workload, and leaves every design's error "not measured").
  bool measure_fidelity = true;
};

struct DesignConstraints {
  unsigned max_banks = 0;  // per card; 0: the device profile's bank count (the board as profiled)
  int min_bits = 7;
  double max_energy_joules = std::numeric_limits<double>::infinity();
  double max_watts = std::numeric_limits<double>::infinity();
  // The picture's error against double-precision visibility on the workload (WidthFidelity, the
  // `accuracy` command's definitions): relative RMSE and relative max of patch radiosity. A design
  // whose fidelity was not measured does not meet a bound that is set.
  double max_error = std::numeric_limits<double>::infinity();
  double max_error_max = std::numeric_limits<double>::infinity();
};

struct DesignPoint;
// A limit of DesignConstraints that is set, as one rule: the option that sets it, its unit, the
// limit and the point's figure it bounds (NaN: not known, which fails the limit) and what a NaN means.
// apply_caps and why_no_design both read this one list.
struct DesignCap {
  const char* option;
  const char* unit;
  double limit;
  double (*figure)(const DesignPoint&);
  const char* unknown;
};
std::vector<DesignCap> design_caps(const DesignConstraints& constraints);

// One width's own solve of the workload and what its arithmetic does to the picture
// (host_sw/studies/fidelity.h): the steps it took, the software-only time of that solve (the host
// testing every segment, simulated), and its patch radiosity's error against ONE double-precision
// solve of the same workload, with the share of visibility decisions that differ along that solve.
struct WidthFidelity {
  int bits = 0;
  SegmentFixOptions fixes;            // the fix the width was solved with (none: any() false)
  int steps = 0;                      // of this width's own solve (what its designs replay)
  double software_seconds = std::numeric_limits<double>::quiet_NaN();
  // NaN: not measured.
  double relative_rmse = std::numeric_limits<double>::quiet_NaN();
  double relative_max = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t decisions_compared = 0, decisions_differ = 0;
  bool measured() const { return relative_rmse == relative_rmse; }
  double decisions_differ_share() const {
    return decisions_compared ? double(decisions_differ) / double(decisions_compared) : std::numeric_limits<double>::quiet_NaN();
  }
};

// What bounds a design, from the one bound model of a board run (host_sw/platform/run_bounds.h, whose
// summary `run` prints as its "bound" line): the largest part of the run's host timeline, what bounded
// the FPGA's stream (its share of FPGA time) and what comes next. `design` and `run` name the same
// bound in the same words for the same design.
struct DesignBound {
  std::string run;        // RunPart::name: "fpga" (waiting for the FPGA), "host_compute", "host_driver", "pci"
  std::string fpga;       // RunBounds::stream_bound_name(): "bank 4 (results, read-modify-write)", "lanes"
  double fpga_share = 0;  // of the FPGA busy time, in the passes it bounded
  std::string next;       // RunBounds::stream_next_name(): what a design that relieves the bound meets
  std::string summary;    // RunBounds::summary(), as `run` prints it
  std::string text() const { return summary; }
};
DesignBound design_bound(const RunReport& report);  // report.board_run must be true

// One design of the space as a configuration the sweep machinery checks and simulates.
struct DesignConfig {
  SweepConfig config;               // device, bits, concurrent, lanes, banks, cards, settings
  board::ResultStore results = board::ResultStore::bank;
  double bank_clock_mhz = 0;
  Multipliers multipliers = Multipliers::block;
  SegmentFixOptions fixes;          // the host-side fixes (their width config.bits); none by default
};

// Every fix of the space's fix axes (their cross product, 0 = off) at `bits`, the no-fix first when
// present. Throws std::invalid_argument naming the option for a coordinate width not below `bits`.
std::vector<SegmentFixOptions> design_fixes(const DesignSpace& space, int bits);

struct DesignCandidate {
  DesignConfig design;
  ConfigCheck check;
  bool spare_banks = false;  // banks beyond the layout's use plus one: pruned (above)
};

// Every design of the space within the constraints' banks and widths, checked; the infeasible ones
// carry their reason. Throws std::invalid_argument for an empty axis or a profile that refuses a value.
std::vector<DesignCandidate> enumerate_designs(const DesignSpace& space, const DesignConstraints& constraints,
                                               const ConfigChecker& checker);

// One simulated design.
struct DesignPoint {
  DesignConfig design;
  SweepRow row;  // simulated seconds, energy, watts, bound columns (sweep_row.h)
  DesignBound bound;
  std::uint64_t tests = 0;         // the lanes' and the host's own (re-tests), as run's visibility_tests
  double bank_bytes_per_test = 0;  // every bank's bytes read and written / the lanes' ray-face tests
  double pci_bytes_per_test = 0;   // both directions
  double tests_per_second = 0;     // over the whole run
  WidthFidelity fidelity;           // of the design's width: steps, software time, error
  bool meets_constraints = false;  // energy, power and error caps
  bool on_front = false;
  board::DeviceProfile profile;     // the design's device profile (its settings applied): `run --device` takes it
};

// Banks count the whole design's: the configuration's banks on every card.
// Indices of the fastest point meeting the constraints (ties: fewer banks, less energy, fewer lanes,
// fewer cards, then the label), or none.
std::optional<std::size_t> fastest(const std::vector<DesignPoint>& points);
// Marks on_front: a point meeting the constraints that no other such point equals or beats in time,
// energy, banks and error (relative RMSE) while beating it in one. A missing energy or error (NaN)
// counts as the worst.
void mark_front(std::vector<DesignPoint>& points);
// Sets meets_constraints from the caps (energy, average power, error: a point whose error was not
// measured fails an error cap).
void apply_caps(std::vector<DesignPoint>& points, const DesignConstraints& constraints);

struct DesignSearchResult {
  std::string device;
  Workload workload;
  std::size_t faces = 0, patches = 0;
  int steps = 0;            // the paper's two-lane design's (its 15-bit solve's); each point has its own width's
  int reference_steps = 0;  // of the double-precision solve the widths' errors are measured against
  std::vector<WidthFidelity> widths;  // every width solved, ascending
  std::size_t designs = 0, infeasible = 0, pruned = 0;  // of the space within the constraints
  bool exhaustive = false;                              // --exhaustive: nothing pruned, every feasible design simulated
  std::vector<std::string> infeasible_reasons;          // one per reason kind, an example each
  std::vector<DesignPoint> points;                      // simulated, in enumeration order
  std::optional<std::size_t> best;
  std::optional<DesignPoint> reference;                 // the paper's two-lane design on this workload
  double software_seconds = 0;  // of the 15-bit solve (the paper's software column); each width's: WidthFidelity
  unsigned max_banks = 0;
};

// The paper's two-lane design (sec 5.5: XC2V6000, 2 lanes, 6 banks, results in the bank, 15 bits,
// block multipliers, one card) with the concurrent driver (sec 4.3): the design to beat.
DesignConfig paper_two_lane_design(const ConfigChecker& checker);

// The timing cases of `candidates` that are simulated (feasible, not pruned unless `exhaustive`),
// for a scene and recording; `index[i]` is the case of candidate i or npos.
struct DesignCases {
  std::vector<TimingCase> cases;
  std::vector<std::size_t> index;
};
DesignCases design_cases(const std::vector<DesignCandidate>& candidates, const Scene& scene, const SolverOptions& solver,
                         const VisibilityRecording& recording, std::uint64_t max_segments, bool exhaustive);
DesignPoint design_point(const DesignConfig& design, const TimingOutcome& outcome, int steps);
// A point's speed-up over the software-only run of its own width's solve (NaN when unknown).
double speedup_over_software(const DesignPoint& p);

// The whole search (runs a timing study: once per process) on `workload` (default_design_workload(),
// workload.h: the paper's 280/4480 box, Table 2's steps, every segment, point), its visibility
// answered by `visibility` at every width searched. Every design replays the steps of the
// workload's policy (steps_to_solve); to convergence, those its own width's solve took. Each width
// is also measured against one double-precision solve of the workload (fidelity.h) and priced as
// software alone (a software timing case per width). `progress` gets one line per phase.
DesignSearchResult search_designs(const Workload& workload, BitExactVisibility visibility, const DesignSpace& space,
                                  const DesignConstraints& constraints, bool exhaustive,
                                  const std::function<void(const std::string&)>& progress);

// When no design meets the constraints, why (docs/design.md, "When no design meets the
// constraints"): per limit set, how many simulated designs meet it, how many have no figure for it
// (no energy table, error not measured) and the least value; then whether the limits contradict
// each other (each met by some design, none by all). Empty when no limit is set.
std::vector<std::string> why_no_design(const DesignSearchResult& result, const DesignConstraints& constraints);

// The roofline of a search's device: the best design's roofs (its lanes and clock, its banks and bank
// clock, PCI, and the flat PCI and host roofs of its run), the paper's rule for the device (sec 5.6:
// lanes that fit at Table 1's clock, 6.125 bytes per test; `paper_software_rate`: Table 2's measured
// peak), the front, the best design and the paper's two-lane design as simulated.
Roofline design_roofline(const DesignSearchResult& result, double paper_software_rate);

// "virtex4-sx55, 6 lanes, 20 banks at 100 MHz, results on chip, 15-bit, block multipliers, 1 card, concurrent",
// with ", offset 2 LSB + neighbours (ring 1)" when the design has fixes.
std::string describe(const DesignConfig& design);

}  // namespace rc
