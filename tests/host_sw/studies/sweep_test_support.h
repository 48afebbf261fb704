// What the sweep tests share: a configuration, and board reports with chosen times (and energy),
// so a row's figures can be checked against the hand-made report.
#pragma once

#include <string>
#include <tuple>

#include "host_sw/studies/sweep_row.h"

namespace rc::sweep_test {

inline const char* const kHost = "athlon-mp-2600-calibrated";

inline SweepConfig config(const std::string& device, unsigned lanes, unsigned banks, int bits = 15) {
  SweepConfig c;
  c.device = device;
  c.bits = bits;
  c.concurrent = true;
  c.lanes = lanes;
  c.banks = banks;
  return c;
}

// A board report: `waiting` and `host` seconds of the host's timeline beside 1 s of driver CPU and
// 0.5 s of PCI, 4 s of FPGA busy time, the results bank the busiest and the limit of most passes.
inline RunReport synthetic_report(double waiting, double host) {
  RunReport r;
  r.board_run = true;
  r.simulated_seconds = waiting + host + 1.0 + 0.5;
  r.time.host_compute = host;
  r.time.driver_cpu = 1.0;
  r.time.pci_transfer = 0.5;
  r.time.waiting = waiting;
  r.time.fpga_busy = 4.0;
  r.board.device.clock_hz = 52.5e6;
  r.board.layout.nominal_rays_per_cycle = 2.0;
  r.board.pci.bus_busy_seconds = 0.25;
  for (const auto& [bank, role, busy] : {std::tuple<unsigned, const char*, double>{0, "faces", 0.1},
                                         {4, "results", 3.0},
                                         {1, "rays g0 X", 2.0}}) {
    BankUseReport b;
    b.bank = bank;
    b.role = role;
    b.busy_seconds = busy;
    r.board.banks.push_back(b);
  }
  r.board.lanes = {{0, 1.0, 0, 0.9}, {1, 1.0, 0, 0.8}};
  r.intersections.per_second_while_fpga_busy = 1e8;
  r.board.stream_limits = {{"bank 4 (results)", 10, 3.0}, {"lanes", 20, 1.0}};
  return r;
}

// A report with an energy estimate of `joules` (fpga 1, sram 2, pci 3, the rest host) over its time.
inline RunReport report_with_energy(double waiting, double joules) {
  RunReport r = synthetic_report(waiting, 2.0);
  energy::EnergyReport e;
  const double host = joules - 6;
  for (const auto& [name, j] : {std::pair<const char*, double>{"fpga", 1}, {"sram", 2}, {"pci", 3}, {"host", host}}) {
    energy::ComponentEnergy c;
    c.name = name;
    c.dynamic_joules = j;
    e.components.push_back(c);
  }
  e.joules = joules;
  e.seconds = r.simulated_seconds;
  e.average_watts = joules / e.seconds;
  e.joules_per_step = joules / 10;
  e.joules_per_intersection = joules / 1e9;
  e.energy_delay_product = joules * e.seconds;
  r.energy = e;
  return r;
}

}  // namespace rc::sweep_test
