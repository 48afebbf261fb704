#include "host_sw/studies/paper_workload.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <numeric>
#include <thread>
#include <stdexcept>


#include "profiles/paper_table.h"
#include "profiles/profile_document.h"
#include "host_sw/studies/workload.h"
#include "host_sw/radiosity/jobs.h"
#include "host_sw/radiosity/radiosity.h"

namespace rc {

std::string PaperRow::label() const { return std::to_string(faces) + "/" + std::to_string(patches); }

std::string default_paper_table_path() { return profiles::default_config_dir() + "/paper-table2.json"; }

const std::vector<PaperRow>& default_paper_table() {
  static std::mutex guard;
  static std::map<std::string, std::vector<PaperRow>> tables;  // by path: --configs may name another folder
  const std::string path = default_paper_table_path();
  const std::lock_guard<std::mutex> lock(guard);
  auto it = tables.find(path);
  if (it == tables.end()) it = tables.emplace(path, load_paper_table(path)).first;
  return it->second;
}

std::vector<PaperRow> load_paper_table(const std::string& path) {
  const profiles::PaperTableLimits limits{static_cast<std::int64_t>(kMaxFaces), static_cast<std::int64_t>(kMaxPatches),
                                          SolverOptions{}.max_steps};
  std::vector<PaperRow> rows;
  for (const profiles::PaperTableRow& t : profiles::read_paper_table(path, limits)) {
    const std::string where = "scenes[" + std::to_string(rows.size()) + "]";
    rows.push_back({t.faces, t.patches, t.steps, t.software_seconds, t.one_pipe_seconds});
    try {
      (void)paper_scene_options(t.faces, t.patches);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(path + ": " + where + ": " + e.what());
    }
    for (std::size_t k = 0; k + 1 < rows.size(); ++k) {
      if (rows[k].faces == t.faces && rows[k].patches == t.patches) {
        throw std::runtime_error(path + ": " + where + ": " + rows.back().label() + " is already scenes[" +
                                 std::to_string(k) + "]; one row per scene");
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

// The scenes are independent, so they are solved side by side, one per job (jobs(): --jobs, else
// every usable core), largest first (each with a single-threaded backend): the cores stay busy
// through the solver's own serial work too.
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
        // others leave idle once they are done (0 = jobs(): every core the process may use).
        p.functional = record_functional_run(p.scene, recorded, backend, bits, k == 0 ? 0 : 1);
        p.convergence_steps = p.functional.convergence_step;
      } catch (...) {
        errors[order[k]] = std::current_exception();
      }
    }
  };
  const unsigned workers = std::max(1u, std::min<unsigned>(jobs(), unsigned(rows.size())));
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
