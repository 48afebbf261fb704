#include "host_sw/studies/sweep_row.h"

#include <cmath>
#include <limits>

#include "host_sw/platform/run_bounds.h"

namespace rc {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

namespace {

void set_no_energy(SweepRow& r) {
  for (double* x : {&r.energy_joules, &r.energy_per_step_joules, &r.energy_per_intersection_nanojoules, &r.average_watts,
                    &r.energy_delay_product_joule_seconds, &r.fpga_joules, &r.sram_joules, &r.pci_joules, &r.host_joules})
    *x = kNaN;
  r.pareto_time_energy = false;
}

double component_joules(const energy::EnergyReport& e, const char* name) {
  for (const energy::ComponentEnergy& c : e.components)
    if (c.name == name) return c.joules();
  return kNaN;
}

void energy_columns(const RunReport& report, SweepRow& r) {
  set_no_energy(r);
  r.energy_missing = report.energy_missing;
  if (!report.energy) return;
  const energy::EnergyReport& e = *report.energy;
  r.energy_joules = e.joules;
  r.energy_per_step_joules = e.joules_per_step > 0 ? e.joules_per_step : kNaN;
  r.energy_per_intersection_nanojoules = e.joules_per_intersection > 0 ? e.joules_per_intersection * 1e9 : kNaN;
  r.average_watts = e.average_watts;
  r.energy_delay_product_joule_seconds = e.energy_delay_product;
  r.fpga_joules = component_joules(e, "fpga");
  r.sram_joules = component_joules(e, "sram");
  r.pci_joules = component_joules(e, "pci");
  r.host_joules = component_joules(e, "host");
}

void set_no_bounds(SweepRow& r) {
  for (double* x : {&r.stream_bound_tests_per_second, &r.stream_next_tests_per_second, &r.lane_tests_per_second_peak,
                    &r.sram_bytes_per_second, &r.sram_bytes_per_test, &r.busiest_bank_bytes_per_second,
                    &r.pci_bytes_per_second_to_board, &r.pci_bytes_per_second_to_host})
    *x = kNaN;
}

double ceiling_of(const ResourceUse* u) { return u && u->tests_per_second_ceiling ? *u->tests_per_second_ceiling : kNaN; }

void bound_columns(const RunReport& report, SweepRow& r) {
  const RunBounds b = run_bounds(report);
  r.stream_bound = b.stream_bound_name();
  r.stream_bound_tests_per_second = ceiling_of(b.stream_bound());
  r.stream_next = b.stream_next_name();
  r.stream_next_tests_per_second = ceiling_of(b.stream_next());
  r.run_bound = b.run[0].name;
  r.run_next = b.run[1].name;
  r.lane_tests_per_second_peak = b.resources.front().capacity;
  r.sram_bytes_per_second = b.sram_bytes_per_second;
  r.sram_bytes_per_test = b.sram_bytes_per_test;
  r.busiest_bank_bytes_per_second = kNaN;
  double most = -1;
  for (const ResourceUse& u : b.resources) {
    if (u.kind == ResourceUse::Kind::bank && u.utilisation > most) {  // the first of equal banks, as busiest_bank
      most = u.utilisation;
      r.busiest_bank_bytes_per_second = u.demand;
    }
    if (u.kind == ResourceUse::Kind::pci) {
      r.pci_bytes_per_second_to_board = u.written_bytes_per_second;
      r.pci_bytes_per_second_to_host = u.read_bytes_per_second;
      r.pci_mode = u.role;
    }
  }
}

}  // namespace

SweepRow invalid_row(const SweepConfig& config, const ConfigCheck& check, int steps) {
  SweepRow r;
  r.config = config;
  r.validity = check.validity;
  r.reason = check.reason;
  r.steps = steps;
  r.clock_mhz = check.clock_mhz > 0 ? check.clock_mhz : kNaN;
  for (double* x : {&r.nominal_rays_per_cycle, &r.simulated_seconds, &r.fpga_busy_seconds, &r.host_compute_seconds,
                    &r.driver_cpu_seconds, &r.pci_transfer_seconds, &r.waiting_seconds, &r.pci_utilisation,
                    &r.max_bank_utilisation, &r.mean_lane_utilisation, &r.intersections_per_second_while_busy,
                    &r.fpga_limit_share, &r.speedup_vs_one_lane, &r.speedup_vs_software})
    *x = kNaN;
  set_no_energy(r);
  set_no_bounds(r);
  return r;
}

namespace {

double ratio(double a, double b) { return b > 0 ? a / b : kNaN; }

void busiest_bank(const std::vector<BankUseReport>& banks, double fpga_busy, SweepRow& r) {
  double most = -1;
  for (const BankUseReport& b : banks) {
    if (b.busy_seconds <= most) continue;  // the first of equal banks wins
    most = b.busy_seconds;
    r.busiest_bank = static_cast<int>(b.bank);
    r.busiest_bank_role = b.role;
  }
  r.max_bank_utilisation = most >= 0 ? ratio(most, fpga_busy) : kNaN;
}

void dominant_limit(const std::vector<StreamLimitReport>& limits, SweepRow& r) {
  double most = -1, total = 0;
  for (const StreamLimitReport& l : limits) {
    total += l.fpga_busy_seconds;
    if (l.fpga_busy_seconds <= most) continue;
    most = l.fpga_busy_seconds;
    r.fpga_limit = l.limit;
  }
  r.fpga_limit_share = most >= 0 ? ratio(most, total) : kNaN;
}

}  // namespace

SweepRow row_from_report(const SweepConfig& config, const RunReport& report, int steps) {
  SweepRow r;
  r.config = config;
  r.steps = steps;
  const RunTime& t = report.time;
  r.clock_mhz = report.board.device.clock_hz / 1e6;
  r.nominal_rays_per_cycle = report.board.layout.nominal_rays_per_cycle;
  r.simulated_seconds = report.simulated_seconds;
  r.fpga_busy_seconds = t.fpga_busy;
  r.host_compute_seconds = t.host_compute;
  r.driver_cpu_seconds = t.driver_cpu;
  r.pci_transfer_seconds = t.pci_transfer;
  r.waiting_seconds = t.waiting;
  r.pci_utilisation = ratio(report.board.pci.bus_busy_seconds, r.simulated_seconds);
  busiest_bank(report.board.banks, r.fpga_busy_seconds, r);
  double lanes = 0;
  for (const LaneReport& l : report.board.lanes) lanes += l.utilisation;
  r.mean_lane_utilisation = report.board.lanes.empty() ? kNaN : lanes / report.board.lanes.size();
  r.intersections_per_second_while_busy = report.intersections.per_second_while_fpga_busy;
  dominant_limit(report.board.stream_limits, r);
  r.bottleneck = bottleneck(r);
  r.speedup_vs_one_lane = r.speedup_vs_software = kNaN;
  energy_columns(report, r);
  bound_columns(report, r);
  return r;
}

std::string fpga_limit_kind(const std::string& limit) {
  if (limit == "lanes") return "fpga_lanes";
  if (limit.rfind("bank ", 0) == 0 && limit.find("(results)") != std::string::npos) return "fpga_result_bank";
  if (limit.rfind("bank ", 0) == 0 && limit.find("(rays") != std::string::npos) return "fpga_ray_bank";
  return "fpga_other";
}

std::string bottleneck(const SweepRow& r) {
  // In this order the first of equal parts wins: the FPGA, then the host's own parts.
  const std::pair<const char*, double> parts[] = {{"fpga", r.waiting_seconds},
                                                  {"host_compute", r.host_compute_seconds},
                                                  {"host_driver", r.driver_cpu_seconds},
                                                  {"pci", r.pci_transfer_seconds}};
  const auto* top = &parts[0];
  for (const auto& p : parts)
    if (p.second > top->second) top = &p;
  return top == &parts[0] ? fpga_limit_kind(r.fpga_limit) : top->first;
}

void fill_speedups(std::vector<SweepRow>& rows, const std::map<std::string, double>& software_seconds) {
  // The same configuration but its lane count (the settings' texts stand for their values).
  auto base_key = [](const SweepConfig& c) {
    std::string key = c.device + "|" + std::to_string(c.bits) + "|" + (c.concurrent ? "1" : "0") + "|" +
                      std::to_string(c.banks) + "|" + c.host + "|" + std::to_string(c.cards) + "|" + choice_name(c.card_split) +
                      "|" + choice_name(c.card_bus);
    for (const ProfileSetting& s : c.settings) key += "|" + s.text();
    return key;
  };
  std::map<std::string, double> one_lane;
  for (const SweepRow& r : rows)
    if (r.validity == Validity::ok && r.config.lanes == 1) one_lane[base_key(r.config)] = r.simulated_seconds;
  for (SweepRow& r : rows) {
    if (r.validity != Validity::ok) continue;
    const auto base = one_lane.find(base_key(r.config));
    r.speedup_vs_one_lane = base != one_lane.end() ? ratio(base->second, r.simulated_seconds) : kNaN;
    const auto sw = software_seconds.find(software_key(r.config));
    r.speedup_vs_software = sw != software_seconds.end() ? ratio(sw->second, r.simulated_seconds) : kNaN;
  }
}

}  // namespace rc
