#include "profiles/paper_table.h"

#include <algorithm>
#include <initializer_list>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/input_file.h"
#include "io/json_text.h"

namespace rc::profiles {

namespace {

constexpr const char* kPaperTableSchema = "rc2000sim.paper-table2/1";

// "<path>: <where>: <problem>", the one shape of every error of the table.
[[noreturn]] void table_fail(const std::string& path, const std::string& where, const std::string& problem) {
  throw std::runtime_error(path + ": " + where + ": " + problem);
}

void only_keys(const nlohmann::json& object, const std::string& path, const std::string& where,
               std::initializer_list<const char*> known) {
  for (auto item = object.begin(); item != object.end(); ++item) {
    const std::string key = item.key();  // a named copy: a structured binding cannot be captured in C++17
    if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) {
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      table_fail(path, where + (where.empty() ? "" : ".") + key, "unknown key (known: " + list + ")");
    }
  }
}

// A whole count in 1..max, given as a JSON integer.
int whole_count(const nlohmann::json& scene, const std::string& path, const std::string& where, const char* key,
                std::int64_t max) {
  const auto it = scene.find(key);
  if (it == scene.end()) table_fail(path, where + "." + key, "missing");
  if (!it->is_number_integer() || it->get<std::int64_t>() < 1 || it->get<std::int64_t>() > max) {
    table_fail(path, where + "." + key, "must be a whole number 1.." + std::to_string(max) + ", got " + it->dump());
  }
  return static_cast<int>(it->get<std::int64_t>());
}

// A measured time: a positive number of seconds, at most a year.
double measured_seconds(const nlohmann::json& scene, const std::string& path, const std::string& where, const char* key) {
  constexpr double kYear = 365.25 * 24 * 3600;
  const auto it = scene.find(key);
  if (it == scene.end()) table_fail(path, where + "." + key, "missing");
  if (!it->is_number() || !(it->get<double>() > 0 && it->get<double>() <= kYear)) {
    table_fail(path, where + "." + key, "must be a measured time, seconds above 0 and at most a year, got " + it->dump());
  }
  return it->get<double>();
}

PaperTableRow paper_row(const nlohmann::json& scene, const std::string& path, const std::string& where,
                        const PaperTableLimits& limits) {
  if (!scene.is_object()) table_fail(path, where, "must be an object {faces, patches, steps, software_seconds, one_pipe_seconds}");
  only_keys(scene, path, where, {"faces", "patches", "steps", "software_seconds", "one_pipe_seconds"});
  PaperTableRow row;
  row.faces = whole_count(scene, path, where, "faces", limits.max_faces);
  row.patches = whole_count(scene, path, where, "patches", limits.max_patches);
  row.steps = whole_count(scene, path, where, "steps", limits.max_steps);
  row.software_seconds = measured_seconds(scene, path, where, "software_seconds");
  row.one_pipe_seconds = measured_seconds(scene, path, where, "one_pipe_seconds");
  return row;
}

}  // namespace

std::vector<PaperTableRow> read_paper_table(const std::string& path, const PaperTableLimits& limits) {
  nlohmann::json j;
  try {
    j = io::parse_json_text(io::read_file(path, io::kProfileLimitBytes, "the paper's Table 2 data"), path);
  } catch (const io::InputFileError& e) {  // the file, or its text (io/json_text.h)
    throw std::runtime_error(e.what());
  }
  if (!j.is_object()) throw std::runtime_error(path + ": must be a JSON object with \"schema\" and \"scenes\"");
  only_keys(j, path, "", {"schema", "description", "source", "scenes"});
  const auto schema = j.find("schema");
  if (schema == j.end() || *schema != kPaperTableSchema) table_fail(path, "schema", std::string("must be \"") + kPaperTableSchema + "\"");
  const auto scenes = j.find("scenes");
  if (scenes == j.end() || !scenes->is_array() || scenes->empty()) table_fail(path, "scenes", "must be a list of at least one scene");
  std::vector<PaperTableRow> rows;
  for (std::size_t i = 0; i < scenes->size(); ++i) rows.push_back(paper_row((*scenes)[i], path, "scenes[" + std::to_string(i) + "]", limits));
  return rows;
}

}  // namespace rc::profiles
