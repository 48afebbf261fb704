// FastFixedVisibility answers exactly what FixedPointVisibility (the brute force) answers: the
// same blocked flag on every segment, at every width, for every thread count.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "tests/host_sw/visibility/adversarial_scenes.h"
#include "tests/host_sw/visibility/fast_test_support.h"

namespace rc {
namespace {

using test::Workload;

TEST(FastVisibility, MatchesBruteForceOnRandomScenes) {
  for (int bits = pipeline::kMinFracBits; bits <= pipeline::kMaxFracBits; ++bits) {
    for (std::uint64_t seed : {1, 2, 3}) {
      // Small faces in a crowd (many near misses), then large ones (many hits).
      const Workload crowd = test::random_workload(300, 3, 400, 0.12, seed);
      const Workload large = test::random_workload(40, 3, 400, 0.6, seed + 10);
      EXPECT_GT(test::expect_same_as_brute_force(crowd, bits, 2, "crowd"), 20u);
      EXPECT_GT(test::expect_same_as_brute_force(large, bits, 2, "large faces"), 20u);
    }
  }
}

TEST(FastVisibility, MatchesBruteForceOnAdversarialLatticeScenes) {
  for (int bits = pipeline::kMinFracBits; bits <= pipeline::kMaxFracBits; ++bits) {
    for (std::uint64_t seed : {1, 2}) {
      const Workload w = test::adversarial_workload(bits, 100 * seed + bits);
      EXPECT_GT(test::expect_same_as_brute_force(w, bits, 1 + static_cast<int>(seed), "adversarial"), 100u)
          << bits;
    }
  }
}

// Faces whose hit region holds much of the batch (a large face close to the start, or any face
// at a narrow width) run the streaming kernel over every segment; mixed with culled faces in one
// batch, the flags are still the brute force's.
TEST(FastVisibility, DenseFacesMatchBruteForce) {
  std::uint64_t dense = 0, culled_runs = 0;
  for (int bits : {7, 9, 12, 15, 31}) {
    Workload w = test::random_workload(200, 3, 500, 0.1, 40 + bits);
    // A large face just in front of each start: its shadow covers much of the scene.
    const auto inside = [](const Vec3& v) { return glm::clamp(v, Vec3(0.001), Vec3(0.998)); };
    for (SegmentBatch& b : w.batches) {
      const Vec3 c = b.start + Vec3{0.02, 0.01, 0.015};
      w.faces.push_back({inside(c + Vec3{-0.3, -0.3, 0.0}), inside(c + Vec3{0.3, -0.25, 0.02}),
                         inside(c + Vec3{0.0, 0.3, 0.01})});
    }
    const test::Comparison c = test::compare_with_brute_force(w, bits, 2, "dense");
    dense += c.dense_faces;
    culled_runs += c.blocked;
  }
  EXPECT_GT(dense, 10u) << "no face took the dense path";
  EXPECT_GT(culled_runs, 100u);
}

// Every instruction-set variant the CPU runs (pipeline/kernel_isa.h: the face loop with the tree
// walk, the tree's marking and the streaming kernel) gives the brute force's flags, and all of
// them run the same tests on the same dense faces.
TEST(FastVisibility, EveryInstructionSetGivesTheSameFlagsAndCounts) {
  for (int bits : {7, 15, 31}) {
    Workload w = test::random_workload(200, 3, 500, 0.1, 60 + bits);
    const auto inside = [](const Vec3& v) { return glm::clamp(v, Vec3(0.001), Vec3(0.998)); };
    for (SegmentBatch& b : w.batches) {  // a dense face per batch, as in DenseFacesMatchBruteForce
      const Vec3 c = b.start + Vec3{0.02, 0.01, 0.015};
      w.faces.push_back({inside(c + Vec3{-0.3, -0.3, 0.0}), inside(c + Vec3{0.3, -0.25, 0.02}),
                         inside(c + Vec3{0.0, 0.3, 0.01})});
    }
    const std::vector<std::vector<std::uint8_t>> expected = test::brute_force_flags(w, bits);
    std::uint64_t tests = 0, dense = 0;
    for (const pipeline::KernelIsa isa : pipeline::supported_kernel_isas()) {
      FastFixedVisibility fast(bits, 2, isa);
      EXPECT_EQ(fast.isa(), isa);
      fast.load_faces(w.faces);
      std::vector<std::uint8_t> flags;
      for (std::size_t b = 0; b < w.batches.size(); ++b) {
        fast.submit(w.batches[b]);
        fast.collect(flags);
        EXPECT_EQ(flags, expected[b]) << bits << " bits, " << pipeline::name(isa) << ", batch " << b;
      }
      if (isa == pipeline::KernelIsa::Baseline) {
        tests = fast.tests_performed();
        dense = fast.dense_faces();
        EXPECT_GT(dense, 0u) << bits << " bits: no face took the dense path";
      }
      EXPECT_EQ(fast.tests_performed(), tests) << bits << " bits, " << pipeline::name(isa);
      EXPECT_EQ(fast.dense_faces(), dense) << bits << " bits, " << pipeline::name(isa);
    }
  }
  EXPECT_EQ(FastFixedVisibility(15, 1).isa(), pipeline::best_kernel_isa());
}

// Every thread count gives the same flags and runs the same tests.
TEST(FastVisibility, ThreadCountDoesNotChangeFlagsOrCounts) {
  const Workload w = test::random_workload(400, 4, 600, 0.15, 5);
  std::vector<std::vector<std::uint8_t>> reference;
  std::uint64_t reference_tests = 0;
  for (int threads : {1, 2, 3}) {
    FastFixedVisibility fast(15, threads);
    EXPECT_EQ(fast.threads(), threads);
    fast.load_faces(w.faces);
    std::vector<std::vector<std::uint8_t>> flags(w.batches.size());
    for (std::size_t b = 0; b < w.batches.size(); ++b) {
      fast.submit(w.batches[b]);
      fast.collect(flags[b]);
    }
    if (threads == 1) {
      reference = flags;
      reference_tests = fast.tests_performed();
    } else {
      EXPECT_EQ(flags, reference) << threads << " threads";
      EXPECT_EQ(fast.tests_performed(), reference_tests) << threads << " threads";
    }
  }
}

TEST(FastVisibility, BruteForceCountIsWhatFixedPointVisibilityCounts) {
  Workload w = test::random_workload(60, 3, 200, 0.2, 9);
  // End faces outside the face list and a batch without a source face count as they do there.
  w.batches[1].end_faces[0] = -1;
  w.batches[1].end_faces[1] = 60;
  w.batches[2].source_face = -1;
  FixedPointVisibility brute(15);
  FastFixedVisibility fast(15, 2);
  brute.load_faces(w.faces);
  fast.load_faces(w.faces);
  for (const SegmentBatch& b : w.batches) {
    std::vector<std::uint8_t> expected, flags;
    brute.submit(b);
    brute.collect(expected);
    fast.submit(b);
    fast.collect(flags);
    EXPECT_EQ(flags, expected);
    EXPECT_EQ(fast.brute_force_tests(), brute.tests_performed());
  }
  EXPECT_LT(fast.tests_performed(), fast.brute_force_tests() / 4) << "culling should skip most pairs";
}

// The same end point several times in one batch, labelled with different end faces: each
// segment skips only its own end face (the brute force's own-face rule), and they share the test.
TEST(FastVisibility, SharedEndPointsKeepTheirOwnFaces) {
  const std::vector<Triangle> faces = {
      {{0.1, 0.1, 0.1}, {0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}},  // 0: source, z = 0.1
      {{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.1, 0.9, 0.5}},  // 1: blocker, z = 0.5
      {{0.1, 0.1, 0.9}, {0.9, 0.1, 0.9}, {0.1, 0.9, 0.9}},  // 2: receiver, z = 0.9
  };
  for (int threads : {1, 2}) {
    FastFixedVisibility v(15, threads);
    v.load_faces(faces);
    SegmentBatch batch;
    batch.source_face = 0;
    batch.start = {0.3, 0.3, 0.1};
    batch.ends = {{0.3, 0.3, 0.9}, {0.3, 0.3, 0.9}, {0.3, 0.3, 0.9}};
    batch.end_faces = {2, 1, 0};
    v.submit(batch);
    std::vector<std::uint8_t> blocked;
    v.collect(blocked);
    EXPECT_EQ(blocked, (std::vector<std::uint8_t>{1, 0, 1}));
    batch.source_face = 1;  // now the blocker is everyone's source face
    v.submit(batch);
    v.collect(blocked);
    EXPECT_EQ(blocked, (std::vector<std::uint8_t>{0, 0, 0}));
  }
}

TEST(FastVisibility, ValidatesWidthsThreadsAndBatches) {
  EXPECT_THROW(FastFixedVisibility(6, 1), std::invalid_argument);
  EXPECT_THROW(FastFixedVisibility(32, 1), std::invalid_argument);
  EXPECT_THROW(FastFixedVisibility(15, -1), std::invalid_argument);
  FastFixedVisibility v(31, 0);
  EXPECT_GE(v.threads(), 1);
  EXPECT_EQ(v.frac_bits(), 31);
  EXPECT_EQ(v.name(), "fast");
  SegmentBatch batch;
  batch.start = {0.3, 0.3, 0.1};
  batch.ends = {{0.3, 0.3, 0.9}};
  EXPECT_THROW(v.submit(batch), std::invalid_argument);  // no end faces
  batch.end_faces = {0};
  batch.ends = {{0.3, 0.3, 1.0}};
  EXPECT_THROW(v.submit(batch), std::out_of_range);
  batch.ends = {{0.3, 0.3, 0.9}};
  batch.start = {-0.1, 0.3, 0.1};
  EXPECT_THROW(v.submit(batch), std::out_of_range);
}

// A batch that throws half way (a point outside the unit cube) leaves no trace: later batches,
// including ones that reuse the points stored before the bad one, still match the brute force.
TEST(FastVisibility, RecoversFromARejectedBatch) {
  Workload w = test::random_workload(200, 3, 300, 0.15, 11);
  SegmentBatch bad = w.batches[0];
  for (auto& e : bad.ends) e = 0.5 * e + Vec3{0.25, 0.25, 0.25};  // all new points...
  bad.ends[150] = {0.5, 1.5, 0.5};                             // ...and one outside
  FastFixedVisibility fast(15, 2);
  FixedPointVisibility brute(15);
  fast.load_faces(w.faces);
  brute.load_faces(w.faces);
  EXPECT_THROW(fast.submit(bad), std::out_of_range);
  bad.ends[150] = {0.5, 0.5, 0.5};
  w.batches.push_back(bad);
  for (const SegmentBatch& b : w.batches) {
    std::vector<std::uint8_t> expected, flags;
    brute.submit(b);
    brute.collect(expected);
    fast.submit(b);
    fast.collect(flags);
    EXPECT_EQ(flags, expected);
  }
}

TEST(FastVisibility, EmptyBatchesFacesAndRepeatedCalls) {
  FastFixedVisibility v(15, 2);
  std::vector<std::uint8_t> blocked{1, 2, 3};
  v.collect(blocked);  // nothing submitted yet
  EXPECT_TRUE(blocked.empty());
  v.load_faces({});
  SegmentBatch batch;
  batch.start = {0.5, 0.5, 0.5};
  batch.ends = {{0.1, 0.2, 0.3}};
  batch.end_faces = {0};
  v.submit(batch);
  v.collect(blocked);
  EXPECT_EQ(blocked, (std::vector<std::uint8_t>{0}));
  EXPECT_EQ(v.tests_performed(), 0u);

  const Workload w = test::random_workload(100, 2, 300, 0.3, 12);
  const auto expected = test::brute_force_flags(w, 15);
  v.load_faces(w.faces);
  v.submit(w.batches[0]);
  v.submit(w.batches[1]);  // submitting again without collecting: the last batch counts
  v.collect(blocked);
  EXPECT_EQ(blocked, expected[1]);
  v.collect(blocked);  // collecting twice returns the same flags
  EXPECT_EQ(blocked, expected[1]);
  SegmentBatch empty;
  empty.start = {0.5, 0.5, 0.5};
  v.submit(empty);
  v.collect(blocked);
  EXPECT_TRUE(blocked.empty());
}

}  // namespace
}  // namespace rc
