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
#pragma once

#include <string>
#include <vector>

#include "pipeline/fixed_format.h"

namespace rc::pipeline {

struct PipelineResources {
  int frac_bits = 0;
  bool block_multipliers_used = false;
  int slices = 0;
  int block_multipliers = 0;
  double clock_mhz = 0;
  bool interpolated = false;  // not a width the paper synthesised for this option
  bool extrapolated = false;  // beyond what the paper could synthesise (block multipliers > 15 bits)
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

struct Device {
  std::string name;
  int slices = 0;
  int block_multipliers = 0;
};

class ResourceModel {
 public:
  // Reads the JSON file; throws std::runtime_error naming the file and the problem.
  static ResourceModel load(const std::string& path);
  static ResourceModel from_json_text(const std::string& text, const std::string& origin = "<text>");
  // configs/pipeline_resources.json of this source tree.
  static ResourceModel load_default();
  static std::string default_path();

  // Throws std::invalid_argument for widths outside 7..31.
  PipelineResources pipeline(FracBits bits, bool use_block_multipliers) const;
  WrapperCost wrapper() const { return wrapper_; }
  double wrapper_clock_mhz(int lanes) const;
  DesignResources design(int bits, bool use_block_multipliers, int lanes) const;
  const Device& reference_device() const { return device_; }  // the XC2V6000 of the paper

  // 18x18 blocks for one signed a-bit by b-bit product: ceil((a-1)/17) * ceil((b-1)/17), each
  // operand split into 17-bit unsigned pieces plus a signed top piece.
  static int blocks_per_product(int a_bits, int b_bits, int block_bits = 18);
  // Sum over the 27 multipliers, with operand widths from bit_bounds.h.
  static int block_multipliers_needed(FracBits bits, int block_bits = 18);

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

  Device device_;
  int block_bits_ = 18;
  int block_synthesis_limit_ = 15;
  std::vector<Point> soft_, hard_;  // without / with block multipliers, ascending width
  Quadratic soft_slices_{}, soft_clock_{};
  WrapperCost wrapper_;
  std::vector<double> wrapper_clock_;  // index lanes - 1
  int design_bits_ = 0;                // the pipeline of the paper's measured designs
  bool design_block_multipliers_ = false;
};

}  // namespace rc::pipeline
