// Test helper: small random triangles in a cube of side `scale`, and a batch from face 0's centroid
// to the centroids of the other faces (as the solver sends patch centres). Deterministic per seed;
// shared by the brute-force backends' tests (fixed and float pipeline).
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "host_sw/radiosity/visibility.h"

namespace rc::test {

inline double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

struct RandomBatch {
  std::vector<Triangle> faces;
  SegmentBatch batch;
};

inline RandomBatch random_batch(std::size_t faces, std::size_t segments, std::uint64_t seed, double scale = 1.0) {
  std::mt19937_64 rng(seed);
  RandomBatch s;
  while (s.faces.size() < faces) {
    const Vec3 c = scale * Vec3{0.1 + 0.8 * uniform(rng), 0.1 + 0.8 * uniform(rng), 0.1 + 0.8 * uniform(rng)};
    const auto corner = [&] {
      return c + 0.2 * scale * Vec3{uniform(rng) - 0.5, uniform(rng) - 0.5, uniform(rng) - 0.5};
    };
    s.faces.push_back({corner(), corner(), corner()});
  }
  s.batch.source_face = 0;
  s.batch.start = s.faces[0].centroid();
  for (std::size_t i = 0; i < segments; ++i) {
    const int face = 1 + static_cast<int>(rng() % (faces - 1));
    s.batch.ends.push_back(s.faces[static_cast<std::size_t>(face)].centroid());
    s.batch.end_faces.push_back(face);
  }
  return s;
}

}  // namespace rc::test
