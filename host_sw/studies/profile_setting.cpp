#include "host_sw/studies/profile_setting.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace rc {

namespace {

std::string last_part(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

std::string comma_joined(const std::vector<std::string>& items) {
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

std::string resolve_field(const std::string& path, const std::string& wanted, const profiles::ProfileDocument& profile,
                          const std::string& file) {
  const std::vector<std::string> fields = profile.sourced_fields();
  if (std::find(fields.begin(), fields.end(), wanted) != fields.end()) return wanted;
  std::vector<std::string> by_leaf;
  if (wanted.find('.') == std::string::npos) {
    for (const std::string& f : fields)
      if (last_part(f) == wanted) by_leaf.push_back(f);
  }
  if (by_leaf.size() == 1) return by_leaf.front();
  if (by_leaf.size() > 1) {
    throw std::invalid_argument("profile path '" + path + "': '" + wanted + "' names several fields of " + file + " (" +
                                comma_joined(by_leaf) + "); write the whole path");
  }
  throw std::invalid_argument("profile path '" + path + "': " + file + " has no sourced field '" + wanted +
                              "'; fields there: " + comma_joined(nearby_fields(fields, wanted)) +
                              (path.rfind("host.", 0) == 0 ? "" : " (host profile fields start with \"host.\")"));
}

profiles::ProfileDocument applied(profiles::ProfileDocument document, const std::vector<ProfileSetting>& settings,
                                  ProfileKind kind, const std::string& study, const std::string& file) {
  for (const ProfileSetting& s : settings) {
    if (s.field.kind != kind) continue;
    if (!document.is_sourced(s.field.field)) {
      throw std::invalid_argument("profile path '" + s.field.path + "': " + file + " has no sourced field '" +
                                  s.field.field + "' (study " + study + ")");
    }
    check_setting_value(s.field, s.value, "study " + study);
    const std::string was = document.value_text(s.field.field);
    document = document.with_field(s.field.field, s.value,
                                   "study " + study + ": " + s.text() + " (the profile's value: " + was + ")");
  }
  return document;
}

// "file with a=1, b=2 (study s)" for error messages; just `file` without settings of this kind.
std::string origin(const std::string& file, const std::vector<ProfileSetting>& settings, ProfileKind kind,
                   const std::string& study) {
  std::vector<std::string> texts;
  for (const ProfileSetting& s : settings)
    if (s.field.kind == kind) texts.push_back(s.text());
  return texts.empty() ? file : file + " with " + comma_joined(texts) + " (study " + study + ")";
}

}  // namespace

const char* to_string(ProfileKind kind) { return kind == ProfileKind::host ? "host" : "device"; }

ProfileField resolve_profile_field(const std::string& path, const profiles::ProfileDocument& device_profile,
                                   const std::string& device_file, const profiles::ProfileDocument& host_profile,
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
  f.numeric = (host ? host_profile : device_profile).holds_number(f.field);
  return f;
}

std::string ProfileSetting::text() const {
  return field.path + "=" + profiles::plain_text(value);
}

void check_setting_value(const ProfileField& field, const profiles::FieldValue& value, const std::string& where) {
  // A caller that names the place itself (a study file's "file:line: key: ") gives no `where`.
  const std::string place = where.empty() ? "" : where + ": " + field.path + ": ";
  if (field.numeric && !profiles::is_number(value)) {
    throw std::invalid_argument(place + "expected a number (the profile's " + field.field + " is a number), got " +
                                profiles::json_text(value));
  }
  if (!field.numeric && profiles::is_number(value)) {
    throw std::invalid_argument(place + "expected a name (the profile's " + field.field + " is a name), got " +
                                profiles::json_text(value));
  }
}

board::DeviceProfile with_settings(const board::DeviceProfile& base, const std::vector<ProfileSetting>& settings,
                                   const std::string& study) {
  return board::device_profile_from_document(applied(base.document, settings, ProfileKind::device, study, base.file),
                                         origin(base.file, settings, ProfileKind::device, study));
}

HostProfile with_settings(const HostProfile& base, const std::vector<ProfileSetting>& settings, const std::string& study) {
  return host_profile_from_document(applied(base.document, settings, ProfileKind::host, study, base.file),
                                origin(base.file, settings, ProfileKind::host, study));
}

}  // namespace rc
