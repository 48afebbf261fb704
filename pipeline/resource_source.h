// Where a design's slices and block multipliers come from (docs/pipeline.md, "Two sources of
// resources"). The clock always comes from the paper's figures: a synthesizer before place and route
// gives no clock for these families.
//   paper_fit: the paper's place-and-route figures (sec 5.2 table, Table 1) where it measured, a fit
//              through them elsewhere (pipeline/resource_model.h); the default.
//   synthesis: Yosys's counts of rtl/mt_pipeline.v for the device's family (configs/synthesis_resources.json)
//              turned into slices by a fit on the paper's published points (pipeline/synthesis_resources.h).
#pragma once

#include <array>
#include <string_view>

#include "io/choice.h"

namespace rc::pipeline {

enum class ResourceSource { paper_fit, synthesis };

}  // namespace rc::pipeline

template <>
struct rc::ChoiceNames<rc::pipeline::ResourceSource> {  // --resources NAME; report.json "resources"
  static constexpr std::string_view what = "resource source";
  static constexpr std::array<std::string_view, 2> names = {"paper", "synthesis"};
};
