// One shooting step's geometry, for every patch at once: the pair geometry and the point or disc
// form factor from the shooter to each patch, as the solver uses them. The patches are kept as
// columns (PatchColumns) and the sweep computes two patches at a time with the same operations and
// no branches (SSE2); each value is computed with exactly the operations, in
// the order, of the per-pair rule it replaces (the shooter's sheet, coincident centres,
// pair_geometry, PairGeometry::exchanges, form_factor), so every bit is the same (test
// ReceiverSweep.EveryPairBitIdenticalToThePairRule). In the paper's largest scenes the per-pair
// branches were most of the solver's own time: whether a receiver exchanges energy is close to a
// coin toss, so the branch mispredicted at every other receiver (docs/results/performance.md).
#pragma once

#include <cstdint>
#include <vector>

#include "host_sw/radiosity/form_factor.h"
#include "scenes/scene.h"

namespace rc {

// The patches' centres, normals, areas and sheets (scenes/sheets.h), one column each.
struct PatchColumns {
  explicit PatchColumns(const Scene& scene);
  std::vector<double> cx, cy, cz, nx, ny, nz, area;
  std::vector<double> sheet_value;  // the first face of the patch's face's sheet, as a double (exact), for the vector compare
  std::vector<Vec3> centre;
  std::vector<int> face;
  std::vector<Spectrum> reflectance;  // the patch's material's, side by side for the energy update
  std::size_t size() const { return area.size(); }
};

// By patch: the shooter-receiver geometry (all 0 where the pair never exchanges because of its
// sheet or coincident centres, as ProgressiveRadiosity's rule gives), whether the pair exchanges
// energy, and its form factor (point or disc; 0 where it does not exchange). The shooter's own
// entry exchanges nothing.
struct ReceiverSweep {
  std::vector<double> cos_shooter, cos_receiver, distance_squared, form_factor;
  std::vector<std::uint8_t> exchanges;
  PairGeometry geometry(std::size_t patch) const {
    return {cos_shooter[patch], cos_receiver[patch], distance_squared[patch]};
  }
};

// Fills `out` for `shooter`. `kind` Analytic leaves form_factor 0 (the caller integrates over the
// shooter's triangle where the pair exchanges).
void sweep_receivers(const PatchColumns& patches, int shooter, FormFactorKind kind, ReceiverSweep& out);

}  // namespace rc
