// A device profile (configs/devices/*.json): the FPGA's clock per lane count, the board's memory
// banks and PCI interface, and the wrapper's fixed cycle costs. Loaded once, then turned into the
// concrete BoardParams of one board instance (board_params.h) together with the run's choices.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "board/bank_layout.h"
#include "profiles/profile_document.h"

namespace rc::board {

struct DeviceProfile {
  std::string name;          // e.g. "xc2v6000"
  std::string part;          // e.g. "XC2V6000"
  std::string file;          // where it was loaded from
  int slices = 0;            // FPGA logic slices
  int block_multipliers = 0; // 18x18 block multipliers
  std::uint64_t block_ram_bits = 0;  // block RAM, all blocks (fpga.block_ram_bits)
  std::map<int, double> clock_mhz_by_lanes;   // measured clocks (paper sec 5.4, 5.5)
  std::optional<double> clock_mhz_default;    // for lane counts not listed
  int clock_bits = 15;       // fractional width the clocks were measured or assumed for
  unsigned pipeline_latency_cycles = 37;

  unsigned bank_count = 6;
  std::uint64_t bank_capacity_bytes = 4u << 20;
  unsigned bank_word_bits = 32;
  double bank_clock_mhz = 100;
  unsigned bank_read_latency_cycles = 2;
  unsigned bank_write_latency_cycles = 2;

  unsigned pci_width_bits = 64;
  double pci_clock_mhz = 66.667;
  double pci_burst_efficiency = 1.0;
  unsigned pci_setup_cycles = 8;
  std::uint64_t pci_max_burst_bytes = 4096;
  unsigned pci_master_abort_cycles = 6;
  unsigned bridge_latency_cycles = 2;  // PCI clock cycles, PCI bridge to the local bus

  unsigned pass_start_cycles = 2;
  unsigned face_setup_cycles = 1;
  unsigned pass_finish_cycles = 1;
  unsigned register_access_cycles = 1;  // device cycles per control/status register access
  ResultStore results = ResultStore::bank;  // wrapper.results: where a pass's blocked bits accumulate

  // The file as loaded, sources included: the energy table reads its section from it, and a study
  // sets fields on it by their dotted paths (profiles/profile_document.h).
  profiles::ProfileDocument document;

  // The device clock for `lanes` pipelines; throws std::invalid_argument if the profile has none.
  double clock_mhz(int lanes) const;
};

// Loads and validates a profile; errors name the file and the field ("banks.clock_mhz: missing").
DeviceProfile load_device_profile(const std::string& path);
// The same checks on a profile already in memory (a study's profile with settings applied);
// `origin` names it in errors and becomes its `file`.
DeviceProfile device_profile_from_document(const profiles::ProfileDocument& document, const std::string& origin);
// By name (configs/devices/NAME.json: read once per process) or by path (read each time).
DeviceProfile find_device_profile(const std::string& name_or_path);

}  // namespace rc::board
