#include "host_sw/studies/profile_setting.h"

#include <algorithm>
#include <stdexcept>

namespace rc {

namespace {

bool is_sourced(const nlohmann::ordered_json& node) { return node.is_object() && node.contains("value"); }

void collect_fields(const nlohmann::ordered_json& node, const std::string& prefix, std::vector<std::string>& out) {
  if (!node.is_object()) return;
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string path = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (is_sourced(it.value())) {
      out.push_back(path);
    } else {
      collect_fields(it.value(), path, out);
    }
  }
}

// The node at a dotted path, or nullptr; Json is const or not.
template <class Json>
Json* find_field(Json& profile, const std::string& field) {
  Json* node = &profile;
  std::size_t from = 0;
  while (true) {
    const std::size_t dot = field.find('.', from);
    const std::string key = field.substr(from, dot == std::string::npos ? std::string::npos : dot - from);
    if (!node->is_object() || !node->contains(key)) return nullptr;
    node = &(*node)[key];
    if (dot == std::string::npos) return node;
    from = dot + 1;
  }
}

std::string last_part(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& s : items) text += (text.empty() ? "" : ", ") + s;
  return text;
}

// The fields worth listing when `wanted` names none: those of its section when the section exists,
// else every field.
std::vector<std::string> nearby_fields(const std::vector<std::string>& fields, const std::string& wanted) {
  const std::string section = wanted.substr(0, wanted.find('.')) + ".";
  std::vector<std::string> near;
  for (const std::string& f : fields)
    if (f.rfind(section, 0) == 0) near.push_back(f);
  return near.empty() ? fields : near;
}

std::string resolve_field(const std::string& path, const std::string& wanted, const nlohmann::ordered_json& profile,
                          const std::string& file) {
  const std::vector<std::string> fields = sourced_fields(profile);
  if (std::find(fields.begin(), fields.end(), wanted) != fields.end()) return wanted;
  std::vector<std::string> by_leaf;
  if (wanted.find('.') == std::string::npos) {
    for (const std::string& f : fields)
      if (last_part(f) == wanted) by_leaf.push_back(f);
  }
  if (by_leaf.size() == 1) return by_leaf.front();
  if (by_leaf.size() > 1) {
    throw std::invalid_argument("profile path '" + path + "': '" + wanted + "' names several fields of " + file + " (" +
                                joined(by_leaf) + "); write the whole path");
  }
  throw std::invalid_argument("profile path '" + path + "': " + file + " has no sourced field '" + wanted +
                              "'; fields there: " + joined(nearby_fields(fields, wanted)) +
                              (path.rfind("host.", 0) == 0 ? "" : " (host profile fields start with \"host.\")"));
}

nlohmann::ordered_json applied(nlohmann::ordered_json json, const std::vector<ProfileSetting>& settings,
                               ProfileKind kind, const std::string& study, const std::string& file) {
  for (const ProfileSetting& s : settings) {
    if (s.field.kind != kind) continue;
    nlohmann::ordered_json* node = find_field(json, s.field.field);
    if (node == nullptr || !is_sourced(*node)) {
      throw std::invalid_argument("profile path '" + s.field.path + "': " + file + " has no sourced field '" +
                                  s.field.field + "' (study " + study + ")");
    }
    check_setting_value(s.field, s.value, "study " + study);
    const std::string was = (*node)["value"].dump();
    (*node)["value"] = s.value;
    (*node)["source"] = "study " + study + ": " + s.text() + " (the profile's value: " + was + ")";
  }
  return json;
}

// "file with a=1, b=2 (study s)" for error messages; just `file` without settings of this kind.
std::string origin(const std::string& file, const std::vector<ProfileSetting>& settings, ProfileKind kind,
                   const std::string& study) {
  std::vector<std::string> texts;
  for (const ProfileSetting& s : settings)
    if (s.field.kind == kind) texts.push_back(s.text());
  return texts.empty() ? file : file + " with " + joined(texts) + " (study " + study + ")";
}

}  // namespace

const char* to_string(ProfileKind kind) { return kind == ProfileKind::host ? "host" : "device"; }

std::vector<std::string> sourced_fields(const nlohmann::ordered_json& profile) {
  std::vector<std::string> fields;
  collect_fields(profile, "", fields);
  return fields;
}

ProfileField resolve_profile_field(const std::string& path, const nlohmann::ordered_json& device_profile,
                                   const std::string& device_file, const nlohmann::ordered_json& host_profile,
                                   const std::string& host_file) {
  ProfileField f;
  f.path = path;
  std::string wanted = path;
  if (path.rfind("host.", 0) == 0) {
    f.kind = ProfileKind::host;
    wanted = path.substr(5);
  } else if (path.rfind("device.", 0) == 0) {
    wanted = path.substr(7);
  }
  if (wanted.empty()) throw std::invalid_argument("profile path '" + path + "': names no field");
  const bool host = f.kind == ProfileKind::host;
  f.field = resolve_field(path, wanted, host ? host_profile : device_profile, host ? host_file : device_file);
  f.numeric = find_field(host ? host_profile : device_profile, f.field)->at("value").is_number();
  return f;
}

std::string ProfileSetting::text() const {
  return field.path + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
}

void check_setting_value(const ProfileField& field, const nlohmann::ordered_json& value, const std::string& where) {
  // A caller that names the place itself (a study file's "file:line: key: ") gives no `where`.
  const std::string place = where.empty() ? "" : where + ": " + field.path + ": ";
  if (field.numeric && !value.is_number()) {
    throw std::invalid_argument(place + "expected a number (the profile's " + field.field + " is a number), got " +
                                value.dump());
  }
  if (!field.numeric && !value.is_string()) {
    throw std::invalid_argument(place + "expected a name (the profile's " + field.field + " is a name), got " +
                                value.dump());
  }
}

board::DeviceProfile with_settings(const board::DeviceProfile& base, const std::vector<ProfileSetting>& settings,
                                   const std::string& study) {
  return board::device_profile_from_json(applied(base.json, settings, ProfileKind::device, study, base.file),
                                         origin(base.file, settings, ProfileKind::device, study));
}

HostProfile with_settings(const HostProfile& base, const std::vector<ProfileSetting>& settings, const std::string& study) {
  return host_profile_from_json(applied(base.json, settings, ProfileKind::host, study, base.file),
                                origin(base.file, settings, ProfileKind::host, study));
}

}  // namespace rc
