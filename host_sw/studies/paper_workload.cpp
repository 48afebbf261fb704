#include "host_sw/studies/paper_workload.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <initializer_list>
#include <mutex>
#include <numeric>
#include <thread>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "board/profile_reader.h"
#include "io/input_file.h"
#include "io/json_text.h"
#include "host_sw/studies/workload.h"
#include "host_sw/radiosity/radiosity.h"

namespace rc {

std::string PaperRow::label() const { return std::to_string(faces) + "/" + std::to_string(patches); }

std::string default_paper_table_path() { return board::default_config_dir() + "/paper-table2.json"; }

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

PaperRow paper_row(const nlohmann::json& scene, const std::string& path, const std::string& where) {
  if (!scene.is_object()) table_fail(path, where, "must be an object {faces, patches, steps, software_seconds, one_pipe_seconds}");
  only_keys(scene, path, where, {"faces", "patches", "steps", "software_seconds", "one_pipe_seconds"});
  PaperRow row;
  row.faces = whole_count(scene, path, where, "faces", static_cast<std::int64_t>(kMaxFaces));
  row.patches = whole_count(scene, path, where, "patches", static_cast<std::int64_t>(kMaxPatches));
  row.steps = whole_count(scene, path, where, "steps", SolverOptions{}.max_steps);
  row.software_seconds = measured_seconds(scene, path, where, "software_seconds");
  row.one_pipe_seconds = measured_seconds(scene, path, where, "one_pipe_seconds");
  try {
    (void)paper_scene_options(row.faces, row.patches);
  } catch (const std::invalid_argument& e) {
    table_fail(path, where, e.what());
  }
  return row;
}

}  // namespace

std::vector<PaperRow> load_paper_table(const std::string& path) {
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
  std::vector<PaperRow> rows;
  for (std::size_t i = 0; i < scenes->size(); ++i) {
    const std::string where = "scenes[" + std::to_string(i) + "]";
    rows.push_back(paper_row((*scenes)[i], path, where));
    for (std::size_t k = 0; k + 1 < rows.size(); ++k) {
      if (rows[k].faces == rows.back().faces && rows[k].patches == rows.back().patches) {
        table_fail(path, where, rows.back().label() + " is already scenes[" + std::to_string(k) + "]; one row per scene");
      }
    }
  }
  return rows;
}

double measured_peak_software_rate(const std::vector<PaperRow>& rows) {
  double peak = 0;
  for (const PaperRow& r : rows) {
    peak = std::max(peak, double(r.steps) * r.patches * r.faces / r.software_seconds);
  }
  return peak;
}

namespace {

// k with base * 4^k == value, or -1.
int power_of_four(int base, int value) {
  int k = 0;
  for (long v = base; v <= value; v *= 4, ++k) {
    if (v == value) return k;
  }
  return -1;
}

}  // namespace

SceneOptions paper_scene_options(int faces, int patches) {
  SceneOptions o;
  o.face_target = 70;
  o.face_levels = power_of_four(70, faces);
  o.patch_levels = power_of_four(faces, patches);
  if (o.face_levels < 0 || o.patch_levels < 0) {
    throw std::invalid_argument("no paper-like scene has " + std::to_string(faces) + " faces and " +
                                std::to_string(patches) + " patches (70 x 4^k faces, faces x 4^m patches)");
  }
  return o;
}

// The scenes are independent, so they are solved side by side, one per core, largest first (each
// with a single-threaded backend): the cores stay busy through the solver's own serial work too.
// Every solve is deterministic, so the results do not depend on the schedule.
std::vector<PaperScene> prepare_paper_scenes(const std::vector<PaperRow>& rows, const std::string& backend, int bits,
                                             const std::function<void(const std::string&)>& progress) {
  std::vector<PaperScene> scenes(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    PaperScene& p = scenes[i];
    p.row = rows[i];
    const Workload w = paper_workload(p.row);  // the paper's construction, steps, segments and rule
    p.scene = prepare_scene(w.scene).scene;
    p.solver = solver_options(w);
    p.recorded_steps = p.row.steps + p.row.steps / 10;
  }
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return double(rows[a].faces) * rows[a].patches * rows[a].steps > double(rows[b].faces) * rows[b].patches * rows[b].steps;
  });
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(rows.size());
  std::mutex report;
  auto worker = [&] {
    for (std::size_t k = next++; k < order.size(); k = next++) {
      PaperScene& p = scenes[order[k]];
      if (progress) {
        std::lock_guard<std::mutex> lock(report);
        progress("solving " + p.row.label() + " (" + std::to_string(p.row.steps) + " steps)");
      }
      try {
        // The paper's step count at least (the replays need it), then on to our own convergence
        // (the "ours" column), at most recorded_steps.
        SolverOptions recorded = p.solver;
        recorded.fixed_steps = 0;
        recorded.min_steps = p.row.steps;
        recorded.max_steps = p.recorded_steps;
        // The largest scene is the critical path: its backend may use every core, which the
        // others leave idle once they are done (0 = every core).
        p.functional = record_functional_run(p.scene, recorded, backend, bits, k == 0 ? 0 : 1);
        p.convergence_steps = p.functional.convergence_step;
      } catch (...) {
        errors[order[k]] = std::current_exception();
      }
    }
  };
  const unsigned workers = std::max(1u, std::min<unsigned>(std::thread::hardware_concurrency(), unsigned(rows.size())));
  std::vector<std::thread> threads;
  for (unsigned w = 1; w < workers; ++w) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  return scenes;
}

const char* to_string(PaperImplementation implementation) {
  switch (implementation) {
    case PaperImplementation::Software: return "software";
    case PaperImplementation::OnePipe: return "one_pipe";
    case PaperImplementation::TwoPipes: return "two_pipes";
    case PaperImplementation::Concurrent: return "concurrent";
  }
  return "unknown";
}

TimingCase paper_timing_case(const PaperScene& s, PaperImplementation implementation, const std::string& host) {
  TimingCase c;
  c.label = s.row.label() + " " + to_string(implementation);
  c.scene = &s.scene;
  c.solver = s.solver;
  c.recording = &s.functional.recording;
  c.software = implementation == PaperImplementation::Software;
  c.host = host;
  c.board.device = "xc2v6000";
  c.board.host = host;
  c.board.lanes = implementation == PaperImplementation::OnePipe ? 1 : 2;
  c.board.concurrent = implementation == PaperImplementation::Concurrent;
  return c;
}

}  // namespace rc
