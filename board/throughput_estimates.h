// Paper sec 5.6: what other devices and the RC2000's memory bandwidth would allow, two ways.
//
// * The paper's rule, reproduced from the figures it prints (docs/calibration.md, "Sec 5.6"):
//   a device holds min(floor(slices / 1976), floor(block multipliers / 30)) copies of Table 1's
//   15-bit block-multiplier pipeline (the Handel-C wrapper is not counted), each doing one
//   intersection per cycle at Table 1's 176.9 MHz; an intersection moves 6.125 bytes (three
//   16-bit coordinates read, one result bit written, sec 5.6(a)); the memory bound is 6 banks x
//   4 bytes x 100 MHz; speedups are over the measured peak software rate of Table 2.
// * Our design-fit estimate: lanes that fit with the wrapper counted and slice-multiplier lanes
//   beyond the block multipliers (design_fit.h), on a board with as many 100 MHz banks as the lanes
//   need at full rate, streaming at the rate the pass-timing formula gives for a long pass, result
//   bank included (a result word shared by two lanes is read and written), or, when the profile keeps
//   results on chip (wrapper.results), without it. The model's RC2000 bandwidth limit divides the
//   same 2.4 GB/s by the bytes the model's measured two-lane design moves per intersection (10 at
//   15 bits: its result word is read and written back once per face), not by the paper's 6.125.
#pragma once

#include <string>
#include <vector>

#include "board/device_profile.h"
#include "pipeline/float_format.h"
#include "pipeline/resource_source.h"

namespace rc::board {

enum class EstimateRule { Paper, Model };
const char* to_string(EstimateRule rule);  // "paper", "model"

struct PaperEstimate {
  std::string estimate;  // "RC2000 bandwidth limit", "measured 2-lane design", "lanes that fit"
  EstimateRule rule = EstimateRule::Paper;
  std::string device;
  int lanes = 0;
  double clock_mhz = 0;
  double intersections_per_s = 0;
  double bytes_per_intersection = 0;
  double bytes_per_cycle = 0;
  double gb_per_s = 0;
  double software_rate = 0;  // intersections per second the speedup is taken against
  double speedup_vs_software = 0;
  std::string note;          // how the figure was reached
  std::string clock_assumption;  // which clock the rate assumes and where it comes from
  pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit;  // the lanes' slices and blocks (model rule)
};

// Bytes one intersection moves as sec 5.6(a) counts them at `bits`: three coordinate fields read,
// one result bit written (6.125 at 15 bits: three 16-bit fields).
double bytes_per_intersection(int bits);

// The paper's sec 5.6 arithmetic on its printed inputs. `software_peak_rate`: the measured peak
// software intersection rate (Table 2: the largest steps x patches x faces / software seconds).
std::vector<PaperEstimate> paper_rule_estimates(double software_peak_rate);

// Our estimate of the same questions at `bits`; `software_rate`: the calibrated host's
// intersections per second (1 / intersection_test).
// `resources`: the source of the lanes' slices and block multipliers (the measured 2-lane design fits
// under either).
std::vector<PaperEstimate> model_estimates(double software_rate, int bits,
                                           pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit);

// "Lanes that fit" on any device, each rule (the same functions give the tables above): what a run's or
// a sweep's device would do at full rate. The paper's rule is Table 1's 15-bit pipeline at 176.9 MHz.
PaperEstimate paper_rule_lanes_that_fit(const DeviceProfile& device, double software_peak_rate);
// `resources`: where the lanes' slices and block multipliers come from (pipeline/resource_source.h).
PaperEstimate model_lanes_that_fit(const DeviceProfile& device, double software_rate, int bits,
                                   pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit);

// Floating point (docs/pipeline.md, "Resources, clock and lanes that fit"): bytes one intersection
// moves as sec 5.6(a) counts them for coordinates of 1+E+M bits packed into the bank words as the
// fixed-point coordinates are (floor(32 / width) fields per 32-bit word, each 32 / that wide; two
// words per coordinate above 32 bits), one result bit written.
double bytes_per_intersection(pipeline::FloatFormat format);

// Lanes that fit at full rate, fixed or float, beside each other: lanes (design_fit.h, wrapper
// counted), their clock, lanes x clock intersections per second, bytes per intersection, and the
// bandwidth that rate needs against the RC2000's banks (6 x 4 bytes x 100 MHz, sec 5.6(a)).
struct FullRateFit {
  std::string device, arithmetic;  // "fixed:15", "float:8,23"
  int lanes = 0, hard_lanes = 0, soft_lanes = 0;
  int slices = 0, block_multipliers = 0;
  double clock_mhz = 0;
  double intersections_per_s = 0;
  double bytes_per_intersection = 0;
  double gb_per_s_needed = 0;
  double rc2000_gb_per_s = 0;
  bool modelled = false;
};
FullRateFit fixed_full_rate_fit(const DeviceProfile& device, int bits);
FullRateFit float_full_rate_fit(const DeviceProfile& device, pipeline::FloatFormat format);

// The float counterpart of model_lanes_that_fit: the full-rate figures above as a PaperEstimate
// (EstimateRule::Model), with the speedup over `software_rate`.
PaperEstimate float_lanes_that_fit(const DeviceProfile& device, double software_rate, pipeline::FloatFormat format);

// Banks that keep `lanes` lanes at `bits` at full rate: three coordinate banks per lane group, one
// for faces, one for results (3 groups + 2; the model's estimates assume a board with that many).
unsigned banks_for_full_rate(const DeviceProfile& device, int lanes, int bits);

// Why the two rules give different lane counts and rates for `device`, in one sentence.
std::string why_estimates_differ(const PaperEstimate& paper, const PaperEstimate& model);

}  // namespace rc::board
