#include "board/throughput_estimates.h"

#include <algorithm>

#include "board/bank_layout.h"
#include "board/design_fit.h"

namespace rc::board {

double bytes_per_intersection(int bits) {
  const BankLayout layout = make_bank_layout(1, 5, bits, 32, 4u << 20);
  return 3.0 * layout.field_bits / 8.0 + 1.0 / 8.0;
}

namespace {

PaperEstimate at_rate(std::string estimate, std::string device, int lanes, double clock_mhz, double rate, int bits,
                      double software_rate) {
  PaperEstimate e;
  e.estimate = std::move(estimate);
  e.device = std::move(device);
  e.lanes = lanes;
  e.clock_mhz = clock_mhz;
  e.intersections_per_s = rate;
  e.bytes_per_cycle = clock_mhz > 0 ? rate / (clock_mhz * 1e6) * bytes_per_intersection(bits) : 0;
  e.gb_per_s = rate * bytes_per_intersection(bits) / 1e9;
  e.speedup_vs_software = rate / software_rate;
  return e;
}

}  // namespace

std::vector<PaperEstimate> paper_estimates(double software_rate, int bits) {
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default();
  std::vector<PaperEstimate> out;

  // (a) Limited by the RC2000's memory bandwidth: every bank streaming a word per memory clock.
  const DeviceProfile rc2000 = find_device_profile("xc2v6000");
  const double bandwidth = rc2000.bank_count * (rc2000.bank_word_bits / 8.0) * rc2000.bank_clock_mhz * 1e6;
  PaperEstimate limit = at_rate("RC2000 bandwidth limit", rc2000.name, 0, rc2000.bank_clock_mhz,
                                bandwidth / bytes_per_intersection(bits), bits, software_rate);
  limit.note = std::to_string(rc2000.bank_count) + " banks x " + std::to_string(rc2000.bank_word_bits / 8) +
               " bytes x " + std::to_string(rc2000.bank_clock_mhz) + " MHz";
  out.push_back(limit);

  // The measured board's peak: two lanes at their clock.
  const DesignFit two = fit_design(rc2000, model, 2, bits);
  out.push_back(at_rate("peak of the measured 2-lane design", rc2000.name, 2, two.clock_mhz, 2 * two.clock_mhz * 1e6, bits,
                        software_rate));

  // (b) Limited by device resources: as many lanes as fit, at the design clock.
  for (const char* name : {"virtex4-sx55", "spartan3-5000", "xc2v6000"}) {
    const DeviceProfile device = find_device_profile(name);
    const int lanes = max_lanes(device, model, bits);
    const DesignFit fit = fit_design(device, model, std::max(lanes, 1), bits);
    PaperEstimate e = at_rate("lanes that fit", device.name, lanes, fit.clock_mhz, lanes * fit.clock_mhz * 1e6, bits,
                              software_rate);
    e.note = std::to_string(fit.hard_lanes) + " with block multipliers, " + std::to_string(fit.soft_lanes) +
             " with slice multipliers; " + std::to_string(fit.slices) + "/" + std::to_string(device.slices) + " slices, " +
             std::to_string(fit.block_multipliers) + "/" + std::to_string(device.block_multipliers) + " multipliers";
    out.push_back(e);
  }
  return out;
}

}  // namespace rc
