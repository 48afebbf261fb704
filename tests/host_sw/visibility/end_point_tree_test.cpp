// EndPointCatalogue keeps end points and their segments straight across batches,
// EndPointTree::query visits every end point a hit region may contain, and query_packet visits
// for each of its regions exactly what query visits for that region alone.
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <set>

#include "tests/host_sw/visibility/fast_test_support.h"
#include "host_sw/visibility/end_point_catalogue.h"
#include "host_sw/visibility/end_point_tree.h"
#include "pipeline/hit_region.h"

namespace rc {
namespace {

SegmentBatch batch_of(const std::vector<Vec3>& ends, const std::vector<int>& faces) {
  SegmentBatch b;
  b.start = {0.5, 0.5, 0.5};
  b.ends = ends;
  b.end_faces = faces;
  return b;
}

std::vector<std::uint32_t> segments_at(const EndPointCatalogue& c, std::uint32_t id) {
  std::vector<std::uint32_t> s;
  for (std::uint32_t k = c.first_segment(id); k != EndPointCatalogue::kNone; k = c.next_segment(k)) s.push_back(k);
  return s;
}

TEST(EndPointCatalogue, KeepsIdsAndLinksSegmentsToTheirPoints) {
  const Vec3 a{0.1, 0.2, 0.3}, b{0.4, 0.5, 0.6}, c{0.7, 0.8, 0.9};
  EndPointCatalogue cat;
  EXPECT_TRUE(cat.assign(batch_of({a, b, a}, {1, 2, 3}), 15));  // new points
  ASSERT_EQ(cat.size(), 2u);
  EXPECT_EQ(segments_at(cat, 0), (std::vector<std::uint32_t>{0, 2}));
  EXPECT_EQ(segments_at(cat, 1), (std::vector<std::uint32_t>{1}));
  EXPECT_EQ(cat.position(1), pipeline::quantize_point(b, 15));
  EXPECT_FALSE(cat.assign(batch_of({b}, {2}), 15));  // nothing new: a keeps its id, no segments
  EXPECT_TRUE(segments_at(cat, 0).empty());
  EXPECT_EQ(segments_at(cat, 1), (std::vector<std::uint32_t>{0}));
  EXPECT_TRUE(cat.assign(batch_of({c, a}, {5, 6}), 15));
  ASSERT_EQ(cat.size(), 3u);
  EXPECT_EQ(segments_at(cat, 2), (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(segments_at(cat, 0), (std::vector<std::uint32_t>{1}));
}

TEST(EndPointCatalogue, StartsAfreshWhenMostPointsAreStale) {
  test::Rng rng(1);
  std::vector<Vec3> many;
  for (int i = 0; i < 20000; ++i) many.push_back(rng.point());
  EndPointCatalogue cat;
  cat.assign(batch_of(many, std::vector<int>(many.size(), 0)), 20);
  EXPECT_EQ(cat.size(), many.size());
  cat.assign(batch_of({many[7]}, {0}), 20);  // 20000 points for a batch of 1: forget them
  EXPECT_EQ(cat.size(), 1u);
  EXPECT_EQ(segments_at(cat, 0), (std::vector<std::uint32_t>{0}));
}

// Every end point inside a random face's exact hit conditions is visited, unless all of its
// segments end on that very face.
TEST(EndPointTree, QueryVisitsEveryPointTheRegionMayHold) {
  for (int bits : {7, 15, 31}) {
    const test::Workload w = test::random_workload(80, 4, 3000, 0.5, 21 + bits);
    EndPointCatalogue cat;
    EndPointTree tree;
    for (const SegmentBatch& batch : w.batches) {
      if (cat.assign(batch, bits)) tree.build(cat);
      tree.mark_batch(cat, batch.end_faces.data());
      const pipeline::FixedVec3 start = pipeline::quantize_point(batch.start, bits);
      std::size_t inside = 0;
      for (int f = 0; f < static_cast<int>(w.faces.size()); ++f) {
        const pipeline::FaceRecord face = pipeline::make_face_record(w.faces[f], bits);
        const pipeline::HitRegion region(face, start, bits);
        const pipeline::ExactHitConditions exact = pipeline::exact_hit_conditions(face, start, bits);
        std::set<std::uint32_t> visited;
        tree.query(region, f, [&](std::uint32_t id) {
          EXPECT_TRUE(visited.insert(id).second) << "twice";
          return true;
        });
        for (std::uint32_t id = 0; id < cat.size(); ++id) {
          bool asks = false;  // some segment of this batch ends here and not on face f
          for (std::uint32_t s : segments_at(cat, id)) asks |= batch.end_faces[s] != f;
          if (!asks || !exact.allows(cat.position(id) - start)) continue;
          ++inside;
          EXPECT_EQ(visited.count(id), 1u) << "point " << id << ", face " << f << ", " << bits << " bits";
        }
      }
      EXPECT_GT(inside, 100u) << bits;
    }
  }
}

// Packets of up to kPacket random faces (some asking about the source's own face, some regions
// stopped after a few points, some slots left out) visit, region by region, the very points
// query() visits, each once; a stopped region gets exactly its first points.
TEST(EndPointTree, PacketQueryVisitsWhatEachRegionAloneVisits) {
  test::Rng rng(5);
  std::size_t compared = 0, stopped = 0;
  for (int bits : {7, 11, 15, 23, 31}) {
    const test::Workload w = test::random_workload(60, 3, 2000, 0.4, 50 + bits);
    EndPointCatalogue cat;
    EndPointTree tree;
    for (const SegmentBatch& batch : w.batches) {
      if (cat.assign(batch, bits)) tree.build(cat);
      tree.mark_batch(cat, batch.end_faces.data());
      const pipeline::FixedVec3 start = pipeline::quantize_point(batch.start, bits);
      constexpr int kPacket = EndPointTree::kPacket;
      for (int first = 0; first < static_cast<int>(w.faces.size()); first += kPacket) {
        std::optional<pipeline::HitRegion> regions[kPacket];
        const pipeline::HitRegion* region_of[kPacket] = {};
        int faces[kPacket] = {};
        std::size_t limit[kPacket] = {};
        unsigned members = 0;
        for (int k = 0; k < kPacket && first + k < static_cast<int>(w.faces.size()); ++k) {
          if (rng.uniform() < 0.15) continue;  // a slot the packet leaves out
          faces[k] = first + k;
          regions[k].emplace(pipeline::make_face_record(w.faces[first + k], bits), start, bits);
          region_of[k] = &*regions[k];
          limit[k] = rng.uniform() < 0.3 ? 1 + static_cast<std::size_t>(rng.uniform() * 4) : SIZE_MAX;
          members |= 1u << k;
        }
        std::map<int, std::vector<std::uint32_t>> visited;
        tree.query_packet(region_of, faces, members, [&](int k, std::uint32_t id) {
          EXPECT_TRUE(members >> k & 1) << "a region outside the packet";
          visited[k].push_back(id);
          return visited[k].size() < limit[k];
        });
        for (int k = 0; k < kPacket; ++k) {
          if (!(members >> k & 1)) continue;
          std::set<std::uint32_t> alone;
          tree.query(*region_of[k], faces[k], [&](std::uint32_t id) { return alone.insert(id), true; });
          const std::vector<std::uint32_t>& got = visited[k];
          const std::set<std::uint32_t> got_set(got.begin(), got.end());
          EXPECT_EQ(got_set.size(), got.size()) << "a point twice, face " << faces[k];
          if (limit[k] < alone.size()) {
            ++stopped;
            EXPECT_EQ(got.size(), limit[k]) << "face " << faces[k];
            for (std::uint32_t id : got) EXPECT_EQ(alone.count(id), 1u) << "face " << faces[k];
          } else {
            EXPECT_EQ(got_set, alone) << "face " << faces[k] << ", " << bits << " bits";
            compared += alone.size();
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 1000u);
  EXPECT_GT(stopped, 20u);
}

// mark_batch against its definition, through query(): in batches where many segments share an
// end point, with end faces drawn from a few (no face among them), and where some catalogue points
// have no segment, query(region, f) visits every point inside the exact conditions that some
// segment not ending on f asks about, and no point without segments in the batch.
TEST(EndPointTree, MarksWhichSubtreesAskAboutWhichFace) {
  test::Rng rng(9);
  std::size_t checked = 0, skipped_own = 0;
  for (int bits : {7, 15, 31}) {
    test::Workload w = test::random_workload(40, 6, 1500, 0.5, 70 + bits);
    EndPointCatalogue cat;
    EndPointTree tree;
    for (SegmentBatch& batch : w.batches) {
      const std::size_t keep = batch.size() / (1 + static_cast<std::size_t>(rng.integer(0, 3)));
      for (std::size_t s = 0; s < batch.size(); ++s) {  // shared end points, few end faces
        if (s > 0 && rng.uniform() < 0.3) batch.ends[s] = batch.ends[static_cast<std::size_t>(rng.integer(0, s - 1))];
        batch.end_faces[s] = static_cast<int>(rng.integer(-1, 3));
      }
      batch.ends.resize(keep);  // later batches leave catalogue points without segments
      batch.end_faces.resize(keep);
      if (cat.assign(batch, bits)) tree.build(cat);
      // Every instruction-set variant of the marking (kernel_isa.h) must mark the same.
      for (const pipeline::KernelIsa isa : pipeline::supported_kernel_isas()) {
      tree.mark_batch(cat, batch.end_faces.data(), isa);
      const pipeline::FixedVec3 start = pipeline::quantize_point(batch.start, bits);
      for (int f = 0; f < static_cast<int>(w.faces.size()); ++f) {
        const pipeline::FaceRecord face = pipeline::make_face_record(w.faces[f], bits);
        const pipeline::HitRegion region(face, start, bits);
        const pipeline::ExactHitConditions exact = pipeline::exact_hit_conditions(face, start, bits);
        const int asked_face = f % 4;  // the end faces' ids
        std::set<std::uint32_t> visited;
        tree.query(region, asked_face, [&](std::uint32_t id) {
          EXPECT_FALSE(segments_at(cat, id).empty()) << "point " << id << " has no segment";
          visited.insert(id);
          return true;
        });
        for (std::uint32_t id = 0; id < cat.size(); ++id) {
          bool asks = false, has = false;
          for (std::uint32_t s : segments_at(cat, id)) has = true, asks |= batch.end_faces[s] != asked_face;
          if (!has || !exact.allows(cat.position(id) - start)) continue;
          if (!asks) {
            skipped_own += visited.count(id) == 0;
            continue;
          }
          ++checked;
          EXPECT_EQ(visited.count(id), 1u) << "point " << id << ", face " << asked_face << ", " << bits << " bits, "
                                           << pipeline::name(isa);
        }
      }
      }
    }
  }
  EXPECT_GT(checked, 2000u);
  EXPECT_GT(skipped_own, 10u);  // subtrees all on the asked face were skipped
}

}  // namespace
}  // namespace rc
