// Where the configs (device and host profiles, the paper's table, pipeline resources, calibration
// variants) are found at run time, in this order:
//   1. the environment variable RC2000SIM_CONFIGS, when set and not empty (any folder, as given); a
//      command's `--configs DIR` sets it (use_config_dir), so the worker processes a command starts
//      (sweep shards) look in the same place (docs/outputs.md, "Config files");
//   2. the configs of the prefix the running program is installed in, when it runs as
//      <prefix>/bin/<program> and <prefix>/share/rc2000tlm exists (an installed rc2000sim, wherever
//      `cmake --install --prefix` put it, uses its own prefix's configs: share_dir_of_program);
//   3. the configs/ folder of the source tree this library was built from, while it still exists
//      (a build tree: edits to configs/ take effect without installing);
//   4. the installed share folder (<prefix>/share/rc2000tlm/configs, the prefix configured at build
//      time), even if absent, so that a missing profile's error names where an installed library
//      looks for it.
#pragma once

#include <string>

namespace rc::io {

inline constexpr const char* kConfigDirVariable = "RC2000SIM_CONFIGS";

// The folder above, for this build (its source and installed folders compiled in).
std::string config_dir();

// <prefix>/share/rc2000tlm when the running program is <prefix>/bin/<program> and that folder
// exists; empty otherwise (a build tree's program, a user's program elsewhere).
std::string share_dir_of_program();

// The installed share folder: share_dir_of_program() when not empty, else the build's configured
// <prefix>/share/rc2000tlm (even if absent). Installed data besides the configs (plot scripts) is
// found here.
std::string installed_share_dir();

// The rule itself, for any three candidates (`env` may be null: unset).
std::string choose_config_dir(const char* env, const std::string& source_dir, const std::string& installed_dir);

// --configs DIR: `dir` must be a directory (InputFileError naming it otherwise); it becomes
// RC2000SIM_CONFIGS for this process and the processes it starts.
void use_config_dir(const std::string& dir);

}  // namespace rc::io
