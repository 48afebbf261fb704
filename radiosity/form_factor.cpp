#include "radiosity/form_factor.h"

#include <stdexcept>

namespace rc {

FormFactorKind parse_form_factor_kind(const std::string& name) {
  if (name == "point") return FormFactorKind::PointToPoint;
  if (name == "disc") return FormFactorKind::Disc;
  throw std::invalid_argument("unknown form factor '" + name + "' (expected point or disc)");
}

std::string to_string(FormFactorKind kind) {
  return kind == FormFactorKind::PointToPoint ? "point" : "disc";
}

}  // namespace rc
