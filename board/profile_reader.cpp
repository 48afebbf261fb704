#include "board/profile_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "io/config_dir.h"
#include "io/json_text.h"

namespace rc::board {

std::string default_config_dir() { return io::config_dir(RC_CONFIG_DIR); }  // io/config_dir.h

std::string resolve_profile_path(const std::string& name_or_path, const std::string& kind) {
  const bool is_path = name_or_path.find('/') != std::string::npos ||
                       (name_or_path.size() > 5 && name_or_path.substr(name_or_path.size() - 5) == ".json");
  const std::string path = is_path ? name_or_path : default_config_dir() + "/" + kind + "/" + name_or_path + ".json";
  std::error_code absent;
  if (!std::filesystem::exists(path, absent)) {
    throw std::invalid_argument("no " + kind + " profile '" + name_or_path + "' (looked for " + path + ")");
  }
  try {  // there, but a folder, a device or a pipe: say so rather than "no profile"
    const std::string singular = !kind.empty() && kind.back() == 's' ? kind.substr(0, kind.size() - 1) : kind;
    io::check_regular_file(path, io::kProfileLimitBytes, "a " + singular + " profile");
  } catch (const io::InputFileError& e) {
    throw std::invalid_argument(e.what());
  }
  return path;
}

nlohmann::ordered_json read_json_file(const std::string& path, std::uint64_t limit_bytes, const std::string& what) {
  try {
    return io::parse_json_text<nlohmann::ordered_json>(io::read_file(path, limit_bytes, what), path);
  } catch (const io::InputFileError& e) {  // the file, or its text (io/json_text.h)
    throw std::invalid_argument(e.what());
  }
}

namespace {

const nlohmann::ordered_json* find_node(const nlohmann::ordered_json& root, const std::string& path) {
  const nlohmann::ordered_json* node = &root;
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

}  // namespace

const nlohmann::ordered_json* ProfileReader::find(const std::string& path) const {
  read_.insert(path);
  return find_node(root_, path);
}

void ProfileReader::fail(const std::string& path, const std::string& problem) const {
  throw std::invalid_argument(file_ + ": " + path + ": " + problem);
}

void ProfileReader::refuse(const std::string& path, const std::string& value, const std::string& problem) const {
  throw std::invalid_argument(file_ + ": " + path + " = " + value + " " + problem);
}

void ProfileReader::schema(const std::string& expected) const {
  const nlohmann::ordered_json* node = find("schema");
  if (node == nullptr) return;
  if (!node->is_string() || node->get<std::string>() != expected)
    fail("schema", "is " + node->dump() + "; this reader takes \"" + expected + "\"");
}

namespace {

bool is_sourced(const nlohmann::ordered_json& node) { return node.is_object() && node.contains("value"); }

std::string parent_of(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

std::string child_of(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

}  // namespace

void ProfileReader::refuse_unknown_keys(const std::vector<std::string>& free_form) const {
  check_known(root_, "", free_form);
}

void ProfileReader::check_known(const nlohmann::ordered_json& node, const std::string& path,
                                const std::vector<std::string>& free_form) const {
  if (std::find(free_form.begin(), free_form.end(), path) != free_form.end()) return;
  const bool read = !path.empty() && (was_read(path) || was_read(path + ".value"));
  if (read && is_sourced(node)) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (it.key() != "value" && it.key() != "source")
        fail(child_of(path, it.key()), "unknown key (a sourced field has only \"value\" and \"source\")");
    }
    return;
  }
  if (node.is_object() && !is_sourced(node)) {
    for (auto it = node.begin(); it != node.end(); ++it) check_known(it.value(), child_of(path, it.key()), free_form);
    return;
  }
  if (read) return;
  // The keys this loader reads beside the unknown one.
  std::set<std::string> known;
  const std::string parent = parent_of(path);
  for (std::string r : read_) {
    for (; !r.empty(); r = parent_of(r)) {
      if (parent_of(r) == parent) known.insert(r.substr(parent.empty() ? 0 : parent.size() + 1));
    }
  }
  for (const std::string& f : free_form)
    if (parent_of(f) == parent) known.insert(f.substr(parent.empty() ? 0 : parent.size() + 1));
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
  fail(path, "unknown key" + (list.empty() ? std::string() : " (known " + (parent.empty() ? std::string("at the top")
                                                                                          : "in " + parent) +
                                                                    ": " + list + ")"));
}

const nlohmann::ordered_json& ProfileReader::sourced(const std::string& path) const {
  const nlohmann::ordered_json* node = find(path);
  if (node == nullptr) fail(path, "missing");
  if (!node->is_object() || !node->contains("value"))
    fail(path, "must be an object {\"value\": number, \"source\": \"where it came from\"}");
  const auto source = node->find("source");  // const operator[] on a missing key is undefined
  if (source == node->end() || !source->is_string() || source->get<std::string>().empty())
    fail(path, "has no \"source\" string (every number must say where it came from)");
  if (!(*node)["value"].is_number()) fail(path, "\"value\" must be a number");
  return *node;
}

double ProfileReader::number(const std::string& path, double min, double max, bool integer) const {
  const double v = sourced(path)["value"].get<double>();
  if (!(v >= min && v <= max)) {
    std::ostringstream msg;
    msg << std::setprecision(15);  // limits such as 1048576 and 4294967295 in full, not 1.04858e+06
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
  const auto source = node->find("source");  // const operator[] on a missing key is undefined
  if (source == node->end() || !source->is_string() || source->get<std::string>().empty())
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
