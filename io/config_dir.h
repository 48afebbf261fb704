// Where the config files (device and host profiles, pipeline resources, the paper's table, study
// files' named profiles) are found, decided at run time rather than only by the build: the
// environment variable RC2000SIM_CONFIGS when it is set and not empty, else the folder the build
// compiled in (the source tree's configs/). A command's `--configs DIR` sets the variable, so worker
// processes a command starts (sweep shards) look in the same place (docs/outputs.md, "Config files").
#pragma once

#include <string>

namespace rc::io {

inline constexpr const char* kConfigDirVariable = "RC2000SIM_CONFIGS";

// The config folder: RC2000SIM_CONFIGS if set and not empty, else `compiled_in`.
std::string config_dir(const std::string& compiled_in);

// --configs DIR: `dir` must be a directory (InputFileError naming it otherwise); it becomes
// RC2000SIM_CONFIGS for this process and the processes it starts.
void use_config_dir(const std::string& dir);

}  // namespace rc::io
