#include "host_sw/studies/roofline.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace rc {

double Roofline::attainable(double bytes_per_test) const {
  double roof = lanes_tests_per_second;
  if (bytes_per_test > 0) roof = std::min(roof, sram_bytes_per_second / bytes_per_test);
  if (pci_tests_per_second > 0) roof = std::min(roof, pci_tests_per_second);
  if (host_tests_per_second > 0) roof = std::min(roof, host_tests_per_second);
  return roof;
}

Roofline device_roofs(const board::DeviceProfile& device, int lanes, double clock_mhz, unsigned banks,
                      double bank_clock_mhz) {
  Roofline r;
  r.device = device.name;
  r.lanes = lanes;
  r.clock_mhz = clock_mhz;
  r.banks = banks;
  r.bank_clock_mhz = bank_clock_mhz;
  r.bank_word_bits = device.bank_word_bits;
  r.lanes_tests_per_second = lanes * clock_mhz * 1e6;
  r.sram_bytes_per_second = banks * (device.bank_word_bits / 8.0) * bank_clock_mhz * 1e6;
  r.pci_bytes_per_second = device.pci_width_bits / 8.0 * device.pci_clock_mhz * 1e6 * device.pci_burst_efficiency;
  return r;
}

void workload_roofs(Roofline& r, double pci_bytes_per_test, double host_seconds, double tests) {
  r.pci_tests_per_second = pci_bytes_per_test > 0 ? r.pci_bytes_per_second / pci_bytes_per_test : 0;
  r.host_tests_per_second = host_seconds > 0 ? tests / host_seconds : 0;
}

namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// A label in a CSV cell: quoted, inner quotes doubled.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string roofline_csv(const std::vector<Roofline>& rooflines) {
  std::string csv = "kind,device,label,bytes_per_test,tests_per_second\n";
  auto row = [&](const std::string& kind, const std::string& device, const std::string& label, double x, double y) {
    csv += kind + "," + device + "," + quoted(label) + "," + number_text(x) + "," + number_text(y) + "\n";
  };
  for (const Roofline& r : rooflines) {
    char text[160];
    std::snprintf(text, sizeof text, "lanes: %d x %.4g MHz", r.lanes, r.clock_mhz);
    row("roof_lanes", r.device, text, 0, r.lanes_tests_per_second);
    std::snprintf(text, sizeof text, "SRAM: %u banks x %u bytes x %.4g MHz", r.banks, r.bank_word_bits / 8, r.bank_clock_mhz);
    row("roof_sram", r.device, text, 0, r.sram_bytes_per_second);
    std::snprintf(text, sizeof text, "PCI: %.4g GB/s", r.pci_bytes_per_second / 1e9);
    if (r.pci_tests_per_second > 0) row("roof_pci", r.device, text, 0, r.pci_tests_per_second);
    if (r.host_tests_per_second > 0) row("roof_host", r.device, "host", 0, r.host_tests_per_second);
    for (const RooflinePoint& p : r.points) row(p.kind, r.device, p.label, p.bytes_per_test, p.tests_per_second);
  }
  return csv;
}

}  // namespace rc
