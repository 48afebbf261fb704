// The Moller-Trumbore pipeline in a floating-point format (pipeline/float_format.h): the same
// division-free data flow as the fixed-point pipeline (mt_core.h) -- the same three stages, the
// same 27 multipliers and 18 add/sub blocks in the order of enum Multiplier / enum AddSub
// (hardware_blocks.h), the same strict decision (core::decide, shared verbatim) -- but every
// operation is one floating-point operator that rounds its exact result to the format
// (round_to_format: nearest even, flush to zero, overflow to infinity).
//
// Every value is held in a double that is exactly a value of the format. Inputs are rounded from
// doubles (world or normalised coordinates alike: there is no [0, 1) requirement); the face
// record's edges are format subtractions of the rounded vertices (the host's three subtractors),
// and direction = end - start is a format subtraction at the pipeline's input, outside the 18
// (as for fixed point). The three multiplications by sign(det) and |det| are exact (a sign flip).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "pipeline/float_format.h"
#include "pipeline/hardware_blocks.h"
#include "pipeline/mt_core.h"
#include "scenes/geometry.h"

namespace rc::pipeline {

// A 3-vector of format values (IntVec3 is a plain 3-tuple; here it holds doubles).
using FloatVec3 = IntVec3<double>;

// One face as a floating-point face bank would hold it: 9 format values.
struct FloatFaceRecord {
  FloatVec3 v0, edge1, edge2;
};
bool operator==(const FloatFaceRecord& a, const FloatFaceRecord& b);

// Each coordinate rounded to the format (RNE from double; no range requirement).
FloatVec3 round_point(const Vec3& p, FloatFormat format);
// v0 rounded; edge_k = round(v_k) - round(v0) as a format subtraction.
FloatFaceRecord make_float_face_record(const Triangle& triangle, FloatFormat format);
bool is_in_format(const FloatVec3& v, FloatFormat format);

// ---- Stage by stage (the same structure as fixed_mt.h) ---------------------------------------
using FloatStage1Result = Stage1Values<double>;
using FloatStage2Result = Stage2Values<double>;
using FloatStage3Result = Stage3Values<double>;

// Input stage: end - start, one format subtraction per component.
FloatVec3 segment_direction(const FloatVec3& start, const FloatVec3& end, FloatFormat format);
FloatStage1Result stage1(const FloatFaceRecord& face, const FloatVec3& start,
                         const FloatVec3& direction, FloatFormat format);
FloatStage2Result stage2(const FloatFaceRecord& face, const FloatStage1Result& s1, FloatFormat format);
FloatStage3Result stage3(const FloatFaceRecord& face, const FloatVec3& direction,
                         const FloatStage1Result& s1, const FloatStage2Result& s2, FloatFormat format);

// ---- Everything at once -------------------------------------------------------------------------
struct FloatTrace {
  PipelineValues<double> values;
  std::array<double, kMultiplierCount> multipliers{};
  std::array<double, kAddSubCount> add_subs{};

  double output(Multiplier m) const { return multipliers[static_cast<int>(m)]; }
  double output(AddSub a) const { return add_subs[static_cast<int>(a)]; }
  bool hit() const { return values.stage3.hit; }
};
// Inputs must be format values (round_point / make_float_face_record); debug builds assert it.
FloatTrace trace(const FloatFaceRecord& face, const FloatVec3& start, const FloatVec3& end,
                 FloatFormat format);
bool segment_hits(const FloatFaceRecord& face, const FloatVec3& start, const FloatVec3& end,
                  FloatFormat format);

// The hardware's streaming order (paper sec 4.1), as occlude_face: one face, one start point, end
// points as structure-of-arrays of format values; ORs each hit into blocked[i] and leaves entries
// with skip[i] != 0 untouched (skip may be null).
void occlude_face(const FloatFaceRecord& face, const FloatVec3& start, const double* end_x,
                  const double* end_y, const double* end_z, std::size_t n, FloatFormat format,
                  std::uint8_t* blocked, const std::uint8_t* skip = nullptr);

}  // namespace rc::pipeline
