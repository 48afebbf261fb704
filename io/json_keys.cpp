#include "io/json_keys.h"

#include "io/json_text.h"

namespace rc::io {

std::optional<std::vector<std::string>> json_object_keys(std::string_view text, const std::string& path) {
  const nlohmann::ordered_json j = parse_json_text<nlohmann::ordered_json>(text, path);
  if (!j.is_object()) return std::nullopt;
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  return keys;
}

}  // namespace rc::io
