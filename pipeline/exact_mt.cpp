#include "pipeline/exact_mt.h"

#include <initializer_list>

#include "pipeline/mt_core.h"

namespace rc::pipeline {

namespace {

using Wide = __int128;
using WideVec = IntVec3<Wide>;

WideVec cross(const WideVec& a, const WideVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Wide dot(const WideVec& a, const WideVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Wide abs(Wide x) { return x < 0 ? -x : x; }

}  // namespace

ExactValues exact_values(const FaceRecord& face, const FixedVec3& start_in, const FixedVec3& end_in) {
  const WideVec v0 = vec_cast<Wide>(face.v0), e1 = vec_cast<Wide>(face.edge1),
                e2 = vec_cast<Wide>(face.edge2), start = vec_cast<Wide>(start_in),
                end = vec_cast<Wide>(end_in);
  const WideVec dir = end - start;
  // Units: inputs 2^-N, cross products 2^-2N. u and det are tvec/edge1 (2^-N) times pvec
  // (2^-2N); v and t are dir/edge2 times qvec: all four land on 2^-3N.
  const WideVec pvec = cross(dir, e2), tvec = start - v0, qvec = cross(tvec, e1);
  ExactValues r;
  r.det = dot(e1, pvec);
  r.u = dot(tvec, pvec);
  r.v = dot(dir, qvec);
  r.t = dot(e2, qvec);
  // The same decision code as the pipeline, on exact values.
  Stage3Values<Wide> s;
  s.u = r.u;
  s.v = r.v;
  s.t = r.t;
  s.sign = r.det < 0 ? -1 : 1;
  s.abs_det = abs(r.det);
  s.u_signed = s.u * s.sign;
  s.v_signed = s.v * s.sign;
  s.t_signed = s.t * s.sign;
  s.uv_sum = s.u_signed + s.v_signed;
  r.hit = core::decide(s);
  return r;
}

bool segment_hits_exact(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end) {
  return exact_values(face, start, end).hit;
}

bool near_decision_boundary(const ExactValues& e, FracBits bits) {
  // One LSB of the pipeline (2^-N) is 2^2N units of the exact values (2^-3N).
  const Wide lsb = Wide{1} << (2 * bits);
  const Wide bound = kDotErrorBoundLsb * lsb;
  const Wide sign = e.det < 0 ? -1 : 1;
  const Wide abs_det = abs(e.det), us = e.u * sign, vs = e.v * sign, ts = e.t * sign;
  // Each compared expression has error below (number of det/u/v/t terms) * bound; a sign flip of
  // det is possible only when |det| itself is within one bound of zero.
  return abs_det < bound || abs(us) < bound || abs(vs) < bound || abs(ts) < bound ||
         abs(abs_det - us) < 2 * bound || abs(abs_det - ts) < 2 * bound ||
         abs(abs_det - us - vs) < 3 * bound;
}

__int128 decision_margin(const ExactValues& e) {
  const Wide sign = e.det < 0 ? -1 : 1;
  const Wide abs_det = abs(e.det), us = e.u * sign, vs = e.v * sign, ts = e.t * sign;
  Wide m = abs_det;
  for (Wide x : {abs(us), abs(vs), abs(ts), abs(abs_det - us), abs(abs_det - ts), abs(abs_det - us - vs)}) {
    if (x < m) m = x;
  }
  return m;
}

}  // namespace rc::pipeline
