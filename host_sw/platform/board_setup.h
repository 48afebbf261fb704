// A board run's setup (the second job of host_sw/platform/board_run.h): the profiles loaded once, the
// lanes fitted to the device, the bank layout made and checked, the driver's options, the energy
// tables; all before elaboration, so a bad choice fails before any simulation.
#pragma once

#include <functional>

#include "board/bank_layout.h"
#include "board/board_params.h"
#include "host_sw/driver/board_visibility.h"
#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/energy/energy_table.h"
#include "host_sw/platform/board_run_options.h"
#include "host_sw/platform/card_options.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/visibility/visibility_recording.h"

namespace rc {

struct BoardSetup {
  board::BoardParams board;
  board::BankLayout layout;  // of `board`, made (and so checked) once, by make_board_setup
  HostProfile host;
  BoardVisibilityOptions driver;
  int trace_first_step = 1, trace_last_step = 0;  // empty range: no trace
  bool stop_when_done = true;                      // sc_stop() when the solver has finished
  // Timing replay (work_replay.h): the host replays this recording's work instead of running the
  // solver, and the board runs the same passes without data. The result then has no radiosity.
  const VisibilityRecording* replay = nullptr;
  std::function<void(const StepProgress&)> on_progress;
  AnswersObserver on_answers;
  CardCount cards = 1;  // identical cards, each `board`
  CardSplit card_split = CardSplit::rays;
  CardBus card_bus = CardBus::shared;
  energy::EnergyTables energy;  // the device's and host's energy tables, or why there are none
};

// Loads the profiles and checks the options (throws std::invalid_argument).
BoardSetup make_board_setup(const BoardRunOptions& options);

}  // namespace rc
