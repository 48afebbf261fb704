// The SystemC system of a board run (host_sw/platform/board_run.h): a host PC whose SC_THREAD runs
// ProgressiveRadiosity with BoardVisibility and the host CPU cost model, plus one or several RC2000
// boards. Tests and tools that need two systems side by side construct two BoardSystem modules in
// one elaboration. Its report is assembled in board_report.cpp.
#pragma once

#include <exception>
#include <memory>
#include <vector>

#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>

#include "board/rc2000.h"
#include "host_sw/driver/board_visibility.h"
#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/driver/multi_card_visibility.h"
#include "host_sw/driver/trace_writer.h"
#include "host_sw/platform/board_setup.h"
#include "host_sw/platform/run_report.h"
#include "host_sw/radiosity/radiosity.h"
#include "scenes/scene.h"

namespace rc {

// One card: the host PC and one RC2000, its driver on the host thread. Several cards (setup.cards):
// identical RC2000s, each with its own PCI bus (its BARs) and a host PCI master of its own; with
// CardBus::shared the buses share card 0's arbitration (tlm/pci_bus.h), so they are one bus in
// time; the solver talks to MultiCardVisibility, whose driver threads run the cards.
class BoardSystem : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<BoardSystem> host_out;  // the host CPU's PCI master of card 0

 private:
  std::vector<std::unique_ptr<board::Rc2000>> m_cards;  // before `board`, which is card 0

 public:
  board::Rc2000& board;  // card 0 (the only one unless setup.cards > 1)

  BoardSystem(const sc_core::sc_module_name& name, const Scene& scene, const SolverOptions& solver,
              const BoardSetup& setup);

  bool finished() const { return m_finished; }
  void rethrow_if_failed() const;
  const SolverResult& result() const { return m_result; }
  sc_core::sc_time end_time() const { return m_end; }  // when the host thread finished
  const HostCpuModel& cpu() const { return m_cpu; }     // the solver's processor
  const BoardVisibility& driver() const { return card_driver(0); }
  unsigned cards() const { return static_cast<unsigned>(m_cards.size()); }
  board::Rc2000& card(unsigned c) { return *m_cards.at(c); }
  const board::Rc2000& card(unsigned c) const { return *m_cards.at(c); }
  const BoardVisibility& card_driver(unsigned c) const;
  const HostCpuModel& card_cpu(unsigned c) const;  // the processor card c's driver runs on
  const MultiCardVisibility* multi_card() const { return m_multi.get(); }  // null with one card
  TraceWriter& trace_writer() { return m_trace; }  // not trace(): sc_object::trace(sc_trace_file*) is virtual
  RunReport report(double wall_seconds = -1) const;

 private:
  void run();
  CardsReport cards_report(double total) const;

  const Scene& m_scene;
  SolverOptions m_solver;
  BoardSetup m_setup;
  HostCpuModel m_cpu;
  TraceWriter m_trace;
  std::unique_ptr<VisibilityBackend> m_cpu_kernel;  // the CPU/FPGA split's answers, when no oracle gives them
  std::unique_ptr<BoardVisibility> m_visibility;  // one card
  std::unique_ptr<MultiCardVisibility> m_multi;   // several
  std::vector<std::unique_ptr<tlm_utils::simple_initiator_socket<BoardSystem>>> m_card_out;  // cards 1..
  SolverResult m_result;
  sc_core::sc_time m_end = sc_core::SC_ZERO_TIME;
  bool m_finished = false;
  std::exception_ptr m_error;
};

}  // namespace rc
