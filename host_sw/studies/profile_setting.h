// A study's setting of one profile field by its path: any sourced number or named choice of a device
// profile (configs/devices/*.json: fpga, clock, pipeline, banks, pci, wrapper) or of a host profile
// (configs/hosts/*.json, prefixed "host."), as a sweep axis or a fixed override (docs/studies.md).
//
//   "banks.clock_mhz"              -> the device profile's banks.clock_mhz
//   "device.pci.width_bits"        -> the same as "pci.width_bits" (the prefix is optional)
//   "host.driver_seconds.word_store", or "host.word_store" when the leaf name is unique
//
// A path is checked against the profile itself: it must name a sourced field ({"value", "source"}),
// and a value must have the field's type (a number for a number, a name for a name). The profile
// with its settings is then read by the profile's own loader, so ranges and relations are checked
// in one place (board::device_profile_from_document, host_profile_from_document). The settings are
// applied to the profile's document at the profile edge (profiles::ProfileDocument::with_field).
// A value is typed (profiles::FieldValue); the study codecs convert it at their edges
// (profiles/field_value_json.h).
#pragma once

#include <string>
#include <vector>

#include "board/device_profile.h"
#include "host_sw/driver/host_cpu_model.h"
#include "profiles/field_value.h"

namespace rc {

enum class ProfileKind { device, host };
const char* to_string(ProfileKind kind);  // "device", "host"

struct ProfileField {
  std::string path;   // as written: "banks.clock_mhz", "host.word_store"
  ProfileKind kind = ProfileKind::device;
  std::string field;  // the dotted path inside the profile: "driver_seconds.word_store"
  bool numeric = true;  // the field holds a number (else a name)
};

// Resolves `path` against `profile` (a device profile's document when the path has no "host." prefix,
// else a host profile's). Throws std::invalid_argument naming the path, the profile's file
// (`profile_file`) and the fields that do exist nearby.
ProfileField resolve_profile_field(const std::string& path, const profiles::ProfileDocument& device_profile,
                                   const std::string& device_file, const profiles::ProfileDocument& host_profile,
                                   const std::string& host_file);

struct ProfileSetting {
  ProfileField field;
  profiles::FieldValue value;    // a number or a name, of the field's type
  std::string text() const;      // "banks.clock_mhz=133"
};

// Throws std::invalid_argument (naming `where` and the path, unless `where` is empty) unless `value`
// has the field's type.
void check_setting_value(const ProfileField& field, const profiles::FieldValue& value, const std::string& where);

// The profile with every setting of its kind applied and read back by the profile's own loader
// (errors name the profile file, the settings and `study`, e.g. "xc2v6000.json with
// banks.clock_mhz=0 (study s.toml): banks.clock_mhz: ..."). Settings of the other kind are skipped.
board::DeviceProfile with_settings(const board::DeviceProfile& base, const std::vector<ProfileSetting>& settings,
                                   const std::string& study);
HostProfile with_settings(const HostProfile& base, const std::vector<ProfileSetting>& settings, const std::string& study);

}  // namespace rc
