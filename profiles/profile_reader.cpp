#include "profiles/profile_reader.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "profiles/profile_json.h"

namespace rc::profiles {

namespace {

using nlohmann::ordered_json;

const ordered_json* find_node(const ordered_json& root, const std::string& path) {
  const ordered_json* node = &root;
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

bool is_sourced(const ordered_json& node) { return node.is_object() && node.contains("value"); }

std::string parent_of(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

std::string child_of(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

}  // namespace

struct ReaderAccess {
  // Looks `path` up and remembers it as read (refuse_unknown_keys).
  static const ordered_json* find(const ProfileReader& r, const std::string& path) {
    r.read_.insert(path);
    return find_node(json_of(r.document_), path);
  }

  static const ordered_json& sourced(const ProfileReader& r, const std::string& path) {
    const ordered_json* node = find(r, path);
    if (node == nullptr) r.fail(path, "missing");
    if (!node->is_object() || !node->contains("value"))
      r.fail(path, "must be an object {\"value\": number, \"source\": \"where it came from\"}");
    const auto source = node->find("source");  // const operator[] on a missing key is undefined
    if (source == node->end() || !source->is_string() || source->get<std::string>().empty())
      r.fail(path, "has no \"source\" string (every number must say where it came from)");
    if (!(*node)["value"].is_number()) r.fail(path, "\"value\" must be a number");
    return *node;
  }

  static void check_known(const ProfileReader& r, const ordered_json& node, const std::string& path,
                          const std::vector<std::string>& free_form) {
    if (std::find(free_form.begin(), free_form.end(), path) != free_form.end()) return;
    const bool read = !path.empty() && (r.was_read(path) || r.was_read(path + ".value"));
    if (read && is_sourced(node)) {
      for (auto it = node.begin(); it != node.end(); ++it) {
        if (it.key() != "value" && it.key() != "source")
          r.fail(child_of(path, it.key()), "unknown key (a sourced field has only \"value\" and \"source\")");
      }
      return;
    }
    if (node.is_object() && !is_sourced(node)) {
      for (auto it = node.begin(); it != node.end(); ++it) check_known(r, it.value(), child_of(path, it.key()), free_form);
      return;
    }
    if (read) return;
    // The keys this loader reads beside the unknown one.
    std::set<std::string> known;
    const std::string parent = parent_of(path);
    for (std::string k : r.read_) {
      for (; !k.empty(); k = parent_of(k)) {
        if (parent_of(k) == parent) known.insert(k.substr(parent.empty() ? 0 : parent.size() + 1));
      }
    }
    for (const std::string& f : free_form)
      if (parent_of(f) == parent) known.insert(f.substr(parent.empty() ? 0 : parent.size() + 1));
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    r.fail(path, "unknown key" + (list.empty() ? std::string()
                                               : " (known " + (parent.empty() ? std::string("at the top") : "in " + parent) +
                                                     ": " + list + ")"));
  }
};

bool ProfileReader::has(const std::string& path) const { return ReaderAccess::find(*this, path) != nullptr; }

std::vector<std::string> ProfileReader::keys(const std::string& path, const std::string& problem) const {
  const ordered_json* node = ReaderAccess::find(*this, path);
  if (node == nullptr) return {};
  if (!node->is_object()) fail(path, problem);
  std::vector<std::string> out;
  for (auto it = node->begin(); it != node->end(); ++it) out.push_back(it.key());
  return out;
}

void ProfileReader::fail(const std::string& path, const std::string& problem) const {
  throw std::invalid_argument(file_ + ": " + path + ": " + problem);
}

void ProfileReader::refuse(const std::string& path, const std::string& value, const std::string& problem) const {
  throw std::invalid_argument(file_ + ": " + path + " = " + value + " " + problem);
}

void ProfileReader::schema(const std::string& expected) const {
  const ordered_json* node = ReaderAccess::find(*this, "schema");
  if (node == nullptr) return;
  if (!node->is_string() || node->get<std::string>() != expected)
    fail("schema", "is " + node->dump() + "; this reader takes \"" + expected + "\"");
}

void ProfileReader::refuse_unknown_keys(const std::vector<std::string>& free_form) const {
  ReaderAccess::check_known(*this, json_of(document_), "", free_form);
}

double ProfileReader::number(const std::string& path, double min, double max, bool integer) const {
  const double v = ReaderAccess::sourced(*this, path)["value"].get<double>();
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

std::string ProfileReader::source(const std::string& path) const {
  return ReaderAccess::sourced(*this, path)["source"].get<std::string>();
}

std::size_t ProfileReader::choice(const std::string& path, const std::vector<std::string>& allowed) const {
  std::string names;
  for (std::size_t i = 0; i < allowed.size(); ++i) names += (i ? ", " : "") + allowed[i];
  const ordered_json* node = ReaderAccess::find(*this, path);
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
  const ordered_json* node = ReaderAccess::find(*this, path);
  if (node == nullptr) fail(path, "missing");
  if (!node->is_string()) fail(path, "must be a string");
  return node->get<std::string>();
}

}  // namespace rc::profiles
