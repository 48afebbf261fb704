// One workload definition (host_sw/studies/workload.h): each command's workload, the solver options
// it gives, and the paper's construction told apart from another one with the same counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "host_sw/studies/paper_workload.h"
#include "host_sw/studies/study_file.h"
#include "host_sw/studies/workload.h"
#include "host_sw/studies/workload_json.h"

namespace rc {
namespace {

SceneOptions built(int face_target, int face_levels, int patch_levels) {
  SceneOptions o;
  o.face_target = face_target;
  o.face_levels = face_levels;
  o.patch_levels = patch_levels;
  return o;
}

Workload of(const SceneOptions& scene) {
  Workload w;
  w.scene = scene;
  return w;
}

TEST(Workload, ThePapersConstructionIsToldFromAnotherWithTheSameCounts) {
  const ConstructionCheck paper = check_construction(of(built(70, 1, 2)), 280, 4480);
  EXPECT_EQ(paper.kind, Construction::paper);
  EXPECT_EQ(paper.note, "");
  const ConstructionCheck other = check_construction(of(built(280, 0, 2)), 280, 4480);
  EXPECT_EQ(other.kind, Construction::other);
  EXPECT_EQ(construction_text(other.paper), "--faces 70 --face-levels 1 --patch-levels 2");
  EXPECT_EQ(other.note.rfind("280 faces and 4480 patches built as --faces 280 --patch-levels 2, not as the paper's "
                             "--faces 70 --face-levels 1 --patch-levels 2",
                             0),
            0u)
      << other.note;
  EXPECT_EQ(check_construction(of(built(0, 0, 1)), 38, 152).kind, Construction::no_paper);  // the 38-face box
  SceneOptions by_size = built(70, 1, 0);
  by_size.patch_size = 0.1;  // patches by size: not the paper's split even when the counts agree
  EXPECT_EQ(check_construction(of(by_size), 280, 4480).kind, Construction::other);
  SceneOptions file = built(70, 1, 2);
  file.file = "room.scene";
  EXPECT_EQ(check_construction(of(file), 280, 4480).kind, Construction::scene_file);
}

// The two constructions really are two meshes: the same counts, other faces.
TEST(Workload, TheTwoConstructionsOfTheSameCountsAreDifferentMeshes) {
  const Scene paper = prepare_scene(built(70, 1, 0)).scene;
  const Scene direct = prepare_scene(built(280, 0, 0)).scene;
  ASSERT_EQ(paper.faces.size(), 280u);
  ASSERT_EQ(direct.faces.size(), 280u);
  auto areas = [](const Scene& s) {
    std::vector<double> a;
    for (const Patch& p : s.patches) a.push_back(p.area);
    std::sort(a.begin(), a.end());
    return a;
  };
  EXPECT_NE(areas(paper), areas(direct));
}

TEST(Workload, EachCommandsWorkloadGivesItsSolverOptions) {
  SolverOptions run;
  run.fixed_steps = 40;
  run.form_factor = FormFactorKind::PointToPoint;
  const Workload r = run_workload(built(70, 0, 1), run);
  EXPECT_EQ(r.source, "embedded:cornell-box");
  EXPECT_EQ(r.steps.kind, StepsChoice::Kind::fixed);
  EXPECT_FALSE(r.paper_faithful);  // `run` culls receivers
  const SolverOptions back = solver_options(r);
  EXPECT_EQ(back.fixed_steps, 40);
  EXPECT_TRUE(back.cull_receivers);
  EXPECT_EQ(back.form_factor, FormFactorKind::PointToPoint);
  EXPECT_EQ(back.convergence, run.convergence);
  EXPECT_EQ(solver_options(run_workload(built(70, 0, 1), SolverOptions{})).fixed_steps, 0);  // to convergence

  PaperRow row;
  row.faces = 280;
  row.patches = 4480;
  row.steps = 5889;
  const Workload p = paper_workload(row);
  EXPECT_EQ(construction_text(p.scene), "--faces 70 --face-levels 1 --patch-levels 2");
  const SolverOptions ps = solver_options(p);
  EXPECT_EQ(ps.fixed_steps, 5889);
  EXPECT_FALSE(ps.cull_receivers);  // every segment, as the paper
  EXPECT_EQ(ps.form_factor, FormFactorKind::PointToPoint);

  const Study study = default_study_settings();
  const Workload s = study_workload(study, study.scenes.front());
  EXPECT_EQ(s.steps.kind, StepsChoice::Kind::paper);
  EXPECT_TRUE(s.paper_faithful);
  EXPECT_EQ(s.form_factor, FormFactorKind::PointToPoint);
  EXPECT_EQ(solver_options(s, 1488).fixed_steps, 1488);  // the paper's count, resolved by the study
}

// `design` and `sweep` take Table 2's count by one rule: only for a scene built the paper's way (the
// counts alone are not enough: another construction with them is another mesh, see above).
TEST(Workload, DesignAndSweepTakeTable2sCountOnlyForThePapersConstruction) {
  Workload design = default_design_workload();  // the paper's 280/4480, Table 2's count
  EXPECT_EQ(design.source, "embedded:cornell-box");
  EXPECT_EQ(construction_text(design.scene), "--faces 70 --face-levels 1 --patch-levels 2");
  EXPECT_EQ(design.steps.kind, StepsChoice::Kind::paper);
  EXPECT_TRUE(design.paper_faithful);
  EXPECT_EQ(design.form_factor, FormFactorKind::PointToPoint);
  EXPECT_EQ(design.convergence, SolverOptions{}.convergence);
  EXPECT_EQ(table2_steps(design, 280, 4480), 5889);
  EXPECT_EQ(table2_steps(design, 280, 1120), 0);  // counts the construction did not give
  const Study study = default_study_settings();
  EXPECT_EQ(table2_steps(study_workload(study, study.scenes.front()), 280, 1120), 1488);  // its 280/1120
  design.scene = built(280, 0, 2);  // the same counts built another way
  EXPECT_EQ(table2_steps(design, 280, 4480), 0);
}

// The steps a workload solves, by its policy: a fixed count whatever the scene, Table 2's only where
// table2_steps gives one, else (and always for converge) 0, to convergence.
TEST(Workload, StepsToSolveFollowTheWorkloadsPolicy) {
  Workload w = default_design_workload();
  EXPECT_EQ(steps_to_solve(w, 280, 4480), 5889);
  EXPECT_EQ(steps_to_solve(w, 280, 1120), 0);
  w.steps.kind = StepsChoice::Kind::converge;
  EXPECT_EQ(steps_to_solve(w, 280, 4480), 0);
  EXPECT_EQ(solver_options(w).fixed_steps, 0);
  w.steps = {StepsChoice::Kind::fixed, 12};
  EXPECT_EQ(steps_to_solve(w, 280, 4480), 12);
  EXPECT_EQ(steps_to_solve(w, 7, 7), 12);
  EXPECT_EQ(solver_options(w).fixed_steps, 12);
  w.scene = built(280, 0, 2);
  w.steps.kind = StepsChoice::Kind::paper;
  EXPECT_EQ(steps_to_solve(w, 280, 4480), 0);
}

TEST(Workload, SceneSourceNamesTheFileOrTheEmbeddedBox) {
  EXPECT_EQ(scene_source(SceneOptions{}), "embedded:cornell-box");
  SceneOptions file;
  file.file = "configs/scenes/room.scene";
  EXPECT_EQ(scene_source(file), "configs/scenes/room.scene");
  SolverOptions converge;
  EXPECT_EQ(run_workload(file, converge).source, "configs/scenes/room.scene");
}

TEST(Workload, TheRecordNamesTheConstructionAndTheNoteOnlyWhenItDiffers) {
  SolverOptions converge;
  const nlohmann::ordered_json other = workload_json(run_workload(built(280, 0, 2), converge), 280, 4480, 1307);
  EXPECT_EQ(other["scene"]["paper_construction"], "other");
  EXPECT_EQ(other["scene"]["paper_options"], "--faces 70 --face-levels 1 --patch-levels 2");
  EXPECT_EQ(other["steps"]["policy"], "converge");
  EXPECT_TRUE(other["steps"]["count"].is_null());
  EXPECT_EQ(other["steps"]["solved"], 1307);
  EXPECT_EQ(other["segments"], "culled");
  const nlohmann::ordered_json paper = workload_json(run_workload(built(70, 1, 2), converge), 280, 4480, 5999);
  EXPECT_EQ(paper["scene"]["paper_construction"], "paper");
  EXPECT_FALSE(paper["scene"].contains("note"));
}

TEST(Workload, ASceneFileIsTakenAsItIsUnlessRefinementIsGiven) {
  const auto none = [](const std::string&) { return false; };
  SceneOptions file = default_design_workload().scene;  // the paper's construction, as design starts
  file.file = "mesh.json";
  take_scene_as_given(file, none);
  const SceneOptions plain;
  EXPECT_EQ(file.face_target, plain.face_target);
  EXPECT_EQ(file.face_levels, plain.face_levels);
  EXPECT_EQ(file.patch_levels, plain.patch_levels);  // run's and accuracy's
  // What was given stays.
  SceneOptions asked = default_design_workload().scene;
  asked.file = "mesh.json";
  asked.patch_levels = 0;
  take_scene_as_given(asked, [](const std::string& option) { return option == "--patch-levels"; });
  EXPECT_EQ(asked.patch_levels, 0);
  EXPECT_EQ(asked.face_target, 0);
  // The embedded box keeps the command's construction (the paper's, for design and sweep).
  SceneOptions box = default_design_workload().scene;
  take_scene_as_given(box, none);
  EXPECT_EQ(box.face_target, 70);
  EXPECT_EQ(kSceneFileFormFactor, run_workload(plain, SolverOptions{}).form_factor);  // run's form factor
}

}  // namespace
}  // namespace rc
