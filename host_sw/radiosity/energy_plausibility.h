// Whether a solve's energy accounting is plausible for its scene, and the notes a run prints about
// how the solve ended (docs/radiosity.md, "Energy plausibility").
//
// The solver books as escaping whatever a shot does not deliver: power that leaves an open scene,
// but also the shortfall of the discrete form factors (a row that sums to 0.95 in a closed room) and
// power that lands on the back of one-sided faces. In a closed room of reflectance 0.999 the
// shortfall costs more per bounce than absorption does, so almost all the power is booked as
// escaping and the radiosity comes out many times too low while the run reports "converged". The
// scene's geometry says how much can really leave: rays cast from the shooters (cosine-weighted,
// as the power leaves a diffuse patch) that reach no face's front leave the scene. When the
// shortfall the solve booked beyond that changes the answer by more than kImplausibleEnergyFactor
// (or less than its inverse), for the effective reflectance the solve saw, the run warns.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host_sw/radiosity/radiosity.h"
#include "scenes/scene.h"

namespace rc {

// The warning's threshold: the factor by which the booked shortfall (or overshoot) changes the
// total radiosity, 1 / (1 - rho (1 - loss)) against the geometry's loss, beyond the sampling noise.
constexpr double kImplausibleEnergyFactor = 1.25;
// And whatever the reflectance: the booked share of the shot power that escapes differs from the
// geometry's by more than this beyond the noise (black emitters facing each other: the absorbed and
// escaping totals are wrong even where the radiosity, their emission, is not).
constexpr double kImplausibleLossShare = 0.1;

// What the geometry says about the power the solve shot: the share of it that leaves the scene
// (rays reaching no face) or lands on the back of a face (no patch receives it there), estimated
// over shooters drawn in proportion to the power they shot (a power-weighted mean).
struct Openness {
  int shooters = 0;           // shooters drawn (distinct)
  int rays_per_shooter = 0;
  double escapes = 0;         // rays reaching no face, weighted
  double back_hits = 0;       // rays whose first face is hit from behind, weighted
  double booked_loss = 0;     // 1 - S, weighted: what the solve booked as escaping for them
  double noise = 0;           // the estimate's sampling allowance (three standard deviations + 1/rays)
  double reflectance = 0;     // the run's effective reflectance: 1 - absorbed / arrived
  // 1 / (1 - rho (1 - booked)) over 1 / (1 - rho (1 - geometric)) at the end of the noise allowance
  // nearest to 1: below 1 the solve's radiosity is too low, above 1 too high.
  double factor = 1;
  // booked_loss minus the geometry's loss beyond the noise allowance (0 within it).
  double excess = 0;
};

// Rays are cast from at most `max_shooters` draws of shooters with up to
// `max_rays` each, fewer when the scene has so many faces that shooters x rays x faces would exceed
// `max_tests`. Deterministic (a fixed set of directions).
Openness measure_openness(const Scene& scene, const SolverResult& result, int max_shooters = 256, int max_rays = 64,
                          std::uint64_t max_tests = 200'000'000);

// "" or the warning for an implausible accounting: factor beyond kImplausibleEnergyFactor either way,
// or an excess beyond kImplausibleLossShare either way.
std::string implausible_energy_warning(const Openness& openness, const SolverResult& result);

// Every note about how the solve ended, as run prints them on stderr and report.json keeps them:
// a solve that stopped for want of normal powers (SolverResult::exhausted), radiosity that
// underflowed on the way back to the scene's units, an all-zero answer, and the energy warning.
std::vector<std::string> solver_end_notes(const Scene& scene, const SolverResult& result, int steps_asked);

}  // namespace rc
