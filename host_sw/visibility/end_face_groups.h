// A batch's segments grouped by the face their end point lies on (a counting sort, linear in
// segments + faces), so a brute-force backend's own-surface mask for face f costs only the segments
// that end on f's sheet. Shared by the fixed- and float-pipeline backends.
#pragma once

#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "host_sw/radiosity/visibility.h"

namespace rc {

class EndFaceGroups {
 public:
  // Segments whose end face is outside [0, face_count) end on no face and are in no group.
  void group(const SegmentBatch& batch, std::size_t face_count);

  // The segments ending on face f, as [begin(f), end(f)) of segment(k).
  std::size_t begin(std::size_t f) const { return first_[f]; }
  std::size_t end(std::size_t f) const { return first_[f + 1]; }
  std::size_t segment(std::size_t k) const { return segments_[k]; }

  // Groups the batch, then calls occlude(f, skip) for every face f < face_count outside the batch's
  // source sheet (every segment's own surface), `skip` marking the segments that end on f's sheet
  // (nullptr when none do): the own-surface rule of visibility.h. A sheet's faces are contiguous, so
  // its segments are one run of groups. Returns the segment-face pairs tested.
  template <class Occlude>
  std::uint64_t occlude_each_face(const SegmentBatch& batch, std::size_t face_count, const FaceSheets& sheets,
                                  std::vector<std::uint8_t>& skip, Occlude&& occlude) {
    group(batch, face_count);
    skip.assign(batch.size(), 0);
    std::uint64_t tests = 0;
    for (std::size_t f = 0; f < face_count; ++f) {
      if (sheets.same(static_cast<int>(f), batch.source_face)) continue;
      // Mask the segments that end on this face's sheet, run the face, clear the mask again.
      const std::size_t first = sheet_begin(f, sheets), last = sheet_end(f, sheets, face_count);
      mark(first, last, skip, 1);
      occlude(f, first != last ? skip.data() : nullptr);
      mark(first, last, skip, 0);
      tests += batch.size() - (last - first);
    }
    return tests;
  }

 private:
  // The run of grouped segments [sheet_begin, sheet_end) ending on face f's sheet.
  std::size_t sheet_begin(std::size_t f, const FaceSheets& sheets) const {
    return begin(static_cast<std::size_t>(sheets.first(static_cast<int>(f))));
  }
  std::size_t sheet_end(std::size_t f, const FaceSheets& sheets, std::size_t face_count) const {
    return end(std::min(static_cast<std::size_t>(sheets.end(static_cast<int>(f))), face_count) - 1);
  }
  // Sets skip[s] to `value` for the grouped segments [first, last).
  void mark(std::size_t first, std::size_t last, std::vector<std::uint8_t>& skip, std::uint8_t value) const {
    for (std::size_t k = first; k < last; ++k) skip[segments_[k]] = value;
  }

  std::vector<std::size_t> first_, segments_;
};

}  // namespace rc
