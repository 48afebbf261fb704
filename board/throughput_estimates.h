// Paper sec 5.6: what other devices and the RC2000's memory bandwidth would allow, from the device
// profiles (configs/devices/) and the resource model, against a software intersection rate.
#pragma once

#include <string>
#include <vector>


namespace rc::board {

struct PaperEstimate {
  std::string estimate;  // what is estimated, e.g. "lanes that fit" or "RC2000 bandwidth limit"
  std::string device;
  int lanes = 0;
  double clock_mhz = 0;
  double intersections_per_s = 0;
  double bytes_per_cycle = 0;
  double gb_per_s = 0;
  double speedup_vs_software = 0;
  std::string note;
};

// Bytes one intersection moves at `bits` (sec 5.6(a)): three coordinate fields read, one result
// bit written (6.125 at 15 bits: three 16-bit fields).
double bytes_per_intersection(int bits);

// `software_rate`: intersections per second of the software implementation (the calibrated host
// profile's 1 / intersection_test cost), for the speedups.
std::vector<PaperEstimate> paper_estimates(double software_rate, int bits);

}  // namespace rc
