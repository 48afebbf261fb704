#include "host_sw/studies/study.h"

#include <algorithm>
#include <optional>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "profiles/profile_json.h"
#include "io/parse_number.h"
#include "rc_version.h"
#include "host_sw/studies/paper_workload.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {

namespace {

std::string where(const Study& s) { return "study " + (s.file.empty() ? s.name : s.file); }

// Every value of every profile axis, on every device and host swept, through the profile's own
// loader (with the fixed settings), so a bad value fails before any work with its path named. Each
// value is applied with the fixed settings in one go, so an error names the profile once with all of
// them ("xc2v6000.json with banks.word_bits=64, banks.capacity_bytes=76 (study s.toml): ...").
template <class Profile>
void check_values(const Study& s, const Profile& profile, ProfileKind kind) {
  const std::string study = s.file.empty() ? s.name : s.file;
  (void)with_settings(profile, s.fixed, study);
  for (const ProfileAxis& a : s.axes.profile) {
    if (a.field.kind != kind) continue;
    for (const ProfileValue& v : a.values) {
      std::vector<ProfileSetting> settings = s.fixed;
      settings.push_back({a.field, v});
      (void)with_settings(profile, settings, study);
    }
  }
}

// Rows, sweep keys and plots name a profile by its "name": two files of one name would make rows
// that cannot be told apart (and duplicate keys in sweep.json).
void check_distinct_name(const Study& s, std::map<std::string, std::string>& files, const std::string& name,
                         const std::string& file, const char* kind) {
  const auto [it, fresh] = files.emplace(name, file);
  if (!fresh) {
    throw std::invalid_argument(where(s) + ": two " + kind + " profiles are named '" + name + "': " + it->second +
                                " and " + file + "; rows and plots are keyed by the name: give each its own \"name\"");
  }
}

void check_profile_values(const Study& s) {
  std::map<std::string, std::string> device_files, host_files;
  for (const std::string& d : s.axes.devices) {
    const board::DeviceProfile p = board::find_device_profile(d);
    check_distinct_name(s, device_files, p.name, p.file, "device");
    check_values(s, p, ProfileKind::device);
  }
  for (const std::string& h : s.axes.hosts) {
    const HostProfile p = find_host_profile(h);
    check_distinct_name(s, host_files, p.name, p.file, "host");
    check_values(s, p, ProfileKind::host);
  }
}

// ---- settings that would change nothing --------------------------------------------------------
// A setting the model never reads in this study is an error, not a silent no-op: the sweep would
// print identical rows for every value and look like a finding.

// The names a host driver_model choice takes in this study: its values swept or fixed, else each
// host profile's own.
std::set<std::string> driver_choices(const Study& s, const std::string& choice) {
  std::set<std::string> values;
  const std::string field = "driver_model." + choice;
  for (const ProfileAxis& a : s.axes.profile)
    if (a.field.kind == ProfileKind::host && a.field.field == field)
      for (const ProfileValue& v : a.values) values.insert(std::get<std::string>(v));
  for (const ProfileSetting& f : s.fixed)
    if (f.field.kind == ProfileKind::host && f.field.field == field) values = {std::get<std::string>(f.value)};
  if (!values.empty()) return values;
  for (const std::string& h : s.axes.hosts) values.insert(profiles::json_of(find_host_profile(h).document).at("driver_model").at(choice).at("value").get<std::string>());
  return values;
}

// Why a profile field is never read in this study, or "" when it is.
std::string unused_because(const Study& s, const ProfileField& f) {
  const auto starts = [&](const char* prefix) { return f.field.rfind(prefix, 0) == 0; };
  if (f.kind == ProfileKind::device) {
    if (f.field == "banks.count") return "a sweep sets the bank count of every configuration: use the banks axis";
    if (f.field == "pci.master_abort_cycles")
      return "a master abort ends only an access no target claims, and the driver makes none";
    if (f.field == "clock.design_bits") {
      return "it records the width the profile's clocks were measured at; the design clock is the lower of the "
             "profile's and the pipeline's at the run's width (board/design_fit.cpp), so sweep bits instead";
    }
    if (starts("clock.mhz_by_lanes.")) {
      // The profile's loader has checked the key is a whole lane count (board/device_profile.cpp).
      const std::string key = f.field.substr(std::string("clock.mhz_by_lanes.").size());
      const std::optional<std::uint64_t> lanes = io::parse_unsigned(key);
      if (!lanes) return "'" + key + "' is not a lane count";
      if (std::find(s.axes.lanes.begin(), s.axes.lanes.end(), static_cast<int>(*lanes)) == s.axes.lanes.end())
        return "the study sweeps no configuration with " + key + " lane(s)";
    }
    return "";
  }
  if (f.field == "clock_mhz")
    return "the host's costs are seconds per unit of work; its clock is recorded in reports, not used in timing";
  static const std::map<std::string, std::string> per_unit = {
      {"driver_seconds.segment_pack", "per_segment"},      {"driver_seconds.result_unpack", "per_segment"},
      {"driver_seconds.face_pack", "per_segment"},         {"driver_seconds.coordinate_convert", "per_word"},
      {"driver_seconds.word_store", "per_word"},           {"driver_seconds.word_load", "per_word"}};
  const auto unit = per_unit.find(f.field);
  if (unit != per_unit.end() && driver_choices(s, "cost_unit").count(unit->second) == 0) {
    return "the driver model charges it only with cost unit " + unit->second +
           ", which no configuration of this study has (sweep or fix host.driver_model.cost_unit)";
  }
  if (f.field == "driver_model.pio_read_round_trip_seconds" && driver_choices(s, "transfer").count("pio") == 0)
    return "only programmed I/O reads wait for it, and no configuration transfers by pio (host.driver_model.transfer)";
  return "";
}

void check_settings_apply(const Study& s) {
  std::vector<const ProfileField*> fields;
  for (const ProfileAxis& a : s.axes.profile) fields.push_back(&a.field);
  for (const ProfileSetting& f : s.fixed) fields.push_back(&f.field);
  for (const ProfileField* f : fields) {
    const std::string why = unused_because(s, *f);
    if (!why.empty()) throw std::invalid_argument(where(s) + ": " + f->path + " changes nothing here: " + why);
  }
}

}  // namespace

ProfileField resolve_study_field(const std::string& path, const std::vector<std::string>& devices,
                                 const std::vector<std::string>& hosts) {
  if (devices.empty() || hosts.empty()) throw std::invalid_argument("profile path '" + path + "': no profile to resolve it in");
  const board::DeviceProfile d = board::find_device_profile(devices.front());
  const HostProfile h = find_host_profile(hosts.front());
  return resolve_profile_field(path, d.document, d.file, h.document, h.file);
}

std::string default_scene_name(const SceneOptions& o) {
  if (!o.file.empty()) return std::filesystem::path(o.file).stem().string();
  for (const PaperRow& row : default_paper_table()) {
    try {
      const SceneOptions p = paper_scene_options(row.faces, row.patches);
      if (p.face_target == o.face_target && p.face_levels == o.face_levels && p.patch_levels == o.patch_levels &&
          o.patch_size == 0)
        return "paper-" + std::to_string(row.faces) + "-" + std::to_string(row.patches);
    } catch (const std::invalid_argument&) {
    }
  }
  return "cornell-box";
}

void check_study(const Study& s) {
  if (s.scenes.empty()) throw std::invalid_argument(where(s) + ": no scenes");
  std::set<std::string> names;
  for (const StudyScene& scene : s.scenes) {
    if (scene.name.empty() || scene.name.find_first_of("/\\") != std::string::npos || scene.name == "." ||
        scene.name == "..")
      throw std::invalid_argument(where(s) + ": scene name '" + scene.name + "' cannot name a folder");
    if (!names.insert(scene.name).second) {
      throw std::invalid_argument(where(s) + ": two scenes are named '" + scene.name +
                                  "'; give each a distinct name (scenes.name)");
    }
  }
  if (!(s.convergence > 0 && s.convergence < 1))
    throw std::invalid_argument(where(s) + ": solver.convergence: must lie strictly between 0 and 1");
  try {
    (void)parse_form_factor_kind(s.form_factor);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(where(s) + ": solver.form_factor: " + e.what());
  }
  std::set<std::string> paths;
  for (const ProfileAxis& a : s.axes.profile) {
    if (!paths.insert(a.field.field + to_string(a.field.kind)).second)
      throw std::invalid_argument(where(s) + ": the profile field " + a.field.path + " is swept twice");
    for (const ProfileSetting& f : s.fixed)
      if (f.field.field == a.field.field && f.field.kind == a.field.kind)
        throw std::invalid_argument(where(s) + ": " + a.field.path + " is both an axis and fixed");
  }
  for (int c : s.axes.cards) {
    if (c < static_cast<int>(CardCount::kMin) || c > static_cast<int>(CardCount::kMax))
      throw std::invalid_argument(where(s) + ": axes.cards: " + std::to_string(c) + " is outside " + std::to_string(CardCount::kMin) + ".." +
                                  std::to_string(CardCount::kMax));
  }
  const bool several_cards = std::any_of(s.axes.cards.begin(), s.axes.cards.end(), [](int c) { return c > 1; });
  if (!several_cards && (s.axes.card_splits != std::vector<CardSplit>{CardSplit::rays} ||
                         s.axes.card_buses != std::vector<CardBus>{CardBus::shared})) {
    throw std::invalid_argument(where(s) + ": axes.card_split and axes.card_bus apply only with more than one card "
                                           "(axes.cards)");
  }
  (void)enumerate_configs(s.axes);  // empty axes and oversized sweeps
  check_profile_values(s);
  check_settings_apply(s);
}

void expand_form_factors(Study& s, const std::vector<std::string>& form_factors) {
  for (std::size_t i = 0; i < form_factors.size(); ++i) {
    (void)parse_form_factor_kind(form_factors[i]);
    for (std::size_t k = 0; k < i; ++k) {
      if (form_factors[k] == form_factors[i]) throw std::invalid_argument("form factor '" + form_factors[i] + "' given twice");
    }
  }
  std::vector<StudyScene> expanded;
  for (const StudyScene& scene : s.scenes) {
    for (const std::string& ff : form_factors) {
      StudyScene one = scene;
      one.name = scene.name + "-" + ff;
      one.form_factor = ff;
      expanded.push_back(std::move(one));
    }
  }
  s.scenes = std::move(expanded);
}

std::string tool_version() { return std::string("rc2000sim ") + RC_VERSION + " (" + RC_GIT_COMMIT + ")"; }

}  // namespace rc
