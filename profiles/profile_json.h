// The JSON side of the profile edge, for the edge itself and the output edge (*_json.cpp writers):
// a ProfileDocument's tree is the parsed file as nlohmann::ordered_json. Model code includes
// profile_document.h and profile_reader.h, never this.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "io/input_file.h"
#include "profiles/profile_document.h"

namespace rc::profiles {

struct ProfileDocument::Tree {
  nlohmann::ordered_json json;
};

inline const nlohmann::ordered_json& json_of(const ProfileDocument& document) { return document.tree().json; }
ProfileDocument document_of(nlohmann::ordered_json json);

// Parses a JSON file of at most `limit_bytes` through io/json_text.h; throws std::invalid_argument
// with the file name on I/O, text or syntax errors.
nlohmann::ordered_json read_json_file(const std::string& path, std::uint64_t limit_bytes = io::kProfileLimitBytes,
                                      const std::string& what = "a profile");

}  // namespace rc::profiles
