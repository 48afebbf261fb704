// Software visibility in double-precision floating point: Moller-Trumbore with the paper's strict,
// division-free decision, every segment against every face (early exit on the first hit).
// This is the model of the paper's software column; it is also the float reference for error tables.
#pragma once

#include "host_sw/radiosity/visibility.h"

namespace rc {

class FloatVisibility : public VisibilityBackend {
 public:
  std::string name() const override { return "float"; }
  void load_triangles(const std::vector<Triangle>& faces) override;
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  std::uint64_t tests_performed() const override { return tests_; }

 private:
  std::vector<Triangle> faces_;
  std::vector<std::uint8_t> blocked_;
  std::uint64_t tests_ = 0;
};

}  // namespace rc
