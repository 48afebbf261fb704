// Prints the pipeline's register widths and the resource/clock model for every fractional width
// (the tables of docs/pipeline.md):
//
//   build-pipeline/bench/pipeline_resources [path/to/pipeline_resources.json]
//
// Not a Google Benchmark program: it has its own main.
#include <cstdio>
#include <exception>

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
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const auto model = argc > 1 ? rc::pipeline::ResourceModel::load(argv[1])
                                : rc::pipeline::ResourceModel::load_default();
    print_register_widths();
    print_resources(model);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
