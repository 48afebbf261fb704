// A roofline per device (docs/design.md, "Roofline"): attainable ray-face tests per second against
// bytes moved per test, under four roofs:
//
//   lanes  lanes x device clock                     tests/s, flat (one test per lane per cycle)
//   SRAM   banks x word bytes x bank clock           bytes/s: at x bytes per test, bandwidth / x tests/s
//   PCI    width bytes x PCI clock x burst efficiency bytes/s over the PCI bytes one test needs in this
//                                                    workload (segments up, results down): flat, tests/s
//   host   tests / (host compute + driver CPU)       tests/s the host keeps up with in this workload: flat
//
// The x axis is bytes of bank traffic per test, the quantity the paper's sec 5.6(a) counts (6.125 at
// 15 bits: three 16-bit coordinates read, one result bit written) and the model measures per run (every
// bank's bytes read and written / tests; 10 with results in the bank and two lanes sharing a result
// word, read and written back once per face). PCI and the host move no bank bytes: their roofs are the
// tests/s they allow at the workload's own PCI bytes and host seconds per test, drawn flat.
#pragma once

#include <string>
#include <vector>

#include "board/device_profile.h"

namespace rc {

struct RooflinePoint {
  std::string kind;   // "paper" (the paper's rule), "design" (simulated), "best", "reference"
  std::string label;
  double bytes_per_test = 0;
  double tests_per_second = 0;
};

struct Roofline {
  std::string device;
  int lanes = 0;
  double clock_mhz = 0;
  unsigned banks = 0;
  double bank_clock_mhz = 0;
  unsigned bank_word_bits = 32;
  double lanes_tests_per_second = 0;
  double sram_bytes_per_second = 0;
  double pci_bytes_per_second = 0;
  double pci_tests_per_second = 0;   // 0: unknown (no simulated design)
  double host_tests_per_second = 0;  // 0: unknown
  std::vector<RooflinePoint> points;

  // The least of the roofs at `bytes_per_test` (the roofs known).
  double attainable(double bytes_per_test) const;
};

// The roofs of a board: `lanes` at `clock_mhz` on `device`'s banks (`banks` of them at `bank_clock_mhz`)
// and PCI. The PCI and host roofs need a simulated design: set them with workload_roofs.
Roofline device_roofs(const board::DeviceProfile& device, int lanes, double clock_mhz, unsigned banks,
                      double bank_clock_mhz);
// The flat roofs of a workload: PCI bytes per test and host seconds per test of a simulated run.
void workload_roofs(Roofline& roofline, double pci_bytes_per_test, double host_seconds, double tests);

// "kind,device,label,bytes_per_test,tests_per_second" rows: one per roof ("roof_lanes", "roof_sram"
// with its bytes/s in tests_per_second, "roof_pci", "roof_host") and one per point; the plot
// (apps/plots/roofline.py) draws one panel per device.
std::string roofline_csv(const std::vector<Roofline>& rooflines);

}  // namespace rc
