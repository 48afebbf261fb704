// The Pareto front of a sweep's rows (sweep_row.h), time against energy.
#pragma once

#include <vector>

#include "host_sw/studies/sweep_row.h"

namespace rc {

// Marks pareto_time_energy: a valid row with energy is on the front when no other such row with the
// same width and the same profile-axis values is at least as fast and as frugal and better in one.
// The front chooses among designs (device, lanes, banks, driver, host, cards); a width makes another
// picture and a profile setting assumes another world (a clock, an SRAM's standby power), so each of
// those has a front of its own.
void mark_pareto_time_energy(std::vector<SweepRow>& rows);

}  // namespace rc
