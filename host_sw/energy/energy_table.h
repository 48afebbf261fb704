// The energy tables of the profiles (docs/energy.md): a device profile's "energy" section (the FPGA,
// the SRAM banks and the PCI interface of one card) and a host profile's (the CPU while it computes
// and while it waits). Every figure is sourced like every other profile number, and keeps its source
// and its path so that a report can say where each joule came from.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>


#include "board/device_profile.h"

namespace rc::energy {

// One figure of an energy table: its value in the unit its key names ("static_w": watts), the key's
// path in the profile and the profile's source for it.
struct Figure {
  double value = 0;
  std::string path;    // "energy.sram.read_nj"
  std::string unit;    // "nJ", "pJ", "W", "mW"
  std::string source;
  double si() const;   // the value in joules or watts
};

struct FpgaEnergy {
  Figure static_w;                 // quiescent power of the configured device (core, aux and I/O banks)
  Figure slice_pj_per_cycle;       // logic and routing of one used slice per cycle of an active lane
  Figure multiplier_pj_per_cycle;  // one used 18x18 block multiplier per cycle of an active lane
  Figure clock_pj_per_slice_cycle; // the clock network to one used slice, every cycle the design runs
};

struct SramEnergy {
  Figure read_nj, write_nj;  // one word access of a bank
  Figure standby_mw;         // one bank, selected or not
};

struct PciEnergy {
  Figure data_phase_nj;   // one data phase (one bus word) moved between host and card
  Figure transaction_nj;  // one transaction's arbitration and address phase
  Figure bridge_w;        // the card's PCI bridge, always on
};

struct DeviceEnergyTable {
  std::string file;
  FpgaEnergy fpga;
  SramEnergy sram;
  PciEnergy pci;
};

struct HostEnergyTable {
  std::string file;
  Figure busy_w;  // the processor running the solver or the driver
  Figure wait_w;  // the same processor waiting (halted in the idle loop) for the card
};

// A profile without an "energy" section: the run still has its times, and its report says why it has
// no energy (never zeros). A section that is there but wrong is an error (std::invalid_argument).
class MissingEnergyTable : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Both throw MissingEnergyTable or std::invalid_argument naming the file and the key.
DeviceEnergyTable device_energy_table(const board::DeviceProfile& profile);
HostEnergyTable host_energy_table(const profiles::ProfileDocument& host_profile, const std::string& file);

// The tables of one run, or why there are none.
struct EnergyTables {
  std::optional<DeviceEnergyTable> device;  // board runs
  std::optional<HostEnergyTable> host;
  std::string missing;  // empty when every table the run needs is here
};

// Loads what the run needs (a software run: no device); a missing section becomes `missing`.
EnergyTables load_energy_tables(const board::DeviceProfile* device, const profiles::ProfileDocument& host_profile,
                                const std::string& host_file);

}  // namespace rc::energy
