// Metamorphic tests of the whole path from a scene file to radiosity (docs/radiosity.md, "How the
// solver is checked"): rotating, translating, uniformly scaling or mirroring a scene, reordering its
// surfaces in the file, and declaring a surface two-sided instead of writing its two faces, must give
// the same radiosity per patch, with every form factor, in double-precision visibility and in 31-bit
// fixed point. Patches are matched by geometry (the original's centre mapped through the transform
// and its normal), not by index: reordering and sheet grouping renumber faces and patches.
//
// Scenes: the Cornell Box, scenes/examples/two-rooms.scene (a free-standing panel written as two
// faces; its panel moved off the patch-centre lattice, nudged_panel, except in the issue's case), scenes/examples/tilted-plate.scene (a 'two-sided quad' tilted off the axes) and a mesh
// through Assimp (the open, concave polygon of assimp-testmodels, tilted, in the Cornell Box).
// Solves run to 1 - 1e-10, so that the order in which near-equal shooters are picked cannot matter
// beyond that (it never changed here: the step counts agree).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

#include "host_sw/visibility/fixed_visibility.h"
#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/radiosity/radiosity.h"
#include "scenes/composition.h"
#include "scenes/cornell_box.h"
#include "scenes/prepare.h"
#include "tests/host_sw/visibility/scene_text.h"

namespace rc {
namespace {

using test::Affine;
using test::SceneText;

// Tolerances, relative per patch and band (docs/radiosity.md, "How the solver is checked"). Float:
// transformed coordinates are rounded once when written (about 1e-16 relative; a translation far
// from the scene's size, or a sliver triangle's centroid and normal, carry it further), and the form
// factors and radiosity follow. Measured over every case here: at most 5.4e-12 (the mesh's slivers,
// rotated), 9.5e-15 on the Cornell Box; the step and blocked-segment counts are identical in every
// case, so the shooting order never changed. 31-bit fixed point: quantising to 2^-31 of the scene
// could flip a segment that grazes an edge; none of these scenes has one (the blocked-segment counts
// agree in every case), and the radiosity agrees as closely as in float (the same 5.4e-12). The
// tolerance leaves a margin of 20 over the largest measured difference.
constexpr double kFloatTolerance = 1e-10;
constexpr double kFixedTolerance = 1e-10;
constexpr double kConvergence = 1 - 1e-10;
// Matching patches: centres closer than this (normalised units; rounding is about 1e-15) and normals
// within 1e-9.
constexpr double kMatchDistance = 1e-9;

enum class Visibility { Float, Fixed31 };

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string temp_path(const std::string& name) {
  static int counter = 0;
  return testing::TempDir() + "invariance_" + std::to_string(getpid()) + "_" + std::to_string(counter++) + "_" + name;
}

// Files this process wrote, removed when it ends.
struct TempFiles {
  std::vector<std::string> paths;
  ~TempFiles() {
    for (const std::string& p : paths) std::remove(p.c_str());
  }
};

std::string write_temp(const std::string& name, const std::string& text) {
  static TempFiles files;
  const std::string path = temp_path(name);
  std::ofstream(path) << text;
  files.paths.push_back(path);
  return path;
}

const std::string kConcave = "/usr/share/assimp/models/OBJ/concave_polygon.obj";

// The open, concave polygon of Assimp's test models (one 66-gon, triangulated on import), tilted in
// the Cornell Box.
std::string mesh_composition() {
  return write_temp("mesh.json", R"({"schema": "rc2000sim.composition/1", "room": "cornell-box", "meshes": [
    {"file": ")" + kConcave + R"(", "rotate": {"axis": [1, 0.3, 0.2], "degrees": 50},
     "fit_into": {"min": [120, 180, 250], "max": [420, 420, 450]},
     "material": {"reflectance": [0.3, 0.4, 0.7]}}]})");
}

// A scene as its source (what `run --scene` reads) and as text to transform.
struct Source {
  std::string file;  // "" = the embedded Cornell Box
  SceneText text;
};

// two-rooms.scene's panel stands on the patch-centre lattice: some segments between patch centres
// pass exactly through its apex or its top edges (2 at level 0, 10 at level 1, 78 at level 2, found
// in exact rational arithmetic by tests/reference/grazing_segments.py), where only rounding decides
// whether they are blocked, so a rotation or a mirror changes those answers (up to 12% on a patch at
// level 1). Moved by (0.0137, 0.0071, 0) the panel is off that lattice (no such segment at levels 0
// to 2) and still stands between the rooms, two-sided as before.
SceneText nudged_panel(SceneText text) {
  for (test::TextSurface& s : text.surfaces) {
    if (s.name.rfind("panel", 0) != 0) continue;
    for (Vec3& v : s.vertices) v += Vec3(0.0137, 0.0071, 0);
  }
  return text;
}

Source source_of(const std::string& scene) {
  if (scene == "CornellBox") return {"", SceneText::of(cornell_box())};
  if (scene == "TwoRoomsNudged") {
    const SceneText text = nudged_panel(SceneText::parse(read_file(std::string(RC_SOURCE_DIR) + "/scenes/examples/two-rooms.scene")));
    return {write_temp("nudged.scene", text.text()), text};
  }
  if (scene == "Mesh") {
    const std::string file = mesh_composition();
    return {file, SceneText::of(load_composition(file).scene)};
  }
  const std::string file = std::string(RC_SOURCE_DIR) + "/scenes/examples/" +
                           (scene == "TwoRooms" ? "two-rooms.scene" : "tilted-plate.scene");
  return {file, SceneText::parse(read_file(file))};
}

// Transforms of the whole scene, by name. Mirror planes and rotation axes are off every axis.
Affine affine_of(const std::string& transform) {
  if (transform == "RotateA") return test::rotation({1, 2, 3}, 37);
  if (transform == "RotateB") return test::rotation({-0.6, 0.2, 0.77}, 211);
  if (transform == "Rotate30AboutVertical") return test::rotation({0, 1, 0}, 30);
  if (transform == "Translate") return test::translation({1234.5, -678.25, 42.125});
  if (transform == "Scale") return test::scaling(0.037);
  if (transform == "Mirror") return test::mirror({1, -2, 0.5});
  if (transform == "Everything") {
    return test::translation({-3.5, 17, 0.25})
        .after(test::scaling(11.3).after(test::mirror({0.3, 1, -0.2}).after(test::rotation({2, -1, 1}, 77))));
  }
  return {};
}

SceneText transformed(const SceneText& text, const std::string& transform) {
  if (transform == "Reorder") return text.reordered(20230);
  if (transform == "TwoSided") {
    const SceneText other = text.two_sided_count() > 0 ? text.two_sided_by_hand() : text.two_sided_declared();
    EXPECT_NE(other.text(), text.text()) << "the scene has no two-sided surface to write either way";
    return other;
  }
  SceneText out = text.transformed(affine_of(transform));
  return transform == "Everything" ? out.reordered(7) : out;
}

struct Solved {
  Scene scene;
  SolverResult result;
};

Solved solve(const std::string& file, int patch_levels, FormFactorKind kind, Visibility visibility) {
  SceneOptions o;
  o.file = file;
  o.patch_levels = patch_levels;
  Solved s{prepare_scene(o).scene, {}};
  std::unique_ptr<VisibilityBackend> backend;
  if (visibility == Visibility::Float) {
    backend = std::make_unique<FloatVisibility>();
  } else {
    backend = std::make_unique<FixedPointVisibility>(31);
  }
  SolverOptions options;
  options.form_factor = kind;
  options.convergence = kConvergence;
  s.result = ProgressiveRadiosity(s.scene, *backend, options).run();
  EXPECT_TRUE(s.result.converged);
  return s;
}

// For each patch of `a`, the patch of `b` at its centre mapped through `t` (from a's file coordinates
// to b's) with its normal mapped; every patch of b is matched once.
std::vector<int> match_patches(const Scene& a, const Scene& b, const Affine& t) {
  std::vector<int> match(a.patches.size(), -1);
  std::vector<char> used(b.patches.size(), 0);
  for (std::size_t i = 0; i < a.patches.size(); ++i) {
    const Patch& p = a.patches[i];
    const Vec3 file_point = p.centre / a.normalisation.scale + a.normalisation.offset;
    const Vec3 centre = b.normalisation.apply(t.apply(file_point));
    const Vec3 normal = t.normal(p.normal);
    double best = kMatchDistance;
    for (std::size_t j = 0; j < b.patches.size(); ++j) {
      const double d = glm::length(b.patches[j].centre - centre);
      if (d < best && glm::dot(b.patches[j].normal, normal) > 1 - 1e-9) best = d, match[i] = static_cast<int>(j);
    }
    if (match[i] < 0) {
      ADD_FAILURE() << "patch " << i << " of the original has no patch of the transformed scene at its place";
      continue;
    }
    EXPECT_FALSE(used[match[i]]) << "two patches of the original match patch " << match[i];
    used[match[i]] = 1;
  }
  EXPECT_EQ(a.patches.size(), b.patches.size());
  return match;
}

struct Difference {
  double largest = 0;  // relative, per patch and band
  int patch = -1;
};

Difference compare(const Solved& a, const Solved& b, const std::vector<int>& match) {
  Difference d;
  for (std::size_t i = 0; i < match.size(); ++i) {
    if (match[i] < 0) continue;
    for (std::size_t band = 0; band < kBands; ++band) {
      const double x = a.result.radiosity[i][band], y = b.result.radiosity[match[i]][band];
      const double scale = std::max(std::fabs(x), std::fabs(y));
      const double relative = scale > 0 ? std::fabs(x - y) / scale : 0.0;
      if (!(relative <= d.largest)) d.largest = relative, d.patch = static_cast<int>(i);
    }
  }
  return d;
}

struct Case {
  std::string scene;
  int patch_levels;
  std::string transform;
  Visibility visibility;
  FormFactorKind kind;
};

class Invariance : public testing::TestWithParam<Case> {};

std::string case_name(const testing::TestParamInfo<Case>& info);

void PrintTo(const Case& c, std::ostream* os) { *os << case_name({c, 0}); }

TEST_P(Invariance, SameRadiosityPerPatch) {
  const Case& c = GetParam();
  if (c.scene == "Mesh" && !std::ifstream(kConcave)) GTEST_SKIP() << kConcave << " missing (Debian package assimp-testmodels)";
  const Source source = source_of(c.scene);
  const std::string file = write_temp(c.transform + ".scene", transformed(source.text, c.transform).text());
  const Solved original = solve(source.file, c.patch_levels, c.kind, c.visibility);
  const Solved moved = solve(file, c.patch_levels, c.kind, c.visibility);
  EXPECT_EQ(original.scene.sheets.shared_sheets(), moved.scene.sheets.shared_sheets());
  EXPECT_EQ(original.scene.sheets.faces_in_shared_sheets(), moved.scene.sheets.faces_in_shared_sheets());
  const std::vector<int> match = match_patches(original.scene, moved.scene, affine_of(c.transform));
  const Difference d = compare(original, moved, match);
  const double tolerance = c.visibility == Visibility::Float ? kFloatTolerance : kFixedTolerance;
  std::printf("%s: %zu patches, largest relative difference %.3g (patch %d); steps %d / %d, blocked segments %llu / %llu\n",
              c.transform.c_str(), original.scene.patches.size(), d.largest, d.patch, original.result.steps,
              moved.result.steps, static_cast<unsigned long long>(original.result.blocked_segments),
              static_cast<unsigned long long>(moved.result.blocked_segments));
  EXPECT_LE(d.largest, tolerance) << "at patch " << d.patch;
  EXPECT_EQ(original.result.blocked_segments, moved.result.blocked_segments) << "a segment's answer changed";
  if (c.transform == "Identity") {  // the text written for a scene is the scene, exactly
    EXPECT_EQ(d.largest, 0.0);
    EXPECT_EQ(original.result.steps, moved.result.steps);
  }
}

std::vector<Case> cases() {
  std::vector<Case> out;
  const std::vector<std::pair<std::string, int>> scenes = {
      {"CornellBox", 1}, {"TwoRoomsNudged", 1}, {"TiltedPlate", 1}, {"Mesh", 0}};
  const std::vector<std::string> transforms = {"RotateA", "RotateB", "Translate", "Scale", "Mirror", "Reorder", "Everything"};
  for (const Visibility v : {Visibility::Float, Visibility::Fixed31}) {
    for (const FormFactorKind k : {FormFactorKind::PointToPoint, FormFactorKind::Disc, FormFactorKind::Analytic}) {
      for (const auto& [scene, levels] : scenes) {
        for (const std::string& t : transforms) out.push_back({scene, levels, t, v, k});
        if (scene != "CornellBox" && scene != "Mesh") out.push_back({scene, levels, "TwoSided", v, k});
      }
      // Issue 23: the example rotated 30 degrees about the vertical differed by 19%, 46% and 97% at
      // patch levels 0, 1 and 2. Level 0 is the example itself: it has 2 segments through the
      // panel's apex, which this rotation happens to decide as the original does (a rotation about
      // another axis, or a mirror, does not: up to 12% on a patch); so the panel is also moved off
      // the lattice (nudged_panel) and rotated at levels 0 to 2.
      out.push_back({"TwoRooms", 0, "Rotate30AboutVertical", v, k});
      for (int levels : {0, 1, 2}) out.push_back({"TwoRoomsNudged", levels, "Rotate30AboutVertical", v, k});
    }
  }
  for (const auto& [scene, levels] : scenes) out.push_back({scene, levels, "Identity", Visibility::Float, FormFactorKind::Analytic});
  return out;
}

std::string case_name(const testing::TestParamInfo<Case>& info) {
  const Case& c = info.param;
  const std::string kind = c.kind == FormFactorKind::PointToPoint ? "Point" : c.kind == FormFactorKind::Disc ? "Disc" : "Analytic";
  return c.scene + "_Level" + std::to_string(c.patch_levels) + "_" + c.transform + "_" +
         (c.visibility == Visibility::Float ? "Float" : "Fixed31") + "_" + kind;
}

INSTANTIATE_TEST_SUITE_P(Transforms, Invariance, testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace rc
