#include "host_sw/studies/timing_study.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host_sw/platform/software_system.h"
#include "host_sw/radiosity/jobs.h"
#include "host_sw/studies/child_guard.h"
#include "host_sw/studies/timing_study_json.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {

RecordedRun record_functional_run(const Scene& scene, const SolverOptions& solver, const std::string& backend, int bits,
                                  int threads) {
  RecordedRun run;
  auto answer = make_functional_answer(backend, bits, threads);
  // With fixes the recording keeps the answers after them (the neighbour rule's) and each step's host
  // re-tests, which a timing replay charges (work_replay.h): the fixes wrap the answer below the
  // recorder instead of inside the solver, the same answers (FixedSegmentsVisibility's promise).
  std::unique_ptr<FixedSegmentsVisibility> fixed;
  SolverOptions options = solver;
  if (solver.fixes.any()) {
    fixed = std::make_unique<FixedSegmentsVisibility>(*answer, solver.fixes);
    options.fixes = {};
  }
  VisibilityBackend& answered = fixed ? static_cast<VisibilityBackend&>(*fixed) : *answer;
  std::function<std::uint64_t()> host_tests;
  if (fixed) host_tests = [&fixed] { return fixed->fixer() ? fixed->fixer()->tests_performed() : 0; };
  RecordingVisibility recorder(answered, run.recording, host_tests);
  ProgressiveRadiosity radiosity(scene, recorder, options);
  radiosity.on_progress([&](const StepProgress& p) {
    if (run.convergence_step == 0 && p.convergence_reached >= solver.convergence) run.convergence_step = p.step;
  });
  run.result = radiosity.run();
  if (fixed && fixed->fixer()) {
    run.result.fix_tests = fixed->fixer()->tests_performed();
    run.result.fix_cleared = fixed->fixer()->segments_cleared();
  }
  return run;
}

namespace {

// One case's system; every case replays its recording's work (work_replay.h).
struct CaseSystem {
  std::unique_ptr<SoftwareSystem> software;
  std::unique_ptr<BoardSystem> board;

  bool finished() const { return software ? software->finished() : board->finished(); }
};

bool elaborate_check(const TimingCase& c) {
  if (c.scene == nullptr || c.recording == nullptr) throw std::invalid_argument("timing case '" + c.label + "' has no scene or recording");
  if (c.solver.fixed_steps <= 0) throw std::invalid_argument("timing case '" + c.label + "' needs a fixed step count");
  return true;
}

CaseSystem elaborate(const TimingCase& c, std::size_t index) {
  elaborate_check(c);
  CaseSystem s;
  const std::string name = "case" + std::to_string(index);
  if (c.software) {
    s.software = std::make_unique<SoftwareSystem>(name.c_str(), *c.scene, c.solver, *c.recording,
                                                  c.host_profile ? *c.host_profile : find_host_profile(c.host));
  } else {
    BoardSetup setup = make_board_setup(c.board);
    setup.stop_when_done = false;
    setup.replay = c.recording;
    s.board = std::make_unique<BoardSystem>(name.c_str(), *c.scene, c.solver, setup);
    // Nothing traces a study's systems: the wrappers' VCD signals would only cost delta cycles.
    for (unsigned card = 0; card < s.board->cards(); ++card) s.board->card(card).wrapper().set_signals({});
  }
  return s;
}

}  // namespace

namespace {

// What run_here does with its systems once their outcomes are taken.
enum class Teardown { destroy, leave_to_exit };

// Elaborates `cases` (indices into all) side by side and runs them to their end in this process.
std::vector<TimingOutcome> run_here(const std::vector<TimingCase>& all, const std::vector<std::size_t>& cases,
                                    Teardown teardown = Teardown::destroy) {
  static bool used = false;
  if (used) throw std::logic_error("run_timing_study may be called once per process (SystemC elaborates once)");
  used = true;
  std::vector<CaseSystem> systems;
  systems.reserve(cases.size());
  for (std::size_t i : cases) systems.push_back(elaborate(all[i], i));
  sc_core::sc_start();  // every host thread runs to its end; nothing else keeps time going
  std::vector<TimingOutcome> out;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    CaseSystem& s = systems[k];
    const TimingCase& c = all[cases[k]];
    TimingOutcome o;
    o.label = c.label;
    if (s.software) {
      s.software->rethrow_if_failed();
      o.report = s.software->report();
      o.steps = s.software->result().steps;
    } else {
      s.board->rethrow_if_failed();
      o.report = s.board->report();
      o.steps = s.board->result().steps;
    }
    if (!s.finished()) throw std::logic_error("timing case '" + c.label + "' did not finish");
    o.simulated_seconds = o.report.simulated_seconds;
    out.push_back(std::move(o));
  }
  // A worker process _exits right after writing the outcomes: destroying its systems (every module,
  // socket, bank page and event of up to kMaxSystemsPerProcess boards) would only hand the OS memory
  // it reclaims at the exit anyway. They hold no file, pipe or other state that needs closing.
  if (teardown == Teardown::leave_to_exit) static_cast<void>(new std::vector<CaseSystem>(std::move(systems)));
  return out;
}

// Cases dealt to `shards` processes, largest first onto the least loaded shard with room for it
// (a case's cost is about its simulated steps; a shard holds at most kMaxSystemsPerProcess, and
// shards * kMaxSystemsPerProcess >= cases), each shard in case order.
std::vector<std::vector<std::size_t>> deal(const std::vector<TimingCase>& cases, unsigned shards) {
  std::vector<std::size_t> order(cases.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cases[a].solver.fixed_steps > cases[b].solver.fixed_steps; });
  std::vector<std::vector<std::size_t>> out(shards);
  std::vector<double> load(shards, 0);
  for (std::size_t i : order) {
    std::size_t s = shards;
    for (std::size_t k = 0; k < shards; ++k) {
      if (out[k].size() < kMaxSystemsPerProcess && (s == shards || load[k] < load[s])) s = k;
    }
    out[s].push_back(i);
    load[s] += cases[i].solver.fixed_steps;
  }
  for (auto& shard : out) std::sort(shard.begin(), shard.end());
  return out;
}

// A child process: runs its shard and writes one JSON document (outcomes or an error) to `fd`.
[[noreturn]] void run_child(const std::vector<TimingCase>& cases, const std::vector<std::size_t>& shard, int fd) {
  WorkerAnswer answer;
  try {
    answer.outcomes = run_here(cases, shard, Teardown::leave_to_exit);
  } catch (const std::exception& e) {
    answer.error = e.what();
  }
  const std::string text = encode_worker_answer(answer);
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0) _exit(3);
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
  _exit(0);  // no atexit handlers, no stdio flush: the parent owns those
}

}  // namespace

std::size_t study_shards(std::size_t cases, unsigned processes) {
  processes = std::max(1u, processes);
  const std::size_t fewest = std::max<std::size_t>(std::max<std::size_t>(1, std::min<std::size_t>(processes, cases)),
                                                   (cases + kMaxSystemsPerProcess - 1) / kMaxSystemsPerProcess);
  if (fewest <= processes) return fewest;
  return (fewest + processes - 1) / processes * processes;  // whole rounds: no shard runs alone at the end
}

// No cap of its own: a study's shards are independent processes, so every core the process may use
// (jobs(): --jobs, RC2000SIM_JOBS, else the affinity mask cut to the cgroup's CPU quota) runs one.
unsigned default_study_processes() { return jobs(); }

namespace {

// One forked child per shard: its pid and the read end of its pipe.
struct Worker {
  pid_t pid = -1;
  int fd = -1;
  std::size_t shard = 0;
  std::string text;
};

Worker start_worker(const std::vector<TimingCase>& cases, const std::vector<std::vector<std::size_t>>& dealt, std::size_t shard,
                    const std::vector<Worker>& running) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("timing study: pipe: ") + std::strerror(errno));
  std::fflush(nullptr);  // nothing buffered may be written twice
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("timing study: fork: ") + std::strerror(errno));
  if (pid == 0) {
    die_with_parent(parent, SIGKILL);  // a worker has nothing to clean up; it must not outlive the study
    ::close(fds[0]);
    for (const Worker& w : running) ::close(w.fd);
    run_child(cases, dealt[shard], fds[1]);
  }
  ::close(fds[1]);
  register_child(pid);  // ended with this process if it is interrupted
  return {pid, fds[0], shard, {}};
}

// Waits for a finished worker and decodes its outcomes into `out`; returns an error message or "".
std::string finish_worker(Worker& w, const std::vector<std::vector<std::size_t>>& dealt, std::vector<TimingOutcome>& out) {
  ::close(w.fd);
  int status = 0;
  ::waitpid(w.pid, &status, 0);
  unregister_child(w.pid);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || w.text.empty()) {
    return "timing study: worker process for shard " + std::to_string(w.shard) + " died (status " + std::to_string(status) + ")";
  }
  WorkerAnswer answer = decode_worker_answer(w.text);
  if (!answer.error.empty()) return answer.error;
  for (std::size_t k = 0; k < answer.outcomes.size(); ++k) out[dealt[w.shard][k]] = std::move(answer.outcomes[k]);
  return "";
}

// Appends what the worker has written; false at its end of file.
bool read_some(Worker& w) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(w.fd, buffer, sizeof buffer);
    if (n > 0) {
      w.text.append(buffer, static_cast<std::size_t>(n));
      return true;
    }
    if (n == 0) return false;
    if (errno != EINTR) {
      throw std::runtime_error(std::string("timing study: reading a worker's results failed: ") + std::strerror(errno));
    }
  }
}

// Every shard in a child of its own, at most `processes` at a time, the next one started as soon
// as one ends. This process elaborates nothing.
std::vector<TimingOutcome> run_in_children(const std::vector<TimingCase>& cases, const std::vector<std::vector<std::size_t>>& dealt,
                                           unsigned processes) {
  std::vector<TimingOutcome> out(cases.size());
  std::vector<Worker> running;
  std::string error;
  std::size_t next = 0;
  while (next < dealt.size() || !running.empty()) {
    while (error.empty() && next < dealt.size() && running.size() < processes) {
      try {
        running.push_back(start_worker(cases, dealt, next++, running));
      } catch (const std::exception& e) {
        error = e.what();  // the running workers are still waited for below
      }
    }
    if (running.empty()) break;
    std::vector<pollfd> fds;
    for (const Worker& w : running) fds.push_back({w.fd, POLLIN, 0});
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("timing study: poll: ") + std::strerror(errno));
    }
    for (std::size_t i = running.size(); i-- > 0;) {
      if (fds[i].revents == 0 || read_some(running[i])) continue;
      const std::string e = finish_worker(running[i], dealt, out);
      if (error.empty()) error = e;
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }
  if (!error.empty()) throw std::runtime_error(error);
  return out;
}

}  // namespace

std::vector<TimingOutcome> run_timing_study(const std::vector<TimingCase>& cases, unsigned processes) {
  for (std::size_t i = 0; i < cases.size(); ++i) {  // bad cases fail here, before any process starts
    if (cases[i].scene == nullptr || cases[i].recording == nullptr || cases[i].solver.fixed_steps <= 0)
      (void)elaborate_check(cases[i]);
  }
  processes = std::max(1u, processes);
  const std::size_t n = cases.size();
  const std::size_t shards = study_shards(n, processes);
  const std::vector<std::vector<std::size_t>> dealt = deal(cases, static_cast<unsigned>(shards));
  if (shards > processes) return run_in_children(cases, dealt, processes);
  // One shard per process: this one runs the first, children the others.
  std::vector<Worker> children;
  for (std::size_t s = 1; s < shards; ++s) children.push_back(start_worker(cases, dealt, s, children));
  std::vector<TimingOutcome> out(n);
  std::exception_ptr error;
  try {
    std::vector<TimingOutcome> mine = run_here(cases, dealt[0]);
    for (std::size_t k = 0; k < mine.size(); ++k) out[dealt[0][k]] = std::move(mine[k]);
  } catch (...) {
    error = std::current_exception();
  }
  std::string child_error;
  for (Worker& w : children) {
    while (read_some(w)) {
    }
    const std::string e = finish_worker(w, dealt, out);
    if (!e.empty()) child_error = e;
  }
  if (error) std::rethrow_exception(error);
  if (!child_error.empty()) throw std::runtime_error(child_error);
  return out;
}

}  // namespace rc
