#include "host_sw/platform/board_system.h"

#include <stdexcept>

#include <tlm_utils/tlm_quantumkeeper.h>

#include "board/fast_wrapper.h"
#include "host_sw/platform/software_system.h"
#include "host_sw/platform/work_replay.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {

namespace {

// The host thread runs ahead of simulated time by up to this much without a context switch. Its
// bus accesses are temporally decoupled (timed at its local time) and it syncs before waiting for
// the interrupt, so the quantum changes no result (paper.json is byte-identical at 1 ms and
// 100 ms); a step of a 4480-patch scene is several ms of host work, so 1 ms cost a few syncs a step.
const sc_core::sc_time kHostQuantum(100, sc_core::SC_MS);

}  // namespace

namespace {

// Card 0 keeps the one-card name, so one card's system is exactly what it always was.
std::vector<std::unique_ptr<board::Rc2000>> make_cards(const BoardSetup& setup) {
  std::vector<std::unique_ptr<board::Rc2000>> cards;
  for (unsigned c = 0; c < setup.cards; ++c) {
    const std::string name = c == 0 ? std::string("rc2000") : "rc2000_" + std::to_string(c);
    cards.push_back(std::make_unique<board::Rc2000>(name.c_str(), setup.board, setup.layout));
  }
  return cards;
}

}  // namespace

BoardSystem::BoardSystem(const sc_core::sc_module_name& name, const Scene& scene, const SolverOptions& solver,
                         const BoardSetup& setup)
    : sc_core::sc_module(name),
      host_out("host_out"),
      m_cards(make_cards(setup)),
      board(*m_cards.front()),
      m_scene(scene),
      m_solver(solver),
      m_setup(setup),
      m_cpu(setup.host),
      m_trace(setup.trace_first_step, setup.trace_last_step) {
  host_out.bind(board.pci.in);
  if (tlm_utils::tlm_quantumkeeper::get_global_quantum() == sc_core::SC_ZERO_TIME)
    tlm_utils::tlm_quantumkeeper::set_global_quantum(kHostQuantum);
  if (setup.trace_last_step >= setup.trace_first_step) m_cpu.set_trace(&m_trace);
  const bool tracing = setup.trace_last_step >= setup.trace_first_step;
  // The driver sees the board only through its ports; what it needs from the wrapper (which answer
  // the lanes copy, timing-only passes, the end of each pass) is wired here.
  auto ports_of = [](board::Rc2000& card, tlm::tlm_initiator_socket<>& out) {
    BoardPorts ports{out, card.dma, card.irq, card.interface(), {}};
    ports.sideband.before_start = [&card](const std::uint8_t* oracle_answer, bool timing_only) {
      card.wrapper().set_oracle(oracle_answer);
      card.wrapper().set_timing_only(timing_only);
    };
    return ports;
  };
  // The lanes' guard band on t is the solver's (SolverOptions::fixes.t_guard): the driver writes it to T_GUARD.
  BoardVisibilityOptions driver_options = setup.driver;
  driver_options.t_guard = solver.fixes.t_guard;
  if (cards() == 1) {
    BoardVisibilityOptions driver = driver_options;
    if (driver.cpu_split.on() && driver.oracle == nullptr && driver.cpu_kernel == nullptr) {
      const board::BankLayout& L = board.layout();
      if (L.float_format && driver.t_guard != 0) throw std::invalid_argument("a t guard band needs fixed-point lanes");
      m_cpu_kernel = make_software_visibility(L.float_format ? L.float_format->to_string() : "fixed", L.bits, 0,
                                              driver.t_guard);
      driver.cpu_kernel = m_cpu_kernel.get();
    }
    m_visibility = std::make_unique<BoardVisibility>(ports_of(board, host_out), m_cpu, driver,
                                                     tracing ? &m_trace : nullptr);
    board.wrapper().on_pass([this](const board::PassRecord& r) { m_visibility->pass_finished(r); });
  } else {
    std::vector<BoardPorts> ports{ports_of(board, host_out)};
    for (unsigned c = 1; c < cards(); ++c) {
      board::Rc2000& k = card(c);
      m_card_out.push_back(std::make_unique<tlm_utils::simple_initiator_socket<BoardSystem>>(
          ("host_out_" + std::to_string(c)).c_str()));
      m_card_out.back()->bind(k.pci.in);
      if (setup.card_bus == CardBus::shared) k.pci.share_arbitration_with(board.pci);
      ports.push_back(ports_of(k, *m_card_out.back()));
    }
    m_multi = std::make_unique<MultiCardVisibility>(std::move(ports), m_cpu, driver_options, setup.card_split,
                                                    tracing ? &m_trace : nullptr);
    for (unsigned c = 0; c < cards(); ++c) {
      card(c).wrapper().on_pass([this, c](const board::PassRecord& r) { m_multi->pass_finished(c, r); });
    }
  }
  SC_HAS_PROCESS(BoardSystem);
  SC_THREAD(run);
}

const BoardVisibility& BoardSystem::card_driver(unsigned c) const {
  if (m_multi) return m_multi->driver(c);
  if (c != 0) throw std::out_of_range("card " + std::to_string(c) + " of a one-card system");
  return *m_visibility;
}

const HostCpuModel& BoardSystem::card_cpu(unsigned c) const {
  if (m_multi) return m_multi->cpu(c);
  if (c != 0) throw std::out_of_range("card " + std::to_string(c) + " of a one-card system");
  return m_cpu;
}

void BoardSystem::run() {
  try {
    VisibilityBackend& visibility = m_multi ? static_cast<VisibilityBackend&>(*m_multi) : *m_visibility;
    if (m_setup.replay != nullptr) {
      visibility.load_faces(m_scene.face_triangles(), m_scene.sheets);
      TimingReplayTarget* target = m_multi ? static_cast<TimingReplayTarget*>(m_multi.get()) : m_visibility.get();
      replay_host_work(*m_setup.replay, {m_scene.patches.size(), m_solver.fixed_steps}, m_cpu, target);
      m_result.steps = m_solver.fixed_steps;
    } else {
      ProgressiveRadiosity solver(m_scene, visibility, m_solver, &m_cpu);
      if (m_setup.on_progress) solver.on_progress(m_setup.on_progress);
      if (m_setup.on_answers) solver.on_answers(m_setup.on_answers);
      m_result = solver.run();
    }
    m_cpu.sync();
  } catch (...) {
    m_error = std::current_exception();
  }
  m_end = sc_core::sc_time_stamp();
  m_finished = true;
  if (m_setup.stop_when_done) sc_core::sc_stop();
}

void BoardSystem::rethrow_if_failed() const {
  if (m_error) std::rethrow_exception(m_error);
}

}  // namespace rc
