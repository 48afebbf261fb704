// Sec 5.6's "lanes that fit" for a sweep: every device and width swept, each rule, on the device
// profile with the study's fixed settings and, when the study sweeps device profile fields, once per
// combination of their values (each estimate says which); the first host with the fixed settings
// (apps/report.h computes one).
#pragma once

#include <string>
#include <vector>

#include "apps/report.h"
#include "host_sw/studies/study.h"

namespace rc {

struct SweptFit {
  std::string device;  // the profile as the study names it
  int bits = 0;
  std::vector<ProfileSetting> settings;  // the device-profile axis values this estimate used, in axis order
  LanesThatFit estimates;
  std::string cannot_exist;  // why these settings make no device profile (then no estimates)
};

std::vector<SweptFit> swept_fits(const Study& study);

// Whether the study sweeps a device profile field (then the estimates are per combination of its values).
bool sweeps_device_fields(const Study& study);

}  // namespace rc
