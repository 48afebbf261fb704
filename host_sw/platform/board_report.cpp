// The report assembly of a board run: BoardSystem::report (host_sw/platform/board_system.h) gathers
// the host's, the drivers' and the cards' counters into the typed RunReport.
#include <algorithm>

#include "host_sw/platform/board_system.h"

namespace rc {

namespace {

double seconds(const sc_core::sc_time& t) { return t.to_seconds(); }

}  // namespace

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
  d.lanes_impl = p.clocked_lanes ? p.clocked_lanes.name : "cpp";
  d.design = {p.fit.hard_lanes, p.fit.soft_lanes, p.fit.slices, p.fit.slices_available, p.fit.block_multipliers,
              p.fit.block_multipliers_available, p.fit.pipeline_clock_mhz, p.fit.modelled, choice_name(p.fit.resources)};
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
  l.ray_split = board::to_string(L.ray_split);
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

}  // namespace rc
