#include "host_sw/timing_study.h"

#include <stdexcept>

#include "host_sw/software_system.h"
#include "host_sw/visibility_factory.h"

namespace rc {

RecordedRun record_functional_run(const Scene& scene, const SolverOptions& solver, const std::string& backend, int bits,
                                  int threads) {
  RecordedRun run;
  auto answer = make_functional_answer(backend, bits, threads);
  RecordingVisibility recorder(*answer, run.recording);
  ProgressiveRadiosity radiosity(scene, recorder, solver);
  radiosity.on_progress([&](const StepProgress& p) {
    if (run.convergence_step == 0 && p.convergence_reached >= solver.convergence) run.convergence_step = p.step;
  });
  run.result = radiosity.run();
  return run;
}

namespace {

// One case's system; every case replays its recording's work (work_replay.h).
struct CaseSystem {
  std::unique_ptr<SoftwareSystem> software;
  std::unique_ptr<BoardSystem> board;

  bool finished() const { return software ? software->finished() : board->finished(); }
};

CaseSystem elaborate(const TimingCase& c, std::size_t index) {
  if (c.scene == nullptr || c.recording == nullptr) throw std::invalid_argument("timing case '" + c.label + "' has no scene or recording");
  if (c.solver.fixed_steps <= 0) throw std::invalid_argument("timing case '" + c.label + "' needs a fixed step count");
  CaseSystem s;
  const std::string name = "case" + std::to_string(index);
  if (c.software) {
    s.software = std::make_unique<SoftwareSystem>(name.c_str(), *c.scene, c.solver, *c.recording, find_host_profile(c.host));
  } else {
    BoardSetup setup = make_board_setup(c.board);
    setup.stop_when_done = false;
    setup.replay = c.recording;
    s.board = std::make_unique<BoardSystem>(name.c_str(), *c.scene, c.solver, setup);
  }
  return s;
}

}  // namespace

std::vector<TimingOutcome> run_timing_study(const std::vector<TimingCase>& cases) {
  static bool used = false;
  if (used) throw std::logic_error("run_timing_study may be called once per process (SystemC elaborates once)");
  used = true;
  std::vector<CaseSystem> systems;
  systems.reserve(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) systems.push_back(elaborate(cases[i], i));
  sc_core::sc_start();  // every host thread runs to its end; nothing else keeps time going
  std::vector<TimingOutcome> out;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    CaseSystem& s = systems[i];
    TimingOutcome o;
    o.label = cases[i].label;
    if (s.software) {
      s.software->rethrow_if_failed();
      o.report = s.software->report();
      o.steps = s.software->result().steps;
    } else {
      s.board->rethrow_if_failed();
      o.report = s.board->report();
      o.steps = s.board->result().steps;
    }
    if (!s.finished()) throw std::logic_error("timing case '" + cases[i].label + "' did not finish");
    o.simulated_seconds = o.report["simulated_seconds"].get<double>();
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace rc
