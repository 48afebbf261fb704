#include "apps/sweep_json.h"

#include <iterator>
#include <sstream>

#include "host_sw/studies/study_json.h"
#include "host_sw/studies/sweep_columns.h"
#include "host_sw/studies/sweep_row_json.h"
#include "host_sw/studies/workload_json.h"
#include "profiles/field_value_json.h"

namespace rc {

nlohmann::ordered_json software_at(const SceneSweep& r, int bits) {
  const std::string prefix = std::to_string(bits) + "-bit ";
  nlohmann::ordered_json by_key = nlohmann::ordered_json::object();
  for (const auto& [key, seconds] : r.software_seconds)
    if (key.rfind(prefix, 0) == 0) by_key[key] = seconds;
  return by_key.size() == 1 ? by_key.begin().value() : by_key;
}

nlohmann::ordered_json sweep_json(const Study& s, const SceneSweep& r, const std::vector<SweptFit>& fits) {
  nlohmann::ordered_json j;
  j["schema"] = "rc2000sim.sweep/1";
  j["scene"] = {{"name", r.scene.name}, {"source", r.scene.source}, {"faces", r.scene.faces}, {"patches", r.scene.patches}};
  j["solver"] = {{"paper_faithful", s.paper_faithful}, {"steps_policy", to_string(s.steps)}, {"convergence", s.convergence},
                 {"visibility", choice_name(s.visibility)}};
  if (s.form_factor != Study{}.form_factor) j["solver"]["form_factor"] = s.form_factor;  // point: as before it existed
  for (const StudyScene& scene : s.scenes) {  // the scene's workload (workload.h), as `run` records it
    if (scene.name == r.scene.name) j["workload"] = workload_json(study_workload(s, scene), r.scene.faces, r.scene.patches, 0);
  }
  j["host_profile"] = s.axes.hosts.size() == 1 ? nlohmann::ordered_json(s.axes.hosts.front())
                                               : nlohmann::ordered_json(s.axes.hosts);
  nlohmann::ordered_json w = nlohmann::ordered_json::array();
  for (const auto& [bits, width] : r.widths) {
    w.push_back({{"bits", bits},
                 {"steps", width.steps},
                 {"convergence_step", width.convergence_step > 0  // null: not within the replayed steps
                                          ? nlohmann::ordered_json(width.convergence_step)
                                          : nlohmann::ordered_json()},
                 {"max_segments_per_step", width.max_segments},
                 {"software_seconds", software_at(r, bits)}});
  }
  j["widths"] = w;
  nlohmann::ordered_json banks;
  for (const auto& [device, bytes] : r.bank_capacities) banks[device] = bytes;
  j["modelled_bank_capacity_bytes"] = banks;
  j["bank_capacity_note"] =
      "0: the profile's banks. Otherwise banks of this size, which change no pass, transfer or time for this "
      "scene (no step batches with either size; host_sw/studies/config_checker.cpp, compact_bank_capacity), to keep the model's memory small";
  nlohmann::ordered_json estimates = nlohmann::ordered_json::array();
  for (const SweptFit& f : fits) {
    nlohmann::ordered_json e = {{"device", f.cannot_exist.empty() ? f.estimates.model.device : f.device}, {"bits", f.bits}};
    if (!f.settings.empty()) {  // the device-profile axis values this estimate used
      nlohmann::ordered_json settings = nlohmann::ordered_json::object();
      for (const ProfileSetting& p : f.settings) settings[p.field.path] = profiles::field_value_json(p.value);
      e["settings"] = settings;
    }
    if (f.cannot_exist.empty()) {
      e.update(lanes_that_fit_json(f.estimates));
    } else {
      e["cannot_exist"] = f.cannot_exist;
    }
    estimates.push_back(e);
  }
  j["lanes_that_fit"] = estimates;
  if (sweeps_device_fields(s)) {
    j["lanes_that_fit_note"] = "on the device profiles with the study's fixed settings and each combination of the "
                               "swept device fields' values (settings), as the rows with those values use them";
  }
  const std::vector<std::string> extra = extra_columns(s.axes);
  nlohmann::ordered_json records = nlohmann::ordered_json::array();
  for (const SweepRow& row : r.rows) records.push_back(sweep_row_json(row, extra));
  j["rows"] = records;
  return j;
}

std::string sweep_json_text(const nlohmann::ordered_json& j) {
  std::ostringstream out;
  out << "{\n";
  for (auto it = j.begin(); it != j.end(); ++it) {
    out << "  " << nlohmann::json(it.key()).dump() << ": ";
    if (it.key() != "rows") {
      out << it.value().dump() << (std::next(it) != j.end() ? ",\n" : "\n");
      continue;
    }
    out << "[\n";
    for (std::size_t i = 0; i < it.value().size(); ++i)
      out << "    " << it.value()[i].dump() << (i + 1 < it.value().size() ? ",\n" : "\n");
    out << "  ]" << (std::next(it) != j.end() ? ",\n" : "\n");
  }
  out << "}\n";
  return out.str();
}

std::string study_record(const StudyResult& r) {
  nlohmann::ordered_json j;
  j["tool"] = r.tool;
  j["study"] = study_json(r.study);
  return j.dump(2) + "\n";
}

}  // namespace rc
