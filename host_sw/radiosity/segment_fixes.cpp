#include "host_sw/radiosity/segment_fixes.h"
#include "host_sw/radiosity/segment_fix_names.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "pipeline/fixed_mt.h"
#include "pipeline/reference_mt.h"

namespace rc {

std::string describe(const SegmentFixOptions& f) {
  std::string name;
  if (f.offset_lsb != 0) name = "offset " + std::to_string(f.offset_lsb) + " LSB";
  if (f.neighbour_rings != 0) name += (name.empty() ? "" : " + ") + std::string("neighbours (ring ") + std::to_string(f.neighbour_rings) + ")";
  if (f.coordinate_bits != 0)
    name += (name.empty() ? "" : " + ") + std::to_string(f.coordinate_bits) + "-bit coordinates (" + std::to_string(f.bits - f.coordinate_bits) + " guard bits)";
  if (f.t_guard != 0) name += (name.empty() ? "" : " + ") + std::string("t guard band ") + std::to_string(f.t_guard) + " LSB";
  return name;
}

std::string coordinate_bits_problem(int bits, int coordinate_bits) {
  if (coordinate_bits == 0 || coordinate_bits < bits) return "";
  return "must be below --bits (" + std::to_string(bits) + "): the lanes compute at --bits on coordinates of fewer bits, got " +
         std::to_string(coordinate_bits);
}

std::vector<std::vector<int>> vertex_neighbours(const std::vector<Triangle>& faces, int rings) {
  std::map<std::array<double, 3>, std::vector<int>> at_vertex;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (const Vec3& v : {faces[f].v0, faces[f].v1, faces[f].v2}) at_vertex[{v.x, v.y, v.z}].push_back(static_cast<int>(f));
  }
  std::vector<std::vector<int>> one(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (const Vec3& v : {faces[f].v0, faces[f].v1, faces[f].v2}) {
      for (int g : at_vertex[{v.x, v.y, v.z}]) {
        if (g != static_cast<int>(f)) one[f].push_back(g);
      }
    }
    std::sort(one[f].begin(), one[f].end());
    one[f].erase(std::unique(one[f].begin(), one[f].end()), one[f].end());
  }
  if (rings <= 1) return one;
  std::vector<std::vector<int>> two(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::vector<int>& n = two[f];
    n = one[f];
    for (int g : one[f]) n.insert(n.end(), one[static_cast<std::size_t>(g)].begin(), one[static_cast<std::size_t>(g)].end());
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
    n.erase(std::remove(n.begin(), n.end(), static_cast<int>(f)), n.end());
  }
  return two;
}

namespace {
Vec3 on_grid(const Vec3& p, int bits) {
  const auto down = [bits](double x) { return std::ldexp(std::floor(std::ldexp(x, bits)), -bits); };
  return {down(p.x), down(p.y), down(p.z)};
}
}  // namespace

SegmentFixer::SegmentFixer(const std::vector<Triangle>& faces, const FaceSheets& sheets, SegmentFixOptions options)
    : faces_(faces), sheets_(sheets), options_(options) {
  if (options_.coordinate_bits != 0 && (options_.bits == 0 || options_.coordinate_bits < 7 || options_.coordinate_bits >= options_.bits)) {
    throw std::invalid_argument("coordinate bits must be 7 or more and below the pipeline's width (" + std::to_string(options_.bits) +
                                " bits), got " + std::to_string(options_.coordinate_bits));
  }
  if (options_.offset_lsb < 0) throw std::invalid_argument("segment offset must be >= 0 LSBs, got " + std::to_string(options_.offset_lsb));
  if (options_.neighbour_rings < 0 || options_.neighbour_rings > 2) {
    throw std::invalid_argument("neighbour rings must be 0, 1 or 2, got " + std::to_string(options_.neighbour_rings));
  }
  if (options_.bits != 0 && (options_.bits < 7 || options_.bits > 31)) {
    throw std::invalid_argument("segment fixes need a width of 7..31 fractional bits, got " + std::to_string(options_.bits));
  }
  if (options_.t_guard != 0 && options_.bits == 0) {
    throw std::invalid_argument("a t guard band counts LSBs of the fixed-point pipeline's t; double precision has none");
  }
  pipeline::validate_t_guard(options_.t_guard);
  if (options_.offset_lsb != 0 && options_.bits == 0) {
    throw std::invalid_argument("a segment offset counts LSBs of a fixed-point width; double precision has none");
  }
  normals_.reserve(faces_.size());
  for (const Triangle& t : faces) {  // the faces' own normals, before any rounding
    const Vec3 c = t.cross();
    normals_.push_back(glm::length(c) > 0 ? glm::normalize(c) : Vec3(0.0));
  }
  if (options_.neighbour_rings > 0) neighbours_ = vertex_neighbours(faces_, options_.neighbour_rings);
  if (options_.coordinate_bits != 0) {
    for (Triangle& t : faces_) t = {on_grid(t.v0, options_.coordinate_bits), on_grid(t.v1, options_.coordinate_bits), on_grid(t.v2, options_.coordinate_bits)};
  }
}

Vec3 SegmentFixer::moved(const Vec3& p, int face) const {
  const int grid = options_.coordinate_bits != 0 ? options_.coordinate_bits : options_.bits;
  Vec3 q = p;
  if (options_.offset_lsb != 0 && face >= 0 && face < static_cast<int>(faces_.size())) {
    const double lsb = std::ldexp(1.0, -grid);
    const double top = 1.0 - lsb;
    q += normals_[static_cast<std::size_t>(face)] * (options_.offset_lsb * lsb);
    q = {std::clamp(q.x, 0.0, top), std::clamp(q.y, 0.0, top), std::clamp(q.z, 0.0, top)};
  }
  return options_.coordinate_bits != 0 ? on_grid(q, options_.coordinate_bits) : q;
}

void SegmentFixer::adjust(SegmentBatch& batch) const {
  if (options_.offset_lsb == 0 && options_.coordinate_bits == 0) return;
  batch.start = moved(batch.start, batch.source_face);
  for (std::size_t s = 0; s < batch.ends.size(); ++s) batch.ends[s] = moved(batch.ends[s], batch.end_faces[s]);
}

bool SegmentFixer::is_neighbour(int face, int of) const {
  if (of < 0 || of >= static_cast<int>(neighbours_.size())) return false;
  const std::vector<int>& n = neighbours_[static_cast<std::size_t>(of)];
  return std::binary_search(n.begin(), n.end(), face);
}

bool SegmentFixer::excluded(int face, int source_face, int end_face) const {
  return sheets_.same(face, source_face) || sheets_.same(face, end_face) || is_neighbour(face, source_face) ||
         is_neighbour(face, end_face);
}

void SegmentFixer::recheck(const SegmentBatch& batch, std::vector<std::uint8_t>& blocked) {
  if (options_.neighbour_rings == 0) return;
  const int bits = options_.bits;
  const bool fixed = bits != 0;
  const pipeline::FixedVec3 start = fixed ? pipeline::quantize_point(batch.start, bits) : pipeline::FixedVec3{};
  const auto hits = [&](int face, std::size_t s) {
    const Triangle& t = faces_[static_cast<std::size_t>(face)];
    if (!fixed) return pipeline::segment_hits_ref(t, batch.start, batch.ends[s]);
    return pipeline::segment_hits(pipeline::make_face_record(t, bits), start, pipeline::quantize_point(batch.ends[s], bits), bits,
                                  options_.t_guard);
  };
  const auto neighbours_of = [&](int face) -> const std::vector<int>& {
    static const std::vector<int> none;
    return face >= 0 && face < static_cast<int>(neighbours_.size()) ? neighbours_[static_cast<std::size_t>(face)] : none;
  };
  // Phase 1: a blocked segment none of whose neighbour faces hits it was blocked by another face,
  // which the rule keeps: its answer stands.
  std::vector<std::size_t> again;
  for (std::size_t s = 0; s < batch.size(); ++s) {
    if (!blocked[s] || !batch.is_needed(s)) continue;
    const int end_face = batch.end_faces[s];
    bool neighbour_hits = false;
    for (const int of : {batch.source_face, end_face}) {
      for (int f : neighbours_of(of)) {
        if (neighbour_hits) break;
        if (sheets_.same(f, batch.source_face) || sheets_.same(f, end_face)) continue;  // the backend never tested it
        ++tests_;
        neighbour_hits = hits(f, s);
      }
    }
    if (neighbour_hits) again.push_back(s);
  }
  if (again.empty()) return;
  // Phase 2: those segments against every face outside their own sheets and neighbours.
  const std::size_t n = again.size();
  std::vector<std::uint8_t> rest(n, 0), hit(n);
  std::vector<std::int64_t> x(n), y(n), z(n);
  if (fixed) {
    for (std::size_t k = 0; k < n; ++k) {
      const pipeline::FixedVec3 e = pipeline::quantize_point(batch.ends[again[k]], bits);
      x[k] = e.x, y[k] = e.y, z[k] = e.z;
    }
  }
  for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
    if (sheets_.same(f, batch.source_face) || is_neighbour(f, batch.source_face)) continue;
    tests_ += n;
    if (fixed) {
      std::fill(hit.begin(), hit.end(), std::uint8_t(0));
      pipeline::occlude_face(pipeline::make_face_record(faces_[static_cast<std::size_t>(f)], bits), start, x.data(), y.data(),
                             z.data(), n, bits, hit.data(), rest.data(), options_.t_guard);
    } else {
      for (std::size_t k = 0; k < n; ++k) hit[k] = !rest[k] && hits(f, again[k]);
    }
    for (std::size_t k = 0; k < n; ++k) {
      const int end_face = batch.end_faces[again[k]];
      if (hit[k] && !sheets_.same(f, end_face) && !is_neighbour(f, end_face)) rest[k] = 1;
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!rest[k]) ++cleared_;
    blocked[again[k]] = rest[k];
  }
}

void FixedSegmentsVisibility::load_triangles(const std::vector<Triangle>& faces) {
  fixer_ = std::make_unique<SegmentFixer>(faces, sheets(), options_);
  inner_.load_faces(fixer_->faces(), sheets());
}

void FixedSegmentsVisibility::submit(const SegmentBatch& batch) {
  batch_ = batch;
  fixer_->adjust(batch_);
  inner_.submit(batch_);
}

void FixedSegmentsVisibility::collect(std::vector<std::uint8_t>& blocked) {
  inner_.collect(blocked);
  fixer_->recheck(batch_, blocked);
}

}  // namespace rc
