// Sec 5.6's "lanes that fit" for a sweep: every device and width swept, each rule, on the profiles
// with the study's fixed settings and the first host (apps/report.h computes one).
#pragma once

#include <vector>

#include "apps/report.h"
#include "host_sw/studies/study.h"

namespace rc {

struct SweptFit {
  int bits = 0;
  LanesThatFit estimates;
};

std::vector<SweptFit> swept_fits(const Study& study);

// Whether the study sweeps a device profile field (then each row's clock and layout differ from the
// estimates, which sweep.json notes).
bool sweeps_device_fields(const Study& study);

}  // namespace rc
