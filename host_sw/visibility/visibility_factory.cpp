#include "host_sw/visibility/visibility_factory.h"

#include <stdexcept>

#include "host_sw/visibility/fast_visibility.h"
#include "host_sw/visibility/fixed_visibility.h"
#include "host_sw/visibility/float_pipeline_visibility.h"
#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/visibility/needed_only_visibility.h"
#include "host_sw/visibility/shooter_memo_visibility.h"

namespace rc {

std::unique_ptr<VisibilityBackend> make_software_visibility(SoftwareVisibility kind, int bits, int threads, int t_guard) {
  switch (kind) {
    case SoftwareVisibility::float_double:
      if (t_guard != 0) throw std::invalid_argument("a t guard band needs the fixed-point pipeline: double-precision visibility has no LSB");
      return std::make_unique<FloatVisibility>();
    case SoftwareVisibility::fixed: return std::make_unique<FixedPointVisibility>(bits, t_guard);
    case SoftwareVisibility::fast: return std::make_unique<FastFixedVisibility>(bits, threads, t_guard);
  }
  throw std::logic_error("make_software_visibility: not a SoftwareVisibility");
}

std::unique_ptr<VisibilityBackend> make_software_visibility(const std::string& name, int bits, int threads, int t_guard) {
  if (pipeline::names_float_format(name)) {
    if (t_guard != 0) throw std::invalid_argument("a t guard band needs the fixed-point pipeline, not " + name);
    return std::make_unique<FloatPipelineVisibility>(pipeline::parse_float_format(name));
  }
  // Only the name's error gets the float hint; the backend's own (a width, RC2000SIM_SIMD) pass as
  // they are.
  SoftwareVisibility kind;
  try {
    kind = parse_choice<SoftwareVisibility>(name);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()) + " or float:E,M");
  }
  return make_software_visibility(kind, bits, threads, t_guard);
}

std::unique_ptr<VisibilityBackend> make_functional_answer(const std::string& name, int bits, int threads, int t_guard) {
  return std::make_unique<ShooterMemoVisibility>(
      std::make_unique<NeededOnlyVisibility>(make_software_visibility(name, bits, threads, t_guard)));
}

}  // namespace rc
