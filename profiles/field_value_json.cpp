#include "profiles/field_value_json.h"

#include <cstdint>
#include <stdexcept>

namespace rc::profiles {

nlohmann::ordered_json field_value_json(const FieldValue& v) {
  return std::visit([](const auto& x) { return nlohmann::ordered_json(x); }, v);
}

FieldValue field_value_from_json(const nlohmann::ordered_json& j, const std::string& what) {
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number_integer() && (!j.is_number_unsigned() || j.get<std::uint64_t>() <= INT64_MAX))
    return j.get<std::int64_t>();
  if (j.is_number()) return j.get<double>();
  throw std::invalid_argument(what + ": expected a number or a name, got " + j.dump());
}

std::string json_text(const FieldValue& v) { return field_value_json(v).dump(); }

std::string plain_text(const FieldValue& v) {
  return is_number(v) ? json_text(v) : std::get<std::string>(v);
}

}  // namespace rc::profiles
