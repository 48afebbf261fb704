// Random and adversarial segment/triangle cases for the numerical stress suite (tests and
// bench/pipeline_stress), and the comparison of every implementation on one case.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pipeline/fixed_format.h"

#include "scenes/geometry.h"

namespace rc::pipeline {

enum class CaseKind {
  Random,         // uniform triangle and segment: mostly clear misses
  Crossing,       // segment aimed at a point near the triangle, ending before or after it
  EdgeHit,        // [lattice] crosses exactly through a point of an edge
  VertexHit,      // [lattice] crosses exactly through a vertex
  Grazing,        // passes within 2^-8..2^-45 of an edge, inside or outside
  Parallel,       // [lattice] direction exactly parallel to the plane, in it or off it
  Degenerate,     // [lattice] collinear or coincident vertices, segment through the line
  EndOnTriangle,  // [lattice] one end point exactly inside the triangle (a self-hit)
  Extreme,        // [lattice] coordinates 0, 2^-N, 1 - 2^-N*2, 1 - 2^-N (the representable ends)
  NearCoplanar,   // segment almost in the plane (det tiny), crossing near the triangle
};
constexpr int kCaseKindCount = 10;
const char* name(CaseKind kind);

struct StressCase {
  CaseKind kind;
  Triangle triangle;
  Vec3 start, end;
};

// `count` reproducible cases of one kind, all coordinates in [0, 1). [lattice] kinds put every
// coordinate on the 2^-bits grid, so quantising at `bits` is exact and the exact reference sees
// the adversarial configuration itself; the others are generic doubles that quantisation moves.
std::vector<StressCase> make_stress_cases(CaseKind kind, FracBits bits, std::size_t count,
                                          std::uint64_t seed);

// Every implementation's answer on one case at one width.
struct CaseOutcome {
  bool fixed;          // the pipeline, on quantised inputs
  bool exact;          // no truncation, same quantised inputs
  bool near_boundary;  // exact values within the proven truncation error of a threshold
  bool fixed_det_zero; // the pipeline's det is exactly 0
  bool ref_double;     // double precision on the un-quantised geometry
  bool ref_float;      // single precision on the un-quantised geometry
};
CaseOutcome evaluate_case(const StressCase& c, int bits);

}  // namespace rc::pipeline
