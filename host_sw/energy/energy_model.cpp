#include "host_sw/energy/energy_model.h"

#include <cmath>
#include <stdexcept>

namespace rc::energy {

namespace {

class Sum {
 public:
  explicit Sum(EnergyReport& r) : r_(r) {}
  void action(const std::string& component, const std::string& counter, double count, const Figure& f) {
    add(component, counter, count, f, false);
  }
  void power(const std::string& component, const std::string& counter, double seconds, const Figure& f) {
    add(component, counter, seconds, f, true);
  }

 private:
  void add(const std::string& component, const std::string& counter, double count, const Figure& f, bool is_static) {
    const double joules = count * f.si();
    r_.terms.push_back({component, counter, count, f, is_static, joules});
    ComponentEnergy* c = nullptr;
    for (ComponentEnergy& e : r_.components)
      if (e.name == component) c = &e;
    if (c == nullptr) c = &r_.components.emplace_back(ComponentEnergy{component});
    (is_static ? c->static_joules : c->dynamic_joules) += joules;
  }
  EnergyReport& r_;
};

void add_board(Sum& sum, const DeviceEnergyTable& t, const Activity& a) {
  const double cards = a.cards;
  // Every lane of every card is clocked for the whole run (the configured design never stops its
  // clock); a lane works one cycle per ray-face test.
  const double lane_cycles = cards * a.lanes * a.device_clock_hz * a.seconds;
  if (static_cast<double>(a.lane_active_cycles) > lane_cycles * (1 + 1e-9) + 1) {
    throw std::invalid_argument("energy: " + std::to_string(a.lane_active_cycles) +
                                " active lane-cycles exceed the lanes' cycles in the run (" +
                                std::to_string(lane_cycles) + ")");
  }
  const double active = static_cast<double>(a.lane_active_cycles);
  sum.power("fpga", "FPGAs configured (cards x seconds)", cards * a.seconds, t.fpga.static_w);
  sum.action("fpga", "slice-cycles of the clock network (cards x lanes x slices per lane x device cycles)",
             lane_cycles * a.slices_per_lane, t.fpga.clock_pj_per_slice_cycle);
  sum.action("fpga", "slice-cycles in active lanes (ray-face tests x slices per lane)", active * a.slices_per_lane,
             t.fpga.slice_pj_per_cycle);
  sum.action("fpga", "multiplier-cycles in active lanes (ray-face tests x block multipliers per lane)",
             active * a.multipliers_per_lane, t.fpga.multiplier_pj_per_cycle);
  sum.action("sram", "bank word reads", static_cast<double>(a.bank_word_reads), t.sram.read_nj);
  sum.action("sram", "bank word writes", static_cast<double>(a.bank_word_writes), t.sram.write_nj);
  sum.power("sram", "banks powered (cards x banks x seconds)", cards * a.banks * a.seconds, t.sram.standby_mw);
  sum.action("pci", "PCI data phases (bus words moved)", static_cast<double>(a.pci_data_phases), t.pci.data_phase_nj);
  sum.action("pci", "PCI transactions (arbitration and address phases)", static_cast<double>(a.pci_transactions),
             t.pci.transaction_nj);
  sum.power("pci", "PCI bridges powered (cards x seconds)", cards * a.seconds, t.pci.bridge_w);
}

void add_host(Sum& sum, const HostEnergyTable& t, const Activity& a) {
  const double cpu_seconds = a.host_cpus * a.seconds;
  if (a.host_busy_cpu_seconds > cpu_seconds * (1 + 1e-9)) {
    throw std::invalid_argument("energy: " + std::to_string(a.host_busy_cpu_seconds) + " busy CPU-seconds exceed the " +
                                std::to_string(a.host_cpus) + " processors' time in the run");
  }
  sum.action("host", "CPU-seconds computing (solver and driver)", a.host_busy_cpu_seconds, t.busy_w);
  sum.power("host", "CPU-seconds waiting (the run's processors, not computing)",
            std::max(0.0, cpu_seconds - a.host_busy_cpu_seconds), t.wait_w);
}

}  // namespace

EnergyReport estimate(const EnergyTables& tables, const Activity& a) {
  if (!tables.host) throw std::invalid_argument("energy: no host energy table (" + tables.missing + ")");
  if (a.cards > 0 && !tables.device) throw std::invalid_argument("energy: no device energy table (" + tables.missing + ")");
  if (!(a.seconds >= 0) || !std::isfinite(a.seconds)) throw std::invalid_argument("energy: simulated time is not finite");
  EnergyReport r;
  Sum sum(r);
  if (a.cards > 0) {
    add_board(sum, *tables.device, a);
    r.device_table = tables.device->file;
  }
  add_host(sum, *tables.host, a);
  r.host_table = tables.host->file;
  r.seconds = a.seconds;
  for (ComponentEnergy& c : r.components) {
    c.average_watts = a.seconds > 0 ? c.joules() / a.seconds : 0.0;
    r.joules += c.joules();
  }
  r.average_watts = a.seconds > 0 ? r.joules / a.seconds : 0.0;
  r.joules_per_step = a.steps > 0 ? r.joules / static_cast<double>(a.steps) : 0.0;
  r.joules_per_intersection = a.intersections > 0 ? r.joules / static_cast<double>(a.intersections) : 0.0;
  r.energy_delay_product = r.joules * a.seconds;
  return r;
}

}  // namespace rc::energy
