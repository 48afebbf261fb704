// Profile axes of a study that changed nothing (issue 39, "ignored options"; docs/studies.md, "Axes
// that change nothing"). A profile field can be swept where the timing never reads it: host.cpu_cores
// without a CPU/FPGA split, a device's clock_mhz_default when every swept lane count has a measured
// clock, a bank field of a bank no layout uses. Such an axis multiplies the rows and gives identical
// ones, which reads as "this field does not matter" when it was never applied.
//
// The check is general: for each profile axis with two values or more, the rows that differ only in
// that axis's value are grouped (every other axis equal: device, width, driver, lanes, banks, host,
// cards and the other profile values). If at least one group has two rows and, in every group, all
// rows agree on validity, clock, simulated time, FPGA time and energy, the axis is named in a
// warning. A field the timing reads but that does not move any figure in these configurations (a
// bank clock when the lanes bound the stream) is named too: the warning says both readings.
#pragma once

#include <string>
#include <vector>

#include "host_sw/studies/sweep_row.h"

namespace rc {

// One warning per inert profile axis of `rows` (one scene's rows of one study), in axis order; empty
// when every profile axis changed some figure or none could be compared.
std::vector<std::string> inert_axis_warnings(const std::vector<SweepRow>& rows);

}  // namespace rc
