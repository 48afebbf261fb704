// Paper sec 5.6 asks what a design would do streaming at its full rate; this asks what each of
// its intersections would cost in energy. One second of the design at full rate becomes an
// Activity for energy::estimate (the same terms, figures and sources as a run's report):
// * the lanes clocked the whole second, each intersection one active lane-cycle;
// * the bank words the long pass moves per intersection (the estimate's bytes per intersection),
//   priced at the mean of the read and write energies, on max(the board's banks, the banks the
//   lanes need at full rate) powered banks;
// * no PCI traffic (a pass streams out of the banks), the bridge powered;
// * the host waiting for the interrupt on one processor.
// Software's energy per intersection is the host computing for a second at the calibrated rate.
#pragma once

#include <string>
#include <vector>

#include "board/device_profile.h"
#include "board/throughput_estimates.h"
#include "host_sw/energy/energy_model.h"

namespace rc::energy {

struct FullRateEnergy {
  std::string estimate;  // the sec 5.6 estimate it prices ("measured 2-lane design", "lanes that fit")
  std::string device;
  int lanes = 0;
  unsigned banks = 0;  // powered
  double clock_mhz = 0;
  double intersections_per_s = 0;
  // Nanojoules per intersection, per component and the card's sum (fpga + sram + pci).
  double fpga_nj = 0, sram_nj = 0, pci_nj = 0, card_nj = 0;
  double host_waiting_nj = 0;  // the host's waiting power over the rate
  double system_nj = 0;        // card + host waiting
  double software_nj = 0;      // the host computing at the software rate, for comparison
  double card_watts = 0;       // the card's average power at full rate
  std::string missing;         // set (and the figures NaN) when a profile has no energy table
  EnergyReport report;         // the one-second estimate, every term with its counter and source
};

// `estimate`: a model estimate of board::model_estimates or model_lanes_that_fit (lanes > 0) for
// `device`; `tables`: the device's and the host's energy tables.
FullRateEnergy full_rate_energy(const board::PaperEstimate& estimate, const board::DeviceProfile& device,
                                const EnergyTables& tables, int bits);

}  // namespace rc::energy
