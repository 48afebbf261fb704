#include "pipeline/float_mt.h"

#include <cassert>

namespace rc::pipeline {

namespace {

// The floating-point operators, each rounding its exact result once (float_format.h explains why
// computing in double first is exact), reporting every block output to the probe. The block
// order and the operand order are those of core::cross / core::dot in mt_core.h.
template <class Probe>
struct FloatOps {
  FloatFormat format;
  Probe& probe;

  double multiply(Multiplier m, double a, double b) {
    const double p = round_to_format(a * b, format);
    probe.multiplier(m, p);
    return p;
  }
  double add(AddSub id, double a, double b) {
    const double s = round_to_format(a + b, format);
    probe.add_sub(id, s);
    return s;
  }
  double subtract(AddSub id, double a, double b) {
    const double d = round_to_format(a - b, format);
    probe.add_sub(id, d);
    return d;
  }
  // Exact: the sign is +-1, so the product is a sign flip of a format value.
  double multiply_by_sign(Multiplier m, double value, double sign) {
    const double p = value * sign;
    probe.multiplier(m, p);
    return p;
  }

  FloatVec3 cross(const FloatVec3& a, const FloatVec3& b, Multiplier first, AddSub first_sub) {
    const auto mul = [&](int k, double x, double y) { return multiply(core::next(first, k), x, y); };
    const auto sub = [&](int k, double x, double y) { return subtract(core::next(first_sub, k), x, y); };
    return {sub(0, mul(0, a.y, b.z), mul(1, a.z, b.y)),
            sub(1, mul(2, a.z, b.x), mul(3, a.x, b.z)),
            sub(2, mul(4, a.x, b.y), mul(5, a.y, b.x))};
  }
  // (x + y) + z on three multipliers and two serial adders (sec 3.2).
  double dot(const FloatVec3& a, const FloatVec3& b, Multiplier first, AddSub partial) {
    const double xy = add(partial, multiply(first, a.x, b.x), multiply(core::next(first, 1), a.y, b.y));
    return add(core::next(partial, 1), xy, multiply(core::next(first, 2), a.z, b.z));
  }

  FloatStage1Result stage1(const FloatFaceRecord& f, const FloatVec3& start, const FloatVec3& dir) {
    return {cross(dir, f.edge2, Multiplier::PvecX_DirY_Edge2Z, AddSub::PvecX),
            {subtract(AddSub::TvecX, start.x, f.v0.x), subtract(AddSub::TvecY, start.y, f.v0.y),
             subtract(AddSub::TvecZ, start.z, f.v0.z)}};
  }
  FloatStage2Result stage2(const FloatFaceRecord& f, const FloatStage1Result& s1) {
    return {cross(s1.tvec, f.edge1, Multiplier::QvecX_TvecY_Edge1Z, AddSub::QvecX),
            dot(f.edge1, s1.pvec, Multiplier::DetX, AddSub::DetPartial)};
  }
  // As the fixed stage3: s = -1 if det < 0 else +1 (det = 0, either sign of zero, and NaN count
  // as positive), |det| by negate-and-select, then the shared strict decision.
  FloatStage3Result stage3(const FloatFaceRecord& f, const FloatVec3& dir, const FloatStage1Result& s1,
                           const FloatStage2Result& s2) {
    FloatStage3Result r;
    r.u = dot(s1.tvec, s1.pvec, Multiplier::UX, AddSub::UPartial);
    r.v = dot(dir, s2.qvec, Multiplier::VX, AddSub::VPartial);
    r.t = dot(f.edge2, s2.qvec, Multiplier::TX, AddSub::TPartial);
    const bool negative = s2.det < 0;
    r.sign = negative ? -1.0 : 1.0;
    r.abs_det = negative ? -s2.det : s2.det;
    r.u_signed = multiply_by_sign(Multiplier::SignU, r.u, r.sign);
    r.v_signed = multiply_by_sign(Multiplier::SignV, r.v, r.sign);
    r.t_signed = multiply_by_sign(Multiplier::SignT, r.t, r.sign);
    r.uv_sum = add(AddSub::UPlusV, r.u_signed, r.v_signed);
    r.hit = core::decide(r);
    return r;
  }
  PipelineValues<double> run(const FloatFaceRecord& f, const FloatVec3& start, const FloatVec3& end) {
    PipelineValues<double> r;
    r.direction = segment_direction(start, end, format);
    r.stage1 = stage1(f, start, r.direction);
    r.stage2 = stage2(f, r.stage1);
    r.stage3 = stage3(f, r.direction, r.stage1, r.stage2);
    return r;
  }
};

template <class Probe>
FloatOps<Probe> ops(FloatFormat format, Probe& probe) {
  return FloatOps<Probe>{format, probe};
}

struct TraceProbe {
  FloatTrace* trace;
  void multiplier(Multiplier m, double v) { trace->multipliers[static_cast<int>(m)] = v; }
  void add_sub(AddSub a, double v) { trace->add_subs[static_cast<int>(a)] = v; }
};

[[maybe_unused]] bool is_float_face_record(const FloatFaceRecord& f, FloatFormat format) {
  return is_in_format(f.v0, format) && is_in_format(f.edge1, format) && is_in_format(f.edge2, format);
}

}  // namespace

bool operator==(const FloatFaceRecord& a, const FloatFaceRecord& b) {
  return a.v0 == b.v0 && a.edge1 == b.edge1 && a.edge2 == b.edge2;
}

FloatVec3 round_point(const Vec3& p, FloatFormat format) {
  return {round_to_format(p.x, format), round_to_format(p.y, format), round_to_format(p.z, format)};
}

FloatFaceRecord make_float_face_record(const Triangle& triangle, FloatFormat format) {
  const FloatVec3 v0 = round_point(triangle.v0, format);
  return {v0, segment_direction(v0, round_point(triangle.v1, format), format),
          segment_direction(v0, round_point(triangle.v2, format), format)};
}

bool is_in_format(const FloatVec3& v, FloatFormat format) {
  return is_in_format(v.x, format) && is_in_format(v.y, format) && is_in_format(v.z, format);
}

FloatVec3 segment_direction(const FloatVec3& start, const FloatVec3& end, FloatFormat format) {
  return {round_to_format(end.x - start.x, format), round_to_format(end.y - start.y, format),
          round_to_format(end.z - start.z, format)};
}

FloatStage1Result stage1(const FloatFaceRecord& face, const FloatVec3& start,
                         const FloatVec3& direction, FloatFormat format) {
  NoProbe probe;
  return ops(format, probe).stage1(face, start, direction);
}

FloatStage2Result stage2(const FloatFaceRecord& face, const FloatStage1Result& s1, FloatFormat format) {
  NoProbe probe;
  return ops(format, probe).stage2(face, s1);
}

FloatStage3Result stage3(const FloatFaceRecord& face, const FloatVec3& direction,
                         const FloatStage1Result& s1, const FloatStage2Result& s2, FloatFormat format) {
  NoProbe probe;
  return ops(format, probe).stage3(face, direction, s1, s2);
}

FloatTrace trace(const FloatFaceRecord& face, const FloatVec3& start, const FloatVec3& end,
                 FloatFormat format) {
  assert(is_float_face_record(face, format) && is_in_format(start, format) && is_in_format(end, format));
  FloatTrace t;
  TraceProbe probe{&t};
  t.values = ops(format, probe).run(face, start, end);
  return t;
}

bool segment_hits(const FloatFaceRecord& face, const FloatVec3& start, const FloatVec3& end,
                  FloatFormat format) {
  assert(is_float_face_record(face, format) && is_in_format(start, format) && is_in_format(end, format));
  NoProbe probe;
  return ops(format, probe).run(face, start, end).stage3.hit;
}

// The whole pipeline per end point; no hoisting, so every value is the traced one by construction.
void occlude_face(const FloatFaceRecord& face, const FloatVec3& start, const double* end_x,
                  const double* end_y, const double* end_z, std::size_t n, FloatFormat format,
                  std::uint8_t* blocked, const std::uint8_t* skip) {
  assert(is_float_face_record(face, format) && is_in_format(start, format));
  NoProbe probe;
  FloatOps<NoProbe> op = ops(format, probe);
  for (std::size_t i = 0; i < n; ++i) {
    if (skip != nullptr && skip[i] != 0) continue;
    const FloatVec3 end{end_x[i], end_y[i], end_z[i]};
    assert(is_in_format(end, format));
    blocked[i] |= std::uint8_t(op.run(face, start, end).stage3.hit);
  }
}

}  // namespace rc::pipeline
