// The timing replay's cost per pass against the SystemC kernel's own floor (issue 36, item 2).
//
//   build/bench/bench_replay_floor
//
// BM_RealReplay: kSystems board systems of a timing study (as host_sw/studies/timing_study.cpp
// elaborates them: a replay of one recording, no VCD signals), side by side in one process, replay
// the 70-face, 280-patch Cornell Box's kSteps steps at 15 bits (1-4 lanes, serial and concurrent
// driver). Around sc_start it counts, from the kernel itself: the passes (the systems' reports), the
// timed notifications (every call of sc_ppq_base::insert, the timed-event queue's insert), the
// thread switches (every sc_cor_pkg_qt::yield, one coroutine to the next) and the delta cycles
// (sc_delta_count). The two kernel functions are counted by interposing them: libsystemc.so calls
// both through its symbol table (a PLT slot and a vtable relocation), so this executable's
// definitions below count the call and hand it to the library's (dlsym RTLD_NEXT).
//
// BM_KernelFloor: the same number of passes with no model at all: SC_THREADs whose passes make, on
// average, the timed notifications and thread switches per pass that BM_RealReplay counted (a mix of
// pass shapes calibrated with the same counters, below; its own counters confirm the match), in as
// many independent groups as there were systems. Its time per pass is what the kernel alone costs for
// that many events; real_over_floor = the replay's CPU per pass / the floor's.
//
// Each measurement runs in a forked child (SystemC elaborates once per process) and times sc_start
// alone, in CPU seconds of the child (CLOCK_PROCESS_CPUTIME_ID: the machine is shared) and wall.
#include <benchmark/benchmark.h>
#include <dlfcn.h>
#include <systemc>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "bench/recorded_box.h"
#include "bench/systemc_benchmark_main.h"
#include "host_sw/platform/board_setup.h"
#include "host_sw/platform/board_system.h"
#include "host_sw/studies/timing_study.h"
#include "scenes/prepare.h"

// ---- the kernel's counters, by interposition ------------------------------------------------------

namespace {
std::uint64_t g_timed_inserts = 0;
std::uint64_t g_yields = 0;

template <class F>
F next_definition(const char* symbol) {
  void* f = dlsym(RTLD_NEXT, symbol);
  if (f == nullptr) {
    std::fprintf(stderr, "bench_replay_floor: %s not found in libsystemc\n", symbol);
    std::abort();
  }
  return reinterpret_cast<F>(f);
}
}  // namespace

// int sc_core::sc_ppq_base::insert(void*) and void sc_core::sc_cor_pkg_qt::yield(sc_core::sc_cor*),
// by their mangled names (the Itanium ABI passes `this` first).
extern "C" int rc_counted_ppq_insert(void* self, void* element) __asm__("_ZN7sc_core11sc_ppq_base6insertEPv");
extern "C" void rc_counted_qt_yield(void* self, void* next) __asm__("_ZN7sc_core13sc_cor_pkg_qt5yieldEPNS_6sc_corE");

int rc_counted_ppq_insert(void* self, void* element) {
  static const auto real = next_definition<int (*)(void*, void*)>("_ZN7sc_core11sc_ppq_base6insertEPv");
  ++g_timed_inserts;
  return real(self, element);
}

void rc_counted_qt_yield(void* self, void* next) {
  static const auto real = next_definition<void (*)(void*, void*)>("_ZN7sc_core13sc_cor_pkg_qt5yieldEPNS_6sc_corE");
  ++g_yields;
  real(self, next);
}

namespace {

constexpr int kSteps = 1000;
constexpr int kSystems = 64;  // one shard: kMaxSystemsPerProcess

// What one child measured around sc_start.
struct Figures {
  double cpu_seconds = 0, wall_seconds = 0;
  double passes = 0, timed = 0, yields = 0, deltas = 0;
};

double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Runs `elaborate` (which returns the passes once sc_start is done) and sc_start in a forked child;
// the counters and times of sc_start alone.
template <class Elaborate>
Figures in_child(const Elaborate& elaborate) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("bench_replay_floor: pipe failed");
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("bench_replay_floor: fork failed");
  if (pid == 0) {
    ::close(fds[0]);
    Figures f;
    try {
      auto passes = elaborate();  // elaboration; returns a callable counting passes afterwards
      const std::uint64_t t0 = g_timed_inserts, y0 = g_yields, d0 = sc_core::sc_delta_count();
      const double c0 = cpu_now();
      const auto w0 = std::chrono::steady_clock::now();
      sc_core::sc_start();
      f.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
      f.cpu_seconds = cpu_now() - c0;
      f.timed = double(g_timed_inserts - t0);
      f.yields = double(g_yields - y0);
      f.deltas = double(sc_core::sc_delta_count() - d0);
      f.passes = double(passes());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_replay_floor: %s\n", e.what());
      f.passes = -1;
    }
    if (::write(fds[1], &f, sizeof f) != sizeof f) _exit(3);
    _exit(0);  // the systems are left to the exit, as a study's worker leaves them
  }
  ::close(fds[1]);
  Figures f;
  const ssize_t n = ::read(fds[0], &f, sizeof f);
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (n != sizeof f || f.passes <= 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("bench_replay_floor: the child process failed");
  return f;
}

// ---- the real replay ------------------------------------------------------------------------------

using Workload = rc::bench::RecordedBox;

const Workload& workload() {
  static const Workload w = rc::bench::record_box(kSteps);
  return w;
}

Figures measure_real() {
  const Workload& w = workload();
  return in_child([&w] {
    // As timing_study.cpp's elaborate() makes a board case's system.
    auto systems = std::make_shared<std::vector<std::unique_ptr<rc::BoardSystem>>>();
    for (int i = 0; i < kSystems; ++i) {
      rc::BoardRunOptions o;
      o.lanes = static_cast<rc::board::LaneCount>(1 + i % 4);
      o.concurrent = i % 2 == 1;
      rc::BoardSetup setup = rc::make_board_setup(o);
      setup.stop_when_done = false;
      setup.replay = &w.recorded.recording;
      const std::string name = "case" + std::to_string(i);
      systems->push_back(std::make_unique<rc::BoardSystem>(name.c_str(), w.scene, w.solver, setup));
      for (unsigned card = 0; card < systems->back()->cards(); ++card) systems->back()->card(card).wrapper().set_signals({});
    }
    return [systems] {
      std::uint64_t passes = 0;
      for (const auto& s : *systems) {
        s->rethrow_if_failed();
        if (!s->finished()) throw std::runtime_error("a replay did not finish");
        passes += s->report().board.batching.passes;
      }
      return passes;
    };
  });
}

const Figures& real() {
  static const Figures f = measure_real();
  return f;
}

// ---- the floor ------------------------------------------------------------------------------------

// The floor: pairs of a "host" and a "wrapper" SC_THREAD (and an "echo" thread) doing a serial pass's
// kernel work and nothing else:
//   host:    wait for the interrupt; write the acknowledge (a timed notification nobody waits for);
//            `extra` more such notifications; `pings` immediate ping-pongs with the echo thread
//            (thread switches without timed notifications); START notified at once;
//   wrapper: woken at START; a long pass waits for the pass's end (a timed notification and a turn
//            of its own) and then notifies the interrupt for its latency, a short one notifies the
//            interrupt for both at once.
// Each knob is a rate per pass (long: a share 0..1; extra and pings: any rate), spread evenly over
// the passes. What each costs in timed notifications and switches is not assumed: calibrate()
// measures three pure shapes with the same counters, and the mix is solved to give, per pass, the
// timed notifications and switches the real replay counted.
struct Knobs {
  double long_share = 1, extra = 0, pings = 0;
};

// How many of the events at `rate` per pass fall in pass k (from 0), spread evenly.
std::uint64_t at(std::uint64_t k, double rate) {
  return static_cast<std::uint64_t>(std::floor(double(k + 1) * rate) - std::floor(double(k) * rate));
}

SC_MODULE(FloorPair) {
  static constexpr int kExtraEvents = 16;
  sc_core::sc_event start, irq, ack, ping, pong;
  sc_core::sc_event extra_events[kExtraEvents];
  std::uint64_t passes;
  Knobs knobs;
  std::uint64_t done = 0;

  SC_HAS_PROCESS(FloorPair);
  FloorPair(const sc_core::sc_module_name& n, std::uint64_t passes_, const Knobs& k)
      : sc_core::sc_module(n), passes(passes_), knobs(k) {
    SC_THREAD(host);
    SC_THREAD(wrapper);
    SC_THREAD(echo);
  }

  void host() {
    wait(sc_core::sc_time(1, sc_core::SC_US));
    for (std::uint64_t k = 0; k < passes; ++k) {
      if (k > 0) {
        wait(irq);
        ack.notify(sc_core::sc_time(30, sc_core::SC_NS));
      }
      const std::uint64_t extra = std::min<std::uint64_t>(at(k, knobs.extra), kExtraEvents);
      for (std::uint64_t e = 0; e < extra; ++e) extra_events[e].notify(sc_core::sc_time(20, sc_core::SC_NS));
      for (std::uint64_t p = at(k, knobs.pings); p > 0; --p) {
        ping.notify();
        wait(pong);
      }
      start.notify();
    }
    wait(irq);
    done = passes;
  }

  void wrapper() {
    for (std::uint64_t k = 0;; ++k) {
      wait(start);
      if (at(k, knobs.long_share) > 0) {
        wait(sc_core::sc_time(2, sc_core::SC_US));
        irq.notify(sc_core::sc_time(100, sc_core::SC_NS));
      } else {
        irq.notify(sc_core::sc_time(2100, sc_core::SC_NS));
      }
    }
  }

  void echo() {
    for (;;) {
      wait(ping);
      pong.notify();
    }
  }
};

Figures measure_floor(std::uint64_t passes_total, const Knobs& knobs) {
  return in_child([=] {
    auto pairs = std::make_shared<std::vector<std::unique_ptr<FloorPair>>>();
    const std::uint64_t each = passes_total / kSystems;
    for (int i = 0; i < kSystems; ++i) {
      const std::string name = "pair" + std::to_string(i);
      pairs->push_back(std::make_unique<FloorPair>(name.c_str(), each + (std::uint64_t(i) < passes_total % kSystems), knobs));
    }
    return [pairs] {
      std::uint64_t passes = 0;
      for (const auto& p : *pairs) passes += p->done;
      return passes;
    };
  });
}

// The knobs whose passes make `timed` timed notifications and `switches` switches each, from three
// measured shapes (short, long, long with one ping a pass); a count below what the bare pass makes is
// out of reach (the floor then has more of it, which the counters show).
Knobs calibrate(double timed, double switches) {
  constexpr std::uint64_t kProbe = 64 * 400;
  const Figures s = measure_floor(kProbe, {0, 0, 0}), l = measure_floor(kProbe, {1, 0, 0}), p = measure_floor(kProbe, {1, 0, 1});
  const auto per = [](const Figures& f, double Figures::*x) { return f.*x / f.passes; };
  const double s_sw = per(s, &Figures::yields), l_sw = per(l, &Figures::yields), ping_sw = per(p, &Figures::yields) - l_sw;
  const double s_t = per(s, &Figures::timed), l_t = per(l, &Figures::timed);
  Knobs k;
  if (switches >= l_sw) {
    k.long_share = 1;
    k.pings = ping_sw > 0 ? (switches - l_sw) / ping_sw : 0;
  } else {
    k.long_share = l_sw > s_sw ? std::max(0.0, (switches - s_sw) / (l_sw - s_sw)) : 0;
  }
  k.extra = std::max(0.0, timed - (s_t + k.long_share * (l_t - s_t)));
  return k;
}

void report(benchmark::State& state, const Figures& f) {
  state.counters["passes"] = f.passes;
  state.counters["timed_per_pass"] = f.timed / f.passes;
  state.counters["switches_per_pass"] = f.yields / f.passes;
  state.counters["deltas_per_pass"] = f.deltas / f.passes;
  state.counters["cpu_ns_per_pass"] = 1e9 * f.cpu_seconds / f.passes;
  state.counters["wall_ns_per_pass"] = 1e9 * f.wall_seconds / f.passes;
}

void BM_RealReplay(benchmark::State& state) {
  Figures f;
  for (auto _ : state) {
    f = real();  // measured once, for the floor too
    state.SetIterationTime(f.cpu_seconds);
  }
  report(state, f);
  state.SetLabel(std::to_string(kSystems) + " board systems, " + std::to_string(kSteps) + " steps of 70 faces / 280 patches");
}
BENCHMARK(BM_RealReplay)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);

void BM_KernelFloor(benchmark::State& state) {
  const Figures& r = real();
  const Knobs knobs = calibrate(r.timed / r.passes, r.yields / r.passes);
  Figures f;
  for (auto _ : state) {
    f = measure_floor(static_cast<std::uint64_t>(r.passes), knobs);
    state.SetIterationTime(f.cpu_seconds);
  }
  report(state, f);
  state.counters["real_over_floor"] = (r.cpu_seconds / r.passes) / (f.cpu_seconds / f.passes);
  state.counters["long_share"] = knobs.long_share;
  state.counters["pings_per_pass"] = knobs.pings;
  state.counters["extra_per_pass"] = knobs.extra;
  state.SetLabel("no model: the real replay's passes, timed notifications and switches per pass");
}
BENCHMARK(BM_KernelFloor)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

// SystemC's library owns main() and calls sc_main (bench/systemc_benchmark_main.h).
int sc_main(int argc, char** argv) { return rc::bench::run_benchmarks(argc, argv); }
