// The exact reference: the same test on the same quantised inputs with no truncation at all, in
// 128-bit integers. It answers "what would the hardware say with infinitely many fractional bits
// inside the pipeline?", so comparing it with the fixed-point pipeline isolates truncation error
// from quantisation error.
#pragma once

#include "pipeline/fixed_format.h"

namespace rc::pipeline {

// det, u, v, t exactly, in units of 2^-3N (every product of three 1.N values is an integer there;
// magnitudes stay below 6 * 2^3N < 2^97). Also the decision on them, by the same strict rule.
struct ExactValues {
  __int128 det, u, v, t;
  bool hit;
};
ExactValues exact_values(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end);
bool segment_hits_exact(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end);

// Proven truncation error of the pipeline at any width: each of det, u, v, t differs from its
// exact value by less than this many units of 2^-N (docs/pipeline.md, "Error bound").
constexpr int kDotErrorBoundLsb = 6;

// True if some quantity the decision compares lies within the proven error bound of its
// threshold, so the pipeline may legitimately decide differently from the exact reference.
// Outside this band the two must agree: the stress tests check exactly that.
bool near_decision_boundary(const ExactValues& exact, FracBits bits);

// The smallest distance, in units of 2^-3N, between a compared quantity and its threshold:
// min(|det|, |u*s|, |v*s|, |t*s|, ||det| - u*s|, ||det| - t*s|, ||det| - u*s - v*s|).
// Zero means the segment touches an edge, a vertex or an end point of the test exactly.
__int128 decision_margin(const ExactValues& exact);

}  // namespace rc::pipeline
