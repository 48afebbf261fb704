#include "host_sw/energy/full_rate_energy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "board/design_fit.h"
#include "pipeline/resource_model.h"

namespace rc::energy {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double component_joules(const EnergyReport& r, const char* name) {
  for (const ComponentEnergy& c : r.components)
    if (c.name == name) return c.joules();
  return 0.0;
}

}  // namespace

FullRateEnergy full_rate_energy(const board::PaperEstimate& e, const board::DeviceProfile& device,
                                const EnergyTables& tables, int bits) {
  if (e.lanes <= 0 || !(e.intersections_per_s > 0)) {
    throw std::invalid_argument("full_rate_energy: '" + e.estimate + "' has no lanes streaming");
  }
  FullRateEnergy out;
  out.estimate = e.estimate;
  out.device = e.device;
  out.lanes = e.lanes;
  out.clock_mhz = e.clock_mhz;
  out.intersections_per_s = e.intersections_per_s;
  out.banks = std::max(device.bank_count, board::banks_for_full_rate(device, e.lanes, bits));
  if (!tables.missing.empty()) {
    out.missing = tables.missing;
    for (double* x : {&out.fpga_nj, &out.sram_nj, &out.pci_nj, &out.card_nj, &out.host_waiting_nj, &out.system_nj,
                      &out.software_nj, &out.card_watts})
      *x = kNaN;
    return out;
  }
  const board::DesignFit fit =
      board::fit_design(device, pipeline::ResourceModel::load_default(e.resources), static_cast<unsigned>(e.lanes), bits);
  Activity a;
  a.seconds = 1.0;
  a.intersections = static_cast<std::uint64_t>(std::llround(e.intersections_per_s));
  a.host_busy_cpu_seconds = 0;  // waiting for the interrupt
  a.host_cpus = 1;
  a.cards = 1;
  a.lanes = static_cast<unsigned>(e.lanes);
  a.device_clock_hz = e.clock_mhz * 1e6;
  a.slices_per_lane = static_cast<double>(fit.slices) / e.lanes;
  a.multipliers_per_lane = static_cast<double>(fit.block_multipliers) / e.lanes;
  a.lane_active_cycles = a.intersections;
  a.banks = out.banks;
  const double words = e.intersections_per_s * e.bytes_per_intersection / (device.bank_word_bits / 8.0);
  a.bank_word_reads = static_cast<std::uint64_t>(std::llround(words / 2));
  a.bank_word_writes = static_cast<std::uint64_t>(std::llround(words / 2));
  out.report = estimate(tables, a);
  const double per = 1e9 / e.intersections_per_s;  // joules in the second -> nJ per intersection
  out.fpga_nj = component_joules(out.report, "fpga") * per;
  out.sram_nj = component_joules(out.report, "sram") * per;
  out.pci_nj = component_joules(out.report, "pci") * per;
  out.card_nj = out.fpga_nj + out.sram_nj + out.pci_nj;
  out.card_watts = out.card_nj * e.intersections_per_s / 1e9;
  out.host_waiting_nj = component_joules(out.report, "host") * per;
  out.system_nj = out.card_nj + out.host_waiting_nj;

  Activity software;
  software.seconds = 1.0;
  software.host_busy_cpu_seconds = 1.0;
  software.intersections = static_cast<std::uint64_t>(std::llround(e.software_rate));
  EnergyTables host_only{std::nullopt, tables.host, ""};
  out.software_nj = e.software_rate > 0 ? estimate(host_only, software).joules * 1e9 / e.software_rate : kNaN;
  return out;
}

}  // namespace rc::energy
