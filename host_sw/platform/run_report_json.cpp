#include "host_sw/platform/run_report_json.h"

#include <cmath>
#include <stdexcept>

#include "host_sw/platform/run_bounds.h"
#include "host_sw/platform/run_bounds_json.h"

namespace rc {

// ---- the internal codec (every field, by name) ------------------------------------------------------

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(WorkTally, count, seconds)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(RunTime, host_compute, driver_cpu, pci_transfer, waiting, fpga_busy, overlap, second_cpu,
                                   second_cpu_compute, second_cpu_wait)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DesignReport, block_multiplier_lanes, slice_multiplier_lanes, slices, slices_available,
                                   block_multipliers, block_multipliers_available, pipeline_clock_mhz, resources_modelled)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DeviceReport, profile, lanes, bits, clock_hz, banks, bank_capacity_bytes, bank_word_bits,
                                   bank_clock_hz, pci_width_bits, pci_clock_hz, pipeline_latency_cycles, wrapper_model, design)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(RayGroupReport, banks, lanes, first_lane, rate_per_lane)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LayoutReport, coordinates_per_word, field_bits, face_bank, result_bank, own_face_table,
                                   ray_groups, spare_banks, nominal_rays_per_cycle)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(BatchingReport, passes, ray_batches, max_batches_per_step, face_sets, face_set_uploads)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PciReport, bytes_to_board, bytes_to_host, dma_transfers, pio_transfers, register_accesses,
                                   bus_transactions, bus_busy_seconds)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(BankUseReport, bank, role, reads, writes, bytes_read, bytes_written, busy_seconds,
                                   bytes_per_second, bytes_per_second_while_fpga_busy)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LaneReport, lane, rate, rays, utilisation)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StreamLimitReport, limit, passes, fpga_busy_seconds)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(IntersectionReport, tests, per_second, per_second_while_fpga_busy)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CardReport, card, faces, passes, tests, fpga_busy_seconds, bytes_to_board, bytes_to_host,
                                   pci_bus_busy_seconds, pci_bus_wait_seconds, driver_cpu_seconds, pci_transfer_seconds,
                                   waiting_seconds, idle_seconds)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(BusReport, cards, busy_seconds, utilisation)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CardsReport, count, split, bus, buses, per_card)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(BoardDetail, device, layout, max_rays_per_batch, max_faces_per_set, batching, pci, banks,
                                   lanes, stream_limits, driver_model, driver, cards)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(RunReport, board_run, simulated_seconds, time, intersections, host_profile, work, board,
                                   has_wall, wall_seconds, wall_seconds_per_step)

}  // namespace rc

namespace rc::energy {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Figure, value, path, unit, source)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EnergyTerm, component, counter, count, figure, is_static, joules)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ComponentEnergy, name, static_joules, dynamic_joules, average_watts)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EnergyReport, terms, components, joules, seconds, average_watts, joules_per_step,
                                   joules_per_intersection, energy_delay_product, device_table, host_table)
}  // namespace rc::energy

namespace rc {

// The energy is optional, which this nlohmann has no conversion for: written beside the macro's fields.
std::string encode(const RunReport& report) {
  nlohmann::json j = report;
  j["energy"] = report.energy ? nlohmann::json(*report.energy) : nlohmann::json();
  j["energy_missing"] = report.energy_missing;
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);  // a foreign byte: U+FFFD
}

RunReport decode(const std::string& text) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    RunReport r = j.get<RunReport>();
    if (!j.at("energy").is_null()) r.energy = j.at("energy").get<energy::EnergyReport>();
    r.energy_missing = j.at("energy_missing").get<std::string>();
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("a run report from a worker process is malformed: ") + e.what());
  }
}

// ---- the writer (docs/outputs.md) -------------------------------------------------------------------

namespace {

using nlohmann::ordered_json;

ordered_json time_json(const RunTime& t, unsigned cards) {
  ordered_json j = {{"host_compute_seconds", t.host_compute},
                    {"driver_cpu_seconds", t.driver_cpu},
                    {"pci_transfer_seconds", t.pci_transfer},
                    {"waiting_seconds", t.waiting},
                    {"fpga_busy_seconds", t.fpga_busy},
                    {"overlap_seconds", t.overlap}};
  const std::string several =
      cards > 1 ? " With several cards the drivers run on their own threads (cards.per_card: driver_cpu + "
                  "pci_transfer + waiting + idle = simulated_seconds each): the host thread's driver_cpu and "
                  "pci_transfer are 0, waiting is its wait for the cards, fpga_busy the sum over the cards."
                : "";
  if (t.second_cpu) {
    j["second_cpu_compute_seconds"] = t.second_cpu_compute;
    j["second_cpu_wait_seconds"] = t.second_cpu_wait;
    j["note"] = "host_compute + driver_cpu + pci_transfer + waiting + second_cpu_wait = simulated_seconds (the "
                "first processor's timeline); the second computes the form factors (second_cpu_compute) beside "
                "it; fpga_busy overlaps host compute by overlap_seconds" + several;
  } else {
    j["note"] = "host_compute + driver_cpu + pci_transfer + waiting = simulated_seconds (the host thread's "
                "timeline); fpga_busy runs beside it, overlapping host compute by overlap_seconds" + several;
  }
  return j;
}

ordered_json device_json(const DeviceReport& d) {
  const DesignReport& f = d.design;
  return {{"profile", d.profile},
          {"lanes", d.lanes},
          {"bits", d.bits},
          {"clock_hz", d.clock_hz},
          {"banks", d.banks},
          {"bank_capacity_bytes", d.bank_capacity_bytes},
          {"bank_word_bits", d.bank_word_bits},
          {"bank_clock_hz", d.bank_clock_hz},
          {"pci_width_bits", d.pci_width_bits},
          {"pci_clock_hz", d.pci_clock_hz},
          {"pipeline_latency_cycles", d.pipeline_latency_cycles},
          {"wrapper_model", d.wrapper_model},
          {"design", {{"block_multiplier_lanes", f.block_multiplier_lanes},
                      {"slice_multiplier_lanes", f.slice_multiplier_lanes},
                      {"slices", f.slices},
                      {"slices_available", f.slices_available},
                      {"block_multipliers", f.block_multipliers},
                      {"block_multipliers_available", f.block_multipliers_available},
                      {"pipeline_clock_mhz", f.pipeline_clock_mhz},
                      {"resources_modelled", f.resources_modelled}}}};
}

ordered_json layout_json(const LayoutReport& l) {
  ordered_json groups = ordered_json::array();
  for (const RayGroupReport& g : l.ray_groups) {
    groups.push_back({{"banks", g.banks}, {"lanes", g.lanes}, {"first_lane", g.first_lane}, {"rate_per_lane", g.rate_per_lane}});
  }
  return {{"coordinates_per_word", l.coordinates_per_word},
          {"field_bits", l.field_bits},
          {"face_bank", l.face_bank},
          {"result_bank", l.result_bank},
          {"own_face_table", l.own_face_table},
          {"ray_groups", groups},
          {"spare_banks", l.spare_banks},
          {"nominal_rays_per_cycle", l.nominal_rays_per_cycle}};
}

ordered_json banks_json(const std::vector<BankUseReport>& banks) {
  ordered_json out = ordered_json::array();
  for (const BankUseReport& b : banks) {
    out.push_back({{"bank", b.bank},
                   {"role", b.role},
                   {"reads", b.reads},
                   {"writes", b.writes},
                   {"bytes_read", b.bytes_read},
                   {"bytes_written", b.bytes_written},
                   {"busy_seconds", b.busy_seconds},
                   {"bytes_per_second", b.bytes_per_second},
                   {"bytes_per_second_while_fpga_busy", b.bytes_per_second_while_fpga_busy}});
  }
  return out;
}

ordered_json cards_json(const CardsReport& c) {
  ordered_json buses = ordered_json::array();
  for (const BusReport& b : c.buses) {
    buses.push_back({{"cards", b.cards}, {"busy_seconds", b.busy_seconds}, {"utilisation", b.utilisation}});
  }
  ordered_json cards = ordered_json::array();
  for (const CardReport& k : c.per_card) {
    cards.push_back({{"card", k.card},
                     {"faces", k.faces},
                     {"passes", k.passes},
                     {"tests", k.tests},
                     {"fpga_busy_seconds", k.fpga_busy_seconds},
                     {"bytes_to_board", k.bytes_to_board},
                     {"bytes_to_host", k.bytes_to_host},
                     {"pci_bus_busy_seconds", k.pci_bus_busy_seconds},
                     {"pci_bus_wait_seconds", k.pci_bus_wait_seconds},
                     {"driver_cpu_seconds", k.driver_cpu_seconds},
                     {"pci_transfer_seconds", k.pci_transfer_seconds},
                     {"waiting_seconds", k.waiting_seconds},
                     {"idle_seconds", k.idle_seconds}});
  }
  return {{"count", c.count}, {"split", c.split}, {"bus", c.bus}, {"buses", buses}, {"per_card", cards}};
}

// "energy": the estimate, or null beside "energy_missing" saying which profile has no table.
void add_energy(ordered_json& j, const RunReport& r) {
  if (r.energy) {
    j["energy"] = energy_report_json(*r.energy);
  } else {
    j["energy"] = nullptr;
    j["energy_missing"] = r.energy_missing;
  }
}

ordered_json board_json(const RunReport& r) {
  const BoardDetail& b = r.board;
  ordered_json j;
  j["schema"] = "rc2000sim.board/1";
  j["simulated_seconds"] = r.simulated_seconds;
  j["time"] = time_json(r.time, b.cards.count);
  j["device"] = device_json(b.device);
  j["layout"] = layout_json(b.layout);
  j["capacity"] = {{"max_rays_per_batch", b.max_rays_per_batch}, {"max_faces_per_set", b.max_faces_per_set}};
  j["batching"] = {{"passes", b.batching.passes},
                   {"ray_batches", b.batching.ray_batches},
                   {"max_batches_per_step", b.batching.max_batches_per_step},
                   {"face_sets", b.batching.face_sets},
                   {"face_set_uploads", b.batching.face_set_uploads}};
  j["pci"] = {{"bytes_to_board", b.pci.bytes_to_board},
              {"bytes_to_host", b.pci.bytes_to_host},
              {"dma_transfers", b.pci.dma_transfers},
              {"pio_transfers", b.pci.pio_transfers},
              {"register_accesses", b.pci.register_accesses},
              {"bus_transactions", b.pci.bus_transactions},
              {"bus_busy_seconds", b.pci.bus_busy_seconds}};
  if (b.cards.count > 1) j["cards"] = cards_json(b.cards);
  j["banks"] = banks_json(b.banks);
  ordered_json lanes = ordered_json::array();
  for (const LaneReport& l : b.lanes) {
    lanes.push_back({{"lane", l.lane}, {"rate", l.rate}, {"rays", l.rays}, {"utilisation", l.utilisation}});
  }
  j["lanes"] = lanes;
  ordered_json limits = ordered_json::array();
  for (const StreamLimitReport& l : b.stream_limits) {
    limits.push_back({{"limit", l.limit}, {"passes", l.passes}, {"fpga_busy_seconds", l.fpga_busy_seconds}});
  }
  j["stream_limits"] = limits;
  j["bounds"] = run_bounds_json(run_bounds(r));  // docs/board.md, "What bounds a run"
  j["intersections"] = {{"tests", r.intersections.tests},
                        {"per_second", r.intersections.per_second},
                        {"per_second_while_fpga_busy", r.intersections.per_second_while_fpga_busy}};
  ordered_json driver;
  for (int k = 0; k < kDriverWorkKinds; ++k) {
    driver[to_string(DriverWork(k))] = {{"count", b.driver[k].count}, {"seconds", b.driver[k].seconds}};
  }
  j["host"] = {{"profile", r.host_profile}, {"driver_model", b.driver_model}, {"work", work_json(r.work)}, {"driver", driver}};
  add_energy(j, r);
  if (r.has_wall) {
    j["wall_seconds"] = r.wall_seconds;
    j["wall_seconds_per_step"] = r.wall_seconds_per_step;
  }
  return j;
}

ordered_json software_json(const RunReport& r) {
  ordered_json j;
  j["schema"] = "rc2000sim.software/1";
  j["simulated_seconds"] = r.simulated_seconds;
  j["time"] = {{"host_compute_seconds", r.time.host_compute}};
  j["intersections"] = {{"tests", r.intersections.tests}, {"per_second", r.intersections.per_second}};
  j["host"] = {{"profile", r.host_profile}, {"work", work_json(r.work)}};
  add_energy(j, r);
  return j;
}

}  // namespace

nlohmann::ordered_json work_json(const std::array<WorkTally, kHostWorkKinds>& work) {
  ordered_json j;
  for (int k = 0; k < kHostWorkKinds; ++k) {
    j[to_string(HostWork(k))] = {{"count", work[k].count}, {"seconds", work[k].seconds}};
  }
  return j;
}

nlohmann::ordered_json energy_report_json(const energy::EnergyReport& e) {
  using nlohmann::ordered_json;
  ordered_json components = ordered_json::array();
  for (const energy::ComponentEnergy& c : e.components) {
    components.push_back({{"name", c.name},
                          {"joules", c.joules()},
                          {"static_joules", c.static_joules},
                          {"dynamic_joules", c.dynamic_joules},
                          {"average_watts", c.average_watts}});
  }
  ordered_json terms = ordered_json::array();
  for (const energy::EnergyTerm& t : e.terms) {
    terms.push_back({{"component", t.component},
                     {"counter", t.counter},
                     {"count", t.count},
                     {"kind", t.is_static ? "static" : "dynamic"},
                     {"figure", {{"key", t.figure.path}, {"value", t.figure.value}, {"unit", t.figure.unit},
                                 {"source", t.figure.source}}},
                     {"joules", t.joules}});
  }
  ordered_json tables = {{"host", e.host_table}};
  if (!e.device_table.empty()) tables["device"] = e.device_table;
  return {{"joules", e.joules},
          {"joules_per_step", e.joules_per_step},
          {"joules_per_intersection", e.joules_per_intersection},
          {"average_watts", e.average_watts},
          {"energy_delay_product_joule_seconds", e.energy_delay_product},
          {"tables", tables},
          {"components", components},
          {"terms", terms}};
}

nlohmann::ordered_json to_json(const RunReport& report) { return report.board_run ? board_json(report) : software_json(report); }

}  // namespace rc
