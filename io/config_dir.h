// Where the configs (device and host profiles, the paper's table, pipeline resources, calibration
// variants) are found at run time, in this order:
//   1. the environment variable RC2000SIM_CONFIGS, when set and not empty (any folder, as given);
//   2. the configs/ folder of the source tree this library was built from, while it still exists
//      (a build tree: edits to configs/ take effect without installing);
//   3. the installed share folder (<prefix>/share/rc2000tlm/configs), even if absent, so that a
//      missing profile's error names where an installed library looks for it.
#pragma once

#include <string>

namespace rc::io {

// The folder above, for this build (its source and installed folders compiled in).
std::string config_dir();

// The rule itself, for any three candidates (`env` may be null: unset).
std::string choose_config_dir(const char* env, const std::string& source_dir, const std::string& installed_dir);

}  // namespace rc::io
