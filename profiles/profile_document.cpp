#include "profiles/profile_document.h"

#include <filesystem>
#include <stdexcept>

#include "io/config_dir.h"
#include "io/json_text.h"
#include "profiles/profile_json.h"

namespace rc::profiles {

namespace {

using nlohmann::ordered_json;

bool sourced(const ordered_json& node) { return node.is_object() && node.contains("value"); }

void collect_fields(const ordered_json& node, const std::string& prefix, std::vector<std::string>& out) {
  if (!node.is_object()) return;
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string path = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (sourced(it.value())) {
      out.push_back(path);
    } else {
      collect_fields(it.value(), path, out);
    }
  }
}

// The node at a dotted path, or nullptr.
const ordered_json* find_field(const ordered_json& root, const std::string& path) {
  const ordered_json* node = &root;
  std::size_t from = 0;
  while (true) {
    const std::size_t dot = path.find('.', from);
    const std::string key = path.substr(from, dot == std::string::npos ? std::string::npos : dot - from);
    if (!node->is_object()) return nullptr;
    const auto it = node->find(key);
    if (it == node->end()) return nullptr;
    node = &*it;
    if (dot == std::string::npos) return node;
    from = dot + 1;
  }
}

}  // namespace

ProfileDocument::ProfileDocument() : tree_(std::make_shared<const Tree>(Tree{ordered_json::object()})) {}

ProfileDocument document_of(ordered_json json) {
  return ProfileDocument(std::make_shared<const ProfileDocument::Tree>(ProfileDocument::Tree{std::move(json)}));
}

std::vector<std::string> ProfileDocument::sourced_fields() const {
  std::vector<std::string> fields;
  collect_fields(tree_->json, "", fields);
  return fields;
}

bool ProfileDocument::is_sourced(const std::string& path) const {
  const ordered_json* node = find_field(tree_->json, path);
  return node != nullptr && sourced(*node);
}

bool ProfileDocument::holds_number(const std::string& path) const {
  return is_sourced(path) && find_field(tree_->json, path)->at("value").is_number();
}

std::vector<std::string> ProfileDocument::top_keys() const {
  std::vector<std::string> keys;
  if (tree_->json.is_object())
    for (auto it = tree_->json.begin(); it != tree_->json.end(); ++it) keys.push_back(it.key());
  return keys;
}

ProfileDocument ProfileDocument::with_field(const std::string& path, const FieldValue& value,
                                            const std::string& source) const {
  ordered_json json = tree_->json;
  ordered_json* node = &json;
  std::size_t from = 0;
  for (std::size_t dot = path.find('.'); ; dot = path.find('.', from)) {
    node = &(*node)[path.substr(from, dot == std::string::npos ? std::string::npos : dot - from)];
    if (dot == std::string::npos) break;
    from = dot + 1;
  }
  std::visit([&](const auto& v) { (*node)["value"] = v; }, value);
  (*node)["source"] = source;
  return document_of(std::move(json));
}

std::string ProfileDocument::value_text(const std::string& path) const {
  const ordered_json* node = find_field(tree_->json, path);
  return node != nullptr && sourced(*node) ? node->at("value").dump() : std::string();
}

bool ProfileDocument::operator==(const ProfileDocument& other) const { return tree_->json == other.tree_->json; }

std::string default_config_dir() { return io::config_dir(); }

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

ordered_json read_json_file(const std::string& path, std::uint64_t limit_bytes, const std::string& what) {
  try {
    return io::parse_json_text<ordered_json>(io::read_file(path, limit_bytes, what), path);
  } catch (const io::InputFileError& e) {  // the file, or its text (io/json_text.h)
    throw std::invalid_argument(e.what());
  }
}

ProfileDocument read_profile_document(const std::string& path, const std::string& what) {
  return document_of(read_json_file(path, io::kProfileLimitBytes, what));
}

}  // namespace rc::profiles
