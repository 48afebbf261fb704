// The fidelity study (host_sw/studies/fidelity.h) against the way `accuracy` measured before it: per
// arithmetic, its own solve and a double-precision solve whose every answer is checked against it
// (ComparingVisibility). Steps, radiosity, errors and decision counts must be equal, at several widths
// and a float format, on a small mesh composition and on the Cornell Box, whatever the jobs.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/studies/fidelity.h"
#include "host_sw/visibility/comparing_visibility.h"
#include "host_sw/visibility/visibility_factory.h"
#include "scenes/prepare.h"
#include "tests/common/small_torus_scene.h"
#include "tests/common/temp_folder.h"

namespace rc::test {
namespace {

// Bit for bit.
bool same(const std::vector<Spectrum>& a, const std::vector<Spectrum>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t band = 0; band < kBands; ++band)
      if (a[i][band] != b[i][band]) return false;
  return true;
}

struct Expected {
  SolverResult solved;
  SolutionError error;
  std::uint64_t compared = 0, arithmetic_only = 0, double_only = 0;
};

Expected per_arithmetic(const Scene& scene, const SolverOptions& solver, const SolverResult& reference, const Arithmetic& a) {
  Expected e;
  auto answer = make_software_visibility(a.backend, a.bits, 1);
  SolverOptions own = solver;  // an arithmetic with fixes: the solver's own fixes
  if (a.fixes.any()) own.fixes = a.fixes;
  e.solved = ProgressiveRadiosity(scene, *answer, own).run();
  e.error = compare_solutions(e.solved.radiosity, reference.radiosity);
  FloatVisibility float_answer;
  auto shadow = make_software_visibility(a.backend, a.bits, 1);
  std::unique_ptr<FixedSegmentsVisibility> fixed;
  if (a.fixes.any()) fixed = std::make_unique<FixedSegmentsVisibility>(*shadow, a.fixes);
  ComparingVisibility compare(float_answer, fixed ? static_cast<VisibilityBackend&>(*fixed) : *shadow);
  ProgressiveRadiosity(scene, compare, solver).run();
  e.compared = compare.segments_compared();
  e.arithmetic_only = compare.shadow_blocks_answer_clear();
  e.double_only = compare.answer_blocks_shadow_clear();
  return e;
}

const std::vector<Arithmetic> kArithmetics = {Arithmetic::fixed(7), Arithmetic::fixed(15), Arithmetic::fixed(23),
                                              Arithmetic::fixed(31), Arithmetic::floating("float:5,10")};

void expect_equal_to_per_arithmetic(const Scene& scene, const SolverOptions& solver,
                                    const std::vector<Arithmetic>& arithmetics = kArithmetics) {
  FloatVisibility float_visibility;
  const SolverResult reference = ProgressiveRadiosity(scene, float_visibility, solver).run();
  std::vector<Expected> expected;
  for (const Arithmetic& a : arithmetics) expected.push_back(per_arithmetic(scene, solver, reference, a));
  for (unsigned jobs : {1u, 2u, 3u}) {
    SCOPED_TRACE("jobs " + std::to_string(jobs));
    FidelityOptions options;
    options.jobs = jobs;
    const FidelityResult f = measure_fidelity(scene, solver, arithmetics, options);
    EXPECT_EQ(f.reference.steps, reference.steps);
    EXPECT_TRUE(same(f.reference.radiosity, reference.radiosity));
    ASSERT_EQ(f.rows.size(), arithmetics.size());
    for (std::size_t i = 0; i < arithmetics.size(); ++i) {
      SCOPED_TRACE(arithmetics[i].label());
      const ArithmeticFidelity& r = f.rows[i];
      const Expected& e = expected[i];
      EXPECT_EQ(r.arithmetic.label(), arithmetics[i].label());
      EXPECT_EQ(r.run.result.steps, e.solved.steps);
      EXPECT_TRUE(same(r.run.result.radiosity, e.solved.radiosity));
      EXPECT_EQ(r.error.rmse, e.error.rmse);
      EXPECT_EQ(r.error.max_abs, e.error.max_abs);
      EXPECT_EQ(r.error.reference_mean, e.error.reference_mean);
      EXPECT_EQ(r.decisions.compared, e.compared);
      EXPECT_EQ(r.decisions.arithmetic_only, e.arithmetic_only);
      EXPECT_EQ(r.decisions.double_only, e.double_only);
      EXPECT_EQ(r.run.recording.steps(), static_cast<std::size_t>(e.solved.steps));
      // The recording keeps the neighbour rule's host re-tests, step by step, for a timing replay.
      EXPECT_EQ(r.run.result.fix_tests, e.solved.fix_tests);
      EXPECT_EQ(r.run.result.fix_cleared, e.solved.fix_cleared);
      std::uint64_t host_tests = 0;
      for (std::size_t s = 0; s < r.run.recording.steps(); ++s) host_tests += r.run.recording.host_tests(s);
      EXPECT_EQ(host_tests, e.solved.fix_tests);
    }
  }
}

class Fidelity : public TempFolderTest {
 protected:
  Fidelity() : TempFolderTest("rc_fidelity") {}
};

// Assimp's open, concave 66-gon (64 triangles) tilted in the Cornell Box: 102 faces, one patch each.
TEST_F(Fidelity, EqualsThePerArithmeticWayOnAMeshComposition) {
  const std::string file = write("mesh.json", R"({"schema": "rc2000sim.composition/1", "room": "cornell-box", "meshes": [
    {"file": "/usr/share/assimp/models/OBJ/concave_polygon.obj", "rotate": {"axis": [1, 0.3, 0.2], "degrees": 50},
     "fit_into": {"min": [120, 180, 250], "max": [420, 420, 450]},
     "material": {"reflectance": [0.3, 0.4, 0.7]}}]})");
  SceneOptions o;
  o.file = file;
  o.patch_levels = 0;
  const Scene scene = prepare_scene(o).scene;
  ASSERT_GT(scene.faces.size(), 38u);
  expect_equal_to_per_arithmetic(scene, SolverOptions{});
}

// The Cornell Box at one level of patches (152), a fixed 300 steps: shooters repeat, so the reused
// answers are exercised.
TEST_F(Fidelity, EqualsThePerArithmeticWayOnTheBox) {
  SceneOptions o;
  o.patch_levels = 1;
  const Scene scene = prepare_scene(o).scene;
  SolverOptions solver;
  solver.fixed_steps = 300;
  expect_equal_to_per_arithmetic(scene, solver);
}

// Arithmetics with the segment fixes (issue 37: the fixes as design axes): each one's own solve is the
// solver's with those fixes, its decisions along the reference those of FixedSegmentsVisibility around
// it, and its recording keeps the neighbour rule's re-tests; on a small smooth mesh (a torus in the box).
TEST(FidelityWithFixes, EqualsThePerArithmeticWay) {
  const Scene scene = small_torus_scene();
  SolverOptions solver;
  solver.fixed_steps = 20;
  const std::vector<Arithmetic> arithmetics = {
      Arithmetic::fixed(15), Arithmetic::fixed(15, {0, 2, 0, 0}), Arithmetic::fixed(15, {0, 0, 1, 0}),
      Arithmetic::fixed(19, {0, 0, 0, 15}), Arithmetic::fixed(15, {0, 2, 2, 11}), Arithmetic::floating("float:5,10")};
  expect_equal_to_per_arithmetic(scene, solver, arithmetics);
  // The fixes change the answers (else this test would prove nothing about them).
  const FidelityResult f = measure_fidelity(scene, solver, {arithmetics[0], arithmetics[2], arithmetics[3]});
  EXPECT_NE(f.rows[0].decisions.differ(), f.rows[1].decisions.differ());
  EXPECT_NE(f.rows[0].error.rmse, f.rows[2].error.rmse);
  EXPECT_GT(f.rows[1].run.result.fix_tests, 0u);
}

TEST(FidelityArithmetic, LabelsAndRefusals) {
  EXPECT_EQ(Arithmetic::fixed(15).label(), "fixed:15");
  const Arithmetic fixed = Arithmetic::fixed(15, {0, 2, 1, 11});
  EXPECT_EQ(fixed.label(), "fixed:15+offset:2+rings:1+coordinates:11");
  EXPECT_EQ(fixed.fixes.bits, 15);  // the fixes act at the arithmetic's width
  EXPECT_EQ(Arithmetic::floating("float:5,10").label(), "float:5,10");
  EXPECT_TRUE(Arithmetic::floating("float:5,10").is_float());
  const Scene scene = prepare_scene(SceneOptions{}).scene;
  EXPECT_THROW(measure_fidelity(scene, SolverOptions{}, {Arithmetic::fixed(6)}), std::invalid_argument);
  EXPECT_THROW(measure_fidelity(scene, SolverOptions{}, {Arithmetic::floating("float:99,1")}), std::invalid_argument);
  // Fixes where they do not apply: coordinates not below the width, a float format, rings beyond 2.
  EXPECT_THROW(measure_fidelity(scene, SolverOptions{}, {Arithmetic::fixed(15, {0, 0, 0, 15})}), std::invalid_argument);
  Arithmetic on_float = Arithmetic::floating("float:5,10");
  on_float.fixes = {0, 2, 0, 0};
  EXPECT_THROW(measure_fidelity(scene, SolverOptions{}, {on_float}), std::invalid_argument);
  EXPECT_THROW(measure_fidelity(scene, SolverOptions{}, {Arithmetic::fixed(15, {0, 0, 3, 0})}), std::invalid_argument);
}

}  // namespace
}  // namespace rc::test
