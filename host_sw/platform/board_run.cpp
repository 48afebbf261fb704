#include "host_sw/platform/board_run.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <tlm_utils/tlm_quantumkeeper.h>

#include "board/device_profile.h"
#include "board/fast_wrapper.h"
#include "host_sw/platform/software_system.h"
#include "host_sw/platform/work_replay.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {

namespace {

double seconds(const sc_core::sc_time& t) { return t.to_seconds(); }

// The host thread runs ahead of simulated time by up to this much without a context switch. Its
// bus accesses are temporally decoupled (timed at its local time) and it syncs before waiting for
// the interrupt, so the quantum changes no result (paper.json is byte-identical at 1 ms and
// 100 ms); a step of a 4480-patch scene is several ms of host work, so 1 ms cost a few syncs a step.
const sc_core::sc_time kHostQuantum(100, sc_core::SC_MS);

}  // namespace

BoardSetup make_board_setup(const BoardRunOptions& o) {
  const board::DeviceProfile device = o.device_profile ? *o.device_profile : board::find_device_profile(o.device);
  BoardSetup s;
  s.host = o.host_profile ? *o.host_profile : find_host_profile(o.host);
  board::BoardChoices c;
  c.lanes = o.lanes;
  c.banks = o.banks;
  c.bits = o.bits;
  c.float_format = o.float_format;
  c.bank_capacity_bytes = o.bank_capacity_bytes;
  c.model = o.model;
  c.irq_latency = s.host.interrupt_latency;
  s.board = board::make_board_params(device, c);
  s.board.report_at_end = o.print_summaries;
  // The layout, made once: a bad configuration fails here, before elaboration, and the board uses it.
  s.layout = board::make_bank_layout(s.board);  // results placed as the profile says (bank or on chip)
  s.driver.concurrent = o.concurrent;
  s.driver.allow_batching = o.allow_batching;
  s.driver.oracle = o.oracle;
  s.driver.cpu_split = o.cpu_split.on() ? o.cpu_split : s.host.driver_model.cpu_split;  // the option, else the profile's
  if (s.driver.cpu_split.on() && o.cards > 1) {
    throw std::invalid_argument("--cpu-share: a CPU/FPGA split drives one card (got " +
                                std::to_string(o.cards.value()) + " cards)");
  }
  if (o.trace) {
    s.trace_first_step = o.trace_first_step;
    s.trace_last_step = o.trace_last_step;
  }
  s.on_progress = o.on_progress;
  s.cards = o.cards;
  s.card_split = o.card_split;
  s.card_bus = o.card_bus;
  s.energy = energy::load_energy_tables(&device, s.host.json, s.host.file);
  return s;
}

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
  if (cards() == 1) {
    BoardVisibilityOptions driver = setup.driver;
    if (driver.cpu_split.on() && driver.oracle == nullptr && driver.cpu_kernel == nullptr) {
      const board::BankLayout& L = board.layout();
      m_cpu_kernel = make_software_visibility(L.float_format ? L.float_format->to_string() : "fixed", L.bits);
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
    m_multi = std::make_unique<MultiCardVisibility>(std::move(ports), m_cpu, setup.driver, setup.card_split,
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

namespace {

std::array<WorkTally, kHostWorkKinds> host_work(const HostCpuModel& cpu) {
  std::array<WorkTally, kHostWorkKinds> work{};
  for (int k = 0; k < kHostWorkKinds; ++k) work[k] = {cpu.count(HostWork(k)), seconds(cpu.time(HostWork(k)))};
  return work;
}

DeviceReport device_report(const board::BoardParams& p) {
  DeviceReport d;
  d.profile = p.device;
  d.lanes = p.lanes;
  d.bits = p.float_format ? 0 : static_cast<int>(p.bits);  // float lanes: no fractional width (as `accuracy`)
  d.clock_hz = 1.0 / seconds(p.timing.device_period);
  d.banks = p.banks;
  d.bank_capacity_bytes = p.bank_capacity_bytes;
  d.bank_word_bits = p.word_bits;
  d.bank_clock_hz = 1.0 / seconds(p.timing.bank_period);
  d.pci_width_bits = p.pci.width_bits;
  d.pci_clock_hz = 1.0 / seconds(p.pci.clock_period);
  d.pipeline_latency_cycles = p.timing.pipeline_latency;
  d.wrapper_model = p.model == board::WrapperModel::fast ? "fast" : "cycle";
  d.design = {p.fit.hard_lanes, p.fit.soft_lanes, p.fit.slices, p.fit.slices_available, p.fit.block_multipliers,
              p.fit.block_multipliers_available, p.fit.pipeline_clock_mhz, p.fit.modelled};
  return d;
}

LayoutReport layout_report(const board::BankLayout& L) {
  LayoutReport l;
  l.coordinates_per_word = L.coords_per_word;
  l.field_bits = L.field_bits;
  l.face_bank = L.face_bank;
  l.result_bank = L.result_bank;
  l.own_face_table = L.mask_bank ? "bank " + std::to_string(*L.mask_bank) : std::string("face bank");
  for (const board::RayGroup& g : L.groups) l.ray_groups.push_back({g.banks, g.lanes, g.first_lane, g.k() / 3.0});
  l.spare_banks = L.spare_banks;
  l.nominal_rays_per_cycle = L.nominal_rays_per_cycle();
  return l;
}

}  // namespace

namespace {

// Several cards' driver statistics as one (one card's: a copy).
void add(BoardDriverStats& into, const BoardDriverStats& d) {
  into.passes += d.passes;
  into.ray_batches += d.ray_batches;
  into.face_set_uploads += d.face_set_uploads;
  into.face_sets += d.face_sets;
  into.max_batches_per_step = std::max(into.max_batches_per_step, d.max_batches_per_step);
  into.dma_transfers += d.dma_transfers;
  into.register_accesses += d.register_accesses;
  into.pio_transfers += d.pio_transfers;
  into.pio_bytes_written += d.pio_bytes_written;
  into.pio_bytes_read += d.pio_bytes_read;
  into.pio += d.pio;
  into.bytes_to_board += d.bytes_to_board;
  into.bytes_to_host += d.bytes_to_host;
  into.tests += d.tests;
  into.pci += d.pci;
  into.waiting += d.waiting;
  into.fpga_busy += d.fpga_busy;
  into.overlap += d.overlap;
  for (const auto& [limit, tally] : d.limits) {
    into.limits[limit].passes += tally.passes;
    into.limits[limit].fpga_busy += tally.fpga_busy;
  }
}

}  // namespace

CardsReport BoardSystem::cards_report(double total) const {
  CardsReport c;
  c.count = cards();
  c.split = choice_name(m_setup.card_split);
  c.bus = choice_name(m_setup.card_bus);
  for (unsigned k = 0; k < cards(); ++k) {
    const BoardDriverStats& d = card_driver(k).stats();
    const tlmx::PciBusReport pci = card(k).pci.report();
    const HostCpuModel& cpu = card_cpu(k);
    c.per_card.push_back({k, m_multi ? m_multi->faces(k) : m_scene.faces.size(), d.passes, d.tests, seconds(d.fpga_busy),
                          d.bytes_to_board, d.bytes_to_host, seconds(pci.total.busy), seconds(pci.total.wait),
                          seconds(cpu.driver_time()), seconds(d.pci), seconds(d.waiting),
                          seconds(m_multi ? m_multi->idle(k, m_end) : sc_core::SC_ZERO_TIME)});
    const bool new_bus = m_setup.card_bus == CardBus::separate || k == 0;
    if (new_bus) c.buses.push_back({});
    BusReport& bus = c.buses.back();
    bus.cards.push_back(k);
    bus.busy_seconds += seconds(pci.total.busy);
    bus.utilisation = total > 0 ? bus.busy_seconds / total : 0.0;
  }
  return c;
}

RunReport BoardSystem::report(double wall_seconds) const {
  const board::BoardParams& p = board.params();
  const board::BankLayout& L = board.layout();
  BoardDriverStats d = card_driver(0).stats();
  for (unsigned c = 1; c < cards(); ++c) add(d, card_driver(c).stats());
  const double total = seconds(m_end);
  const double busy = seconds(d.fpga_busy);

  RunReport r;
  r.board_run = true;
  r.simulated_seconds = total;
  r.time.host_compute = seconds(m_cpu.compute_time() - m_cpu.second_cpu_compute());
  r.time.driver_cpu = seconds(m_cpu.driver_time());  // with several cards: 0 (the drivers have their threads)
  r.time.pci_transfer = m_multi ? 0.0 : seconds(d.pci);
  r.time.waiting = seconds(m_multi ? m_multi->waiting() : d.waiting);
  r.time.fpga_busy = busy;
  r.time.overlap = seconds(m_multi ? m_multi->overlap() : d.overlap);
  r.time.second_cpu = (m_setup.driver.concurrent && m_setup.host.driver_model.overlap == DriverModel::Overlap::DualCpu) ||
                      (m_setup.driver.cpu_split.on() && m_setup.driver.cpu_split.cores == 2);
  if (r.time.second_cpu) {
    r.time.second_cpu_compute = seconds(m_cpu.second_cpu_compute());
    r.time.second_cpu_wait = seconds(m_cpu.second_cpu_wait());
  }
  BoardDetail& b = r.board;
  b.device = device_report(p);
  b.layout = layout_report(L);
  b.max_rays_per_batch = L.max_rays_per_batch;
  b.max_faces_per_set = L.max_faces_per_set;
  b.batching = {d.passes, d.ray_batches, d.max_batches_per_step, d.face_sets, d.face_set_uploads};
  std::uint64_t bus_transactions = 0;
  sc_core::sc_time bus_busy = sc_core::SC_ZERO_TIME;
  for (unsigned c = 0; c < cards(); ++c) {
    const tlmx::PciBusReport pci = card(c).pci.report();
    bus_transactions += pci.total.transactions;
    bus_busy += pci.total.busy;
  }
  b.pci = {d.bytes_to_board, d.bytes_to_host, d.dma_transfers, d.pio_transfers, d.register_accesses, bus_transactions,
           seconds(bus_busy)};
  for (unsigned bank = 0; bank < p.banks; ++bank) {
    tlmx::SramBankReport br = card(0).bank(bank).report();
    for (unsigned c = 1; c < cards(); ++c) {
      const tlmx::SramBankReport o = card(c).bank(bank).report();
      br.reads += o.reads;
      br.writes += o.writes;
      br.bytes_read += o.bytes_read;
      br.bytes_written += o.bytes_written;
      br.busy += o.busy;
    }
    const double bytes = static_cast<double>(br.bytes_read + br.bytes_written);
    b.banks.push_back({bank, L.role(bank), br.reads, br.writes, br.bytes_read, br.bytes_written, seconds(br.busy),
                       total > 0 ? bytes / total : 0.0, busy > 0 ? bytes / busy : 0.0});
  }
  std::uint64_t busy_cycles = 0;
  for (unsigned c = 0; c < cards(); ++c) busy_cycles += card(c).wrapper().stats().busy_cycles;
  for (const board::RayGroup& g : L.groups) {
    for (unsigned j = 0; j < g.lanes; ++j) {
      const unsigned lane = g.first_lane + j;
      std::uint64_t rays = 0;
      for (unsigned c = 0; c < cards(); ++c) rays += card(c).wrapper().stats().lane_rays[lane];
      b.lanes.push_back({lane, g.k() / 3.0, rays, busy_cycles > 0 ? static_cast<double>(rays) / busy_cycles : 0.0});
    }
  }
  for (const auto& [limit, tally] : d.limits) b.stream_limits.push_back({limit, tally.passes, seconds(tally.fpga_busy)});
  r.intersections = {d.tests, total > 0 ? d.tests / total : 0.0, busy > 0 ? d.tests / busy : 0.0};
  r.host_profile = m_setup.host.name;
  r.work = host_work(m_cpu);
  b.driver_model = m_setup.host.driver_model.name();
  for (int k = 0; k < kDriverWorkKinds; ++k) {
    std::uint64_t count = 0;
    sc_core::sc_time time = sc_core::SC_ZERO_TIME;
    for (unsigned c = 0; c < cards(); ++c) {
      count += card_cpu(c).count(DriverWork(k));
      time += card_cpu(c).time(DriverWork(k));
    }
    b.driver[k] = {count, seconds(time)};
  }
  if (cards() > 1) b.cards = cards_report(total);
  if (wall_seconds >= 0) {
    r.has_wall = true;
    r.wall_seconds = wall_seconds;
    r.wall_seconds_per_step = m_result.steps > 0 ? wall_seconds / m_result.steps : 0.0;
  }
  attach_energy(r, m_setup.energy, static_cast<std::uint64_t>(m_result.steps));
  return r;
}

BoardRunResult run_radiosity_on_board(const Scene& scene, const SolverOptions& solver, const BoardRunOptions& options) {
  static BoardSystem* system = nullptr;  // SystemC keeps elaborated modules until the process ends
  if (system != nullptr) throw std::logic_error("run_radiosity_on_board may be called once per process (SystemC elaborates once)");
  const BoardSetup setup = make_board_setup(options);
  system = new BoardSystem("rc2000sim", scene, solver, setup);
  sc_core::sc_trace_file* vcd = nullptr;
  if (!options.vcd_path.empty()) {
    std::string base = options.vcd_path;
    if (base.size() > 4 && base.substr(base.size() - 4) == ".vcd") base.resize(base.size() - 4);
    vcd = sc_core::sc_create_vcd_trace_file(base.c_str());
    sc_core::sc_trace(vcd, system->board.start_signal, "start");
    sc_core::sc_trace(vcd, system->board.busy_signal, "busy");
    sc_core::sc_trace(vcd, system->board.done_signal, "done");
    sc_core::sc_trace(vcd, system->board.irq_signal, "irq");
  }
  const auto t0 = std::chrono::steady_clock::now();
  sc_core::sc_start();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (vcd != nullptr) sc_core::sc_close_vcd_trace_file(vcd);
  system->rethrow_if_failed();
  return {system->result(), system->report(wall), options.trace ? system->trace_writer().text() : std::string()};
}

}  // namespace rc
