#include "rtl/sim/rtl_pipeline.h"

#include <sstream>
#include <stdexcept>

#include "rtl/sim/rtl_models.h"

namespace rc::rtl {

namespace {

std::string list(const std::vector<int>& widths) {
  std::ostringstream out;
  for (std::size_t i = 0; i < widths.size(); ++i) out << (i ? ", " : "") << widths[i];
  return out.str();
}

}  // namespace

bool rtl_models_built() { return !detail::model_widths(false).empty(); }
std::vector<int> rtl_widths() { return detail::model_widths(false); }
std::vector<int> rtl_array_widths() { return detail::model_widths(true); }

std::string rtl_unavailable_reason(int bits, bool array_multipliers) {
  if (!rtl_models_built())
    return "this build has no Verilated RTL models (Verilator was not found when it was configured; "
           "install the package verilator and configure again)";
  const std::vector<int> widths = detail::model_widths(array_multipliers);
  for (int w : widths)
    if (w == bits) return "";
  return "the RTL pipeline " + std::string(array_multipliers ? "with array multipliers " : "") +
         "is built for fractional widths " + list(widths) + " only, not " + std::to_string(bits) +
         " (configure with -DRC_RTL_WIDTHS=... to add widths)";
}

std::unique_ptr<RtlPipeline> make_rtl_pipeline(int bits, bool array_multipliers) {
  const std::string why = rtl_unavailable_reason(bits, array_multipliers);
  if (!why.empty()) throw std::invalid_argument(why);
  std::unique_ptr<RtlPipeline> model = detail::make_model(bits, array_multipliers);
  model->reset();
  return model;
}

}  // namespace rc::rtl
