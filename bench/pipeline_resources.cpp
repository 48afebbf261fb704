// Prints the pipeline's register widths and the resource/clock model for every fractional width
// (the tables of docs/pipeline.md), then the synthesis source (pipeline/synthesis_resources.h): its
// rule fitted on the paper's points with the leave-one-out errors, its slices and block multipliers
// per family and width, and the lanes that fit on every device profile under both sources (the
// tables of docs/results/synthesis.md, which `scripts/synthesize page` copies):
//
//   build/bench/pipeline_resources [path/to/pipeline_resources.json [path/to/synthesis_resources.json]]
//
// Not a Google Benchmark program: it has its own entry, sc_main (the device profiles it reads live in
// board/, which links SystemC, whose library supplies main()).
#include <cstdio>
#include <exception>
#include <string>

#include <systemc>  // declares sc_main with C linkage

#include "board/design_fit.h"
#include "board/device_profile.h"
#include "pipeline/bit_bounds.h"
#include "pipeline/fixed_format.h"
#include "pipeline/resource_model.h"

namespace {

using rc::pipeline::Quantity;

void print_register_widths() {
  struct Row {
    Quantity q;
    const char* what;
  };
  const Row rows[] = {
      {Quantity::Position, "position (start, end, v0), unsigned 0.N"},
      {Quantity::Difference, "difference (dir, edge1, edge2, tvec)"},
      {Quantity::Product1Raw, "pvec/qvec product before truncation"},
      {Quantity::Product1, "pvec/qvec product after truncation"},
      {Quantity::CrossComponent, "pvec, qvec component"},
      {Quantity::Product2Raw, "det/u/v/t product before truncation"},
      {Quantity::Product2, "det/u/v/t product after truncation"},
      {Quantity::DotPartial, "first dot-product sum"},
      {Quantity::Dot, "det, u, v, t"},
      {Quantity::SignedDot, "u*s, v*s, t*s"},
      {Quantity::AbsDet, "|det|"},
      {Quantity::UvSum, "u*s + v*s"},
  };
  std::printf("Register widths (two's complement, sign included) and value ranges.\n\n");
  std::printf("| quantity | bits at N | N=7 | N=15 | N=31 | range at N=31 (units of 2^-31) |\n");
  std::printf("|---|---:|---:|---:|---:|---|\n");
  for (const Row& r : rows) {
    const int w7 = rc::pipeline::signed_bits(r.q, 7);
    const int w31 = rc::pipeline::signed_bits(r.q, 31);
    const bool doubled = (w31 - w7) == 2 * (31 - 7);
    const int offset = doubled ? w7 - 14 : w7 - 7;
    const rc::pipeline::ValueRange range = rc::pipeline::value_range(r.q, 31);
    std::printf("| %s | %sN%+d | %d | %d | %d | [%lld, %lld] |\n", r.what, doubled ? "2" : "", offset, w7,
                rc::pipeline::signed_bits(r.q, 15), w31, static_cast<long long>(range.lo),
                static_cast<long long>(range.hi));
  }
}

void print_resources(const rc::pipeline::ResourceModel& model) {
  std::printf("\nOne pipeline on the XC2V6000 (* = modelled, not synthesised by the paper;"
              " ! = with block multipliers beyond the paper's synthesis limit).\n\n");
  std::printf("| bits | slices | MHz | slices (block mults) | block mults | MHz (block mults) |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|\n");
  for (int bits = rc::pipeline::kMinFracBits; bits <= rc::pipeline::kMaxFracBits; ++bits) {
    const auto soft = model.pipeline(bits, false), hard = model.pipeline(bits, true);
    const char* s = soft.interpolated ? "*" : "";
    const char* h = hard.extrapolated ? "!" : (hard.interpolated ? "*" : "");
    std::printf("| %d | %d%s | %.1f%s | %d%s | %d | %.1f%s |\n", bits, soft.slices, s, soft.clock_mhz, s,
                hard.slices, h, hard.block_multipliers, hard.clock_mhz, h);
  }
  const auto w = model.wrapper();
  std::printf("\nWrapper: %d slices + %d slices per lane, %d block multipliers.\n\n", w.fixed_slices,
              w.per_lane_slices, w.block_multipliers);
  std::printf("| design | lanes | slices | block mults | MHz | measured |\n|---|---:|---:|---:|---:|---|\n");
  for (int bits : {7, 15, 23, 31}) {
    for (bool hard : {true, false}) {
      for (int lanes = 1; lanes <= 4; ++lanes) {
        const auto d = model.design(bits, hard, lanes);
        std::printf("| %d bits, %s | %d | %d | %d | %.3f | %s |\n", bits, hard ? "block mults" : "soft mults", lanes,
                    d.slices, d.block_multipliers, d.clock_mhz, d.interpolated ? "model" : "paper");
      }
    }
  }
  std::printf("\nThe guard band on t (--t-guard, the T_GUARD port; pipeline::TGuardCost): added to one lane, counted "
              "LUTs and flip-flops, slices by the model's packing; latency unchanged.\n\n");
  std::printf("| bits | comparator bits | LUTs | flip-flops | slices | share of the lane (soft mults) | added latency |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int bits : {7, 11, 15, 19, 23, 27, 31}) {
    const rc::pipeline::TGuardCost c = model.t_guard_cost(bits);
    std::printf("| %d | %d | %d | %d | %d | %.2f%% | %d |\n", bits, c.comparator_bits, c.luts, c.flip_flops, c.slices,
                100.0 * c.slices / model.pipeline(bits, false).slices, c.added_latency);
  }
}

// `paper`: the model the synthesis source was made from (its figures beside); `model`: with the synthesis.
void print_synthesis(const rc::pipeline::ResourceModel& paper, const rc::pipeline::ResourceModel& model) {
  const rc::pipeline::SynthesisResources& syn = *model.synthesis();
  const rc::pipeline::SynthesisSliceFit& fit = syn.fit();
  std::printf("\n## The synthesis source\n\n");
  std::printf("Rule: slices = %.4f x (LUTs + SRLs) + %.4f x flip-flops, least squares on the paper's %zu published "
              "pipelines paired with %s's counts for the paper's family; largest error of the fit on its own points "
              "%.1f%%, largest leave-one-out error %.1f%%.\n\n",
              fit.per_lut, fit.per_flip_flop, fit.leave_one_out.size(), syn.synthesizer().c_str(),
              100.0 * fit.max_abs_fit_error, 100.0 * fit.max_abs_leave_one_out);
  std::printf("| bits | block mults | paper slices | fitted on the others | leave-one-out error |\n|---:|---|---:|---:|---:|\n");
  for (const rc::pipeline::LeaveOneOutError& e : fit.leave_one_out) {
    std::printf("| %d | %s | %.0f | %.0f | %+.1f%% |\n", e.point.frac_bits, e.point.block_multipliers ? "yes" : "no",
                e.point.slices, e.predicted, 100.0 * e.relative_error);
  }
  std::printf("\nOne pipeline by the synthesis source (* = counts interpolated between synthesised widths, ! = "
              "extrapolated beyond them; paper-fit slices beside).\n\n");
  std::printf("| family | bits | slices | paper fit | slices (block mults) | block mults | paper fit (block mults) | paper block mults |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  // The counts' own flags: under the synthesis source every figure is a fitted rule (`interpolated`),
  // so whether the synthesizer ran at this width is read from the counts.
  const auto mark = [](const rc::pipeline::SynthesisCounts& c) { return c.extrapolated ? "!" : (c.interpolated ? "*" : ""); };
  for (const char* part : {"XC2V", "XC3S", "XC4V"}) {
    for (int bits = rc::pipeline::kMinFracBits; bits <= rc::pipeline::kMaxFracBits; ++bits) {
      const auto soft = model.pipeline(bits, false, part), hard = model.pipeline(bits, true, part);
      const auto paper_soft = paper.pipeline(bits, false), paper_hard = paper.pipeline(bits, true);
      std::printf("| %s | %d | %d%s | %d | %d%s | %d | %d | %d |\n", soft.synthesis_family.c_str(), bits, soft.slices,
                  mark(syn.counts(part, bits, false)), paper_soft.slices, hard.slices, mark(syn.counts(part, bits, true)),
                  hard.block_multipliers, paper_hard.slices, paper_hard.block_multipliers);
    }
  }
}

void print_lanes_by_source(int bits) {
  std::printf("\nLanes that fit at %d bits on the device profiles of configs/devices/ (wrapper counted; block-multiplier lanes first, slice "
              "multipliers beyond):\n\n", bits);
  std::printf("| device | part | paper fit: lanes | slices | blocks | synthesis: lanes | slices | blocks |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string name : {"xc2v6000", "virtex4-sx55", "spartan3-5000"}) {
    const rc::board::DeviceProfile device = rc::board::find_device_profile(name);
    const rc::board::LanesBySource l = rc::board::lanes_by_source(device, bits);
    std::printf("| %s | %s | %d (%d block + %d slice) | %d | %d | %d (%d block + %d slice) | %d | %d |\n", name.c_str(),
                device.part.c_str(), l.paper_lanes, l.paper.hard_lanes, l.paper.soft_lanes, l.paper.slices,
                l.paper.block_multipliers, l.synthesis_lanes, l.synthesis.hard_lanes, l.synthesis.soft_lanes,
                l.synthesis.slices, l.synthesis.block_multipliers);
  }
}

}  // namespace

int sc_main(int argc, char* argv[]) {
  try {
    const auto model = argc > 1 ? rc::pipeline::ResourceModel::load(argv[1])
                                : rc::pipeline::ResourceModel::load_default();
    print_register_widths();
    print_resources(model);
    const std::string synthesis_path = argc > 2 ? argv[2] : rc::pipeline::ResourceModel::default_synthesis_path();
    print_synthesis(model, model.with_synthesis(rc::profiles::read_synthesis_table(synthesis_path), synthesis_path));
    for (int bits : {15, 23}) print_lanes_by_source(bits);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
