#include "host_sw/outputs/run_report_json.h"

#include <cmath>
#include <stdexcept>

#include "host_sw/platform/run_bounds.h"
#include "host_sw/outputs/run_bounds_json.h"
#include "host_sw/outputs/fields_json.h"

namespace rc::fields {

// ---- every field of a run report, under its one name (fields_json.h) --------------------------------

template <>
struct FieldList<WorkTally> {
  static constexpr auto list = std::make_tuple(field("count", &WorkTally::count), field("seconds", &WorkTally::seconds));
};
template <>
struct FieldList<RunTime> {
  static constexpr auto list = std::make_tuple(
      field("host_compute_seconds", &RunTime::host_compute), field("driver_cpu_seconds", &RunTime::driver_cpu),
      field("pci_transfer_seconds", &RunTime::pci_transfer), field("waiting_seconds", &RunTime::waiting),
      field("fpga_busy_seconds", &RunTime::fpga_busy), field("overlap_seconds", &RunTime::overlap),
      field("second_cpu", &RunTime::second_cpu), field("second_cpu_compute_seconds", &RunTime::second_cpu_compute),
      field("second_cpu_wait_seconds", &RunTime::second_cpu_wait));
};
template <>
struct FieldList<DesignReport> {
  static constexpr auto list = std::make_tuple(
      field("block_multiplier_lanes", &DesignReport::block_multiplier_lanes),
      field("slice_multiplier_lanes", &DesignReport::slice_multiplier_lanes), field("slices", &DesignReport::slices),
      field("slices_available", &DesignReport::slices_available),
      field("block_multipliers", &DesignReport::block_multipliers),
      field("block_multipliers_available", &DesignReport::block_multipliers_available),
      field("pipeline_clock_mhz", &DesignReport::pipeline_clock_mhz),
      field("resources_modelled", &DesignReport::resources_modelled), field("resources", &DesignReport::resources));
};
template <>
struct FieldList<DeviceReport> {
  static constexpr auto list = std::make_tuple(
      field("profile", &DeviceReport::profile), field("lanes", &DeviceReport::lanes), field("bits", &DeviceReport::bits),
      field("clock_hz", &DeviceReport::clock_hz), field("banks", &DeviceReport::banks),
      field("bank_capacity_bytes", &DeviceReport::bank_capacity_bytes),
      field("bank_word_bits", &DeviceReport::bank_word_bits), field("bank_clock_hz", &DeviceReport::bank_clock_hz),
      field("pci_width_bits", &DeviceReport::pci_width_bits), field("pci_clock_hz", &DeviceReport::pci_clock_hz),
      field("pipeline_latency_cycles", &DeviceReport::pipeline_latency_cycles),
      field("wrapper_model", &DeviceReport::wrapper_model), field("lanes_impl", &DeviceReport::lanes_impl),
      field("design", &DeviceReport::design));
};
template <>
struct FieldList<RayGroupReport> {
  static constexpr auto list =
      std::make_tuple(field("banks", &RayGroupReport::banks), field("lanes", &RayGroupReport::lanes),
                      field("first_lane", &RayGroupReport::first_lane), field("rate_per_lane", &RayGroupReport::rate_per_lane));
};
template <>
struct FieldList<LayoutReport> {
  static constexpr auto list = std::make_tuple(
      field("coordinates_per_word", &LayoutReport::coordinates_per_word), field("field_bits", &LayoutReport::field_bits),
      field("face_bank", &LayoutReport::face_bank), field("result_bank", &LayoutReport::result_bank),
      field("own_face_table", &LayoutReport::own_face_table), field("ray_groups", &LayoutReport::ray_groups),
      field("spare_banks", &LayoutReport::spare_banks),
      field("nominal_rays_per_cycle", &LayoutReport::nominal_rays_per_cycle),
      field("ray_split", &LayoutReport::ray_split));
};
template <>
struct FieldList<BatchingReport> {
  static constexpr auto list = std::make_tuple(
      field("passes", &BatchingReport::passes), field("ray_batches", &BatchingReport::ray_batches),
      field("max_batches_per_step", &BatchingReport::max_batches_per_step),
      field("face_sets", &BatchingReport::face_sets), field("face_set_uploads", &BatchingReport::face_set_uploads));
};
template <>
struct FieldList<PciReport> {
  static constexpr auto list = std::make_tuple(
      field("bytes_to_board", &PciReport::bytes_to_board), field("bytes_to_host", &PciReport::bytes_to_host),
      field("dma_transfers", &PciReport::dma_transfers), field("pio_transfers", &PciReport::pio_transfers),
      field("register_accesses", &PciReport::register_accesses),
      field("bus_transactions", &PciReport::bus_transactions), field("bus_busy_seconds", &PciReport::bus_busy_seconds));
};
template <>
struct FieldList<BankUseReport> {
  static constexpr auto list = std::make_tuple(
      field("bank", &BankUseReport::bank), field("role", &BankUseReport::role), field("reads", &BankUseReport::reads),
      field("writes", &BankUseReport::writes), field("bytes_read", &BankUseReport::bytes_read),
      field("bytes_written", &BankUseReport::bytes_written), field("busy_seconds", &BankUseReport::busy_seconds),
      field("bytes_per_second", &BankUseReport::bytes_per_second),
      field("bytes_per_second_while_fpga_busy", &BankUseReport::bytes_per_second_while_fpga_busy));
};
template <>
struct FieldList<LaneReport> {
  static constexpr auto list =
      std::make_tuple(field("lane", &LaneReport::lane), field("rate", &LaneReport::rate), field("rays", &LaneReport::rays),
                      field("utilisation", &LaneReport::utilisation));
};
template <>
struct FieldList<StreamLimitReport> {
  static constexpr auto list =
      std::make_tuple(field("limit", &StreamLimitReport::limit), field("passes", &StreamLimitReport::passes),
                      field("fpga_busy_seconds", &StreamLimitReport::fpga_busy_seconds));
};
template <>
struct FieldList<IntersectionReport> {
  static constexpr auto list = std::make_tuple(
      field("tests", &IntersectionReport::tests), field("per_second", &IntersectionReport::per_second),
      field("per_second_while_fpga_busy", &IntersectionReport::per_second_while_fpga_busy));
};
template <>
struct FieldList<CardReport> {
  static constexpr auto list = std::make_tuple(
      field("card", &CardReport::card), field("faces", &CardReport::faces), field("passes", &CardReport::passes),
      field("tests", &CardReport::tests), field("fpga_busy_seconds", &CardReport::fpga_busy_seconds),
      field("bytes_to_board", &CardReport::bytes_to_board), field("bytes_to_host", &CardReport::bytes_to_host),
      field("pci_bus_busy_seconds", &CardReport::pci_bus_busy_seconds),
      field("pci_bus_wait_seconds", &CardReport::pci_bus_wait_seconds),
      field("driver_cpu_seconds", &CardReport::driver_cpu_seconds),
      field("pci_transfer_seconds", &CardReport::pci_transfer_seconds),
      field("waiting_seconds", &CardReport::waiting_seconds), field("idle_seconds", &CardReport::idle_seconds));
};
template <>
struct FieldList<BusReport> {
  static constexpr auto list =
      std::make_tuple(field("cards", &BusReport::cards), field("busy_seconds", &BusReport::busy_seconds),
                      field("utilisation", &BusReport::utilisation));
};
template <>
struct FieldList<CardsReport> {
  static constexpr auto list =
      std::make_tuple(field("count", &CardsReport::count), field("split", &CardsReport::split),
                      field("bus", &CardsReport::bus), field("buses", &CardsReport::buses),
                      field("per_card", &CardsReport::per_card));
};
template <>
struct FieldList<BoardDetail> {
  static constexpr auto list = std::make_tuple(
      field("device", &BoardDetail::device), field("layout", &BoardDetail::layout),
      field("max_rays_per_batch", &BoardDetail::max_rays_per_batch),
      field("max_faces_per_set", &BoardDetail::max_faces_per_set), field("batching", &BoardDetail::batching),
      field("pci", &BoardDetail::pci), field("banks", &BoardDetail::banks), field("lanes", &BoardDetail::lanes),
      field("stream_limits", &BoardDetail::stream_limits), field("driver_model", &BoardDetail::driver_model),
      tallies<DriverWork>("driver", &BoardDetail::driver), field("cards", &BoardDetail::cards));
};
template <>
struct FieldList<energy::Figure> {
  static constexpr auto list =
      std::make_tuple(field("key", &energy::Figure::path), field("value", &energy::Figure::value),
                      field("unit", &energy::Figure::unit), field("source", &energy::Figure::source));
};
template <>
struct FieldList<energy::EnergyTerm> {
  static constexpr auto list = std::make_tuple(
      field("component", &energy::EnergyTerm::component), field("counter", &energy::EnergyTerm::counter),
      field("count", &energy::EnergyTerm::count), word("kind", &energy::EnergyTerm::is_static, "static", "dynamic"),
      field("figure", &energy::EnergyTerm::figure), field("joules", &energy::EnergyTerm::joules));
};
template <>
struct FieldList<energy::ComponentEnergy> {
  static constexpr auto list = std::make_tuple(
      field("name", &energy::ComponentEnergy::name), derived("joules", &energy::ComponentEnergy::joules),
      field("static_joules", &energy::ComponentEnergy::static_joules),
      field("dynamic_joules", &energy::ComponentEnergy::dynamic_joules),
      field("average_watts", &energy::ComponentEnergy::average_watts));
};
template <>
struct FieldList<energy::EnergyReport> {
  static constexpr auto list = std::make_tuple(
      field("joules", &energy::EnergyReport::joules), field("joules_per_step", &energy::EnergyReport::joules_per_step),
      field("joules_per_intersection", &energy::EnergyReport::joules_per_intersection),
      field("average_watts", &energy::EnergyReport::average_watts),
      field("energy_delay_product_joule_seconds", &energy::EnergyReport::energy_delay_product),
      field("seconds", &energy::EnergyReport::seconds), field("host", &energy::EnergyReport::host_table),
      field("device", &energy::EnergyReport::device_table), field("components", &energy::EnergyReport::components),
      field("terms", &energy::EnergyReport::terms));
};
template <>
struct FieldList<RunReport> {
  static constexpr auto list = std::make_tuple(
      field("board_run", &RunReport::board_run), field("simulated_seconds", &RunReport::simulated_seconds),
      field("time", &RunReport::time), field("intersections", &RunReport::intersections),
      field("profile", &RunReport::host_profile), tallies<HostWork>("work", &RunReport::work),
      field("board", &RunReport::board), field("has_wall", &RunReport::has_wall),
      field("wall_seconds", &RunReport::wall_seconds), field("wall_seconds_per_step", &RunReport::wall_seconds_per_step),
      field("energy", &RunReport::energy), field("energy_missing", &RunReport::energy_missing));
};

}  // namespace rc::fields

namespace rc {

using fields::add;
using fields::name_of;
using fields::out;

// ---- the internal codec: every field of the lists above ---------------------------------------------

std::string encode(const RunReport& report) {
  const nlohmann::json j = fields::write_all<nlohmann::json>(report);
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);  // a foreign byte: U+FFFD
}

RunReport decode(const std::string& text) {
  try {
    RunReport r;
    fields::read_all(nlohmann::json::parse(text), r);
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("a run report from a worker process is malformed: ") + e.what());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("a run report from a worker process is malformed: ") + e.what());
  }
}

// ---- the writer (docs/outputs.md): the fields above, grouped as the document groups them ---------------

namespace {

using nlohmann::ordered_json;

ordered_json time_json(const RunTime& t, unsigned cards) {
  ordered_json j;
  add(j, t, &RunTime::host_compute, &RunTime::driver_cpu, &RunTime::pci_transfer, &RunTime::waiting, &RunTime::fpga_busy,
      &RunTime::overlap);
  const std::string several =
      cards > 1 ? " With several cards the drivers run on their own threads (cards.per_card: driver_cpu + "
                  "pci_transfer + waiting + idle = simulated_seconds each): the host thread's driver_cpu and "
                  "pci_transfer are 0, waiting is its wait for the cards, fpga_busy the sum over the cards."
                : "";
  if (t.second_cpu) {
    add(j, t, &RunTime::second_cpu_compute, &RunTime::second_cpu_wait);
    j["note"] = "host_compute + driver_cpu + pci_transfer + waiting + second_cpu_wait = simulated_seconds (the "
                "first processor's timeline); the second computes the form factors (second_cpu_compute) beside "
                "it; fpga_busy overlaps host compute by overlap_seconds" + several;
  } else {
    j["note"] = "host_compute + driver_cpu + pci_transfer + waiting = simulated_seconds (the host thread's "
                "timeline); fpga_busy runs beside it, overlapping host compute by overlap_seconds" + several;
  }
  return j;
}

// "energy": the estimate, or null beside "energy_missing" saying which profile has no table.
void add_energy(ordered_json& j, const RunReport& r) {
  if (r.energy) {
    j[name_of<RunReport>(&RunReport::energy)] = energy_report_json(*r.energy);
  } else {
    add(j, r, &RunReport::energy, &RunReport::energy_missing);
  }
}

ordered_json board_json(const RunReport& r) {
  const BoardDetail& b = r.board;
  ordered_json j;
  j["schema"] = "rc2000sim.board/1";
  add(j, r, &RunReport::simulated_seconds);
  j[name_of<RunReport>(&RunReport::time)] = time_json(r.time, b.cards.count);
  add(j, b, &BoardDetail::device, &BoardDetail::layout);
  ordered_json capacity;
  add(capacity, b, &BoardDetail::max_rays_per_batch, &BoardDetail::max_faces_per_set);
  j["capacity"] = capacity;
  add(j, b, &BoardDetail::batching, &BoardDetail::pci);
  if (b.cards.count > 1) add(j, b, &BoardDetail::cards);
  add(j, b, &BoardDetail::banks, &BoardDetail::lanes, &BoardDetail::stream_limits);
  j["bounds"] = run_bounds_json(run_bounds(r));  // docs/board.md, "What bounds a run"
  add(j, r, &RunReport::intersections);
  ordered_json host;
  add(host, r, &RunReport::host_profile);
  add(host, b, &BoardDetail::driver_model);
  add(host, r, &RunReport::work);
  add(host, b, &BoardDetail::driver);
  j["host"] = host;
  add_energy(j, r);
  if (r.has_wall) add(j, r, &RunReport::wall_seconds, &RunReport::wall_seconds_per_step);
  return j;
}

ordered_json software_json(const RunReport& r) {
  ordered_json j;
  j["schema"] = "rc2000sim.software/1";
  add(j, r, &RunReport::simulated_seconds);
  ordered_json time;
  add(time, r.time, &RunTime::host_compute);
  j[name_of<RunReport>(&RunReport::time)] = time;
  ordered_json intersections;
  add(intersections, r.intersections, &IntersectionReport::tests, &IntersectionReport::per_second);
  j[name_of<RunReport>(&RunReport::intersections)] = intersections;
  ordered_json host;
  add(host, r, &RunReport::host_profile, &RunReport::work);
  j["host"] = host;
  add_energy(j, r);
  return j;
}

}  // namespace

nlohmann::ordered_json work_json(const std::array<WorkTally, kHostWorkKinds>& work) {
  RunReport r;
  r.work = work;
  ordered_json j;
  add(j, r, &RunReport::work);
  return j.front();
}

nlohmann::ordered_json energy_report_json(const energy::EnergyReport& e) {
  using energy::EnergyReport;
  ordered_json j;
  add(j, e, &EnergyReport::joules, &EnergyReport::joules_per_step, &EnergyReport::joules_per_intersection,
      &EnergyReport::average_watts, &EnergyReport::energy_delay_product);
  ordered_json tables;
  add(tables, e, &EnergyReport::host_table);
  if (!e.device_table.empty()) add(tables, e, &EnergyReport::device_table);
  j["tables"] = tables;
  add(j, e, &EnergyReport::components, &EnergyReport::terms);
  return j;
}

nlohmann::ordered_json to_json(const RunReport& report) { return report.board_run ? board_json(report) : software_json(report); }

}  // namespace rc
