// Finding the sheets of a normalised scene (scenes/sheets.h): faces back to back that form one
// two-sided surface, found by geometry, then made contiguous.
//
// Two faces are twins when, in the normalised scene (the unit cube):
//   - they face opposite ways: the sine of the angle between one normal and the other's negation is
//     at most kSheetAngle (1e-6);
//   - they lie in one plane: every vertex of each is within kSheetDistance (1e-9) of the other's
//     plane: about two steps of the finest pipeline grid (2^-31 = 4.7e-10), so no width can put
//     anything between them, and far above the rounding of normalisation (about 1e-16);
//   - they overlap: the area their interiors share, in that plane, exceeds kSheetOverlap (1e-9)
//     times the smaller face's area (faces that only touch along an edge or at a corner share none).
// A sheet is a connected group of twins, joined by their surfaces' coplanar neighbours: faces of
// one source surface (Face::surface: a quad's two triangles, and what subdivision made of them) that
// share an edge and face the same way within kMaxSheetFoldDegrees (5, the fold a quad may have)
// join the sheet when the surface has a twin. So a two-sided quad is one sheet of four triangles
// however it was written: as one 'two-sided quad' (each half's twin is its back half), or as two
// quads back to back split along different diagonals (each triangle overlaps both of the other's).
// Neighbours of one-sided surfaces never join: the paper's own-face rule is kept for them.
// Faces that face the same way never form a sheet: the Cornell Box's light lies in its ceiling's
// plane and overlaps it, but both face down (they are one-sided and exchange nothing: cos = 0).
#pragma once

#include <cstddef>
#include <vector>

#include "scenes/scene.h"

namespace rc {

constexpr double kSheetAngle = 1e-6;
constexpr double kSheetDistance = 1e-9;
constexpr double kSheetOverlap = 1e-9;
constexpr double kMaxSheetFoldDegrees = 5.0;

// The pairs (a, b), a < b, of twin faces among `faces`, sorted. Candidates: faces are bucketed by
// their plane (normal up to sign and distance from the origin, to 1e-3) and, within a bucket, swept
// along their bounding boxes in the plane, so the cost grows with the faces and the pairs of
// coplanar faces whose boxes meet, not with faces squared.
std::vector<std::pair<int, int>> find_twin_faces(const std::vector<Face>& faces);

// Finds the sheets of scene.faces, reorders the faces so that each sheet's faces are contiguous
// (a sheet takes the place of its lowest-numbered face, its faces in their old order; every other
// face keeps its order, so a scene without twins is unchanged) and sets scene.sheets. Call after
// normalisation and before patches are made (patches name their faces by index). Throws
// std::logic_error if the scene already has patches.
void find_sheets(Scene& scene);

}  // namespace rc
