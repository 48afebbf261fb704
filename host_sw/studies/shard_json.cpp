#include "host_sw/studies/shard_json.h"

#include <cstdint>
#include <map>
#include <stdexcept>

#include "host_sw/studies/study_json.h"
#include "host_sw/studies/sweep_columns.h"
#include "host_sw/studies/sweep_row_json.h"

namespace rc {

namespace {

nlohmann::ordered_json group_json(const GroupResult& g, const std::vector<std::string>& extra) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const auto& [index, row] : g.rows) {
    nlohmann::ordered_json r = sweep_row_json(row, extra);
    r["plan_index"] = index;
    rows.push_back(r);
  }
  return {{"scene", g.scene},
          {"bits", g.bits},
          {"steps", g.width.steps},
          {"convergence_step", g.width.convergence_step},
          {"max_segments_per_step", g.width.max_segments},
          {"software_seconds", g.software_seconds},
          {"bank_capacities", g.bank_capacities},
          {"rows", rows}};
}

GroupResult group_from_json(const nlohmann::ordered_json& j, const std::vector<SweepConfig>& plan) {
  GroupResult g;
  g.scene = j.at("scene").get<std::size_t>();
  g.bits = j.at("bits").get<int>();
  g.width.steps = j.at("steps").get<int>();
  g.width.convergence_step = j.at("convergence_step").get<int>();
  g.width.max_segments = j.at("max_segments_per_step").get<std::uint64_t>();
  g.software_seconds = j.at("software_seconds").get<std::map<std::string, double>>();
  g.bank_capacities = j.at("bank_capacities").get<std::map<std::string, std::uint64_t>>();
  for (const auto& r : j.at("rows")) {
    const std::size_t index = r.at("plan_index").get<std::size_t>();
    if (index >= plan.size()) throw std::invalid_argument("row plan_index " + std::to_string(index) + " is beyond the plan");
    if (plan[index].bits != g.bits) throw std::invalid_argument("row " + std::to_string(index) + " is not at the group's width");
    g.rows.emplace(index, sweep_row_from_json(r, plan[index]));
  }
  return g;
}

}  // namespace

nlohmann::ordered_json shard_json(const ShardResult& s) {
  nlohmann::ordered_json j;
  j["schema"] = "rc2000sim.shard/1";
  j["tool"] = s.tool;
  j["shard"] = {{"index", s.shard.index}, {"count", s.shard.count}};
  j["groups_in_study"] = s.groups_in_study;
  nlohmann::ordered_json prints = nlohmann::ordered_json::array();
  for (const ProfileFingerprint& p : s.profiles)
    prints.push_back({{"kind", p.kind}, {"name", p.name}, {"fingerprint", p.fingerprint}});
  j["profiles"] = prints;
  j["study"] = study_json(s.study);
  nlohmann::ordered_json scenes = nlohmann::ordered_json::array();
  for (const auto& [index, scene] : s.scenes) {
    scenes.push_back({{"index", index},
                      {"name", scene.name},
                      {"source", scene.source},
                      {"faces", scene.faces},
                      {"patches", scene.patches}});
  }
  j["scenes"] = scenes;
  const std::vector<std::string> extra = extra_columns(s.study.axes);
  nlohmann::ordered_json groups = nlohmann::ordered_json::array();
  for (const GroupResult& g : s.groups) groups.push_back(group_json(g, extra));
  j["groups"] = groups;
  return j;
}

ShardResult shard_from_json(const nlohmann::ordered_json& j, const std::string& origin) {
  if (j.value("schema", "") != "rc2000sim.shard/1")
    throw std::invalid_argument(origin + ": not a shard file (schema rc2000sim.shard/1)");
  try {
    ShardResult s;
    s.tool = j.at("tool").get<std::string>();
    s.shard.index = j.at("shard").at("index").get<unsigned>();
    s.shard.count = j.at("shard").at("count").get<unsigned>();
    s.groups_in_study = j.at("groups_in_study").get<std::size_t>();
    if (j.contains("profiles")) {  // shards of builds before issue 39 have none (merge then compares counts)
      for (const auto& p : j.at("profiles"))
        s.profiles.push_back({p.at("kind").get<std::string>(), p.at("name").get<std::string>(),
                              p.at("fingerprint").get<std::string>()});
    }
    s.study = study_from_json(j.at("study"));
    for (const auto& scene : j.at("scenes")) {
      s.scenes[scene.at("index").get<std::size_t>()] = {scene.at("name").get<std::string>(),
                                                         scene.at("source").get<std::string>(),
                                                         scene.at("faces").get<std::uint64_t>(),
                                                         scene.at("patches").get<std::uint64_t>()};
    }
    const std::vector<SweepConfig> plan = enumerate_configs(s.study.axes);
    for (const auto& g : j.at("groups")) s.groups.push_back(group_from_json(g, plan));
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(origin + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(origin + ": " + e.what());
  }
}

}  // namespace rc
