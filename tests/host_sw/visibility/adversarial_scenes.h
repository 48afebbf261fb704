// Adversarial workloads on the 2^-bits lattice, where quantisation is exact and the pipeline sees
// the configuration itself: segments exactly through edges and vertices of tiles, segments lying
// in a tiled plane, a second tiling one LSB above it (nearly coplanar faces), start points on
// other faces' planes (t = 0), end points on edges, and degenerate faces.
#pragma once

#include <cstdint>

#include "tests/host_sw/visibility/fast_test_support.h"

namespace rc::test {

// One tiling of an axis-aligned plane: quads of `tile` grid units in [lo, hi)^2, two triangles
// each, on the plane where axis `normal` has lattice coordinate `level`.
struct Tiling {
  int normal;          // 0, 1, 2: x, y or z
  std::int64_t level;  // lattice coordinate of the plane
  int first_face;      // index of its first face in the workload
  int count = 0;
};

class AdversarialBuilder {
 public:
  // At the narrowest widths small tiles never register a hit (det and t truncate to almost
  // nothing), so tiles are larger there.
  explicit AdversarialBuilder(int bits, std::uint64_t seed)
      : bits_(bits), unit_(std::int64_t{1} << (bits - 5)), tile_(bits < 11 ? 12 : 4), rng_(seed) {}

  Workload build() {
    bottom_ = tile(2, 4 * unit_);
    middle_ = tile(2, 16 * unit_);
    above_ = tile(2, 16 * unit_ + 1);  // one LSB above the middle: nearly coplanar faces
    top_ = tile(2, 28 * unit_);
    wall_ = tile(0, 20 * unit_);
    // Degenerate faces: three collinear vertices, and two coincident ones.
    w_.faces.push_back({at(5, 5, 10), at(9, 9, 10), at(13, 13, 10)});
    w_.faces.push_back({at(6, 20, 12), at(6, 20, 12), at(10, 24, 12)});
    through_edges_and_vertices();
    in_the_plane();
    from_a_plane_to_everywhere();
    return w_;
  }

 private:
  Vec3 at(std::int64_t gx, std::int64_t gy, std::int64_t gz) const {
    return lattice_point(gx * unit_, gy * unit_, gz * unit_, bits_);
  }
  // A lattice point on a tiling: grid coordinates (a, b) in its plane, plus a small offset in
  // LSB (so that points land on edges, vertices, or just beside them).
  Vec3 on(const Tiling& t, std::int64_t a, std::int64_t b, std::int64_t da = 0, std::int64_t db = 0) const {
    std::int64_t c[3];
    c[t.normal] = t.level;
    c[(t.normal + 1) % 3] = a * unit_ + da;
    c[(t.normal + 2) % 3] = b * unit_ + db;
    return lattice_point(c[0], c[1], c[2], bits_);
  }
  // Which face of the tiling holds grid point (a, b) (any one, if it lies on an edge).
  int face_at(const Tiling& t, double a, double b) const {
    const int qa = static_cast<int>((a - kLo) / tile_), qb = static_cast<int>((b - kLo) / tile_);
    const int cells = (kHi - kLo) / tile_;  // per axis, as tile() lays them
    const int ca = qa < 0 ? 0 : (qa >= cells ? cells - 1 : qa), cb = qb < 0 ? 0 : (qb >= cells ? cells - 1 : qb);
    const double fa = a - kLo - ca * tile_, fb = b - kLo - cb * tile_;
    return t.first_face + 2 * (ca * cells + cb) + (fb > fa ? 1 : 0);
  }

  Tiling tile(int normal, std::int64_t level) {
    Tiling t{normal, level, static_cast<int>(w_.faces.size())};
    for (int a = kLo; a + tile_ <= kHi; a += tile_) {
      for (int b = kLo; b + tile_ <= kHi; b += tile_) {
        const Vec3 p00 = on(t, a, b), p10 = on(t, a + tile_, b), p11 = on(t, a + tile_, b + tile_),
                   p01 = on(t, a, b + tile_);
        w_.faces.push_back({p00, p10, p11});  // below the diagonal (b - lo < a - lo)
        w_.faces.push_back({p00, p11, p01});  // above it
        t.count += 2;
      }
    }
    return t;
  }

  // From the bottom tiling through an exact vertex or edge point of the middle tiling to the top
  // tiling: the middle plane lies exactly halfway, so end = 2 * crossing - start is a lattice
  // point.
  void through_edges_and_vertices() {
    for (int k = 0; k < 3; ++k) {
      SegmentBatch batch;
      const std::int64_t sa = rng_.integer(10, 22), sb = rng_.integer(10, 22);
      batch.start = on(bottom_, sa, sb);
      batch.source_face = face_at(bottom_, double(sa), double(sb));
      for (std::int64_t pa = kLo; pa <= kHi; ++pa) {
        for (std::int64_t pb = kLo; pb <= kHi; ++pb) {
          const std::int64_t ea = 2 * pa - sa, eb = 2 * pb - sb;
          if (ea < kLo || ea > kHi || eb < kLo || eb > kHi) continue;
          // Exactly through the crossing, and one LSB beside it.
          for (std::int64_t d : {0, 1, -1}) {
            batch.ends.push_back(on(top_, ea, eb, d, 0));
            batch.end_faces.push_back(face_at(top_, double(ea), double(eb)));
          }
        }
      }
      w_.batches.push_back(batch);
    }
  }

  // Segments lying in the middle plane (exact det = 0 for its faces, where truncation makes
  // phantom hits) and in the plane one LSB above it.
  void in_the_plane() {
    for (const Tiling* t : {&middle_, &above_}) {
      SegmentBatch batch;
      const std::int64_t sa = rng_.integer(kLo, kHi), sb = rng_.integer(kLo, kHi);
      // One draw per statement (argument order is unspecified; this is the order gcc used).
      const std::int64_t db = rng_.integer(0, 3), da = rng_.integer(0, 3);
      batch.start = on(*t, sa, sb, da, db);
      batch.source_face = face_at(*t, double(sa), double(sb));
      for (int i = 0; i < 600; ++i) {
        const std::int64_t ea = rng_.integer(kLo, kHi), eb = rng_.integer(kLo, kHi);
        const std::int64_t nb = rng_.integer(-1, 1), na = rng_.integer(-1, 1);
        batch.ends.push_back(on(*t, ea, eb, na, nb));
        batch.end_faces.push_back(face_at(*t, double(ea), double(eb)));
      }
      w_.batches.push_back(batch);
    }
  }

  // A start on each tiling (so t = 0 exactly for the faces of its own plane) towards points on
  // every tiling, on and beside edges and vertices.
  void from_a_plane_to_everywhere() {
    const Tiling* all[] = {&bottom_, &middle_, &above_, &top_, &wall_};
    for (const Tiling* from : all) {
      SegmentBatch batch;
      const std::int64_t sa = rng_.integer(kLo + 1, kHi - 1), sb = rng_.integer(kLo + 1, kHi - 1);
      batch.start = on(*from, sa, sb);
      batch.source_face = face_at(*from, double(sa), double(sb));
      for (const Tiling* to : all) {
        if (to == from) continue;
        for (int i = 0; i < 120; ++i) {
          // On a grid line (an edge) half the time, anywhere else otherwise.
          const std::int64_t ea = rng_.integer(kLo, kHi), eb = rng_.integer(kLo, kHi);
          const std::int64_t da = i % 2 ? 0 : rng_.integer(0, unit_ - 1);
          const std::int64_t db = i % 3 ? 0 : rng_.integer(0, unit_ - 1);
          batch.ends.push_back(on(*to, ea, eb, da, db));
          batch.end_faces.push_back(face_at(*to, double(ea), double(eb)));
        }
      }
      w_.batches.push_back(batch);
    }
  }

  static constexpr int kLo = 2, kHi = 30;  // grid units (32 across the cube)
  int bits_;
  std::int64_t unit_;  // LSB per grid unit
  int tile_;           // grid units per tile
  Rng rng_;
  Workload w_;
  Tiling bottom_{}, middle_{}, above_{}, top_{}, wall_{};
};

inline Workload adversarial_workload(int bits, std::uint64_t seed) {
  return AdversarialBuilder(bits, seed).build();
}

}  // namespace rc::test
