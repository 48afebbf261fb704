#include "host_sw/visibility_factory.h"

#include <stdexcept>

#include "host_sw/float_visibility.h"

namespace rc {

std::unique_ptr<VisibilityBackend> make_software_visibility(const std::string& name, int bits) {
  (void)bits;
  if (name == "float") return std::make_unique<FloatVisibility>();
  throw std::invalid_argument("unknown visibility backend '" + name + "' (expected float or fixed)");
}

}  // namespace rc
