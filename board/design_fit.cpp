#include "board/design_fit.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace rc::board {

std::string DesignFit::describe() const {
  char line[512];
  std::snprintf(line, sizeof line,
                "%d lane(s) at %d bits on %s (%d with block multipliers, %d with slice multipliers) need %d "
                "slices and %d block multipliers of %d and %d: %s; clock %.3f MHz",
                lanes, bits, device.c_str(), hard_lanes, soft_lanes, slices, block_multipliers, slices_available,
                block_multipliers_available, fits ? "fits" : "does not fit", clock_mhz);
  // The paper fit is the default and says nothing; the other source is named (docs/pipeline.md).
  if (resources != pipeline::ResourceSource::paper_fit) return std::string(line) + " (resources: " + choice_name(resources) + ")";
  return line;
}

namespace {

// Lanes on block multipliers while the device has them, the rest on slice multipliers; the wrapper
// counted; the clock the slower of the kinds used and the profile's. `Lane` is a fixed- or
// float-point lane's resources (slices, block_multipliers, clock_mhz).
template <class Lane>
void place_lanes(const DeviceProfile& device, const pipeline::WrapperCost& wrapper, int lanes, const Lane& hard,
                 const Lane& soft, DesignFit& f) {
  f.device = device.name;
  f.lanes = lanes;
  f.slices_available = device.slices;
  f.block_multipliers_available = device.block_multipliers;
  const int spare_multipliers = std::max(0, device.block_multipliers - wrapper.block_multipliers);
  f.hard_lanes = hard.block_multipliers > 0 ? std::min(lanes, spare_multipliers / hard.block_multipliers) : lanes;
  f.soft_lanes = lanes - f.hard_lanes;
  f.slices = wrapper.fixed_slices + lanes * wrapper.per_lane_slices + f.hard_lanes * hard.slices +
             f.soft_lanes * soft.slices;
  f.block_multipliers = wrapper.block_multipliers + f.hard_lanes * hard.block_multipliers;
  f.block_ram_bits = 0;  // assumption, see design_fit.h
  f.block_ram_bits_available = device.block_ram_bits;
  f.fits = f.slices <= device.slices && f.block_multipliers <= device.block_multipliers;
  f.pipeline_clock_mhz = std::min(f.hard_lanes > 0 ? hard.clock_mhz : soft.clock_mhz,
                                  f.soft_lanes > 0 ? soft.clock_mhz : hard.clock_mhz);
  f.clock_mhz = std::min(device.clock_mhz(lanes), f.pipeline_clock_mhz);
}

}  // namespace

DesignFit fit_design(const DeviceProfile& device, const pipeline::ResourceModel& resources, LaneCount lane_count,
                     pipeline::FracBits bits) {
  const int lanes = static_cast<int>(lane_count.value());
  const pipeline::PipelineResources hard = resources.pipeline(bits, true, device.part);
  const pipeline::PipelineResources soft = resources.pipeline(bits, false, device.part);
  const pipeline::WrapperCost wrapper = resources.wrapper();

  DesignFit f;
  f.bits = bits;
  f.resources = resources.source();
  place_lanes(device, wrapper, lanes, hard, soft, f);
  f.modelled = (f.hard_lanes > 0 && (hard.interpolated || hard.extrapolated)) ||
               (f.soft_lanes > 0 && (soft.interpolated || soft.extrapolated));
  return f;
}

int max_lanes(const DeviceProfile& device, const pipeline::ResourceModel& resources, pipeline::FracBits bits) {
  int lanes = 0;
  while (lanes < static_cast<int>(LaneCount::kMax) && fit_design(device, resources, lanes + 1, bits).fits) ++lanes;
  return lanes;
}

LanesBySource lanes_by_source(const DeviceProfile& device, pipeline::FracBits bits) {
  LanesBySource out;
  out.device = device.name;
  out.bits = bits;
  const auto most = [&](pipeline::ResourceSource source, DesignFit& fit) {
    const pipeline::ResourceModel model = pipeline::ResourceModel::load_default(source);
    const int lanes = max_lanes(device, model, bits);
    fit = fit_design(device, model, std::max(lanes, 1), bits);
    return lanes;
  };
  out.paper_lanes = most(pipeline::ResourceSource::paper_fit, out.paper);
  out.synthesis_lanes = most(pipeline::ResourceSource::synthesis, out.synthesis);
  return out;
}

FloatDesignFit fit_float_design(const DeviceProfile& device, const pipeline::ResourceModel& resources,
                                LaneCount lane_count, pipeline::FloatFormat format) {
  const int lanes = static_cast<int>(lane_count.value());
  const pipeline::FloatFamily& family = resources.float_family_of_part(device.part);
  const pipeline::FloatPipelineResources hard = resources.float_pipeline(format, family, true);
  const pipeline::FloatPipelineResources soft = resources.float_pipeline(format, family, false);
  const pipeline::WrapperCost wrapper = resources.wrapper();

  FloatDesignFit f;
  f.format = format;
  f.family = family.name;
  f.block_multiplier = family.block_multiplier;
  f.bits = format.bits_per_value();
  place_lanes(device, wrapper, lanes, hard, soft, f);
  f.modelled = true;
  return f;
}

int max_float_lanes(const DeviceProfile& device, const pipeline::ResourceModel& resources, pipeline::FloatFormat format) {
  int lanes = 0;
  while (lanes < static_cast<int>(LaneCount::kMax) && fit_float_design(device, resources, lanes + 1, format).fits) ++lanes;
  return lanes;
}

}  // namespace rc::board
