// Uniform subdivision of faces (paper: 70 -> 280 -> 1120 faces) and of faces into patches, plus a
// deterministic refinement to an exact face count (e.g. the paper's 70).
#pragma once

#include <vector>

#include "scenes/scene.h"

namespace rc {

// The most levels of midpoint splitting of a face (4^8 = 65536 pieces), for faces and patches alike.
constexpr int kMaxSplitLevels = 8;

// Each level splits every triangle into 4 at its edge midpoints, so `levels` multiplies the count
// by 4^levels. Children of a face stay together, in a fixed order.
std::vector<Face> split_faces(const std::vector<Face>& faces, int levels);

// Repeatedly bisects the largest face (lowest index on ties) across its longest edge (first edge
// on ties) until there are exactly `target` faces, the second half placed right after the first.
// Runs in O(target log target). Throws if target < faces.size().
std::vector<Face> refine_to_count(const std::vector<Face>& faces, int target);

// Patches: each face split uniformly into 4^levels sub-triangles, grouped by face in face order.
std::vector<Patch> make_patches(const std::vector<Face>& faces, int levels);

// Patches of a target size for meshes that are not grids: each face is split into 4^k patches with
// the smallest k whose patches' longest edge is at most `size` (midpoint splits halve every edge).
// `size` is in the scene's units (normalised: [0, 1)). Throws std::invalid_argument for size <= 0
// and for a face that would need more than kMaxSplitLevels (the size is never silently missed).
std::vector<Patch> make_patches_of_size(const std::vector<Face>& faces, double size);
int levels_for_size(const Triangle& t, double size);

// Splits one triangle into its 4 midpoint children.
std::vector<Triangle> split4(const Triangle& t);

}  // namespace rc
