// refine_to_count in O(n log n) gives exactly the faces, in exactly the order, of its definition
// (bisect the largest face, lowest index on ties, second half inserted after the first), which the
// quadratic list algorithm it replaced implements literally; that algorithm is kept here as the
// oracle.
#include <gtest/gtest.h>

#include <algorithm>

#include "scenes/cornell_box.h"
#include "scenes/scene_file.h"
#include "scenes/subdivide.h"
#include "tests/common/simple_scenes.h"

namespace rc {
namespace {

std::pair<Triangle, Triangle> bisect_longest_edge(const Triangle& t) {
  const Vec3 v[3] = {t.v0, t.v1, t.v2};
  int longest = 0;
  double best = -1;
  for (int e = 0; e < 3; ++e) {
    const double len = glm::length(v[(e + 1) % 3] - v[e]);
    if (len > best) best = len, longest = e;
  }
  const Vec3& a = v[longest];
  const Vec3& b = v[(longest + 1) % 3];
  const Vec3& c = v[(longest + 2) % 3];
  const Vec3 mid = 0.5 * (a + b);
  return {{a, mid, c}, {mid, b, c}};
}

// The definition, as the code before issue 15 ran it: O(n^2).
std::vector<Face> refine_by_list(const std::vector<Face>& faces, int target) {
  std::vector<Face> out = faces;
  while (static_cast<int>(out.size()) < target) {
    std::size_t largest = 0;
    for (std::size_t i = 1; i < out.size(); ++i) {
      if (out[i].tri.area() > out[largest].tri.area()) largest = i;
    }
    const auto [first, second] = bisect_longest_edge(out[largest].tri);
    const Face parent = out[largest];
    out[largest].tri = first;
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(largest) + 1, Face{second, parent.material, parent.surface});
  }
  return out;
}

void expect_identical(const std::vector<Face>& a, const std::vector<Face>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(a[i].tri.v0 == b[i].tri.v0 && a[i].tri.v1 == b[i].tri.v1 && a[i].tri.v2 == b[i].tri.v2 &&
                a[i].material == b[i].material && a[i].surface == b[i].surface)
        << what << ": face " << i << " differs";
  }
}

void expect_same_as_definition(const std::vector<Face>& faces, std::initializer_list<int> targets, const char* scene) {
  for (int target : targets) {
    expect_identical(refine_to_count(faces, target), refine_by_list(faces, target),
                     std::string(scene) + " refined to " + std::to_string(target));
  }
}

TEST(Refinement, HeapGivesTheDefinitionsFacesOnTheCornellBox) {
  expect_same_as_definition(cornell_box().faces, {38, 39, 70, 101, 1000, 4000}, "cornell box");
}

TEST(Refinement, HeapGivesTheDefinitionsFacesOnTheExampleScene) {
  const LoadedScene s = load_scene_file(std::string(RC_SOURCE_DIR) + "/scenes/examples/two-rooms.scene");
  expect_same_as_definition(s.scene.faces, {10, 11, 64, 333, 2500}, "two-rooms");
}

// Twelve faces of equal area: every choice is decided by the tie rule (lowest index first).
TEST(Refinement, HeapBreaksAreaTiesByPlaceAsTheDefinitionDoes) {
  expect_same_as_definition(test::furnace_box(1, 0.5, 0).faces, {12, 13, 24, 25, 48, 97, 1500}, "furnace");
}

TEST(Refinement, FiftyThousandFacesKeepEveryFaceAndTheArea) {
  const std::vector<Face> faces = cornell_box().faces;
  const std::vector<Face> refined = refine_to_count(faces, 50000);
  ASSERT_EQ(refined.size(), 50000u);
  double before = 0, after = 0, largest = 0, smallest_split = 1e300;
  for (const Face& f : faces) before += f.tri.area();
  for (const Face& f : refined) {
    after += f.tri.area();
    largest = std::max(largest, f.tri.area());
  }
  // Every piece of a split face is within a factor of 2 of the largest: only the largest is split.
  for (const Face& f : refined) {
    if (std::find_if(faces.begin(), faces.end(), [&](const Face& g) { return g.tri.v0 == f.tri.v0 && g.tri.v1 == f.tri.v1 && g.tri.v2 == f.tri.v2; }) == faces.end()) {
      smallest_split = std::min(smallest_split, f.tri.area());
    }
  }
  EXPECT_NEAR(after, before, 1e-9 * before);
  EXPECT_GE(smallest_split, 0.5 * largest * (1 - 1e-9));
}

}  // namespace
}  // namespace rc
