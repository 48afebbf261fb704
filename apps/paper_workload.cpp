#include "apps/paper_workload.h"

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace rc {

std::string PaperRow::label() const { return std::to_string(faces) + "/" + std::to_string(patches); }

std::string default_paper_table_path() { return std::string(RC_SOURCE_DIR) + "/configs/paper-table2.json"; }

std::vector<PaperRow> load_paper_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the paper's Table 2 data");
  std::vector<PaperRow> rows;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const auto& s : j.at("scenes")) {
      rows.push_back({s.at("faces").get<int>(), s.at("patches").get<int>(), s.at("steps").get<int>(),
                      s.at("software_seconds").get<double>(), s.at("one_pipe_seconds").get<double>()});
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  if (rows.empty()) throw std::runtime_error(path + ": no scenes");
  return rows;
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

std::vector<PaperScene> prepare_paper_scenes(const std::vector<PaperRow>& rows, const std::string& backend, int bits,
                                             const std::function<void(const std::string&)>& progress) {
  std::vector<PaperScene> scenes;
  for (const PaperRow& row : rows) {
    if (progress) progress("solving " + row.label() + " (" + std::to_string(row.steps) + " steps)");
    PaperScene p;
    p.row = row;
    p.scene = prepare_scene(paper_scene_options(row.faces, row.patches)).scene;
    p.solver.cull_receivers = false;
    p.solver.fixed_steps = row.steps;
    SolverOptions recorded = p.solver;
    recorded.fixed_steps = row.steps + row.steps / 10;
    p.functional = record_functional_run(p.scene, recorded, backend, bits);
    p.convergence_steps = p.functional.convergence_step;
    p.recorded_steps = recorded.fixed_steps;
    scenes.push_back(std::move(p));
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
