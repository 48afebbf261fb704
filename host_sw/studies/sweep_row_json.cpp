#include "host_sw/studies/sweep_row_json.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "host_sw/studies/sweep_columns.h"

namespace rc {

namespace {

constexpr double kNullAsNaN = std::numeric_limits<double>::quiet_NaN();

nlohmann::ordered_json json_value(const SweepCell& v) {
  switch (v.kind) {
    case SweepCell::Kind::none: return nlohmann::ordered_json();
    case SweepCell::Kind::text: return v.text;
    case SweepCell::Kind::integer: return v.integer;
    case SweepCell::Kind::number: return v.number;
  }
  throw std::logic_error("json_value: not a SweepCell kind");
}

}  // namespace

nlohmann::ordered_json sweep_row_json(const SweepRow& r, const std::vector<std::string>& extra) {
  const std::vector<std::string> names = sweep_columns(extra);
  const std::vector<SweepCell> values = sweep_cells(r, extra);
  nlohmann::ordered_json j;
  for (std::size_t i = 0; i < values.size(); ++i) j[names[i]] = json_value(values[i]);
  j["concurrent"] = r.config.concurrent;  // a JSON boolean; the CSV writes 1 or 0
  return j;
}

namespace {

double number_from(const nlohmann::ordered_json& j, const char* key) {
  const nlohmann::ordered_json& v = j.at(key);
  return v.is_null() ? kNullAsNaN : v.get<double>();
}

Validity validity_from(const std::string& status, const std::string& kind) {
  if (status == "ok") return Validity::ok;
  for (Validity v : {Validity::does_not_fit, Validity::too_few_banks, Validity::other})
    if (kind == to_string(v)) return v;
  throw std::invalid_argument("sweep row: unknown invalid_kind '" + kind + "'");
}

const char* const kRowFigures[] = {"steps", "clock_mhz", "nominal_rays_per_cycle", "simulated_seconds",
                                   "fpga_busy_seconds", "host_compute_seconds", "driver_cpu_seconds",
                                   "pci_transfer_seconds", "waiting_seconds", "pci_utilisation", "max_bank_utilisation",
                                   "busiest_bank", "mean_lane_utilisation", "intersections_per_second_while_busy",
                                   "fpga_limit_share", "speedup_vs_one_lane", "speedup_vs_software", "energy_joules",
                                   "energy_per_step_joules", "energy_per_intersection_nanojoules", "average_watts",
                                   "energy_delay_product_joule_seconds", "fpga_joules", "sram_joules", "pci_joules",
                                   "host_joules", "stream_bound_tests_per_second", "stream_next_tests_per_second",
                                   "lane_tests_per_second_peak", "sram_bytes_per_second", "sram_bytes_per_test",
                                   "busiest_bank_bytes_per_second", "pci_bytes_per_second_to_board",
                                   "pci_bytes_per_second_to_host"};

// A row read back (a shard file, hand-edited or damaged) must hold figures a run can produce: every
// number finite and non-negative (null: not measured), a simulated row's time positive and at most
// kMaxRowSeconds, shares and utilisations at most 1. Otherwise merge would write the number as a
// result (negative or 1e308 simulated seconds were accepted).
void check_row_figures(const nlohmann::ordered_json& j, const SweepRow& r) {
  const std::string row = "row " + r.config.label() + ": ";
  for (const char* key : kRowFigures) {
    const nlohmann::ordered_json& v = j.at(key);
    if (v.is_null()) continue;
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0) {
      throw std::invalid_argument(row + key + " = " + v.dump() +
                                  " is not a figure a run produces (a finite number, not negative, or null)");
    }
  }
  if (r.validity != Validity::ok) return;
  const double seconds = number_from(j, "simulated_seconds");
  if (!(seconds > 0 && seconds <= kMaxRowSeconds)) {
    char text[96];
    std::snprintf(text, sizeof text, "%g is outside (0, %g]", seconds, kMaxRowSeconds);
    throw std::invalid_argument(row + "simulated_seconds = " + text + " for a simulated row (kMaxRowSeconds)");
  }
  for (const char* key : {"pci_utilisation", "mean_lane_utilisation", "fpga_limit_share"}) {
    const double x = number_from(j, key);
    if (x > 1 + 1e-9) throw std::invalid_argument(row + key + " = " + j.at(key).dump() + " is above 1 (a share)");
  }
  // A bank's busy time over the FPGA's: the host's DMA into a bank while the FPGA is idle counts too,
  // so it may exceed 1 (a one-lane Virtex-4 run: 1.0005); never beyond the whole run over the FPGA's.
  const double fpga = number_from(j, "fpga_busy_seconds"), bank = number_from(j, "max_bank_utilisation");
  if (fpga > 0 && bank * fpga > seconds * (1 + 1e-9)) {
    throw std::invalid_argument(row + "max_bank_utilisation = " + j.at("max_bank_utilisation").dump() +
                                " is above simulated_seconds / fpga_busy_seconds (a bank is busy at most the whole run)");
  }
}

}  // namespace

SweepRow sweep_row_from_json(const nlohmann::ordered_json& j, const SweepConfig& config) {
  SweepRow r;
  r.config = config;
  const bool same = j.at("lanes").get<unsigned>() == config.lanes && j.at("banks").get<unsigned>() == config.banks &&
                    j.at("bits").get<int>() == config.bits && j.at("concurrent").get<bool>() == config.concurrent;
  if (!same) throw std::invalid_argument("sweep row " + j.dump() + " is not the plan's " + config.label());
  r.config.device = j.at("device").get<std::string>();  // the profile's name (the plan may hold a path)
  r.validity = validity_from(j.at("status").get<std::string>(), j.at("invalid_kind").get<std::string>());
  check_row_figures(j, r);  // before any figure is read as a number
  r.reason = j.at("reason").get<std::string>();
  r.steps = j.at("steps").get<int>();
  r.clock_mhz = number_from(j, "clock_mhz");
  r.nominal_rays_per_cycle = number_from(j, "nominal_rays_per_cycle");
  r.simulated_seconds = number_from(j, "simulated_seconds");
  r.fpga_busy_seconds = number_from(j, "fpga_busy_seconds");
  r.host_compute_seconds = number_from(j, "host_compute_seconds");
  r.driver_cpu_seconds = number_from(j, "driver_cpu_seconds");
  r.pci_transfer_seconds = number_from(j, "pci_transfer_seconds");
  r.waiting_seconds = number_from(j, "waiting_seconds");
  r.pci_utilisation = number_from(j, "pci_utilisation");
  r.max_bank_utilisation = number_from(j, "max_bank_utilisation");
  r.busiest_bank = j.at("busiest_bank").is_null() ? -1 : j.at("busiest_bank").get<int>();
  r.busiest_bank_role = j.at("busiest_bank_role").get<std::string>();
  r.mean_lane_utilisation = number_from(j, "mean_lane_utilisation");
  r.intersections_per_second_while_busy = number_from(j, "intersections_per_second_while_busy");
  r.fpga_limit = j.at("fpga_limit").get<std::string>();
  r.fpga_limit_share = number_from(j, "fpga_limit_share");
  r.bottleneck = j.at("bottleneck").get<std::string>();
  r.speedup_vs_one_lane = number_from(j, "speedup_vs_one_lane");
  r.speedup_vs_software = number_from(j, "speedup_vs_software");
  r.energy_joules = number_from(j, "energy_joules");
  r.energy_per_step_joules = number_from(j, "energy_per_step_joules");
  r.energy_per_intersection_nanojoules = number_from(j, "energy_per_intersection_nanojoules");
  r.average_watts = number_from(j, "average_watts");
  r.energy_delay_product_joule_seconds = number_from(j, "energy_delay_product_joule_seconds");
  r.fpga_joules = number_from(j, "fpga_joules");
  r.sram_joules = number_from(j, "sram_joules");
  r.pci_joules = number_from(j, "pci_joules");
  r.host_joules = number_from(j, "host_joules");
  r.energy_missing = j.at("energy_missing").get<std::string>();
  r.pareto_time_energy = !j.at("pareto_time_energy").is_null() && j.at("pareto_time_energy").get<int>() == 1;
  r.stream_bound = j.at("stream_bound").get<std::string>();
  r.stream_bound_tests_per_second = number_from(j, "stream_bound_tests_per_second");
  r.stream_next = j.at("stream_next").get<std::string>();
  r.stream_next_tests_per_second = number_from(j, "stream_next_tests_per_second");
  r.run_bound = j.at("run_bound").get<std::string>();
  r.run_next = j.at("run_next").get<std::string>();
  r.lane_tests_per_second_peak = number_from(j, "lane_tests_per_second_peak");
  r.sram_bytes_per_second = number_from(j, "sram_bytes_per_second");
  r.sram_bytes_per_test = number_from(j, "sram_bytes_per_test");
  r.busiest_bank_bytes_per_second = number_from(j, "busiest_bank_bytes_per_second");
  r.pci_bytes_per_second_to_board = number_from(j, "pci_bytes_per_second_to_board");
  r.pci_bytes_per_second_to_host = number_from(j, "pci_bytes_per_second_to_host");
  r.pci_mode = j.at("pci_mode").get<std::string>();
  return r;
}

}  // namespace rc
