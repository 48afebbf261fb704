// The bandwidth and bound model of one board run (docs/board.md, "What bounds a run"): for every
// resource the run used, what it asked of it (demand) and what the resource can give (capacity), in
// one set of units, and which resource bounds the FPGA's stream, which bounds the whole run, and
// which comes next. A pure function of the run's measured statistics (RunReport, whose `board.device`
// holds the device profile's clocks and widths as the run used them): nothing is simulated here.
//
//   const RunBounds b = run_bounds(report);          // report.board_run must be true
//   b.stream.bound   -> the index in b.resources of what bounded most of the FPGA's stream time
//   b.summary()      -> "run: FPGA 62% of the time (next: host compute 30%); FPGA stream: bank 4
//                        (results, read-modify-write) 96% busy, 1.04e+08 tests/s; next: lanes at 2.1e+08 tests/s"
//
// Units. Every resource has a timeline and a busy time on it: the FPGA's resources (lanes, banks) the
// FPGA busy time, the host's (PCI, host compute, driver) the simulated time. Its utilisation is busy
// / timeline. Demand and capacity are rates in the resource's own unit: ray-face tests per second for
// the lanes (also per cycle: tests_per_cycle_*), bytes per second for a bank (one word per bank
// cycle, read or written) and for PCI (its width times its clock), seconds per second for host
// compute and the driver (one CPU: capacity 1). Every resource also has a ceiling in one common
// unit: the tests per second the run would reach if this resource alone limited it, doing the same
// work per test (tests / busy seconds; the lanes: their peak, lanes x tests per cycle x clock). The
// lowest ceiling is the bound; the next lowest is what a design that relieves the bound meets next.
//
// Bounds. The FPGA stream's bound is what the pass-time formula (board/pass_timing.h) found binding
// for the most FPGA time (RunReport's stream_limits: exact, per pass), as one of `resources`; its
// next is the FPGA resource with the lowest ceiling besides it. The run's bound is the largest part
// of the host thread's timeline (waiting for the FPGA, host compute, driver CPU, PCI transfers: the
// part whose removal would save the most, as sweep rows' `bottleneck`), its next the second largest.
//
// Several cards: the FPGA's figures are per card (the report sums FPGA busy time, bank traffic and
// lane tests over the cards, so sums over sums give a card's average); the host's are the run's.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "host_sw/platform/run_report.h"

namespace rc {

struct ResourceUse {
  enum class Kind { lanes, bank, pci, host_compute, driver };
  Kind kind = Kind::lanes;
  std::string name;    // "lanes", "bank 4", "PCI", "host compute", "driver"
  std::string role;    // bank: "results, read-modify-write", "rays g0 X", "faces", "spare"; PCI: "DMA",
                       // "PIO" or "DMA and PIO"; else empty
  bool fpga = true;    // on the FPGA's timeline (lanes, banks), else the host's
  std::string unit;    // of demand and capacity: "tests/s", "bytes/s", "s/s"
  double demand = 0;   // per second of its timeline
  double capacity = 0;
  double read_bytes_per_second = 0, written_bytes_per_second = 0;  // banks (read by the wrapper or the
                                                                   // host); PCI: to the host, to the board
  double busy_seconds = 0;
  double utilisation = 0;  // busy_seconds / its timeline's seconds
  std::optional<double> tests_per_second_ceiling;  // none: the resource did no work (a spare bank)
};

// A bound and what comes after it: indexes into RunBounds::resources (run parts: see RunBounds::run).
struct Bound {
  std::optional<std::size_t> bound, next;
};

// The run's timeline part that bounds it: "fpga" (waiting for the FPGA), "host_compute",
// "host_driver", "pci"; its share of the simulated time.
struct RunPart {
  std::string name;
  double seconds = 0, share = 0;
};

struct RunBounds {
  unsigned cards = 1;
  double clock_hz = 0;               // the FPGA design clock
  std::uint64_t tests = 0;           // ray-face tests of the run
  double tests_per_second = 0;       // over the simulated time
  double tests_per_second_while_fpga_busy = 0;  // per card
  double tests_per_cycle_demand = 0, tests_per_cycle_capacity = 0;  // the lanes, per card
  double sram_bytes_per_second = 0;  // every bank, while the FPGA is busy (per card)
  double sram_bytes_per_test = 0;    // every bank's bytes (the host's included) per test
  std::vector<ResourceUse> resources;  // lanes, each bank in order, PCI, host compute, driver
  Bound stream;                        // the FPGA stream's
  double stream_bound_share = 0;       // of the FPGA busy time, in passes the bound bounded
  std::vector<RunPart> run;            // the host timeline's parts, largest first (ties: fpga first)

  const ResourceUse* stream_bound() const { return stream.bound ? &resources[*stream.bound] : nullptr; }
  const ResourceUse* stream_next() const { return stream.next ? &resources[*stream.next] : nullptr; }
  // "bank 4 (results, read-modify-write)", "lanes"; "" without passes.
  std::string stream_bound_name() const;
  std::string stream_next_name() const;
  // One line for the run summary (see the example at the top).
  std::string summary() const;
  // One line of bandwidths: lanes, SRAM (the busiest bank), PCI each way and its mode.
  std::string bandwidth_line() const;
};

// Throws std::invalid_argument unless report.board_run.
RunBounds run_bounds(const RunReport& report);

// The label a resource carries in a bound: "lanes", "bank 4 (results, read-modify-write)", "PCI (DMA)".
std::string resource_label(const ResourceUse& resource);

}  // namespace rc
