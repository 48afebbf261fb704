// One workload definition (issue 25; docs/scenes.md, "One workload") shared by `run`, studies
// (`sweep`) and `paper`: the scene and how it is built, how many shooting steps, which segments are
// sent and the form factor. Each command makes its Workload in one place (run_workload,
// study_workload, paper_workload; `design` starts from default_design_workload and its options set
// the rest, host_sw/studies/design_options.h) and solves from it (solver_options); report.json,
// sweep.json and design.json record it (workload_json.h).
//
// The paper's Table 2 scenes are our Cornell Box refined to 70 faces, then split (70 x 4^k faces,
// faces x 4^m patches: paper_scene_options). The same counts can be built another way (`--faces 280
// --patch-levels 2` refines straight to 280 faces): another mesh, with another number of steps to
// convergence (1,307 against the paper's construction's 5,999 for 280/4,480). check_construction
// tells the two apart, so a run can say so.
//
//   const Workload w = run_workload(options.scene, options.solver);
//   const ConstructionCheck c = check_construction(w, scene.faces.size(), scene.patches.size());
//   if (c.kind == Construction::other) std::fprintf(stderr, "note: %s\n", c.note.c_str());
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "host_sw/radiosity/radiosity.h"
#include "host_sw/studies/sweep_options.h"
#include "scenes/prepare.h"

namespace rc {

struct PaperRow;
struct Study;
struct StudyScene;

struct Workload {
  std::string source = "embedded:cornell-box";  // the scene file, or the embedded box (scene_source)
  SceneOptions scene;                           // how it is built
  StepsChoice steps;                            // Table 2's count, to convergence, or a fixed count
  double convergence = SolverOptions{}.convergence;
  bool paper_faithful = true;  // every segment to every other patch (the paper), or receivers culled
  FormFactorKind form_factor = FormFactorKind::PointToPoint;
};

// `run`: converges (or --steps N), receivers culled, its form factor.
Workload run_workload(const SceneOptions& scene, const SolverOptions& solver);
// A study's scene (the study's steps policy, segments and that scene's form factor).
Workload study_workload(const Study& study, const StudyScene& scene);
// A Table 2 row as `paper` solves it: the paper's construction and step count, every segment, point.
Workload paper_workload(const PaperRow& row);
// `design`'s default (design_search.h): the paper's 280-face, 4,480-patch Cornell Box as `sweep` and
// `paper` build it (our box refined to 70 faces, each split into 4 faces and those into 16 patches),
// Table 2's count (5,889 steps), every segment sent, the paper's point form factor.
Workload default_design_workload();

// One rule for a scene file in every command (issue 37; docs/scenes.md, "One workload"): it is taken
// as it is (no refinement, SceneOptions{}'s patch levels, as `run` and `accuracy` take it) unless the
// options given ask otherwise; `given(option)` says whether "--faces", "--face-levels" or
// "--patch-levels" was given. The embedded box is left alone: each command's default construction of
// it (the paper's, for sweep and design) stays. `sweep`, `design` and rc2000tlm.design() call it.
void take_scene_as_given(SceneOptions& scene, const std::function<bool(const std::string& option)>& given);
// The form factor a scene file is solved with unless --form-factor is given: `run`'s analytic rule,
// which never creates energy (closed meshes and rooms need it: docs/radiosity.md); the paper's point
// rule stays the default for the embedded box, whose workload sweep and design replicate.
constexpr FormFactorKind kSceneFileFormFactor = FormFactorKind::Analytic;

// Workload::source of a scene built from `scene`: its file, or "embedded:cornell-box".
std::string scene_source(const SceneOptions& scene);

// The solver's options for `w`; `steps` > 0 runs exactly that many (the paper's count, resolved by
// the caller), else the workload's own policy (a fixed count, or to convergence).
SolverOptions solver_options(const Workload& w, int steps = 0);

enum class Construction {
  paper,       // the paper's construction for these counts
  other,       // counts the paper's construction makes, built another way
  no_paper,    // counts the paper's construction cannot make
  scene_file,  // a scene file: not the paper's box
};
const char* to_string(Construction c);  // "paper", "other", "no_paper", "scene_file"

struct ConstructionCheck {
  Construction kind = Construction::no_paper;
  SceneOptions paper;  // the paper's construction for the counts (kind paper or other)
  std::string note;    // kind other: what differs and why it matters, one sentence
};

// How `w`'s scene, which came out with `faces` faces and `patches` patches, relates to the paper's
// construction for those counts.
ConstructionCheck check_construction(const Workload& w, std::uint64_t faces, std::uint64_t patches);

// Table 2's step count when `w`'s scene (`faces`, `patches` as it came out) is one of the paper's,
// built the paper's way; 0 otherwise (StepsChoice::Kind::paper then converges).
int table2_steps(const Workload& w, std::uint64_t faces, std::uint64_t patches);

// The steps to solve `w`'s scene (`faces`, `patches` as it came out) by its policy: the fixed count,
// Table 2's (table2_steps), or 0: to convergence (a converge policy, or a paper policy on a scene
// that is not one of Table 2's as the paper built it).
int steps_to_solve(const Workload& w, std::uint64_t faces, std::uint64_t patches);

// "--faces 70 --face-levels 1 --patch-levels 2": the options that build `scene`.
std::string construction_text(const SceneOptions& scene);

}  // namespace rc
