// The paper's eight Table 2 scenes as rc2000sim runs them: our Cornell Box refined to exactly 70
// faces, split to 280 and 1120 faces and into 280..4480 patches, solved paper-faithfully (every
// segment to every other patch, every face) for exactly the paper's step counts, with the answers
// recorded once for replay by every timing configuration.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "host_sw/studies/timing_study.h"
#include "scenes/prepare.h"

namespace rc {

// One row of the measured columns of Table 2 (configs/paper-table2.json).
struct PaperRow {
  int faces = 0, patches = 0, steps = 0;
  double software_seconds = 0, one_pipe_seconds = 0;
  std::string label() const;  // e.g. "1120/4480"
};

std::vector<PaperRow> load_paper_table(const std::string& path);
// The measured peak software intersection rate of sec 5.6(a), from Table 2's printed figures:
// the largest steps x patches x faces (every segment against every face) over software seconds.
double measured_peak_software_rate(const std::vector<PaperRow>& rows);
std::string default_paper_table_path();
// The table at default_paper_table_path(), read once per process and path (a run's sec 5.6 estimate and
// its timing interval both need it: each file is read once, Cli.RunReadsEachProfileOnce). Thread-safe.
const std::vector<PaperRow>& default_paper_table();

// The scene options that give exactly `faces` faces and `patches` patches (70 x 4^k faces,
// faces x 4^m patches); throws std::invalid_argument for other counts.
SceneOptions paper_scene_options(int faces, int patches);

struct PaperScene {
  PaperRow row;
  Scene scene;
  SolverOptions solver;  // paper-faithful, exactly row.steps steps
  RecordedRun functional;
  int convergence_steps = 0;  // steps our scene needs for 99.5% (0: more than recorded)
  int recorded_steps = 0;     // at most this many steps are solved (the paper's + 10%)
};

// The paper's four implementations (Table 2's columns) as timing cases of one scene.
enum class PaperImplementation { Software, OnePipe, TwoPipes, Concurrent };
constexpr int kPaperImplementations = 4;
const char* to_string(PaperImplementation implementation);  // "software", "one_pipe", ...
// software: host CPU only; one_pipe / two_pipes: the XC2V6000 RC2000 with 1 / 2 lanes, serial
// driver; concurrent: 2 lanes with the concurrent driver (sec 4.3, the paper's "enhanced driver").
TimingCase paper_timing_case(const PaperScene& scene, PaperImplementation implementation, const std::string& host);

// Solves every row once with the bit-exact `backend` at `bits`, recording the paper's steps and on
// to our own 99.5% convergence (at most 10% more), which is reported beside the paper's count. The
// rows are solved in parallel, one per job (jobs(), host_sw/radiosity/jobs.h); the result does not
// depend on it.
std::vector<PaperScene> prepare_paper_scenes(const std::vector<PaperRow>& rows, const std::string& backend, int bits,
                                             const std::function<void(const std::string&)>& progress);

}  // namespace rc
