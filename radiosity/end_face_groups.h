// A batch's segments grouped by the face their end point lies on (a counting sort, linear in
// segments + faces), so a brute-force backend's own-face mask for face f costs only the segments
// that end on f. Shared by the fixed- and float-pipeline backends.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "radiosity/visibility.h"

namespace rc {

class EndFaceGroups {
 public:
  // Segments whose end face is outside [0, face_count) end on no face and are in no group.
  void group(const SegmentBatch& batch, std::size_t face_count);

  // The segments ending on face f, as [begin(f), end(f)) of segment(k).
  std::size_t begin(std::size_t f) const { return first_[f]; }
  std::size_t end(std::size_t f) const { return first_[f + 1]; }
  std::size_t segment(std::size_t k) const { return segments_[k]; }

  // Groups the batch, then calls occlude(f, skip) for every face f < face_count but the batch's source
  // face (every segment's own face), `skip` marking the segments that end on f (nullptr when none do):
  // the own-face rule of visibility.h. Returns the segment-face pairs tested.
  template <class Occlude>
  std::uint64_t occlude_each_face(const SegmentBatch& batch, std::size_t face_count, std::vector<std::uint8_t>& skip,
                                  Occlude&& occlude) {
    group(batch, face_count);
    skip.assign(batch.size(), 0);
    std::uint64_t tests = 0;
    for (std::size_t f = 0; f < face_count; ++f) {
      if (static_cast<int>(f) == batch.source_face) continue;
      // Mask the segments that end on this face, run the face, clear the mask again.
      mark(f, skip, 1);
      occlude(f, begin(f) != end(f) ? skip.data() : nullptr);
      mark(f, skip, 0);
      tests += batch.size() - (end(f) - begin(f));
    }
    return tests;
  }

 private:
  // Sets skip[s] to `value` for the segments ending on face f.
  void mark(std::size_t f, std::vector<std::uint8_t>& skip, std::uint8_t value) const {
    for (std::size_t k = begin(f); k < end(f); ++k) skip[segments_[k]] = value;
  }

  std::vector<std::size_t> first_, segments_;
};

}  // namespace rc
