#include "platform/board_run.h"

#include <chrono>
#include <stdexcept>

#include <tlm_utils/tlm_quantumkeeper.h>

#include "board/device_profile.h"
#include "board/fast_wrapper.h"
#include "platform/software_system.h"
#include "platform/work_replay.h"

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
  const board::DeviceProfile device = board::find_device_profile(o.device);
  BoardSetup s;
  s.host = o.host_profile ? *o.host_profile : find_host_profile(o.host);
  board::BoardChoices c;
  c.lanes = o.lanes;
  c.banks = o.banks;
  c.bits = o.bits;
  c.bank_capacity_bytes = o.bank_capacity_bytes;
  c.model = o.model;
  c.irq_latency = s.host.interrupt_latency;
  if (o.lanes == 0) throw std::invalid_argument("lanes must be at least 1");
  s.board = board::make_board_params(device, c);
  s.board.report_at_end = o.print_summaries;
  // Checks the layout now, so that a bad configuration fails before elaboration.
  (void)board::make_bank_layout(s.board.lanes, s.board.banks, s.board.bits, s.board.word_bits,
                                s.board.bank_capacity_bytes);
  s.driver.concurrent = o.concurrent;
  s.driver.allow_batching = o.allow_batching;
  s.driver.oracle = o.oracle;
  if (!o.trace_path.empty()) {
    s.trace_first_step = o.trace_first_step;
    s.trace_last_step = o.trace_last_step;
  }
  s.on_progress = o.on_progress;
  return s;
}

BoardSystem::BoardSystem(const sc_core::sc_module_name& name, const Scene& scene, const SolverOptions& solver,
                         const BoardSetup& setup)
    : sc_core::sc_module(name),
      host_out("host_out"),
      board("rc2000", setup.board),
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
  BoardPorts ports{host_out, board.dma, board.irq, board.interface(), {}};
  ports.sideband.before_start = [this](const std::uint8_t* oracle_answer, bool timing_only) {
    board.wrapper().set_oracle(oracle_answer);
    board.wrapper().set_timing_only(timing_only);
  };
  m_visibility = std::make_unique<BoardVisibility>(ports, m_cpu, setup.driver, tracing ? &m_trace : nullptr);
  board.wrapper().on_pass([this](const board::PassRecord& r) { m_visibility->pass_finished(r); });
  SC_HAS_PROCESS(BoardSystem);
  SC_THREAD(run);
}

void BoardSystem::run() {
  try {
    if (m_setup.replay != nullptr) {
      m_visibility->load_faces(m_scene.face_triangles());
      replay_host_work(*m_setup.replay, {m_scene.patches.size(), m_solver.fixed_steps}, m_cpu, m_visibility.get());
      m_result.steps = m_solver.fixed_steps;
    } else {
      ProgressiveRadiosity solver(m_scene, *m_visibility, m_solver, &m_cpu);
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

nlohmann::ordered_json BoardSystem::report(double wall_seconds) const {
  using nlohmann::ordered_json;
  const board::BoardParams& p = board.params();
  const board::BankLayout& L = board.layout();
  const BoardDriverStats& d = m_visibility->stats();
  const board::WrapperStats& w = board.wrapper().stats();
  const double total = seconds(m_end);
  const double busy = seconds(d.fpga_busy);

  ordered_json r;
  r["schema"] = "rc2000sim.board/1";
  r["simulated_seconds"] = total;
  r["time"] = {{"host_compute_seconds", seconds(m_cpu.compute_time() - m_cpu.second_cpu_compute())},
               {"driver_cpu_seconds", seconds(m_cpu.driver_time())},
               {"pci_transfer_seconds", seconds(d.pci)},
               {"waiting_seconds", seconds(d.waiting)},
               {"fpga_busy_seconds", busy},
               {"overlap_seconds", seconds(d.overlap)}};
  if (m_setup.driver.concurrent && m_setup.host.driver_model.overlap == DriverModel::Overlap::DualCpu) {
    r["time"]["second_cpu_compute_seconds"] = seconds(m_cpu.second_cpu_compute());
    r["time"]["second_cpu_wait_seconds"] = seconds(m_cpu.second_cpu_wait());
    r["time"]["note"] = "host_compute + driver_cpu + pci_transfer + waiting + second_cpu_wait = simulated_seconds (the "
                        "first processor's timeline); the second computes the form factors (second_cpu_compute) beside "
                        "it; fpga_busy overlaps host compute by overlap_seconds";
  } else {
    r["time"]["note"] = "host_compute + driver_cpu + pci_transfer + waiting = simulated_seconds (the host thread's "
                        "timeline); fpga_busy runs beside it, overlapping host compute by overlap_seconds";
  }
  r["device"] = {{"profile", p.device},
                 {"lanes", p.lanes},
                 {"bits", p.bits},
                 {"clock_hz", 1.0 / seconds(p.timing.device_period)},
                 {"banks", p.banks},
                 {"bank_capacity_bytes", p.bank_capacity_bytes},
                 {"bank_word_bits", p.word_bits},
                 {"bank_clock_hz", 1.0 / seconds(p.timing.bank_period)},
                 {"pci_width_bits", p.pci.width_bits},
                 {"pci_clock_hz", 1.0 / seconds(p.pci.clock_period)},
                 {"pipeline_latency_cycles", p.timing.pipeline_latency},
                 {"wrapper_model", p.model == board::WrapperModel::fast ? "fast" : "cycle"},
                 {"design", {{"block_multiplier_lanes", p.fit.hard_lanes},
                             {"slice_multiplier_lanes", p.fit.soft_lanes},
                             {"slices", p.fit.slices},
                             {"slices_available", p.fit.slices_available},
                             {"block_multipliers", p.fit.block_multipliers},
                             {"block_multipliers_available", p.fit.block_multipliers_available},
                             {"pipeline_clock_mhz", p.fit.pipeline_clock_mhz},
                             {"resources_modelled", p.fit.modelled}}}};
  ordered_json groups = ordered_json::array();
  for (const board::RayGroup& g : L.groups)
    groups.push_back({{"banks", g.banks}, {"lanes", g.lanes}, {"first_lane", g.first_lane},
                      {"rate_per_lane", g.k() / 3.0}});
  r["layout"] = {{"coordinates_per_word", L.coords_per_word},
                 {"field_bits", L.field_bits},
                 {"face_bank", L.face_bank},
                 {"result_bank", L.result_bank},
                 {"own_face_table", L.mask_bank ? "bank " + std::to_string(*L.mask_bank) : std::string("face bank")},
                 {"ray_groups", groups},
                 {"spare_banks", L.spare_banks},
                 {"nominal_rays_per_cycle", L.nominal_rays_per_cycle()}};
  r["capacity"] = {{"max_rays_per_batch", L.max_rays_per_batch}, {"max_faces_per_set", L.max_faces_per_set}};
  r["batching"] = {{"passes", d.passes},
                   {"ray_batches", d.ray_batches},
                   {"max_batches_per_step", d.max_batches_per_step},
                   {"face_sets", d.face_sets},
                   {"face_set_uploads", d.face_set_uploads}};
  const tlmx::PciBusReport pci = board.pci.report();
  r["pci"] = {{"bytes_to_board", d.bytes_to_board},
              {"bytes_to_host", d.bytes_to_host},
              {"dma_transfers", d.dma_transfers},
              {"pio_transfers", d.pio_transfers},
              {"register_accesses", d.register_accesses},
              {"bus_transactions", pci.total.transactions},
              {"bus_busy_seconds", seconds(pci.total.busy)}};
  ordered_json banks = ordered_json::array();
  for (unsigned b = 0; b < p.banks; ++b) {
    const tlmx::SramBankReport br = board.bank(b).report();
    const double bytes = static_cast<double>(br.bytes_read + br.bytes_written);
    banks.push_back({{"bank", b},
                     {"role", L.role(b)},
                     {"reads", br.reads},
                     {"writes", br.writes},
                     {"bytes_read", br.bytes_read},
                     {"bytes_written", br.bytes_written},
                     {"busy_seconds", seconds(br.busy)},
                     {"bytes_per_second", total > 0 ? bytes / total : 0.0},
                     {"bytes_per_second_while_fpga_busy", busy > 0 ? bytes / busy : 0.0}});
  }
  r["banks"] = banks;
  ordered_json lanes = ordered_json::array();
  for (const board::RayGroup& g : L.groups) {
    for (unsigned j = 0; j < g.lanes; ++j) {
      const unsigned lane = g.first_lane + j;
      const std::uint64_t rays = w.lane_rays[lane];
      lanes.push_back({{"lane", lane},
                       {"rate", g.k() / 3.0},
                       {"rays", rays},
                       {"utilisation", w.busy_cycles > 0 ? static_cast<double>(rays) / w.busy_cycles : 0.0}});
    }
  }
  r["lanes"] = lanes;
  ordered_json limits = ordered_json::array();
  for (const auto& [limit, tally] : d.limits)
    limits.push_back({{"limit", limit}, {"passes", tally.passes}, {"fpga_busy_seconds", seconds(tally.fpga_busy)}});
  r["stream_limits"] = limits;  // what bounded each pass's stream (board/pass_timing.h), and its FPGA time
  r["intersections"] = {{"tests", d.tests},
                        {"per_second", total > 0 ? d.tests / total : 0.0},
                        {"per_second_while_fpga_busy", busy > 0 ? d.tests / busy : 0.0}};
  const ordered_json work = host_work_json(m_cpu);
  ordered_json driver;
  for (int k = 0; k < kDriverWorkKinds; ++k)
    driver[to_string(DriverWork(k))] = {{"count", m_cpu.count(DriverWork(k))},
                                        {"seconds", seconds(m_cpu.time(DriverWork(k)))}};
  r["host"] = {{"profile", m_setup.host.name},
               {"driver_model", m_setup.host.driver_model.name()},
               {"work", work},
               {"driver", driver}};
  if (wall_seconds >= 0) {
    r["wall_seconds"] = wall_seconds;
    r["wall_seconds_per_step"] = m_result.steps > 0 ? wall_seconds / m_result.steps : 0.0;
  }
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
  if (!options.trace_path.empty()) system->trace().write(options.trace_path);
  return {system->result(), system->report(wall)};
}

}  // namespace rc
