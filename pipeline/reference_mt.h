// Floating-point references: plain Moller-Trumbore on the un-quantised geometry, with the
// pipeline's division-free strict decision (the very same decide() code). Double is the accuracy
// reference of the stress suite; float is what a software or GPU kernel would do instead.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pipeline/kernel_isa.h"
#include "scenes/geometry.h"

namespace rc::pipeline {

bool segment_hits_ref(const Triangle& triangle, const Vec3& start, const Vec3& end);
bool segment_hits_ref_float(const Triangle& triangle, const Vec3& start, const Vec3& end);

// The float reference in the hardware's streaming order, for the throughput comparison with
// occlude_face: one face, one start, end points as structure-of-arrays; ORs hits into blocked[i]
// and leaves entries with skip[i] != 0 untouched (skip may be null).
void occlude_face_float(const Triangle& face, const Vec3& start, const float* end_x,
                        const float* end_y, const float* end_z, std::size_t n,
                        std::uint8_t* blocked, const std::uint8_t* skip = nullptr);
void occlude_face_float(KernelIsa isa, const Triangle& face, const Vec3& start,
                        const float* end_x, const float* end_y, const float* end_z,
                        std::size_t n, std::uint8_t* blocked, const std::uint8_t* skip = nullptr);

}  // namespace rc::pipeline
