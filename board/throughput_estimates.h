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
//   results on chip (wrapper.results), without it.
#pragma once

#include <string>
#include <vector>

#include "board/device_profile.h"

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
};

// Bytes one intersection moves as sec 5.6(a) counts them at `bits`: three coordinate fields read,
// one result bit written (6.125 at 15 bits: three 16-bit fields).
double bytes_per_intersection(int bits);

// The paper's sec 5.6 arithmetic on its printed inputs. `software_peak_rate`: the measured peak
// software intersection rate (Table 2: the largest steps x patches x faces / software seconds).
std::vector<PaperEstimate> paper_rule_estimates(double software_peak_rate);

// Our estimate of the same questions at `bits`; `software_rate`: the calibrated host's
// intersections per second (1 / intersection_test).
std::vector<PaperEstimate> model_estimates(double software_rate, int bits);

// "Lanes that fit" on any device, each rule (the same functions give the tables above): what a run's or
// a sweep's device would do at full rate. The paper's rule is Table 1's 15-bit pipeline at 176.9 MHz.
PaperEstimate paper_rule_lanes_that_fit(const DeviceProfile& device, double software_peak_rate);
PaperEstimate model_lanes_that_fit(const DeviceProfile& device, double software_rate, int bits);

// Why the two rules give different lane counts and rates for `device`, in one sentence.
std::string why_estimates_differ(const PaperEstimate& paper, const PaperEstimate& model);

}  // namespace rc::board
