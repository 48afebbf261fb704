// The registry of Verilated models, generated per build (rtl/CMakeLists.txt writes rtl_models.cpp; a
// build without Verilator gets an empty registry). Internal to rtl/sim.
#pragma once

#include <memory>
#include <vector>

#include "rtl/sim/rtl_pipeline.h"

namespace rc::rtl::detail {

std::vector<int> model_widths(bool array_multipliers);
std::unique_ptr<RtlPipeline> make_model(int bits, bool array_multipliers);  // a width model_widths lists

}  // namespace rc::rtl::detail
