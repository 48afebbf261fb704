#include "pipeline/reference_mt.h"

#include "pipeline/mt_core.h"

namespace rc::pipeline {

namespace {

template <class Real>
using RVec = IntVec3<Real>;  // IntVec3 is a plain 3-tuple; here it holds floating point.

template <class Real>
RVec<Real> to(const Vec3& v) {
  return {static_cast<Real>(v.x), static_cast<Real>(v.y), static_cast<Real>(v.z)};
}
template <class Real>
RVec<Real> cross(const RVec<Real>& a, const RVec<Real>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class Real>
Real dot(const RVec<Real>& a, const RVec<Real>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// A face as a float kernel keeps it: the edges are computed in the working precision.
template <class Real>
struct RefFace {
  RVec<Real> v0, edge1, edge2;
  explicit RefFace(const Triangle& t)
      : v0(to<Real>(t.v0)), edge1(to<Real>(t.v1) - v0), edge2(to<Real>(t.v2) - v0) {}
};

template <class Real>
bool reference_hits(const RefFace<Real>& f, const RVec<Real>& start, const RVec<Real>& end) {
  const RVec<Real> dir = end - start;
  const RVec<Real> pvec = cross(dir, f.edge2), tvec = start - f.v0, qvec = cross(tvec, f.edge1);
  const Real det = dot(f.edge1, pvec);
  Stage3Values<Real> s;
  s.u = dot(tvec, pvec);
  s.v = dot(dir, qvec);
  s.t = dot(f.edge2, qvec);
  s.sign = det < 0 ? Real(-1) : Real(1);
  s.abs_det = det < 0 ? -det : det;
  s.u_signed = s.u * s.sign;
  s.v_signed = s.v * s.sign;
  s.t_signed = s.t * s.sign;
  s.uv_sum = s.u_signed + s.v_signed;
  return core::decide(s);
}

// One face against a stream of end points; always inlined into each instruction-set variant.
template <bool kMasked>
[[gnu::always_inline]] inline void float_loop(const RefFace<float>& f, const RVec<float>& s,
                                              const float* __restrict end_x,
                                              const float* __restrict end_y,
                                              const float* __restrict end_z, std::size_t n,
                                              std::uint8_t* __restrict blocked,
                                              const std::uint8_t* __restrict skip) {
  for (std::size_t i = 0; i < n; ++i) {
    bool hit = reference_hits(f, s, {end_x[i], end_y[i], end_z[i]});
    if constexpr (kMasked) hit &= skip[i] == 0;
    blocked[i] |= std::uint8_t(hit);
  }
}

using FloatFn = void (*)(const RefFace<float>&, const RVec<float>&, const float*, const float*,
                         const float*, std::size_t, std::uint8_t*, const std::uint8_t*);
struct FloatKernels {
  FloatFn plain, masked;
};

#define RC_FLOAT_PARAMS                                                                       \
  const RefFace<float>&f, const RVec<float>&s, const float *x, const float *y, const float *z, \
      std::size_t n, std::uint8_t *blocked, const std::uint8_t *skip
#define RC_DEFINE_FLOAT_KERNELS(isa, target)                                                    \
  target void float_##isa(RC_FLOAT_PARAMS) { float_loop<false>(f, s, x, y, z, n, blocked, skip); } \
  target void float_masked_##isa(RC_FLOAT_PARAMS) {                                           \
    float_loop<true>(f, s, x, y, z, n, blocked, skip);                                        \
  }                                                                                           \
  constexpr FloatKernels kFloat_##isa{float_##isa, float_masked_##isa};

RC_DEFINE_FLOAT_KERNELS(baseline, )
#if RC_HAVE_ISA_VARIANTS
RC_DEFINE_FLOAT_KERNELS(v3, RC_TARGET_X86_64_V3)
RC_DEFINE_FLOAT_KERNELS(v4, RC_TARGET_X86_64_V4)
#endif
#undef RC_DEFINE_FLOAT_KERNELS
#undef RC_FLOAT_PARAMS

const FloatKernels& float_kernels(KernelIsa isa) {
#if RC_HAVE_ISA_VARIANTS
  return *pick_variant(isa, &kFloat_baseline, &kFloat_v3, &kFloat_v4);
#else
  return *pick_variant(isa, &kFloat_baseline, &kFloat_baseline, &kFloat_baseline);
#endif
}

}  // namespace

bool segment_hits_ref(const Triangle& triangle, const Vec3& start, const Vec3& end) {
  return reference_hits(RefFace<double>(triangle), to<double>(start), to<double>(end));
}

bool segment_hits_ref_float(const Triangle& triangle, const Vec3& start, const Vec3& end) {
  return reference_hits(RefFace<float>(triangle), to<float>(start), to<float>(end));
}

void occlude_face_float(const Triangle& face, const Vec3& start, const float* end_x,
                        const float* end_y, const float* end_z, std::size_t n,
                        std::uint8_t* blocked, const std::uint8_t* skip) {
  occlude_face_float(best_kernel_isa(), face, start, end_x, end_y, end_z, n, blocked, skip);
}

void occlude_face_float(KernelIsa isa, const Triangle& face, const Vec3& start,
                        const float* end_x, const float* end_y, const float* end_z,
                        std::size_t n, std::uint8_t* blocked, const std::uint8_t* skip) {
  const FloatKernels& k = float_kernels(isa);
  (skip == nullptr ? k.plain : k.masked)(RefFace<float>(face), to<float>(start), end_x, end_y,
                                         end_z, n, blocked, skip);
}

}  // namespace rc::pipeline
