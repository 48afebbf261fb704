#include "board/throughput_estimates.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "board/bank_layout.h"
#include "board/board_params.h"
#include "board/design_fit.h"
#include "board/pass_timing.h"

namespace rc::board {

const char* to_string(EstimateRule rule) { return rule == EstimateRule::Paper ? "paper" : "model"; }

double bytes_per_intersection(int bits) {
  const BankLayout layout = make_bank_layout(1, 5, bits, 32, 4u << 20);
  return 3.0 * layout.field_bits / 8.0 + 1.0 / 8.0;
}

namespace {

// The devices of sec 5.6(b), in the paper's order.
constexpr const char* kEstimateDevices[] = {"virtex4-sx55", "spartan3-5000"};

PaperEstimate at_rate(std::string estimate, EstimateRule rule, std::string device, int lanes, double clock_mhz,
                      double rate, double bytes_per_intersection, double software_rate) {
  PaperEstimate e;
  e.estimate = std::move(estimate);
  e.rule = rule;
  e.device = std::move(device);
  e.lanes = lanes;
  e.clock_mhz = clock_mhz;
  e.intersections_per_s = rate;
  e.bytes_per_intersection = bytes_per_intersection;
  e.bytes_per_cycle = clock_mhz > 0 ? rate / (clock_mhz * 1e6) * bytes_per_intersection : 0;
  e.gb_per_s = rate * bytes_per_intersection / 1e9;
  e.software_rate = software_rate;
  e.speedup_vs_software = rate / software_rate;
  return e;
}

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, a, b, c, d);
  return text;
}

// Sec 5.6(a): every bank streaming one word per memory clock, over `bytes` per intersection (the
// paper's 6.125, or what the model's two-lane design moves).
PaperEstimate bandwidth_limit(EstimateRule rule, double software_rate, double bytes, const std::string& why_bytes) {
  const DeviceProfile rc2000 = find_device_profile("xc2v6000");
  const double bandwidth = rc2000.bank_count * (rc2000.bank_word_bits / 8.0) * rc2000.bank_clock_mhz * 1e6;
  PaperEstimate e = at_rate("RC2000 bandwidth limit", rule, rc2000.name, 0, rc2000.bank_clock_mhz, bandwidth / bytes,
                            bytes, software_rate);
  e.note = format("%g banks x %g bytes x %g MHz = %.4g GB/s", rc2000.bank_count, rc2000.bank_word_bits / 8.0,
                  rc2000.bank_clock_mhz, bandwidth / 1e9) +
           format(" over %g bytes per intersection", bytes) + why_bytes;
  e.clock_assumption = format("bank clock %g MHz (sec 5.6(a)'s peak memory clock)", rc2000.bank_clock_mhz);
  return e;
}

// A long pass (one face after another, results read and written) on `lanes` lanes of `device`
// at `bits`, with as many banks as full-rate lanes need: intersections per device cycle and the
// bank bytes each moves, from the pass-timing formula.
struct StreamRate {
  double rays_per_cycle = 0, bytes_per_ray = 0;
  std::string limit;
};

StreamRate long_pass_rate(const DeviceProfile& device, int lanes, int bits) {
  BoardChoices choices;
  choices.lanes = static_cast<unsigned>(lanes);
  choices.banks = banks_for_full_rate(device, lanes, bits);
  choices.bits = bits;
  const BoardParams params = make_board_params(device, choices);
  const BankLayout layout = make_bank_layout(params);  // results where the profile keeps them
  const std::uint64_t rays = std::min<std::uint64_t>(layout.max_rays_per_batch, std::uint64_t{1} << 20);
  const RaySplit split = split_rays(layout, rays);
  StreamRate r;
  const std::uint64_t cycles = stream_cycles(layout, params.timing, split, false, &r.limit);
  double words = 0;
  for (std::size_t g = 0; g < layout.groups.size(); ++g) {
    // On chip the result words reach the bank once a pass, not once a face: over a long pass's faces
    // that vanishes, and a ray moves only its three coordinate words.
    const unsigned result = layout.results == ResultStore::on_chip ? 0 : layout.groups[g].result_accesses();
    words += double(split.packets[g]) * (3 + result);
  }
  r.rays_per_cycle = double(rays) / double(cycles);
  r.bytes_per_ray = words * (layout.word_bits / 8.0) / double(rays);
  return r;
}

}  // namespace

unsigned banks_for_full_rate(const DeviceProfile& device, int lanes, int bits) {
  const BankLayout probe = make_bank_layout(static_cast<unsigned>(lanes), 64, bits, device.bank_word_bits, device.bank_capacity_bytes);
  return 3 * static_cast<unsigned>(probe.groups.size()) + 2;
}

std::vector<PaperEstimate> paper_rule_estimates(double software_peak_rate) {
  const double bytes = bytes_per_intersection(15);
  std::vector<PaperEstimate> out{bandwidth_limit(EstimateRule::Paper, software_peak_rate, bytes, " (sec 5.6(a))")};

  // Sec 5.7: "2 parallel pipelines at 52 MHz".
  PaperEstimate measured = at_rate("measured 2-lane design", EstimateRule::Paper, "xc2v6000", 2, 52.0, 2 * 52.0e6, bytes,
                                   software_peak_rate);
  measured.note = "sec 5.7: 2 parallel pipelines at 52 MHz";
  measured.clock_assumption = "sec 5.7's 52 MHz (the measured design, sec 5.5: 52.5 MHz)";
  out.push_back(measured);

  for (const char* name : kEstimateDevices) out.push_back(paper_rule_lanes_that_fit(find_device_profile(name), software_peak_rate));
  return out;
}

PaperEstimate paper_rule_lanes_that_fit(const DeviceProfile& device, double software_peak_rate) {
  const pipeline::PipelineResources table1 = pipeline::ResourceModel::load_default().pipeline(15, true);
  const int by_slices = device.slices / table1.slices;
  const int by_multipliers = device.block_multipliers / table1.block_multipliers;
  const int lanes = std::min(by_slices, by_multipliers);
  PaperEstimate e = at_rate("lanes that fit", EstimateRule::Paper, device.name, lanes, table1.clock_mhz,
                            lanes * table1.clock_mhz * 1e6, bytes_per_intersection(15), software_peak_rate);
  e.note = format("min(%g slices / %g, %g multipliers / %g)", device.slices, table1.slices, device.block_multipliers,
                  table1.block_multipliers) +
           format(" = min(%g, %g); wrapper not counted", by_slices, by_multipliers);
  e.clock_assumption = format("Table 1's 15-bit block-multiplier pipeline clock, %g MHz", table1.clock_mhz);
  return e;
}

std::vector<PaperEstimate> model_estimates(double software_rate, int bits, pipeline::ResourceSource resources) {
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default(resources);
  const DeviceProfile rc2000 = find_device_profile("xc2v6000");
  const DesignFit two = fit_design(rc2000, model, 2, bits);
  const StreamRate two_rate = long_pass_rate(rc2000, 2, bits);
  std::vector<PaperEstimate> out{bandwidth_limit(EstimateRule::Model, software_rate, two_rate.bytes_per_ray,
                                                 " (the model's 2-lane design below)")};
  PaperEstimate measured = at_rate("measured 2-lane design", EstimateRule::Model, rc2000.name, 2, two.clock_mhz,
                                   two_rate.rays_per_cycle * two.clock_mhz * 1e6, two_rate.bytes_per_ray, software_rate);
  measured.note = format("%.3f rays per cycle (bound: ", two_rate.rays_per_cycle) + two_rate.limit + ")";
  measured.clock_assumption = format("the profile's measured 2-lane design clock, %g MHz (sec 5.5)", two.clock_mhz);
  out.push_back(measured);

  for (const char* name : kEstimateDevices)
    out.push_back(model_lanes_that_fit(find_device_profile(name), software_rate, bits, resources));
  return out;
}

PaperEstimate model_lanes_that_fit(const DeviceProfile& device, double software_rate, int bits,
                                   pipeline::ResourceSource resources) {
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default(resources);
  const int lanes = max_lanes(device, model, bits);
  const DesignFit fit = fit_design(device, model, std::max(lanes, 1), bits);
  const StreamRate rate = lanes > 0 ? long_pass_rate(device, lanes, bits) : StreamRate{};
  PaperEstimate e = at_rate("lanes that fit", EstimateRule::Model, device.name, lanes, fit.clock_mhz,
                            rate.rays_per_cycle * fit.clock_mhz * 1e6, rate.bytes_per_ray, software_rate);
  e.note = format("%g with block multipliers, %g with slice multipliers, wrapper counted; ", fit.hard_lanes,
                  fit.soft_lanes) +
           format("%.3f rays per cycle (bound: ", rate.rays_per_cycle) + (lanes > 0 ? rate.limit : "no lane fits") + ")" +
           (resources == pipeline::ResourceSource::paper_fit ? "" : "; resources: " + choice_name(resources));
  e.clock_assumption = format("the profile's design clock for these lanes, %g MHz", fit.clock_mhz);
  e.resources = resources;
  return e;
}

double bytes_per_intersection(pipeline::FloatFormat number_format) {
  constexpr int kWordBits = 32;
  const int width = number_format.bits_per_value();
  const int per_word = kWordBits / width;
  const int field_bits = per_word > 0 ? kWordBits / per_word : kWordBits * ((width + kWordBits - 1) / kWordBits);
  return 3.0 * field_bits / 8.0 + 1.0 / 8.0;
}

namespace {

double rc2000_bandwidth() {
  const DeviceProfile rc2000 = find_device_profile("xc2v6000");
  return rc2000.bank_count * (rc2000.bank_word_bits / 8.0) * rc2000.bank_clock_mhz * 1e6;
}

FullRateFit full_rate(const DesignFit& fit, const std::string& arithmetic, double bytes) {
  FullRateFit r;
  r.device = fit.device;
  r.arithmetic = arithmetic;
  r.lanes = fit.fits ? fit.lanes : 0;
  r.hard_lanes = fit.fits ? fit.hard_lanes : 0;
  r.soft_lanes = fit.fits ? fit.soft_lanes : 0;
  r.slices = fit.fits ? fit.slices : 0;
  r.block_multipliers = fit.fits ? fit.block_multipliers : 0;
  r.clock_mhz = fit.fits ? fit.clock_mhz : 0;
  r.intersections_per_s = r.lanes * r.clock_mhz * 1e6;
  r.bytes_per_intersection = bytes;
  r.gb_per_s_needed = r.intersections_per_s * bytes / 1e9;
  r.rc2000_gb_per_s = rc2000_bandwidth() / 1e9;
  r.modelled = fit.modelled;
  return r;
}

}  // namespace

FullRateFit fixed_full_rate_fit(const DeviceProfile& device, int bits) {
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default();
  const int lanes = max_lanes(device, model, bits);
  const DesignFit fit = fit_design(device, model, std::max(lanes, 1), bits);
  return full_rate(fit, "fixed:" + std::to_string(bits), bytes_per_intersection(bits));
}

FullRateFit float_full_rate_fit(const DeviceProfile& device, pipeline::FloatFormat number_format) {
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default();
  const int lanes = max_float_lanes(device, model, number_format);
  const FloatDesignFit fit = fit_float_design(device, model, std::max(lanes, 1), number_format);
  return full_rate(fit, number_format.to_string(), bytes_per_intersection(number_format));
}

PaperEstimate float_lanes_that_fit(const DeviceProfile& device, double software_rate,
                                   pipeline::FloatFormat number_format) {
  const FullRateFit f = float_full_rate_fit(device, number_format);
  PaperEstimate e = at_rate("lanes that fit (" + f.arithmetic + ")", EstimateRule::Model, device.name, f.lanes, f.clock_mhz,
                            f.intersections_per_s, f.bytes_per_intersection, software_rate);
  e.note = format("%g with block multipliers, %g with slice multipliers, wrapper counted; full rate, estimate; ",
                       f.hard_lanes, f.soft_lanes) +
           format("needs %.3g GB/s of the RC2000's %.3g", f.gb_per_s_needed, f.rc2000_gb_per_s);
  e.clock_assumption = format("the float lanes' clock on this device, %g MHz (estimate)", f.clock_mhz);
  return e;
}

std::string why_estimates_differ(const PaperEstimate& paper, const PaperEstimate& model) {
  if (paper.estimate == "RC2000 bandwidth limit") {
    return "same 2.4 GB/s; the paper counts " + format("%g", paper.bytes_per_intersection) +
           " bytes per intersection (three coordinates read, one result bit written), the model's two-lane design moves " +
           format("%g", model.bytes_per_intersection) +
           " (coordinate words, and its result word read and written back once per face); the speedups also differ by the "
           "software rate (paper: Table 2's peak, model: the calibrated intersection test)";
  }
  if (paper.estimate == "measured 2-lane design") {
    return "the paper rounds the clock to 52 MHz and counts one result per cycle per lane; the model runs at 52.5 MHz "
           "and its result bank (read-modify-write of words two lanes share) holds the lanes to " +
           format("%.0f%%", 100 * model.intersections_per_s / (2 * model.clock_mhz * 1e6)) +
           ", moving " + format("%g", model.bytes_per_intersection) + " bytes per intersection, not 6.125";
  }
  std::string why = "the paper counts only Table 1's pipeline (1976 slices, 30 multipliers per lane); the model adds "
                    "the Handel-C wrapper (fixed and per-lane slices, sec 5.4-5.5)";
  if (model.lanes > paper.lanes) why += " and builds lanes beyond the block multipliers from slice multipliers (sec 5.2)";
  const double per_lane = model.lanes > 0 ? model.intersections_per_s / (model.lanes * model.clock_mhz * 1e6) : 0;
  if (per_lane < 0.999) {
    why += "; one result bank for all lanes, read and written per word, caps the stream at " +
           format("%.2f", model.intersections_per_s / (model.clock_mhz * 1e6)) + " intersections per cycle";
  }
  return why;
}

}  // namespace rc::board
