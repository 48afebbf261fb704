#include "host_sw/visibility/fast_visibility.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "pipeline/fixed_mt.h"
#include "pipeline/hit_region.h"
#include "pipeline/mt_core.h"

namespace rc {

namespace {

// A face whose hit region holds more than 1/kDenseShare of the batch's segments runs the
// streaming kernel (16 or 8 lanes) over all of them: one pass of the kernel over a batch costs
// about what collecting and testing that many candidates does (measured with bench_visibility:
// 1/8, 1/32, 1/64 and 1/128 gave 0.30, 0.42, 0.48 and 0.51 of Embree's speed at 7 bits, where
// regions are large, and the same speed at 15 and 31 bits).
constexpr std::size_t kDenseShare = 128;

// Fewer candidates than this run the scalar kernel one by one: gathering them for the vectorised
// kernel (32-bit lanes up to 15 bits, 64-bit above) costs more than it saves.
constexpr std::size_t kVectorCandidates = 16;

// End points in 32-bit banks where the kernel's arithmetic is 32-bit (pipeline::occlude_kernel32).
bool narrow_banks(int bits) { return pipeline::core_fits<std::int32_t>(bits); }

// Copies the coordinates of n points into three banks of integer type Bank.
template <class Bank, class Position>
void fill_banks(std::size_t n, std::vector<Bank>& x, std::vector<Bank>& y, std::vector<Bank>& z, Position&& position) {
  x.resize(n);
  y.resize(n);
  z.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const pipeline::FixedVec3& e = position(i);
    x[i] = static_cast<Bank>(e.x);
    y[i] = static_cast<Bank>(e.y);
    z[i] = static_cast<Bank>(e.z);
  }
}

}  // namespace

// test_faces is compiled for AVX-512 and AVX2 as well as the baseline, and the backend's variant
// (pipeline::best_kernel_isa() unless given) is picked when it is built: the end-point tree's
// eight-box test (always inlined into it) then runs on one vector register. Integer and
// rounding-safe code only, so every variant gives the same answers (docs/fast-visibility.md,
// "Floating point").
struct FastFixedVisibility::Variants {
  static std::uint64_t baseline(const FastFixedVisibility& v, std::size_t first, std::size_t last, WorkerOutput& out) {
    return v.test_faces(first, last, out);
  }
#if RC_HAVE_ISA_VARIANTS
  RC_TARGET_X86_64_V3 static std::uint64_t v3(const FastFixedVisibility& v, std::size_t first, std::size_t last,
                                              WorkerOutput& out) {
    return v.test_faces(first, last, out);
  }
  RC_TARGET_X86_64_V4 static std::uint64_t v4(const FastFixedVisibility& v, std::size_t first, std::size_t last,
                                              WorkerOutput& out) {
    return v.test_faces(first, last, out);
  }
#else
  static constexpr TestFaces v3 = baseline, v4 = baseline;
#endif
};

FastFixedVisibility::FastFixedVisibility(pipeline::FracBits frac_bits, int threads, int t_guard)
    : FastFixedVisibility(frac_bits, threads, pipeline::best_kernel_isa(), t_guard) {}

FastFixedVisibility::FastFixedVisibility(pipeline::FracBits frac_bits, int threads, pipeline::KernelIsa isa, int t_guard)
    : bits_(frac_bits),
      t_guard_((pipeline::validate_t_guard(t_guard), t_guard)),
      isa_(isa),
      test_faces_(pipeline::pick_variant<TestFaces>(isa, Variants::baseline, Variants::v3, Variants::v4)),
      occlude_(narrow_banks(frac_bits) ? nullptr : pipeline::occlude_kernel(isa, frac_bits, false)),
      occlude32_(narrow_banks(frac_bits) ? pipeline::occlude_kernel32(isa, frac_bits, false) : nullptr),
      pool_(threads) {
  outputs_.resize(static_cast<std::size_t>(pool_.size()));
}

FastFixedVisibility::~FastFixedVisibility() { pool_.finish(); }

void FastFixedVisibility::load_triangles(const std::vector<Triangle>& faces) {
  finish_batch();
  points_.clear();
  faces_.clear();
  faces_.reserve(faces.size());
  face_terms_.reserve(faces.size());
  face_terms_.clear();
  for (const Triangle& t : faces) {
    faces_.push_back(pipeline::make_face_record(t, bits_));
    face_terms_.push_back(pipeline::face_error_terms(faces_.back(), bits_));
  }
}

// FixedPointVisibility's count: for every face outside the source's sheet, every segment not ending
// on its sheet. From the segments grouped by end sheet (submit's counting sort): a pass over the
// faces, not the segments.
std::uint64_t FastFixedVisibility::count_brute_force_tests(int source_face) const {
  const FaceSheets& sheets = this->sheets();
  const int faces = static_cast<int>(faces_.size());
  // Faces of sheet [first, end) inside [0, faces).
  const auto faces_of = [&](int f) -> std::uint64_t {
    const int first = std::max(sheets.first(f), 0), end = std::min(sheets.end(f), faces);
    return end > first ? static_cast<std::uint64_t>(end - first) : 0;
  };
  // Segments ending on no face or on a face this backend does not hold are on no held sheet
  // (faces_of gives 0 for them), and sheet_begin_ leaves them out.
  std::uint64_t ending_on_tested_faces = 0;
  for (int sheet = 0; sheet < faces; ++sheet) {
    const auto ending = static_cast<std::uint64_t>(sheet_begin_[sheet + 1] - sheet_begin_[sheet]);
    if (ending != 0 && sheet != source_sheet_) ending_on_tested_faces += ending * faces_of(sheet);
  }
  const std::uint64_t tested_faces = faces_.size() - faces_of(source_face);
  return tested_faces * segments_ - ending_on_tested_faces;
}

void FastFixedVisibility::submit(const SegmentBatch& batch) {
  finish_batch();
  const std::size_t n = batch.size();
  batch.check();
  start_ = pipeline::quantize_point(batch.start, bits_);
  if (points_.assign(batch, bits_)) tree_.build(points_);
  // Segments are matched with faces by sheet (the own-surface rule): the end point tree notes each
  // node's one end sheet, named by its first face, exactly as it would note one end face.
  if (sheets().one_sided()) {  // every face its own sheet
    end_sheets_.assign(batch.end_faces.begin(), batch.end_faces.end());
  } else {
    end_sheets_.resize(n);
    for (std::size_t s = 0; s < n; ++s) end_sheets_[s] = sheets().first(batch.end_faces[s]);
  }
  // The segments ending on each sheet, grouped by sheet (a counting sort): a dense face sets
  // its own sheet's segments back after the unmasked kernel.
  // Segments ending on no face (-1) or on a face this backend does not hold are on no face's sheet.
  const auto faces = static_cast<int>(faces_.size());
  const auto held = [faces](int sheet) { return sheet >= 0 && sheet < faces; };
  // A solver's segments come in runs ending on one sheet (a face's patches are consecutive), so
  // both passes go run by run: counting one segment at a time would make every increment wait
  // for the previous one's store to the same counter.
  const auto run_end = [&](std::size_t first) {
    std::size_t end = first + 1;
    while (end < n && end_sheets_[end] == end_sheets_[first]) ++end;
    return end;
  };
  sheet_begin_.assign(faces_.size() + 1, 0);
  for (std::size_t s = 0, end = 0; s < n; s = end) {
    end = run_end(s);
    if (held(end_sheets_[s])) sheet_begin_[static_cast<std::size_t>(end_sheets_[s]) + 1] += static_cast<std::uint32_t>(end - s);
  }
  for (std::size_t f = 0; f < faces_.size(); ++f) sheet_begin_[f + 1] += sheet_begin_[f];
  sheet_segments_.resize(sheet_begin_.back());
  sheet_next_.assign(sheet_begin_.begin(), sheet_begin_.end() - 1);
  for (std::size_t s = 0, end = 0; s < n; s = end) {
    end = run_end(s);
    if (!held(end_sheets_[s])) continue;
    std::uint32_t& next = sheet_next_[static_cast<std::size_t>(end_sheets_[s])];
    std::uint32_t at = next;  // a local: the stores below could alias the counter
    for (std::size_t k = s; k < end; ++k) sheet_segments_[at++] = static_cast<std::uint32_t>(k);
    next = at;
  }
  tree_.mark_batch(points_, end_sheets_.data(), isa_);
  source_sheet_ = sheets().first(batch.source_face);
  segments_ = n;
  const auto end_of = [&](std::size_t s) -> const pipeline::FixedVec3& {
    return points_.position(points_.point_of(static_cast<std::uint32_t>(s)));
  };
  if (occlude32_ != nullptr) {
    fill_banks(n, end32_x_, end32_y_, end32_z_, end_of);
  } else {
    fill_banks(n, end_x_, end_y_, end_z_, end_of);
  }
  brute_force_tests_ += count_brute_force_tests(batch.source_face);
  for (WorkerOutput& out : outputs_) {
    out.blocked.assign(n, 0);
    out.tests = out.dense_faces = out.dense_tests = 0;
  }
  next_face_.value.store(0, std::memory_order_relaxed);
  pending_ = true;
  pool_.start([this](int worker) { run_worker(worker); });
}

void FastFixedVisibility::collect(std::vector<std::uint8_t>& blocked) {
  finish_batch();
  blocked = blocked_;
}

// Waits for the workers and ORs their flags together.
void FastFixedVisibility::finish_batch() {
  if (!pending_) return;
  pool_.finish();
  pending_ = false;
  // One worker's flags are the answer as they are (swapped in: submit assigns them afresh).
  if (outputs_.size() == 1) {
    blocked_.swap(outputs_.front().blocked);
  } else {
    blocked_.assign(segments_, 0);
    for (const WorkerOutput& out : outputs_) {
      for (std::size_t s = 0; s < segments_; ++s) blocked_[s] |= out.blocked[s];
    }
  }
  for (const WorkerOutput& out : outputs_) {
    tests_ += out.tests;
    dense_faces_ += out.dense_faces;
    dense_tests_ += out.dense_tests;
  }
}

void FastFixedVisibility::run_worker(int worker) {
  WorkerOutput& out = outputs_[static_cast<std::size_t>(worker)];
  for (;;) {
    const std::size_t first = next_face_.value.fetch_add(kFacesPerClaim, std::memory_order_relaxed);
    if (first >= faces_.size()) return;
    out.tests += test_faces_(*this, first, std::min(first + kFacesPerClaim, faces_.size()), out);
  }
}

// Faces [first, last) (at most kFacesPerClaim) against the end points their hit regions may
// contain, in the pipeline's arithmetic. Returns the number of tests run. Always inlined into
// Variants' functions, one per instruction set.
[[gnu::always_inline]] inline std::uint64_t FastFixedVisibility::test_faces(std::size_t first, std::size_t last,
                                                                           WorkerOutput& out) const {
  std::optional<pipeline::HitRegion> regions[kFacesPerClaim];
  const pipeline::HitRegion* region_of[kFacesPerClaim] = {};
  int sheet_of[kFacesPerClaim] = {};
  unsigned members = 0;
  for (std::size_t f = first; f < last; ++f) {
    const std::size_t k = f - first;
    out.candidates[k].clear();
    out.dense[k] = false;
    sheet_of[k] = sheets().first(static_cast<int>(f));
    if (sheet_of[k] == source_sheet_) continue;  // every segment's own surface
    regions[k].emplace(faces_[f], face_terms_[f], start_, bits_);
    region_of[k] = &*regions[k];
    members |= 1u << k;
  }
  // Candidates: end points inside a face's region with a segment that does not end on its sheet.
  const std::size_t dense = segments_ / kDenseShare;
  tree_.query_packet(region_of, sheet_of, members, [&](int k, std::uint32_t point) {
    const int sheet = sheet_of[k];
    std::uint32_t s = points_.first_segment(point);
    while (s != EndPointCatalogue::kNone && end_sheets_[s] == sheet) s = points_.next_segment(s);
    if (s == EndPointCatalogue::kNone) return true;
    const double* p = points_.coords(point);
    if (!region_of[k]->may_hit(p[0], p[1], p[2])) return true;
    out.candidates[k].push_back(point);
    out.dense[k] = out.candidates[k].size() > dense;
    return !out.dense[k];
  });
  std::uint64_t tests = 0;
  for (unsigned m = members; m; m &= m - 1) {
    const int k = __builtin_ctz(m);
    const int face = static_cast<int>(first) + k;
    tests += out.dense[k] ? test_every_segment(face, out) : test_candidates(face, sheet_of[k], out.candidates[k], out);
  }
  return tests;
}

// One face against its candidate end points (few enough: not a dense face).
std::uint64_t FastFixedVisibility::test_candidates(int face, int sheet, const std::vector<std::uint32_t>& candidates,
                                                   WorkerOutput& out) const {
  const pipeline::FaceRecord& record = faces_[static_cast<std::size_t>(face)];
  const std::size_t n = candidates.size();
  if (n < kVectorCandidates) {
    if (t_guard_ == 0) {
      for (const std::uint32_t point : candidates) {
        if (pipeline::pipeline_hits(record.v0, record.edge1, record.edge2, start_, points_.position(point), bits_)) {
          block_segments_ending_at(point, sheet, out);
        }
      }
    } else {
      const auto guard = std::int64_t(t_guard_);
      for (const std::uint32_t point : candidates) {
        if (pipeline::pipeline_hits(record.v0, record.edge1, record.edge2, start_, points_.position(point), bits_, guard)) {
          block_segments_ending_at(point, sheet, out);
        }
      }
    }
    return n;
  }
  // The candidates' end points side by side, through the vectorised streaming kernel.
  out.candidate_hit.assign(n, 0);
  const auto candidate = [&](std::size_t i) -> const pipeline::FixedVec3& { return points_.position(candidates[i]); };
  if (occlude32_ != nullptr) {
    fill_banks(n, out.candidate32_x, out.candidate32_y, out.candidate32_z, candidate);
    occlude32_(record, start_, out.candidate32_x.data(), out.candidate32_y.data(), out.candidate32_z.data(), n, bits_,
               out.candidate_hit.data(), nullptr, t_guard_);
  } else {
    fill_banks(n, out.candidate_x, out.candidate_y, out.candidate_z, candidate);
    occlude_(record, start_, out.candidate_x.data(), out.candidate_y.data(), out.candidate_z.data(), n, bits_,
             out.candidate_hit.data(), nullptr, t_guard_);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (out.candidate_hit[i]) block_segments_ending_at(candidates[i], sheet, out);
  }
  return n;
}

// A hit at `point` blocks every segment of the batch ending there, except those ending on the
// face's own sheet.
void FastFixedVisibility::block_segments_ending_at(std::uint32_t point, int sheet, WorkerOutput& out) const {
  for (std::uint32_t s = points_.first_segment(point); s != EndPointCatalogue::kNone; s = points_.next_segment(s)) {
    if (end_sheets_[s] != sheet) out.blocked[s] = 1;
  }
}

// The brute force's way for one face: the streaming kernel over every segment of the batch. The
// segments ending on the face's sheet are not its business: their flags are saved before and put
// back after, which leaves them exactly as the masked kernel would (it ORs nothing into them).
std::uint64_t FastFixedVisibility::test_every_segment(int face, WorkerOutput& out) const {
  ++out.dense_faces;
  const auto sheet = static_cast<std::size_t>(sheets().first(face));
  const std::uint32_t* own = sheet_segments_.data() + sheet_begin_[sheet];
  const std::size_t owned = sheet_begin_[sheet + 1] - sheet_begin_[sheet];
  out.saved.resize(owned);
  for (std::size_t k = 0; k < owned; ++k) out.saved[k] = out.blocked[own[k]];
  const pipeline::FaceRecord& record = faces_[static_cast<std::size_t>(face)];
  if (occlude32_ != nullptr) {
    occlude32_(record, start_, end32_x_.data(), end32_y_.data(), end32_z_.data(), segments_, bits_, out.blocked.data(),
               nullptr, t_guard_);
  } else {
    occlude_(record, start_, end_x_.data(), end_y_.data(), end_z_.data(), segments_, bits_, out.blocked.data(), nullptr,
             t_guard_);
  }
  for (std::size_t k = 0; k < owned; ++k) out.blocked[own[k]] = out.saved[k];
  out.dense_tests += segments_ - owned;
  return segments_ - owned;
}

}  // namespace rc
