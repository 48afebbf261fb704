// `rc2000sim sweep --list-fields`: every profile field a study can sweep or fix, with its value in
// each profile of the study's devices and hosts.
#pragma once

#include "host_sw/studies/study.h"

namespace rc {

int run_list_fields(const Study& study);

}  // namespace rc
