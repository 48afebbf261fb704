// The pipeline's 27 multipliers and 18 addition/subtraction blocks (paper sec 3.4 and 5.1), named
// so that a trace, the golden vectors and the resource model all index the same hardware.
//
// Order is stage order (paper sec 3.2): Stage 1 computes temp1 = pvec = dir x edge2 and
// temp2 = tvec = start - v0; Stage 2 temp3 = qvec = tvec x edge1 and det = edge1 . pvec; Stage 3
// u = tvec . pvec, v = dir . qvec, t = edge2 . qvec, then u, v, t times sign(det) and u*s + v*s.
// Not counted by the paper among these 45 blocks (its "some logic elements", see docs/pipeline.md):
// the direction subtraction end - start (input stage), |det| (negate and select on det's sign
// bit), and the six comparators of the decision.
#pragma once

#include "pipeline/bit_bounds.h"

namespace rc::pipeline {

enum class Multiplier {
  // Stage 1, pvec = dir x edge2 (component = first product - second product).
  PvecX_DirY_Edge2Z, PvecX_DirZ_Edge2Y,
  PvecY_DirZ_Edge2X, PvecY_DirX_Edge2Z,
  PvecZ_DirX_Edge2Y, PvecZ_DirY_Edge2X,
  // Stage 2, qvec = tvec x edge1.
  QvecX_TvecY_Edge1Z, QvecX_TvecZ_Edge1Y,
  QvecY_TvecZ_Edge1X, QvecY_TvecX_Edge1Z,
  QvecZ_TvecX_Edge1Y, QvecZ_TvecY_Edge1X,
  // Stage 2, det = edge1 . pvec.
  DetX, DetY, DetZ,
  // Stage 3, u = tvec . pvec, v = dir . qvec, t = edge2 . qvec.
  UX, UY, UZ,
  VX, VY, VZ,
  TX, TY, TZ,
  // Stage 3, the three multiplications by sign(det) (sec 3.4).
  SignU, SignV, SignT,
};
constexpr int kMultiplierCount = 27;

enum class AddSub {
  // Stage 1.
  TvecX, TvecY, TvecZ,  // start - v0
  PvecX, PvecY, PvecZ,  // cross-product subtractions
  // Stage 2.
  QvecX, QvecY, QvecZ,
  DetPartial, Det,  // (x + y) + z: two serial additions per dot product (sec 3.2)
  // Stage 3.
  UPartial, U,
  VPartial, V,
  TPartial, T,
  UPlusV,  // u*s + v*s, compared against |det|
};
constexpr int kAddSubCount = 18;

// Short names for traces, golden-file headers and reports, e.g. "pvec.x:dir.y*edge2.z".
const char* name(Multiplier m);
const char* name(AddSub a);

// Pipeline stage (1..3) a block belongs to.
int stage_of(Multiplier m);
int stage_of(AddSub a);

// Operand kinds of a multiplier, for sizing it (resource model) and checking it (debug asserts).
struct MultiplierOperands {
  Quantity a, b;
};
constexpr MultiplierOperands operands_of(Multiplier m) {
  if (m <= Multiplier::QvecZ_TvecY_Edge1X) return {Quantity::Difference, Quantity::Difference};
  if (m <= Multiplier::TZ) return {Quantity::Difference, Quantity::CrossComponent};
  return {Quantity::Dot, Quantity::Sign};
}

// Kind of value a block outputs (a multiplier's output is after truncation).
constexpr Quantity result_of(Multiplier m) {
  if (m <= Multiplier::QvecZ_TvecY_Edge1X) return Quantity::Product1;
  if (m <= Multiplier::TZ) return Quantity::Product2;
  return Quantity::SignedDot;
}
constexpr Quantity result_of(AddSub a) {
  switch (a) {
    case AddSub::TvecX: case AddSub::TvecY: case AddSub::TvecZ: return Quantity::Difference;
    case AddSub::DetPartial: case AddSub::UPartial: case AddSub::VPartial: case AddSub::TPartial:
      return Quantity::DotPartial;
    case AddSub::Det: case AddSub::U: case AddSub::V: case AddSub::T: return Quantity::Dot;
    case AddSub::UPlusV: return Quantity::UvSum;
    default: return Quantity::CrossComponent;
  }
}

}  // namespace rc::pipeline
