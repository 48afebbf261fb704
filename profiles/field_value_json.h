// profiles::FieldValue (field_value.h) at the JSON edge: the study codec's values, read and written.
#pragma once

#include <nlohmann/json.hpp>

#include "profiles/field_value.h"

namespace rc::profiles {

nlohmann::ordered_json field_value_json(const FieldValue& v);
// A number or a string; a whole number stays whole (an unsigned one above INT64_MAX becomes a
// double). Throws std::invalid_argument naming `what` for anything else.
FieldValue field_value_from_json(const nlohmann::ordered_json& j, const std::string& what);

}  // namespace rc::profiles
