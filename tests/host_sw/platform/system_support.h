// Helpers for the tests that run the whole system (host thread with the solver, RC2000 board).
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "host_sw/platform/board_run.h"
#include "host_sw/visibility/fixed_visibility.h"
#include "tests/common/simple_scenes.h"

namespace rc::test {

// The paper's smallest scene (Table 2, first row): the Cornell Box refined to 70 faces, 280 patches.
inline Scene small_cornell_box() { return cornell_box(1, 70); }

inline SolverOptions steps(int n) {
  SolverOptions s;
  s.fixed_steps = n;
  return s;
}

// Bit for bit: every band of every patch.
inline void expect_identical(const std::vector<Spectrum>& a, const std::vector<Spectrum>& b) {
  ASSERT_EQ(a.size(), b.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differ += std::memcmp(&a[i], &b[i], sizeof(Spectrum)) != 0;
  EXPECT_EQ(differ, 0u) << "patches whose radiosity differs";
}

// The cycle-level wrapper against the fast one on the same run: the same radiosity bit for bit, the
// same end time, FPGA busy time and wrapper cycles, and the same reads, writes and busy time per bank.
inline void expect_cycle_model_matches_fast(const BoardSystem& fast, const BoardSystem& cycle) {
  expect_identical(fast.result().radiosity, cycle.result().radiosity);
  EXPECT_EQ(fast.end_time(), cycle.end_time());
  EXPECT_EQ(fast.driver().stats().fpga_busy, cycle.driver().stats().fpga_busy);
  EXPECT_EQ(fast.board.wrapper().stats().busy_cycles, cycle.board.wrapper().stats().busy_cycles);
  for (unsigned b = 0; b < fast.board.params().banks; ++b) {
    EXPECT_EQ(fast.board.bank(b).report().reads, cycle.board.bank(b).report().reads) << "bank " << b;
    EXPECT_EQ(fast.board.bank(b).report().writes, cycle.board.bank(b).report().writes) << "bank " << b;
    EXPECT_EQ(fast.board.bank(b).report().busy, cycle.board.bank(b).report().busy) << "bank " << b;
  }
}

inline SolverResult cpu_fixed_point(const Scene& scene, const SolverOptions& options, int bits) {
  FixedPointVisibility v(bits, options.fixes.t_guard);  // the lanes' guard band on t, when the options set one
  return ProgressiveRadiosity(scene, v, options).run();
}

// A setup from the shipped profiles; the system does not stop the simulation when it finishes.
inline BoardSetup setup(BoardRunOptions o) {
  BoardSetup s = make_board_setup(o);
  s.stop_when_done = false;
  return s;
}

// Runs until every system's host thread has finished (the cycle-level model's clock never runs
// out of events, so the simulation is stopped explicitly).
inline void run_all(const std::vector<BoardSystem*>& systems) {
  auto done = [&] {
    for (BoardSystem* s : systems)
      if (!s->finished()) return false;
    return true;
  };
  while (!done()) sc_core::sc_start(sc_core::sc_time(1, sc_core::SC_MS));
  sc_core::sc_stop();
  for (BoardSystem* s : systems) s->rethrow_if_failed();
}

}  // namespace rc::test
