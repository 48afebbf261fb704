// The branch-free sweep over every receiver (receiver_sweep.h) against the per-pair rule it
// replaced in ProgressiveRadiosity::shoot, kept here as the oracle: the same bits for every
// shooter-receiver pair of scenes with sheets, coincident centres, patches behind and in front.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <utility>

#include "host_sw/radiosity/radiosity.h"
#include "host_sw/radiosity/receiver_sweep.h"
#include "scenes/prepare.h"
#include "scenes/scene_builder.h"
#include "scenes/sheet_finder.h"
#include "scenes/subdivide.h"

namespace rc {
namespace {

// The solver's rule before the sweep (radiosity.cpp, exchange_geometry), pair by pair.
PairGeometry pair_rule(const Scene& scene, const Patch& shooter, const Patch& receiver) {
  if (scene.sheets.same(shooter.face, receiver.face)) return {};
  const PairGeometry g = pair_geometry(shooter.centre, shooter.normal, receiver.centre, receiver.normal);
  const double size_squared = std::max(shooter.area, receiver.area);
  if (g.distance_squared < kCoincidentDistance * kCoincidentDistance * size_squared) return {};
  return g;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Every pair of `scene`, every kind: geometry, exchange flag and (point, disc) form factor. Returns
// how many pairs exchange and how many there are.
std::pair<std::size_t, std::size_t> expect_sweep_is_the_pair_rule(const Scene& scene) {
  const PatchColumns columns(scene);
  ReceiverSweep sweep;
  std::size_t exchanging = 0, pairs = 0;
  for (FormFactorKind kind : {FormFactorKind::PointToPoint, FormFactorKind::Disc, FormFactorKind::Analytic}) {
    for (std::size_t s = 0; s < scene.patches.size(); ++s) {
      sweep_receivers(columns, static_cast<int>(s), kind, sweep);
      const Patch& shooter = scene.patches[s];
      for (std::size_t r = 0; r < scene.patches.size(); ++r) {
        SCOPED_TRACE(to_string(kind) + " shooter " + std::to_string(s) + " receiver " + std::to_string(r));
        if (r == s) {
          EXPECT_EQ(sweep.exchanges[r], 0);
          EXPECT_TRUE(same_bits(sweep.form_factor[r], 0.0));
          continue;
        }
        const PairGeometry g = pair_rule(scene, shooter, scene.patches[r]);
        EXPECT_TRUE(same_bits(sweep.cos_shooter[r], g.cos_shooter));
        EXPECT_TRUE(same_bits(sweep.cos_receiver[r], g.cos_receiver));
        EXPECT_TRUE(same_bits(sweep.distance_squared[r], g.distance_squared));
        EXPECT_EQ(sweep.exchanges[r] != 0, g.exchanges());
        const double expected = kind == FormFactorKind::Analytic ? 0.0 : form_factor(kind, g, shooter.area);
        EXPECT_TRUE(same_bits(sweep.form_factor[r], expected)) << sweep.form_factor[r] << " against " << expected;
        exchanging += g.exchanges();
        ++pairs;
      }
    }
  }
  return {exchanging, pairs};
}

// Not a vacuous comparison: some pairs exchange, some do not.
void expect_some_exchange(std::pair<std::size_t, std::size_t> counts) {
  EXPECT_GT(counts.first, 0u);
  EXPECT_LT(counts.first, counts.second);
}

TEST(ReceiverSweep, EveryPairBitIdenticalToThePairRule) {
  SceneOptions options;
  options.face_target = 70;
  options.face_levels = 0;
  options.patch_levels = 1;
  expect_some_exchange(expect_sweep_is_the_pair_rule(prepare_scene(options).scene));
}

// Two-sided surfaces (sheets of several faces: pairs on one sheet never exchange) and the box's
// faces made two-sided.
TEST(ReceiverSweep, SheetsOfSeveralFacesBitIdenticalToThePairRule) {
  SceneOptions options;
  options.face_target = 70;
  options.face_levels = 0;
  options.patch_levels = 0;
  Scene scene = prepare_scene(options).scene;
  scene.patches.clear();  // find_sheets reorders the faces
  add_back_faces(scene);
  find_sheets(scene);
  ASSERT_GT(scene.sheets.shared_sheets(), 0u);
  scene.patches = make_patches(scene.faces, 0);
  expect_some_exchange(expect_sweep_is_the_pair_rule(scene));
}

// Centres that coincide (closer than kCoincidentDistance x the larger size) or are equal.
TEST(ReceiverSweep, CoincidentCentresBitIdenticalToThePairRule) {
  std::pair<std::size_t, std::size_t> total{0, 0};
  for (double gap : {0.0, 1e-7, 1e-5, 0.5}) {
    Scene s;
    s.materials.push_back({"m", Spectrum::uniform(0.5), Spectrum::uniform(1)});
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0), up(0, 0, gap);
    s.faces = {{{a, b, c}, 0, 0}, {{a, c, d}, 0, 0}, {{a + up, c + up, b + up}, 0, 0}, {{a + up, d + up, c + up}, 0, 0}};
    s.patches = make_patches(s.faces, 1);
    SCOPED_TRACE(gap);
    const auto counts = expect_sweep_is_the_pair_rule(s);
    total.first += counts.first, total.second += counts.second;
  }
  expect_some_exchange(total);
}

}  // namespace
}  // namespace rc
