#include "host_sw/studies/study_json.h"

#include <filesystem>
#include <stdexcept>
#include <string>

#include "profiles/field_value_json.h"

namespace rc {

namespace {

nlohmann::ordered_json scene_json(const StudyScene& s) {
  nlohmann::ordered_json j = {{"name", s.name},
                              {"file", s.source},
                              {"faces", s.options.face_target},
                              {"face_levels", s.options.face_levels},
                              {"patch_levels", s.options.patch_levels},
                              {"patch_size", s.options.patch_size}};
  if (!s.form_factor.empty()) j["form_factor"] = s.form_factor;  // a form-factor axis only
  return j;
}

StudyScene scene_from_json(const nlohmann::ordered_json& j) {
  StudyScene s;
  s.name = j.at("name").get<std::string>();
  s.source = j.at("file").get<std::string>();
  s.options.file = s.source;  // a recorded study is merged, not solved: nothing loads it
  s.options.face_target = j.at("faces").get<int>();
  s.options.face_levels = j.at("face_levels").get<int>();
  s.options.patch_levels = j.at("patch_levels").get<int>();
  s.options.patch_size = j.at("patch_size").get<double>();
  s.form_factor = j.value("form_factor", std::string());
  if (!s.form_factor.empty()) (void)parse_form_factor_kind(s.form_factor);
  return s;
}

nlohmann::ordered_json setting_json(const ProfileSetting& s) {
  return {{"path", s.field.path}, {"value", profiles::field_value_json(s.value)}};
}

nlohmann::ordered_json values_json(const std::vector<ProfileValue>& values) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const ProfileValue& v : values) j.push_back(profiles::field_value_json(v));
  return j;
}

}  // namespace

nlohmann::ordered_json study_json(const Study& s) {
  nlohmann::ordered_json j;
  j["schema"] = "rc2000sim.study/1";
  j["name"] = s.name;
  j["description"] = s.description;
  j["file"] = std::filesystem::path(s.file).filename().string();  // where it lay is not part of the study
  // Recorded when not the paper fit, so records made before the choice existed read as before.
  if (s.resources != Study{}.resources) j["resources"] = choice_name(s.resources);
  j["ray_split"] = board::to_string(s.ray_split);  // always: which split ran (board/bank_layout.h)
  nlohmann::ordered_json scenes = nlohmann::ordered_json::array();
  for (const StudyScene& scene : s.scenes) scenes.push_back(scene_json(scene));
  j["scenes"] = scenes;
  j["solver"] = {{"steps", to_string(s.steps)},
                 {"convergence", s.convergence},
                 {"paper_faithful", s.paper_faithful},
                 {"visibility", choice_name(s.visibility)},
                 {"full_banks", s.full_banks}};
  // Recorded when not the paper's point rule, so records of point studies read as before it existed.
  if (s.form_factor != Study{}.form_factor) j["solver"]["form_factor"] = s.form_factor;
  nlohmann::ordered_json profile = nlohmann::ordered_json::array();
  for (const ProfileAxis& a : s.axes.profile) profile.push_back({{"path", a.field.path}, {"values", values_json(a.values)}});
  nlohmann::ordered_json concurrent = nlohmann::ordered_json::array();
  for (bool c : s.axes.concurrent) concurrent.push_back(c);
  j["axes"] = {{"devices", s.axes.devices},         {"bits", s.axes.bits},
               {"concurrent", concurrent},            {"hosts", s.axes.hosts},
               {"cards", s.axes.cards},               {"card_split", choice_name_vector(s.axes.card_splits)},
               {"card_bus", choice_name_vector(s.axes.card_buses)},       {"profile", profile},
               {"lanes", s.axes.lanes},               {"banks", s.axes.banks}};
  nlohmann::ordered_json fixed = nlohmann::ordered_json::array();
  for (const ProfileSetting& f : s.fixed) fixed.push_back(setting_json(f));
  j["fixed"] = fixed;
  return j;
}

Study study_from_json(const nlohmann::ordered_json& j) {
  if (j.value("schema", "") != "rc2000sim.study/1")
    throw std::invalid_argument("not a resolved study (schema rc2000sim.study/1)");
  Study s;
  try {
    s.name = j.at("name").get<std::string>();
    s.description = j.at("description").get<std::string>();
    s.file = j.at("file").get<std::string>();
    s.resources = parse_choice<pipeline::ResourceSource>(j.value("resources", choice_name(Study{}.resources)));
    // Records made before the choice existed ran the paper's nominal split.
    s.ray_split = board::parse_ray_split(j.value("ray_split", std::string("nominal")));
    for (const auto& scene : j.at("scenes")) s.scenes.push_back(scene_from_json(scene));
    const auto& solver = j.at("solver");
    s.steps = parse_steps(solver.at("steps").get<std::string>());
    s.convergence = solver.at("convergence").get<double>();
    s.paper_faithful = solver.at("paper_faithful").get<bool>();
    try {
      s.visibility = parse_choice<BitExactVisibility>(solver.at("visibility").get<std::string>());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("study " + (s.file.empty() ? s.name : s.file) + ": solver.visibility: " + e.what());
    }
    s.full_banks = solver.at("full_banks").get<bool>();
    s.form_factor = solver.value("form_factor", Study{}.form_factor);
    const auto& axes = j.at("axes");
    s.axes.devices = axes.at("devices").get<std::vector<std::string>>();
    s.axes.bits = axes.at("bits").get<std::vector<int>>();
    s.axes.concurrent = axes.at("concurrent").get<std::vector<bool>>();
    s.axes.hosts = axes.at("hosts").get<std::vector<std::string>>();
    s.axes.cards = axes.at("cards").get<std::vector<int>>();
    s.axes.card_splits = parse_choices<CardSplit>(axes.at("card_split").get<std::vector<std::string>>());
    s.axes.card_buses = parse_choices<CardBus>(axes.at("card_bus").get<std::vector<std::string>>());
    s.axes.lanes = axes.at("lanes").get<std::vector<int>>();
    s.axes.banks = axes.at("banks").get<std::vector<int>>();
    for (const auto& a : axes.at("profile")) {
      ProfileAxis axis{resolve_study_field(a.at("path").get<std::string>(), s.axes.devices, s.axes.hosts), {}};
      for (const auto& v : a.at("values")) axis.values.push_back(profiles::field_value_from_json(v, "axes.profile " + axis.field.path));
      s.axes.profile.push_back(axis);
    }
    for (const auto& f : j.at("fixed")) {
      s.fixed.push_back({resolve_study_field(f.at("path").get<std::string>(), s.axes.devices, s.axes.hosts),
                         profiles::field_value_from_json(f.at("value"), "fixed " + f.at("path").get<std::string>())});
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("resolved study: ") + e.what());
  }
  check_study(s);
  return s;
}

}  // namespace rc
