// Adaptive patches (paper sec 6, "adaptive subdivision"): split the patches where the solution
// changes fast, instead of every patch. The criterion is the radiosity gradient: a patch's largest
// luminance difference to a neighbour (a patch of the same face sharing a corner with it), relative
// to the brightest patch of the scene. Shadow boundaries and the light's falloff are where it is
// large. Children are made by the same midpoint split as uniform patches (split4), so every patch
// is a node of its face's uniform hierarchy and a uniform patch set is one adaptive outcome.
// docs/results/adaptive-patches.md.
#pragma once

#include <cstddef>
#include <vector>

#include "scenes/scene.h"
#include "scenes/spectrum.h"

namespace rc {

// Luminance (Rec. 709 weights of the three bands; the mean band for other band counts).
double luminance(const Spectrum& s);

// Each patch's gradient: max |Y(p) - Y(q)| over the patches q of the same face that share a corner
// with p (exact coordinates: midpoint splits reproduce shared corners bit for bit), divided by the
// largest patch luminance (0 for a black scene). A corner of p in the middle of a coarser
// neighbour's edge (a T-junction) is not that neighbour's corner: the coarser neighbour is missed
// there, and found through the corners the two do share.
std::vector<double> radiosity_gradients(const Scene& scene, const std::vector<Spectrum>& radiosity);

// How many midpoint splits below its face a patch is (from the area ratio, exact for split4).
int patch_depth(const Scene& scene, const Patch& patch);

// The scene's patches with the `count` patches of largest gradient split into their four children
// (ties: the lower index first), each set of children where its parent was, so patches stay grouped
// by face in face order. Patches already `max_depth` splits below their face are not split; fewer
// than `count` patches are split when too few may be. Returns the new patch list.
std::vector<Patch> split_steepest(const Scene& scene, const std::vector<double>& gradients, std::size_t count,
                                  int max_depth);

}  // namespace rc
