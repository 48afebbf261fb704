#include "host_sw/studies/sweep_columns.h"

#include <climits>
#include <cmath>
#include <iterator>
#include <stdexcept>

namespace rc {

std::vector<std::string> extra_columns(const SweepAxes& axes) {
  std::vector<std::string> columns;
  if (axes.hosts.size() > 1) columns.push_back("host");
  if (axes.cards != std::vector<int>{1}) {
    for (const char* c : {"cards", "card_split", "card_bus"}) columns.push_back(c);
  }
  for (const ProfileAxis& a : axes.profile) columns.push_back(a.field.path);
  return columns;
}

namespace {

const char* const kColumns[] = {"device",
                                "lanes",
                                "banks",
                                "bits",
                                "concurrent",
                                "status",
                                "invalid_kind",
                                "reason",
                                "steps",
                                "clock_mhz",
                                "nominal_rays_per_cycle",
                                "simulated_seconds",
                                "fpga_busy_seconds",
                                "host_compute_seconds",
                                "driver_cpu_seconds",
                                "pci_transfer_seconds",
                                "waiting_seconds",
                                "pci_utilisation",
                                "max_bank_utilisation",
                                "busiest_bank",
                                "busiest_bank_role",
                                "mean_lane_utilisation",
                                "intersections_per_second_while_busy",
                                "fpga_limit",
                                "fpga_limit_share",
                                "bottleneck",
                                "speedup_vs_one_lane",
                                "speedup_vs_software",
                                "energy_joules",
                                "energy_per_step_joules",
                                "energy_per_intersection_nanojoules",
                                "average_watts",
                                "energy_delay_product_joule_seconds",
                                "fpga_joules",
                                "sram_joules",
                                "pci_joules",
                                "host_joules",
                                "energy_missing",
                                "pareto_time_energy",
                                "stream_bound",
                                "stream_bound_tests_per_second",
                                "stream_next",
                                "stream_next_tests_per_second",
                                "run_bound",
                                "run_next",
                                "lane_tests_per_second_peak",
                                "sram_bytes_per_second",
                                "sram_bytes_per_test",
                                "busiest_bank_bytes_per_second",
                                "pci_bytes_per_second_to_board",
                                "pci_bytes_per_second_to_host",
                                "pci_mode"};

constexpr std::size_t kConfigColumns = 5;  // device .. concurrent: the extra columns follow them

SweepCell none() { return {}; }
SweepCell text(const std::string& s) { return {SweepCell::Kind::text, s, 0, 0}; }
SweepCell integer(long long i) { return {SweepCell::Kind::integer, {}, i, 0}; }
SweepCell number_cell(double x) { return std::isnan(x) ? none() : SweepCell{SweepCell::Kind::number, {}, 0, x}; }

// A profile setting's value as the study gave it: a name, an integer or a number. (The one place
// here that reads a setting's value; it follows profile_setting.h's type.)
SweepCell setting_cell(const ProfileValue& v) {
  if (const std::string* name = std::get_if<std::string>(&v)) return text(*name);
  if (const std::int64_t* whole = std::get_if<std::int64_t>(&v)) return integer(*whole);
  return SweepCell{SweepCell::Kind::number, {}, 0, std::get<double>(v)};
}

// The value of an extra column: the host, the cards, or the setting of the profile axis with that path.
SweepCell extra_value(const SweepConfig& c, const std::string& column) {
  if (column == "host") return text(c.host);
  if (column == "cards") return integer(c.cards);
  if (column == "card_split") return c.cards > 1 ? text(choice_name(c.card_split)) : none();
  if (column == "card_bus") return c.cards > 1 ? text(choice_name(c.card_bus)) : none();
  for (const ProfileSetting& s : c.settings)
    if (s.field.path == column) return setting_cell(s.value);
  throw std::logic_error("sweep column '" + column + "' has no value in " + c.label());
}

}  // namespace

std::vector<std::string> sweep_columns(const std::vector<std::string>& extra) {
  std::vector<std::string> names(std::begin(kColumns), std::end(kColumns));
  names.insert(names.begin() + kConfigColumns, extra.begin(), extra.end());
  return names;
}

std::vector<SweepCell> sweep_cells(const SweepRow& r, const std::vector<std::string>& extra) {
  const bool ok = r.validity == Validity::ok;
  std::vector<SweepCell> values = {text(r.config.device), integer(r.config.lanes), integer(r.config.banks),
                                   integer(r.config.bits), integer(r.config.concurrent ? 1 : 0)};
  for (const std::string& column : extra) values.push_back(extra_value(r.config, column));
  const std::vector<SweepCell> rest = {
      text(ok ? "ok" : "invalid"),
      text(ok ? std::string() : to_string(r.validity)),
      text(r.reason),
      integer(r.steps),
      number_cell(r.clock_mhz),
      number_cell(r.nominal_rays_per_cycle),
      number_cell(r.simulated_seconds),
      number_cell(r.fpga_busy_seconds),
      number_cell(r.host_compute_seconds),
      number_cell(r.driver_cpu_seconds),
      number_cell(r.pci_transfer_seconds),
      number_cell(r.waiting_seconds),
      number_cell(r.pci_utilisation),
      number_cell(r.max_bank_utilisation),
      ok && r.busiest_bank >= 0 ? integer(r.busiest_bank) : none(),
      text(r.busiest_bank_role),
      number_cell(r.mean_lane_utilisation),
      number_cell(r.intersections_per_second_while_busy),
      text(r.fpga_limit),
      number_cell(r.fpga_limit_share),
      text(r.bottleneck),
      number_cell(r.speedup_vs_one_lane),
      number_cell(r.speedup_vs_software),
      number_cell(r.energy_joules),
      number_cell(r.energy_per_step_joules),
      number_cell(r.energy_per_intersection_nanojoules),
      number_cell(r.average_watts),
      number_cell(r.energy_delay_product_joule_seconds),
      number_cell(r.fpga_joules),
      number_cell(r.sram_joules),
      number_cell(r.pci_joules),
      number_cell(r.host_joules),
      text(r.energy_missing),
      ok && std::isfinite(r.energy_joules) ? integer(r.pareto_time_energy ? 1 : 0) : none(),
      text(r.stream_bound),
      number_cell(r.stream_bound_tests_per_second),
      text(r.stream_next),
      number_cell(r.stream_next_tests_per_second),
      text(r.run_bound),
      text(r.run_next),
      number_cell(r.lane_tests_per_second_peak),
      number_cell(r.sram_bytes_per_second),
      number_cell(r.sram_bytes_per_test),
      number_cell(r.busiest_bank_bytes_per_second),
      number_cell(r.pci_bytes_per_second_to_board),
      number_cell(r.pci_bytes_per_second_to_host),
      text(r.pci_mode)};
  values.insert(values.end(), rest.begin(), rest.end());
  return values;
}

}  // namespace rc
