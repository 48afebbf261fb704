// Sheets: which faces form one surface for the visibility rule and the solver (docs/scenes.md,
// "Two-sided surfaces"). A surface lit from both sides is written as faces back to back: coplanar,
// facing opposite ways, overlapping. Its faces are one sheet. A segment that ends on a sheet is never
// blocked by a face of that sheet (the end point lies inside each of them, where only rounding could
// decide), and patches of one sheet never exchange energy. A one-sided face is a sheet of its own,
// so one-sided scenes (the paper's Cornell Box) keep the paper's own-face rule exactly.
//
// The faces of a sheet are contiguous (find_sheets orders them so), and a sheet is named by its
// first face: the sheet of face f is the face range [first(f), end(f)). That is what lets the
// board's wrapper mask a sheet's rays as one contiguous range (docs/board.md, "Own-surface rule in hardware").
#pragma once

#include <cstddef>
#include <vector>

namespace rc {

class FaceSheets {
 public:
  // Every face a sheet of its own (also for any face count).
  FaceSheets() = default;
  // first_of_face[f]: the first face of f's sheet. Throws std::invalid_argument unless every sheet is
  // a contiguous run of faces named by its first face.
  explicit FaceSheets(std::vector<int> first_of_face);

  // True when every face is its own sheet.
  bool one_sided() const { return first_.empty(); }
  // A face outside the map (a batch's "no face", -1, or a face another card holds) is a sheet of
  // its own, so the own-surface rule never matches it with a face of the map.
  int first(int face) const { return inside(face) ? first_[face] : face; }
  // One past the last face of face's sheet.
  int end(int face) const { return inside(face) ? end_[face] : face + 1; }
  int size_of(int face) const { return end(face) - first(face); }
  bool same(int a, int b) const { return first(a) == first(b); }
  // Faces in sheets of more than one face.
  std::size_t faces_in_shared_sheets() const;
  // Sheets of more than one face.
  std::size_t shared_sheets() const;
  const std::vector<int>& first_of_face() const { return first_; }
  // The sheets of faces [first, first + count) alone, renumbered from 0: a sheet that reaches past
  // the range keeps the part inside it (a card that holds a share of the faces, host_sw/driver/multi_card_visibility).
  FaceSheets restricted(int first, int count) const;

  friend bool operator==(const FaceSheets& a, const FaceSheets& b) { return a.first_ == b.first_; }

 private:
  bool inside(int face) const { return face >= 0 && face < static_cast<int>(first_.size()); }

  std::vector<int> first_;  // empty: one-sided
  std::vector<int> end_;
};

}  // namespace rc
