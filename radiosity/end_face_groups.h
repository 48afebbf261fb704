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

  // Sets skip[s] to `value` for the segments ending on face f.
  void mark(std::size_t f, std::vector<std::uint8_t>& skip, std::uint8_t value) const {
    for (std::size_t k = begin(f); k < end(f); ++k) skip[segments_[k]] = value;
  }

 private:
  std::vector<std::size_t> first_, segments_;
};

}  // namespace rc
