// A design-space study as data (docs/studies.md): the scenes, the steps policy and solver settings,
// the axes (the classic five, hosts, and any profile field by its path) and fixed profile
// settings. It comes from a study file (study_file.h) or from `rc2000sim sweep`'s options, and is
// recorded, resolved (every default filled in), in every output folder and shard as
// study_json() (study_json.h); study_from_json() reads that record back (`sweep merge` plans from it).
#pragma once

#include "pipeline/resource_source.h"

#include <string>
#include <vector>

#include "board/bank_layout.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/visibility/visibility_factory.h"
#include "scenes/prepare.h"
#include "host_sw/studies/sweep_config.h"
#include "host_sw/studies/sweep_options.h"

namespace rc {

struct StudyScene {
  std::string name;      // the scene's output folder when the study has several scenes
  SceneOptions options;  // how it is made (prepare_scene); options.file is resolved for this machine
  // The scene file as the study wrote it (relative to the study file) or the command line gave it;
  // empty for the embedded box. Outputs record this, so they do not depend on where a shard ran.
  std::string source;
  // The form factor of this scene's solves; empty: the study's (Study::form_factor). Set by a
  // form-factor axis (expand_form_factors), which makes each scene one workload per form factor.
  std::string form_factor;
};

struct Study {
  std::string name = "command-line";
  std::string description;
  std::string file;  // the study file as given; empty for a command line (recorded by its name only)
  std::vector<StudyScene> scenes;
  StepsChoice steps;  // the paper's, to convergence or a count (parse_steps reads its text)
  double convergence = SolverOptions{}.convergence;
  bool paper_faithful = true;
  BitExactVisibility visibility = BitExactVisibility::fast;  // answers visibility once per width; parsed where it enters
  // The solver's form factor (form_factor_names()). The paper's point rule by default: a sweep
  // replicates the paper's workload (Table 2's steps, every segment sent) on other boards.
  std::string form_factor = "point";
  // The form factor of `scene`'s solves: its own (a form-factor axis) or the study's.
  const std::string& form_factor_of(const StudyScene& scene) const {
    return scene.form_factor.empty() ? form_factor : scene.form_factor;
  }
  bool full_banks = false;          // false: banks as small as change no pass (compact_bank_capacity)
  // Where the lanes' slices and block multipliers come from (pipeline/resource_source.h): decides
  // which lane counts fit each device; the study file's top-level `resources`, sweep's --resources.
  pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit;
  // How every configuration's passes divide their rays over the ray groups (board/bank_layout.h):
  // the study file's top-level `ray_split`, sweep's --ray-split.
  board::RaySplitRule ray_split = board::RaySplitRule::limit;
  SweepAxes axes;
  std::vector<ProfileSetting> fixed;  // applied to every configuration's profiles
};

// Checks what can be checked without solving: a steps policy, the visibility backend, scene names
// unique, every profile known, every profile path a field of every device (or host) swept and every
// value accepted by the profile's loader, and the size of the sweep. Errors name the study.
void check_study(const Study& study);

// Resolves a profile path against the study's first device and first host (profile_setting.h).
ProfileField resolve_study_field(const std::string& path, const std::vector<std::string>& devices,
                                 const std::vector<std::string>& hosts);

// A form-factor axis (docs/studies.md, "[axes] form_factors"): every scene becomes one scene per form
// factor, named "<scene>-<form factor>" (a form factor changes the workload itself: the steps to
// convergence, hence every configuration's time), in the order scenes x form factors. Throws
// std::invalid_argument naming a form factor that is not one, or one given twice.
void expand_form_factors(Study& s, const std::vector<std::string>& form_factors);

// "paper-280-1120" for the paper's scenes, the file's stem, or "cornell-box".
std::string default_scene_name(const SceneOptions& options);

// The tool that ran a study, recorded beside it: "rc2000sim <version> (<git commit>)".
std::string tool_version();

}  // namespace rc
