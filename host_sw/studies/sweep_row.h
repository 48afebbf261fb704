// One sweep configuration's outcome (`rc2000sim sweep`, docs/results/sweep.md): the row made from
// its board report, the bottleneck it names, and the speedups against other rows. Its columns and
// their writers: sweep_columns.h, sweep_csv.h, sweep_row_json.h.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "host_sw/platform/run_report.h"
#include "host_sw/studies/config_checker.h"
#include "host_sw/studies/sweep_config.h"

namespace rc {

// One configuration's outcome: the CSV row and the JSON record (docs/results/sweep.md defines
// every column). Numbers of an invalid row are NaN (empty in the CSV, null in the JSON).
struct SweepRow {
  SweepConfig config;
  Validity validity = Validity::ok;
  std::string reason;
  int steps = 0;
  double clock_mhz = 0;  // NaN when the lanes do not fit
  double nominal_rays_per_cycle = 0;
  double simulated_seconds = 0, fpga_busy_seconds = 0;
  double host_compute_seconds = 0, driver_cpu_seconds = 0, pci_transfer_seconds = 0, waiting_seconds = 0;
  double pci_utilisation = 0;       // PCI bus busy / simulated
  double max_bank_utilisation = 0;  // busiest bank's busy time / FPGA busy time
  int busiest_bank = -1;
  std::string busiest_bank_role;
  double mean_lane_utilisation = 0;
  double intersections_per_second_while_busy = 0;
  std::string fpga_limit;        // the stream limit that took the most FPGA time ("lanes", "bank 4 (results)")
  double fpga_limit_share = 0;   // its share of the FPGA busy time
  std::string bottleneck;        // bottleneck() below
  double speedup_vs_one_lane = 0;  // NaN when 1 lane was not swept at the same device, width, driver, banks
  double speedup_vs_software = 0;  // NaN without a software time for the width
  // Energy (docs/energy.md), NaN when the row is invalid or a profile has no energy table (then
  // energy_missing says which).
  double energy_joules = 0, energy_per_step_joules = 0, energy_per_intersection_nanojoules = 0;
  double average_watts = 0, energy_delay_product_joule_seconds = 0;
  double fpga_joules = 0, sram_joules = 0, pci_joules = 0, host_joules = 0;
  std::string energy_missing;
  // On the Pareto front of time against energy (pareto_time_energy below); false off it, and for rows
  // without both.
  bool pareto_time_energy = false;
  // The bound model (host_sw/platform/run_bounds.h): what bounds the FPGA's stream and what comes
  // next, each with its ceiling in tests/s (per card); the host timeline's largest part and the next
  // (fpga, host_compute, host_driver, pci); the bandwidths. NaN and empty for an invalid row.
  std::string stream_bound, stream_next;
  double stream_bound_tests_per_second = 0, stream_next_tests_per_second = 0;
  std::string run_bound, run_next;
  double lane_tests_per_second_peak = 0;
  double sram_bytes_per_second = 0, sram_bytes_per_test = 0, busiest_bank_bytes_per_second = 0;
  double pci_bytes_per_second_to_board = 0, pci_bytes_per_second_to_host = 0;
  std::string pci_mode;  // "DMA", "PIO" or "DMA and PIO"
};

SweepRow invalid_row(const SweepConfig& config, const ConfigCheck& check, int steps);
// From a board report (rc2000sim.board/1 with stream_limits); speedups are filled by fill_speedups.
SweepRow row_from_report(const SweepConfig& config, const RunReport& report, int steps);

// "lanes" -> "fpga_lanes"; "bank N (results)" -> "fpga_result_bank"; "bank N (rays ...)" ->
// "fpga_ray_bank"; anything else -> "fpga_other".
std::string fpga_limit_kind(const std::string& limit);

// The largest part of the host thread's timeline (host compute, driver CPU, PCI transfers, waiting
// for the FPGA's interrupt): the part whose removal would save the most. Waiting means the FPGA
// bounds the run, and then what bounded its stream is named (fpga_limit_kind). Values:
// host_compute, host_driver, pci, fpga_lanes, fpga_result_bank, fpga_ray_bank, fpga_other.
std::string bottleneck(const SweepRow& row);

// speedup_vs_one_lane from the 1-lane rows of the same configuration but lanes; speedup_vs_software
// from software seconds by software_key (keys missing from the map: NaN).
void fill_speedups(std::vector<SweepRow>& rows, const std::map<std::string, double>& software_seconds);

}  // namespace rc
