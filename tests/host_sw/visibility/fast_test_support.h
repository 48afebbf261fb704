// Scenes, batches and a brute-force comparison shared by the fast-visibility tests.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "host_sw/visibility/fast_visibility.h"
#include "host_sw/visibility/fixed_visibility.h"
#include "pipeline/fixed_mt.h"

namespace rc::test {

// Reproducible on every platform: mt19937_64 is fully specified; no std:: distributions.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {  // [lo, hi]
    return lo + static_cast<std::int64_t>(engine_() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  std::size_t index(std::size_t n) { return static_cast<std::size_t>(engine_() % n); }
  Vec3 point() { return {uniform(), uniform(), uniform()}; }

 private:
  std::mt19937_64 engine_;
};

// Faces plus batches to ask about them.
struct Workload {
  std::vector<Triangle> faces;
  std::vector<SegmentBatch> batches;
};

// The point k * 2^-bits per axis: exactly representable at `bits`, so adversarial configurations
// survive quantisation.
inline Vec3 lattice_point(std::int64_t x, std::int64_t y, std::int64_t z, int bits) {
  const double scale = 1.0 / static_cast<double>(std::int64_t{1} << bits);
  return {static_cast<double>(x) * scale, static_cast<double>(y) * scale, static_cast<double>(z) * scale};
}

// The blocked flags of the brute-force backend for every batch.
inline std::vector<std::vector<std::uint8_t>> brute_force_flags(const Workload& w, int bits) {
  FixedPointVisibility brute(bits);
  brute.load_faces(w.faces);
  std::vector<std::vector<std::uint8_t>> all;
  for (const SegmentBatch& b : w.batches) {
    brute.submit(b);
    all.emplace_back();
    brute.collect(all.back());
  }
  return all;
}

// Runs the fast backend on every batch and checks every flag against the brute force. Returns
// the number of blocked segments (so callers can check that the workload tests something) and
// how many faces took the dense path.
struct Comparison {
  std::size_t blocked = 0;       // segments the brute force reports blocked
  std::uint64_t dense_faces = 0; // faces the fast backend ran over the whole batch
};

inline Comparison compare_with_brute_force(const Workload& w, int bits, int threads, const std::string& what) {
  const std::vector<std::vector<std::uint8_t>> expected = brute_force_flags(w, bits);
  FastFixedVisibility fast(bits, threads);
  fast.load_faces(w.faces);
  std::size_t blocked = 0, differing = 0;
  std::vector<std::uint8_t> flags;
  for (std::size_t b = 0; b < w.batches.size(); ++b) {
    fast.submit(w.batches[b]);
    fast.collect(flags);
    EXPECT_EQ(flags.size(), expected[b].size());
    for (std::size_t s = 0; s < flags.size() && s < expected[b].size(); ++s) {
      differing += flags[s] != expected[b][s];
      blocked += expected[b][s];
    }
  }
  EXPECT_EQ(differing, 0u) << what << ", " << bits << " bits, " << threads << " threads";
  EXPECT_LE(fast.tests_performed(), fast.brute_force_tests());
  return {blocked, fast.dense_faces()};
}

inline std::size_t expect_same_as_brute_force(const Workload& w, int bits, int threads,
                                              const std::string& what) {
  return compare_with_brute_force(w, bits, threads, what).blocked;
}

// Random small triangles through the unit cube, and batches from a point on one face to points
// on others (centroids and random interior points, as a solver sends patch centres).
inline Workload random_workload(std::size_t faces, std::size_t batches, std::size_t segments,
                                double size, std::uint64_t seed) {
  Rng rng(seed);
  Workload w;
  while (w.faces.size() < faces) {
    const double lo = 0.01 + size / 2, hi = 0.99 - size / 2;  // corners stay inside [0, 1)^3
    const Vec3 c{rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
    const auto corner = [&] {
      return c + size * Vec3{rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5};
    };
    w.faces.push_back({corner(), corner(), corner()});
  }
  const auto point_on = [&](std::size_t f) {
    const double a = rng.uniform(), b = rng.uniform() * (1 - a);
    const Triangle& t = w.faces[f];
    return t.v0 + a * (t.v1 - t.v0) + b * (t.v2 - t.v0);
  };
  for (std::size_t k = 0; k < batches; ++k) {
    SegmentBatch batch;
    batch.source_face = static_cast<int>(rng.index(faces));
    batch.start = point_on(static_cast<std::size_t>(batch.source_face));
    for (std::size_t i = 0; i < segments; ++i) {
      const std::size_t f = rng.index(faces);
      batch.ends.push_back(i % 2 ? w.faces[f].centroid() : point_on(f));
      batch.end_faces.push_back(static_cast<int>(f));
    }
    w.batches.push_back(batch);
  }
  return w;
}

}  // namespace rc::test
