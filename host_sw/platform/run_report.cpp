#include <cmath>

#include "host_sw/platform/run_report.h"

namespace rc {

energy::Activity activity_of(const RunReport& r, std::uint64_t steps) {
  energy::Activity a;
  a.seconds = r.simulated_seconds;
  a.steps = steps;
  a.intersections = r.intersections.tests;
  // The solver's processor computes (host work and, on one card, the driver's); a second processor
  // joins for form factors with DualCpu; several cards' drivers run on threads of their own.
  a.host_busy_cpu_seconds = r.time.host_compute + r.time.driver_cpu + r.time.second_cpu_compute;
  a.host_cpus = r.time.second_cpu ? 2 : 1;
  if (!r.board_run) return a;
  const BoardDetail& b = r.board;
  // Programmed I/O keeps the processor moving the words; a DMA transfer leaves it waiting.
  const std::uint64_t transfers = b.pci.dma_transfers + b.pci.pio_transfers;
  if (transfers > 0) a.host_busy_cpu_seconds += r.time.pci_transfer * b.pci.pio_transfers / static_cast<double>(transfers);
  for (const CardReport& c : b.cards.per_card) a.host_busy_cpu_seconds += c.driver_cpu_seconds;
  if (a.host_busy_cpu_seconds > a.host_cpus * a.seconds) {
    a.host_cpus = static_cast<unsigned>(std::ceil(a.host_busy_cpu_seconds / a.seconds));
  }
  a.cards = b.cards.count;
  a.lanes = b.device.lanes;
  a.device_clock_hz = b.device.clock_hz;
  a.slices_per_lane = static_cast<double>(b.device.design.slices) / b.device.lanes;
  a.multipliers_per_lane = static_cast<double>(b.device.design.block_multipliers) / b.device.lanes;
  for (const LaneReport& l : b.lanes) a.lane_active_cycles += l.rays;
  a.banks = b.device.banks;
  const double word_bytes = b.device.bank_word_bits / 8.0;
  for (const BankUseReport& bank : b.banks) {
    a.bank_word_reads += static_cast<std::uint64_t>(std::ceil(bank.bytes_read / word_bytes));
    a.bank_word_writes += static_cast<std::uint64_t>(std::ceil(bank.bytes_written / word_bytes));
  }
  const std::uint64_t pci_word_bytes = b.device.pci_width_bits / 8;
  a.pci_data_phases = (b.pci.bytes_to_board + b.pci.bytes_to_host + pci_word_bytes - 1) / pci_word_bytes;
  a.pci_transactions = b.pci.bus_transactions;
  return a;
}

// Every joule with its counter and the profile figure it used (docs/energy.md, docs/outputs.md).
void attach_energy(RunReport& report, const energy::EnergyTables& tables, std::uint64_t steps) {
  if (!tables.missing.empty()) {
    report.energy.reset();
    report.energy_missing = tables.missing;
    return;
  }
  report.energy = energy::estimate(tables, activity_of(report, steps));
  report.energy_missing.clear();
}

}  // namespace rc
