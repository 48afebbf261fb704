// `rc2000sim sweep merge DIR... --out DIR`: the shards of a study put together, the same outputs as
// one machine writes (host_sw/studies/sweep_study.h, merge_shards).
#pragma once

#include <CLI/CLI.hpp>

namespace rc {

// Adds `merge` under the sweep command; its callback sets `exit_code`.
void add_merge_command(CLI::App& sweep, int& exit_code);

}  // namespace rc
