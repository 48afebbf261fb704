#include "rtl/lanes/rtl_lanes.h"

#include <stdexcept>

#include "rtl/sim/rtl_pipeline.h"

namespace rc::rtl {

namespace {

class RtlLanes final : public board::ClockedLanes {
 public:
  RtlLanes(unsigned lanes, int bits) {
    for (unsigned i = 0; i < lanes; ++i) models_.push_back(make_rtl_pipeline(bits));
  }
  unsigned lanes() const override { return static_cast<unsigned>(models_.size()); }
  void clock_edge(const std::vector<board::ClockedLaneInput>& inputs) override {
    for (std::size_t i = 0; i < models_.size(); ++i) {
      const board::ClockedLaneInput& in = inputs[i];
      RtlInputs ports;
      ports.valid = in.valid;
      ports.start = in.start;
      ports.end = in.end;
      ports.face = in.face;
      ports.t_guard = in.t_guard;
      models_[i]->clock(ports);
    }
  }
  bool out_valid(unsigned lane) const override { return models_.at(lane)->out_valid(); }
  bool out_hit(unsigned lane) const override { return models_.at(lane)->out_hit(); }

 private:
  std::vector<std::unique_ptr<RtlPipeline>> models_;
};

}  // namespace

board::ClockedLanesFactory rtl_lanes_factory() {
  board::ClockedLanesFactory f;
  f.name = "rtl";
  f.make = [](unsigned lanes, pipeline::FracBits bits) -> std::unique_ptr<board::ClockedLanes> {
    return std::make_unique<RtlLanes>(lanes, bits);
  };
  return f;
}

}  // namespace rc::rtl
