// What a reader needs to know of a JSON text before choosing its reader (a scene file's format: a
// composition has "schema", glTF has "asset"), without seeing JSON values: the top-level keys.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rc::io {

// The keys of the top-level object in file order, or nullopt when the text is JSON but not an object.
// Throws JsonTextError (io/json_text.h) for text that is not valid JSON, naming `path`.
std::optional<std::vector<std::string>> json_object_keys(std::string_view text, const std::string& path);

}  // namespace rc::io
