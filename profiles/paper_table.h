// configs/paper-table2.json (schema rc2000sim.paper-table2/1) read at the profile edge: the
// measured columns of the paper's Table 2 as typed rows. Errors have one shape, "<path>: <where>:
// <problem>" (std::runtime_error), naming the row and key. The study that uses the rows checks what
// only it knows (that each scene can be built: host_sw/studies/paper_workload.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rc::profiles {

struct PaperTableRow {
  int faces = 0, patches = 0, steps = 0;
  double software_seconds = 0, one_pipe_seconds = 0;
};

// The bounds of the whole counts, from the models that use them (scenes, the solver).
struct PaperTableLimits {
  std::int64_t max_faces = 0, max_patches = 0, max_steps = 0;
};

std::vector<PaperTableRow> read_paper_table(const std::string& path, const PaperTableLimits& limits);

}  // namespace rc::profiles
