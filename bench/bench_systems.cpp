// Time per simulated system of a timing study (studies/timing_study.h) against the number of
// systems elaborated in one process: a study that scales linearly keeps the time per system flat
// from 100 to 4,000 systems.
//
//   build/bench/bench_systems
//
// Every system replays the same recording (the 70-face, 280-patch Cornell Box, kSteps shooting
// steps at 15 bits) on a board configuration of its own (1-4 lanes, serial or concurrent, every
// fourth one the software-only implementation), so the systems are what a design search
// elaborates. SystemC elaborates once per process, so every measurement runs in a forked child
// with one process (run_timing_study(cases, 1)); the child reports elaboration plus simulation
// wall time, which is what the benchmark's manual time is.
//
// Counters: us_per_system = the study's wall time (elaboration, simulation, reports) / systems:
// the figure that must stay flat as the systems grow.
//
// BM_StudyProcesses: one study of kScalingSystems such systems run with 1, 2, 4, ... processes up
// to the cores this process may use (usable_cores(), host_sw/radiosity/jobs.h), then one more and
// twice as many (oversubscribed: the curve must flatten there); wall time per count, three
// repetitions each (median, mean and spread reported). speedup = the 1-process median / this one's
// (computed from the printed medians); cpu_s = the user + system CPU of the study's processes, which
// must stay about flat (the same work) while the wall time falls as long as there are idle cores.
#include <benchmark/benchmark.h>
#include <systemc>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench/recorded_box.h"
#include "bench/systemc_benchmark_main.h"
#include "host_sw/radiosity/jobs.h"
#include "scenes/prepare.h"
#include "host_sw/studies/timing_study.h"

namespace {

constexpr int kSteps = 40;

using Workload = rc::bench::RecordedBox;

const Workload& workload() {
  static const Workload w = rc::bench::record_box(kSteps);
  return w;
}

std::vector<rc::TimingCase> make_cases(const Workload& w, int systems) {
  std::vector<rc::TimingCase> cases;
  cases.reserve(static_cast<std::size_t>(systems));
  for (int i = 0; i < systems; ++i) {
    rc::TimingCase c;
    c.label = std::to_string(i);
    c.scene = &w.scene;
    c.solver = w.solver;
    c.recording = &w.recorded.recording;
    c.software = i % 4 == 3;
    c.board.lanes = static_cast<rc::board::LaneCount>(1 + i % 4);
    c.board.concurrent = i % 2 == 1;
    cases.push_back(c);
  }
  return cases;
}

double cpu_seconds(int who) {
  rusage u{};
  getrusage(who, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Runs the study in a forked child (one SystemC elaboration per process) and returns its wall
// time in seconds, as the child measured it (the fork and the pipe are not part of it); `cpu`, if
// given, receives the user + system CPU of the child and its study workers.
double study_seconds(const std::vector<rc::TimingCase>& cases, unsigned processes = 1, double* cpu = nullptr) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("bench_systems: pipe failed");
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("bench_systems: fork failed");
  if (pid == 0) {
    ::close(fds[0]);
    double seconds[2] = {-1, 0};
    try {
      const double c0 = cpu_seconds(RUSAGE_SELF) + cpu_seconds(RUSAGE_CHILDREN);
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<rc::TimingOutcome> outcomes = rc::run_timing_study(cases, processes);
      seconds[0] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      seconds[1] = cpu_seconds(RUSAGE_SELF) + cpu_seconds(RUSAGE_CHILDREN) - c0;
      if (outcomes.size() != cases.size()) seconds[0] = -1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_systems: %s\n", e.what());
    }
    if (::write(fds[1], seconds, sizeof seconds) != sizeof seconds) _exit(3);
    _exit(0);
  }
  ::close(fds[1]);
  double seconds[2] = {-1, 0};
  const ssize_t n = ::read(fds[0], &seconds, sizeof seconds);
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (n != sizeof seconds || seconds[0] < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error("bench_systems: the study's child process failed");
  }
  if (cpu != nullptr) *cpu = seconds[1];
  return seconds[0];
}

// range(0): systems in one process.
void BM_TimingStudy(benchmark::State& state) {
  const Workload& w = workload();
  const int systems = static_cast<int>(state.range(0));
  const std::vector<rc::TimingCase> cases = make_cases(w, systems);
  double total = 0;
  for (auto _ : state) {
    const double seconds = study_seconds(cases);
    state.SetIterationTime(seconds);
    total += seconds;
  }
  state.counters["systems"] = systems;
  state.counters["us_per_system"] = 1e6 * total / static_cast<double>(state.iterations()) / systems;
  state.SetItemsProcessed(state.iterations() * systems);
  state.SetLabel(std::to_string(kSteps) + " steps of 70 faces / 280 patches per system");
}
BENCHMARK(BM_TimingStudy)
    ->ArgName("systems")
    ->Arg(100)
    ->Arg(250)
    ->Arg(500)
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(4000)
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

constexpr int kScalingSystems = 1024;  // 16 shards of 64 at 1 process: every count has whole rounds

// range(0): processes.
void BM_StudyProcesses(benchmark::State& state) {
  const Workload& w = workload();
  const unsigned processes = static_cast<unsigned>(state.range(0));
  const std::vector<rc::TimingCase> cases = make_cases(w, kScalingSystems);
  double cpu = 0;
  for (auto _ : state) state.SetIterationTime(study_seconds(cases, processes, &cpu));
  state.counters["cpu_s"] = cpu;  // user + system of the study's processes (the last iteration)
  state.counters["processes"] = processes;
  state.counters["shards"] = static_cast<double>(rc::study_shards(cases.size(), processes));
  state.counters["cores"] = rc::usable_cores();
  state.SetLabel(std::to_string(kScalingSystems) + " systems of " + std::to_string(kSteps) + " steps");
}
BENCHMARK(BM_StudyProcesses)
    ->ArgName("processes")
    ->Apply([](benchmark::internal::Benchmark* b) {
      const unsigned cores = rc::usable_cores();
      for (unsigned p = 1; p < cores; p *= 2) b->Arg(p);
      b->Arg(cores)->Arg(cores + 1);
      if (2 * cores > cores + 1) b->Arg(2 * cores);
    })
    ->Iterations(1)
    ->Repetitions(3)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

// SystemC's library owns main() and calls sc_main (bench/systemc_benchmark_main.h).
int sc_main(int argc, char** argv) { return rc::bench::run_benchmarks(argc, argv); }
