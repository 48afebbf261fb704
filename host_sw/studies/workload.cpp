#include "host_sw/studies/workload.h"

#include <cstdio>
#include <stdexcept>

#include "host_sw/studies/paper_workload.h"
#include "host_sw/studies/study.h"

namespace rc {

Workload run_workload(const SceneOptions& scene, const SolverOptions& solver) {
  Workload w;
  w.source = scene_source(scene);
  w.scene = scene;
  w.steps.kind = solver.fixed_steps > 0 ? StepsChoice::Kind::fixed : StepsChoice::Kind::converge;
  w.steps.steps = solver.fixed_steps;
  w.convergence = solver.convergence;
  w.paper_faithful = !solver.cull_receivers;
  w.form_factor = solver.form_factor;
  return w;
}

Workload study_workload(const Study& study, const StudyScene& scene) {
  Workload w;
  w.source = scene.source.empty() ? "embedded:cornell-box" : scene.source;
  w.scene = scene.options;
  w.steps = study.steps;
  w.convergence = study.convergence;
  w.paper_faithful = study.paper_faithful;
  w.form_factor = parse_form_factor_kind(study.form_factor_of(scene));
  return w;
}

Workload paper_workload(const PaperRow& row) {
  Workload w;
  w.scene = paper_scene_options(row.faces, row.patches);
  w.steps.kind = StepsChoice::Kind::fixed;
  w.steps.steps = row.steps;
  w.paper_faithful = true;
  w.form_factor = FormFactorKind::PointToPoint;  // the paper's rule (sec 2)
  return w;
}

Workload default_design_workload() {
  Workload w;
  w.scene = paper_scene_options(280, 4480);
  w.source = scene_source(w.scene);
  w.steps.kind = StepsChoice::Kind::paper;
  w.paper_faithful = true;
  w.form_factor = FormFactorKind::PointToPoint;  // the paper's rule (sec 2)
  return w;
}

void take_scene_as_given(SceneOptions& scene, const std::function<bool(const std::string& option)>& given) {
  if (scene.file.empty()) return;
  const SceneOptions plain;
  if (!given("--faces")) scene.face_target = plain.face_target;
  if (!given("--face-levels")) scene.face_levels = plain.face_levels;
  if (!given("--patch-levels")) scene.patch_levels = plain.patch_levels;
}

std::string scene_source(const SceneOptions& scene) { return scene.file.empty() ? "embedded:cornell-box" : scene.file; }

int table2_steps(const Workload& w, std::uint64_t faces, std::uint64_t patches) {
  if (check_construction(w, faces, patches).kind != Construction::paper) return 0;
  for (const PaperRow& row : default_paper_table()) {
    if (static_cast<std::uint64_t>(row.faces) == faces && static_cast<std::uint64_t>(row.patches) == patches) return row.steps;
  }
  return 0;
}

int steps_to_solve(const Workload& w, std::uint64_t faces, std::uint64_t patches) {
  switch (w.steps.kind) {
    case StepsChoice::Kind::fixed: return w.steps.steps;
    case StepsChoice::Kind::paper: return table2_steps(w, faces, patches);
    case StepsChoice::Kind::converge: return 0;
  }
  throw std::logic_error("steps_to_solve: not a StepsChoice::Kind");
}

SolverOptions solver_options(const Workload& w, int steps) {
  SolverOptions o;
  o.convergence = w.convergence;
  o.cull_receivers = !w.paper_faithful;
  o.form_factor = w.form_factor;
  o.fixed_steps = steps > 0 ? steps : w.steps.kind == StepsChoice::Kind::fixed ? w.steps.steps : 0;
  return o;
}

const char* to_string(Construction c) {
  switch (c) {
    case Construction::paper: return "paper";
    case Construction::other: return "other";
    case Construction::no_paper: return "no_paper";
    case Construction::scene_file: return "scene_file";
  }
  throw std::logic_error("to_string: not a Construction");
}

std::string construction_text(const SceneOptions& s) {
  std::string text;
  if (s.face_target > 0) text += "--faces " + std::to_string(s.face_target) + " ";
  if (s.face_levels > 0) text += "--face-levels " + std::to_string(s.face_levels) + " ";
  if (s.patch_size > 0) {
    char size[48];
    std::snprintf(size, sizeof size, "--patch-size %g", s.patch_size);
    return text + size;
  }
  return text + "--patch-levels " + std::to_string(s.patch_levels);
}

ConstructionCheck check_construction(const Workload& w, std::uint64_t faces, std::uint64_t patches) {
  ConstructionCheck c;
  if (!w.scene.file.empty()) {
    c.kind = Construction::scene_file;
    return c;
  }
  try {
    c.paper = paper_scene_options(static_cast<int>(faces), static_cast<int>(patches));
  } catch (const std::invalid_argument&) {
    return c;  // no_paper
  }
  const bool same = c.paper.face_target == w.scene.face_target && c.paper.face_levels == w.scene.face_levels &&
                    c.paper.patch_levels == w.scene.patch_levels && w.scene.patch_size == 0;
  c.kind = same ? Construction::paper : Construction::other;
  if (!same) {
    c.note = std::to_string(faces) + " faces and " + std::to_string(patches) + " patches built as " +
             construction_text(w.scene) + ", not as the paper's " + construction_text(c.paper) +
             ": another mesh, with another number of steps to convergence (docs/scenes.md, \"One workload\")";
  }
  return c;
}

}  // namespace rc
