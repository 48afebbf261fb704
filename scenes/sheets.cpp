#include "scenes/sheets.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rc {

FaceSheets::FaceSheets(std::vector<int> first_of_face) {
  const int n = static_cast<int>(first_of_face.size());
  bool shared = false;
  for (int f = 0; f < n; ++f) {
    const int first = first_of_face[f];
    const bool starts = first == f;
    const bool continues = f > 0 && first == first_of_face[f - 1];
    if (!starts && !continues) {
      throw std::invalid_argument("face " + std::to_string(f) + " names face " + std::to_string(first) +
                                  " as its sheet's first face, but a sheet's faces must be contiguous and named by "
                                  "the first of them");
    }
    shared = shared || !starts;
  }
  if (!shared) return;  // every face its own sheet: the one-sided representation
  first_ = std::move(first_of_face);
  end_.assign(n, n);
  for (int f = n - 1; f >= 0; --f) {
    end_[f] = (f + 1 < n && first_[f + 1] == first_[f]) ? end_[f + 1] : f + 1;
  }
}

std::size_t FaceSheets::faces_in_shared_sheets() const {
  std::size_t count = 0;
  for (std::size_t f = 0; f < first_.size(); ++f) count += size_of(static_cast<int>(f)) > 1;
  return count;
}

std::size_t FaceSheets::shared_sheets() const {
  std::size_t count = 0;
  for (std::size_t f = 0; f < first_.size(); ++f) {
    count += first_[f] == static_cast<int>(f) && size_of(static_cast<int>(f)) > 1;
  }
  return count;
}

FaceSheets FaceSheets::restricted(int first, int count) const {
  if (one_sided()) return {};
  std::vector<int> local(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) local[i] = std::max(first_[first + i], first) - first;
  return FaceSheets(std::move(local));
}

}  // namespace rc
