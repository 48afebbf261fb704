#include "board/profile_reader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rc::board {

std::string default_config_dir() { return RC_CONFIG_DIR; }

std::string resolve_profile_path(const std::string& name_or_path, const std::string& kind) {
  const bool is_path = name_or_path.find('/') != std::string::npos ||
                       (name_or_path.size() > 5 && name_or_path.substr(name_or_path.size() - 5) == ".json");
  const std::string path = is_path ? name_or_path : default_config_dir() + "/" + kind + "/" + name_or_path + ".json";
  if (!std::filesystem::is_regular_file(path)) {
    throw std::invalid_argument("no " + kind + " profile '" + name_or_path + "' (looked for " + path + ")");
  }
  return path;
}

nlohmann::ordered_json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot open " + path);
  try {
    return nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(path + ": not valid JSON: " + e.what());
  }
}

const nlohmann::ordered_json* ProfileReader::find(const std::string& path) const {
  const nlohmann::ordered_json* node = &root_;
  std::stringstream parts(path);
  std::string key;
  while (std::getline(parts, key, '.')) {
    if (!node->is_object()) return nullptr;
    const auto it = node->find(key);
    if (it == node->end()) return nullptr;
    node = &*it;
  }
  return node;
}

void ProfileReader::fail(const std::string& path, const std::string& problem) const {
  throw std::invalid_argument(file_ + ": " + path + ": " + problem);
}

const nlohmann::ordered_json& ProfileReader::sourced(const std::string& path) const {
  const nlohmann::ordered_json* node = find(path);
  if (node == nullptr) fail(path, "missing");
  if (!node->is_object() || !node->contains("value"))
    fail(path, "must be an object {\"value\": number, \"source\": \"where it came from\"}");
  const auto& source = (*node)["source"];
  if (!source.is_string() || source.get<std::string>().empty())
    fail(path, "has no \"source\" string (every number must say where it came from)");
  if (!(*node)["value"].is_number()) fail(path, "\"value\" must be a number");
  return *node;
}

double ProfileReader::number(const std::string& path, double min, double max, bool integer) const {
  const double v = sourced(path)["value"].get<double>();
  if (!(v >= min && v <= max)) {
    std::ostringstream msg;
    msg << "value " << v << " is outside [" << min << ", " << max << "]";
    fail(path, msg.str());
  }
  if (integer && std::floor(v) != v) fail(path, "value must be a whole number");
  return v;
}

std::uint64_t ProfileReader::integer(const std::string& path, std::uint64_t min, std::uint64_t max) const {
  return static_cast<std::uint64_t>(number(path, static_cast<double>(min), static_cast<double>(max), true));
}

std::optional<double> ProfileReader::optional_number(const std::string& path, double min, double max) const {
  if (!has(path)) return std::nullopt;
  return number(path, min, max);
}

std::string ProfileReader::source(const std::string& path) const { return sourced(path)["source"].get<std::string>(); }

std::size_t ProfileReader::choice(const std::string& path, const std::vector<std::string>& allowed) const {
  std::string names;
  for (std::size_t i = 0; i < allowed.size(); ++i) names += (i ? ", " : "") + allowed[i];
  const nlohmann::ordered_json* node = find(path);
  if (node == nullptr) fail(path, "missing (one of " + names + ")");
  if (!node->is_object() || !node->contains("value"))
    fail(path, "must be an object {\"value\": name, \"source\": \"where it came from\"} (one of " + names + ")");
  const auto& source = (*node)["source"];
  if (!source.is_string() || source.get<std::string>().empty())
    fail(path, "has no \"source\" string (every choice must say where it came from)");
  if (!(*node)["value"].is_string()) fail(path, "\"value\" must be a name, one of " + names);
  const std::string value = (*node)["value"].get<std::string>();
  for (std::size_t i = 0; i < allowed.size(); ++i)
    if (value == allowed[i]) return i;
  fail(path, "'" + value + "' is not one of " + names);
}

std::string ProfileReader::text(const std::string& path) const {
  const nlohmann::ordered_json* node = find(path);
  if (node == nullptr) fail(path, "missing");
  if (!node->is_string()) fail(path, "must be a string");
  return node->get<std::string>();
}

}  // namespace rc::board
