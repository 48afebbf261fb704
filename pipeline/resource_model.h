// FPGA cost of the pipeline and its wrapper at any fractional width: slices, 18x18 block
// multipliers and maximum clock, from the paper's synthesis results in
// configs/pipeline_resources.json, with a documented model for the widths and lane counts the
// paper did not synthesise (docs/pipeline.md, "Resource and clock model"):
//   * without block multipliers: the paper's figures at 7/15/23/31 bits; other widths from a
//     least-squares quadratic in N through those four points (soft multipliers grow as N^2);
//   * with block multipliers: the paper's figures at 7/15 bits; slices and clock linear in N
//     between them and, above 15 bits, slices on the same line and the clock scaled from the
//     soft-multiplier clock by the ratio measured at 15 bits; the block multiplier count from
//     splitting each product into 18x18 pieces (reproduces the paper's 27 and 30);
//   * wrapper: a fixed part plus a per-lane part, solved from the 1- and 2-lane designs.
// With ResourceSource::synthesis (with_synthesis(), load_default(synthesis)) a pipeline's slices and
// block multipliers come from the synthesizer's counts for the device's family instead
// (pipeline/synthesis_resources.h); the clock and the wrapper stay the paper's.
// Floating-point lanes (float_pipeline, docs/pipeline.md "Resources, clock and lanes that fit"):
// ESTIMATES only -- operator logic counted by documented rules, the lane's registers and glue and
// the slice-multiplier cost scaled from the paper's fixed-point figures, the clock taken from the
// fixed lane at the significand width -- for Virtex-II, Virtex-4 and Spartan-3.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "pipeline/fixed_format.h"
#include "pipeline/float_format.h"
#include "pipeline/resource_source.h"
#include "pipeline/synthesis_resources.h"
#include "profiles/resource_table.h"
#include "profiles/synthesis_table.h"

namespace rc::pipeline {

struct PipelineResources {
  int frac_bits = 0;
  bool block_multipliers_used = false;
  int slices = 0;
  int block_multipliers = 0;
  double clock_mhz = 0;
  bool interpolated = false;  // not a width the paper synthesised for this option
  bool extrapolated = false;  // beyond what the paper could synthesise (block multipliers > 15 bits)
  ResourceSource source = ResourceSource::paper_fit;  // of slices and block multipliers (clock: the paper's)
  std::string synthesis_family;  // synthesis: the family whose counts were used ("xc4v")
};

// Handel-C wrapper logic around L pipelines: fixed_slices + L * per_lane_slices.
struct WrapperCost {
  int fixed_slices = 0;
  int per_lane_slices = 0;
  int block_multipliers = 0;
};

// A whole configured device: wrapper plus `lanes` identical pipelines.
struct DesignResources {
  int lanes = 0;
  PipelineResources pipeline;
  int slices = 0;
  int block_multipliers = 0;
  double clock_mhz = 0;       // min(pipeline clock, wrapper clock at this lane count)
  bool interpolated = false;  // any ingredient was modelled rather than measured
};

// What the guard band on t (mt_core.h, core::decide(s, t_guard); rtl/mt_pipeline.v's t_guard input) adds
// to one fixed-point lane, counted by fixed_arithmetic_luts' rules: the subtractor |det| - g (one LUT per
// bit of |det|), its register and delay line to the decision (ages 26..35: ten flip-flops per bit, plain
// chains as in the RTL) and the comparison 0 < t*s widened to g < t*s (a comparator of the t*s width
// instead of a zero detect of it). The latency is unchanged: the subtraction sits beside the dot
// products, which take nine more cycles. At 15 bits: 31 LUTs, 190 flip-flops, 95 slices, which is what
// Yosys finds between rtl/mt_pipeline.v with T_GUARD = 1 and 0 (xc2v, block multipliers: +12 LUTs, +190
// flip-flops, +39 carry cells, +95 slices by scripts/synthesize's packing rule). Not part of
// PipelineResources (the paper's lanes have no guard): a design with the T_GUARD port adds it.
struct TGuardCost {
  int luts = 0;
  int flip_flops = 0;
  int slices = 0;
  int added_latency = 0;  // cycles
  int comparator_bits = 0;  // the width of the subtractor and of the widened comparator (t*s, |det|)
};

struct Device {
  std::string name;
  int slices = 0;
  int block_multipliers = 0;
};

// ---- Floating-point lanes (docs/pipeline.md, "Resources, clock and lanes that fit") ----------
// Every figure is an ESTIMATE (no vendor data for the Floating-Point Operator on these families
// was reachable): see resource_model.cpp for the counting rules and the calibration on the
// paper's fixed-point lanes.

// The FPGA families of the paper's devices; the family of a part from its prefix (XC2V, XC4V, XC3S).
struct FloatFamily {
  std::string name;              // "Virtex-II", "Virtex-4", "Spartan-3"
  std::string part_prefix;       // "XC2V", "XC4V", "XC3S"
  std::string block_multiplier;  // "MULT18X18" or "DSP48"
  int operand_bits = 18;         // signed operand width of the block multiplier
};

// One floating-point operator.
struct FloatOperatorCost {
  int luts = 0;        // counted 4-input LUTs of its logic
  int flip_flops = 0;  // fully pipelined: every LUT output registered
  int slices = 0;
  int block_multipliers = 0;
};

// One floating-point lane.
struct FloatPipelineResources {
  int exponent_bits = 0, fraction_bits = 0;
  std::string family, block_multiplier;
  bool block_multipliers_used = false;
  FloatOperatorCost multiplier, adder;  // one of each
  int multipliers = 0, add_subs = 0, sign_flips = 0, comparators = 0;
  int operator_slices = 0;  // multipliers + add/subs
  int decision_slices = 0;  // sign flips, comparators, the final AND (|det| is wiring: clear the sign bit)
  int glue_slices = 0;      // registers and glue of the data flow, scaled from the paper's fixed lanes
  int slices = 0;
  int block_multipliers = 0;
  double clock_mhz = 0;
  int clock_frac_bits = 0;    // the fixed-point width whose (paper or modelled) clock is used
  bool clock_interpolated = false;   // that clock was not measured by the paper
  bool clock_extrapolated = false;   // block multipliers above the paper's synthesis limit
};

class ResourceModel {
 public:
  // Reads the file through the profile edge (profiles/resource_table.h); throws
  // std::runtime_error naming the file and the problem.
  static ResourceModel load(const std::string& path);
  static ResourceModel from_text(const std::string& text, const std::string& origin = "<text>");
  // The model of a table already read; `origin` names it in errors.
  static ResourceModel from_table(const profiles::ResourceTable& table, const std::string& origin);
  // pipeline_resources.json in io::config_dir() (io/config_dir.h).
  static ResourceModel load_default(ResourceSource source = ResourceSource::paper_fit);
  static std::string default_path();
  static std::string default_synthesis_path();  // synthesis_resources.json in io::config_dir()

  // This model with its slices and block multipliers from a synthesizer's table (the fit on the
  // paper's published points is made here; throws std::runtime_error naming `origin`).
  ResourceModel with_synthesis(const profiles::SynthesisTable& table, const std::string& origin) const;
  ResourceSource source() const { return source_; }
  const SynthesisResources* synthesis() const { return synthesis_.get(); }  // null with the paper fit
  std::vector<PublishedSlices> published_slices() const;  // the paper's pipeline points

  // One pipeline on a device whose part is `part` ("XC4VSX55"; empty: the paper's XC2V6000). The part
  // matters only with the synthesis source (its family's counts). Throws std::invalid_argument for a
  // part the synthesis file has no family for.
  PipelineResources pipeline(FracBits bits, bool use_block_multipliers, const std::string& part = {}) const;
  WrapperCost wrapper() const { return wrapper_; }
  double wrapper_clock_mhz(int lanes) const;
  DesignResources design(int bits, bool use_block_multipliers, int lanes) const;
  const Device& reference_device() const { return device_; }  // the XC2V6000 of the paper

  // 18x18 blocks for one signed a-bit by b-bit product: ceil((a-1)/17) * ceil((b-1)/17), each
  // operand split into 17-bit unsigned pieces plus a signed top piece.
  static int blocks_per_product(int a_bits, int b_bits, int block_bits = 18);
  // Sum over the 27 multipliers, with operand widths from bit_bounds.h.
  static int block_multipliers_needed(FracBits bits, int block_bits = 18);

  // ---- Floating point (estimates) ----
  const std::vector<FloatFamily>& float_families() const { return families_; }
  // The family whose part_prefix starts `part` (case-insensitive); throws std::invalid_argument.
  const FloatFamily& float_family_of_part(const std::string& part) const;
  const FloatFamily& float_family(const std::string& name) const;  // by name; throws
  // Blocks for one p x p significand product: ceil(p / (block_bits - 1))^2 (unsigned p-bit
  // significands cut into 17-bit pieces for 18x18 signed blocks).
  static int float_multiplier_blocks(FloatFormat format, int block_bits = 18);
  FloatOperatorCost float_adder(FloatFormat format) const;
  FloatOperatorCost float_multiplier(FloatFormat format, bool use_block_multipliers, int block_bits = 18) const;
  FloatPipelineResources float_pipeline(FloatFormat format, const FloatFamily& family, bool use_block_multipliers) const;
  // Calibrations on the paper's fixed-point figures (see resource_model.cpp):
  // slices per partial-product bit of a slice multiplier (sec 5.2 vs Table 1 at 15 bits),
  double soft_multiplier_slices_per_bit_product() const;
  // counted LUTs of the fixed lane's add/subs, direction subtractors, |det| and comparators,
  static int fixed_arithmetic_luts(FracBits bits);
  // The guard band on t's extra logic in one lane (TGuardCost).
  TGuardCost t_guard_cost(FracBits bits) const;
  // the rest of the measured fixed lane (registers, glue), linear in the width and evaluated at
  // `word_bits` (the fixed lane's coordinate is `bits` wide).
  double glue_slices(int word_bits) const;

 private:
  struct Point {
    int frac_bits;
    double clock_mhz;
    double slices;
  };
  struct Quadratic {
    double a, b, c;
    double operator()(double n) const { return a + n * (b + n * c); }
  };

  static const Point* find(const std::vector<Point>& points, int bits);
  static double interpolate(const std::vector<Point>& points, int bits, double Point::*field);
  static Quadratic fit(const std::vector<Point>& points, double Point::*field);

  PipelineResources paper_pipeline(FracBits bits, bool use_block_multipliers) const;

  Device device_;
  ResourceSource source_ = ResourceSource::paper_fit;
  std::shared_ptr<const SynthesisResources> synthesis_;
  int block_bits_ = 18;
  int block_synthesis_limit_ = 15;
  std::vector<Point> soft_, hard_;  // without / with block multipliers, ascending width
  Quadratic soft_slices_{}, soft_clock_{};
  WrapperCost wrapper_;
  std::vector<double> wrapper_clock_;  // index lanes - 1
  int design_bits_ = 0;                // the pipeline of the paper's measured designs
  bool design_block_multipliers_ = false;

  // Floating point.
  std::vector<FloatFamily> families_;
  int float_multipliers_ = 24, float_add_subs_ = 21, float_sign_flips_ = 3, float_comparators_ = 6;
  int guard_bits_ = 3, luts_per_slice_ = 2, flip_flops_per_slice_ = 2;
  int slices_for(int luts, int flip_flops) const;
};

}  // namespace rc::pipeline
