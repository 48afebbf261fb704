// What `rc2000sim sweep` prints for a scene: its widths and software times, one lanes x banks block
// of simulated seconds per device, width, driver, host and profile values (with the fastest and
// most frugal design of each), and sec 5.6's lanes that fit.
#pragma once

#include <string>
#include <vector>

#include "apps/sweep_lanes_fit.h"
#include "host_sw/studies/sweep_study.h"

namespace rc {

// 1,2,3,5 -> "1-3,5".
template <class Int>
std::string range_list_text(const std::vector<Int>& values) {
  std::string text;
  for (std::size_t i = 0; i < values.size();) {
    std::size_t j = i;
    while (j + 1 < values.size() && values[j + 1] == values[j] + 1) ++j;
    text += (text.empty() ? "" : ",") + std::to_string(values[i]) + (j > i ? "-" + std::to_string(values[j]) : "");
    i = j + 1;
  }
  return text;
}

// a,b,c -> "a,b,c".
std::string name_list_text(const std::vector<std::string>& items);

void print_sweep_scene(const Study& study, const SceneSweep& scene, const std::vector<SweptFit>& fits);

}  // namespace rc
