// RunReport (host_sw/platform/run_report.h): the typed report of a board run, its one JSON writer, and the
// codec the timing study's worker processes use, which must keep every field exactly.
#include <gtest/gtest.h>

#include "host_sw/outputs/run_report_json.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

TEST(RunReport, CodecKeepsEveryFieldAndTheWriterTheDocument) {
  BoardRunOptions o;
  o.lanes = 2;
  o.concurrent = true;
  const Scene scene = small_cornell_box();  // the system keeps a reference to it
  BoardSystem board("board", scene, steps(3), setup(o));
  run_all({&board});
  const RunReport report = board.report(1.25);
  const RunReport back = decode(encode(report));
  EXPECT_EQ(to_json(back).dump(), to_json(report).dump());
  EXPECT_EQ(encode(back), encode(report));
  // The writer's document: the board schema, the timeline identity, the wall-clock fields.
  const nlohmann::ordered_json j = to_json(report);
  EXPECT_EQ(j["schema"], "rc2000sim.board/1");
  EXPECT_DOUBLE_EQ(j["time"]["host_compute_seconds"].get<double>() + j["time"]["driver_cpu_seconds"].get<double>() +
                       j["time"]["pci_transfer_seconds"].get<double>() + j["time"]["waiting_seconds"].get<double>(),
                   report.simulated_seconds);
  EXPECT_EQ(j["wall_seconds"], 1.25);
  EXPECT_EQ(j["host"]["driver_model"], board.cpu().profile().driver_model.name());
  EXPECT_EQ(j["lanes"].size(), 2u);
  EXPECT_THROW(decode(R"({"not": "a report"})"), std::invalid_argument);
}

// Every field a distinct value no default has (k-th value: k + 0.1, not exact in binary), so a field
// the codec forgets comes back as its default and differs.
struct Filler {
  int k = 0;
  double real() { return ++k + 0.1; }
  unsigned count() { return static_cast<unsigned>(++k); }
  std::string text() { return "t" + std::to_string(++k) + " \u00e9"; }
};

RunReport every_field_set() {
  Filler f;
  RunReport r;
  r.board_run = true;
  r.simulated_seconds = f.real();
  r.time = {f.real(), f.real(), f.real(), f.real(), f.real(), f.real(), true, f.real(), f.real()};
  r.intersections = {f.count(), f.real(), f.real()};
  r.host_profile = f.text();
  for (WorkTally& w : r.work) w = {f.count(), f.real()};
  BoardDetail& b = r.board;
  b.device = {f.text(), f.count(), -static_cast<int>(f.count()), f.real(), f.count(), f.count(), f.count(), f.real(),
              f.count(), f.real(), f.count(), f.text(), f.text(), {}};
  b.device.design = {static_cast<int>(f.count()), static_cast<int>(f.count()), static_cast<int>(f.count()),
                     static_cast<int>(f.count()), static_cast<int>(f.count()), static_cast<int>(f.count()), f.real(), true,
                     f.text()};
  b.layout = {f.count(), f.count(), f.count(), f.count(), f.text(), {}, {f.count(), f.count()}, f.real(), f.text()};
  b.layout.ray_groups = {{{f.count(), f.count()}, f.count(), f.count(), f.real()}, {{f.count()}, f.count(), f.count(), f.real()}};
  b.max_rays_per_batch = f.count();
  b.max_faces_per_set = f.count();
  b.batching = {f.count(), f.count(), f.count(), f.count(), f.count()};
  b.pci = {f.count(), f.count(), f.count(), f.count(), f.count(), f.count(), f.real()};
  b.banks = {{f.count(), f.text(), f.count(), f.count(), f.count(), f.count(), f.real(), f.real(), f.real()}};
  b.lanes = {{f.count(), f.real(), f.count(), f.real()}, {f.count(), f.real(), f.count(), f.real()}};
  b.stream_limits = {{f.text(), f.count(), f.real()}};
  b.driver_model = f.text();
  for (WorkTally& w : b.driver) w = {f.count(), f.real()};
  b.cards.count = 2;
  b.cards.split = f.text();
  b.cards.bus = f.text();
  b.cards.buses = {{{f.count(), f.count()}, f.real(), f.real()}};
  b.cards.per_card = {{f.count(), f.count(), f.count(), f.count(), f.real(), f.count(), f.count(), f.real(), f.real(),
                       f.real(), f.real(), f.real(), f.real()}};
  r.has_wall = true;
  r.wall_seconds = f.real();
  r.wall_seconds_per_step = f.real();
  energy::EnergyReport e;
  e.terms = {{f.text(), f.text(), f.real(), {f.real(), f.text(), f.text(), f.text()}, true, f.real()},
             {f.text(), f.text(), f.real(), {f.real(), f.text(), f.text(), f.text()}, false, f.real()}};
  e.components = {{f.text(), f.real(), f.real(), f.real()}};
  e.joules = f.real();
  e.seconds = f.real();
  e.average_watts = f.real();
  e.joules_per_step = f.real();
  e.joules_per_intersection = f.real();
  e.energy_delay_product = f.real();
  e.device_table = f.text();
  e.host_table = f.text();
  r.energy = e;
  r.energy_missing = f.text();  // not both in a real report, but the codec must keep whatever it is given
  return r;
}

void expect_same(const WorkTally& a, const WorkTally& b) {
  EXPECT_EQ(a.count, b.count);
  EXPECT_EQ(a.seconds, b.seconds);
}

void expect_same_board(const BoardDetail& a, const BoardDetail& b) {
  const DeviceReport &d = a.device, &e = b.device;
  EXPECT_EQ(d.profile, e.profile);
  EXPECT_EQ(d.lanes, e.lanes);
  EXPECT_EQ(d.bits, e.bits);
  EXPECT_EQ(d.clock_hz, e.clock_hz);
  EXPECT_EQ(d.banks, e.banks);
  EXPECT_EQ(d.bank_capacity_bytes, e.bank_capacity_bytes);
  EXPECT_EQ(d.bank_word_bits, e.bank_word_bits);
  EXPECT_EQ(d.bank_clock_hz, e.bank_clock_hz);
  EXPECT_EQ(d.pci_width_bits, e.pci_width_bits);
  EXPECT_EQ(d.pci_clock_hz, e.pci_clock_hz);
  EXPECT_EQ(d.pipeline_latency_cycles, e.pipeline_latency_cycles);
  EXPECT_EQ(d.wrapper_model, e.wrapper_model);
  EXPECT_EQ(d.lanes_impl, e.lanes_impl);
  EXPECT_EQ(d.design.resources, e.design.resources);
  EXPECT_EQ(d.design.block_multiplier_lanes, e.design.block_multiplier_lanes);
  EXPECT_EQ(d.design.slice_multiplier_lanes, e.design.slice_multiplier_lanes);
  EXPECT_EQ(d.design.slices, e.design.slices);
  EXPECT_EQ(d.design.slices_available, e.design.slices_available);
  EXPECT_EQ(d.design.block_multipliers, e.design.block_multipliers);
  EXPECT_EQ(d.design.block_multipliers_available, e.design.block_multipliers_available);
  EXPECT_EQ(d.design.pipeline_clock_mhz, e.design.pipeline_clock_mhz);
  EXPECT_EQ(d.design.resources_modelled, e.design.resources_modelled);
  const LayoutReport &l = a.layout, &m = b.layout;
  EXPECT_EQ(l.coordinates_per_word, m.coordinates_per_word);
  EXPECT_EQ(l.field_bits, m.field_bits);
  EXPECT_EQ(l.face_bank, m.face_bank);
  EXPECT_EQ(l.result_bank, m.result_bank);
  EXPECT_EQ(l.own_face_table, m.own_face_table);
  ASSERT_EQ(l.ray_groups.size(), m.ray_groups.size());
  for (std::size_t i = 0; i < l.ray_groups.size(); ++i) {
    EXPECT_EQ(l.ray_groups[i].banks, m.ray_groups[i].banks);
    EXPECT_EQ(l.ray_groups[i].lanes, m.ray_groups[i].lanes);
    EXPECT_EQ(l.ray_groups[i].first_lane, m.ray_groups[i].first_lane);
    EXPECT_EQ(l.ray_groups[i].rate_per_lane, m.ray_groups[i].rate_per_lane);
  }
  EXPECT_EQ(l.spare_banks, m.spare_banks);
  EXPECT_EQ(l.nominal_rays_per_cycle, m.nominal_rays_per_cycle);
  EXPECT_EQ(a.max_rays_per_batch, b.max_rays_per_batch);
  EXPECT_EQ(a.max_faces_per_set, b.max_faces_per_set);
  EXPECT_EQ(a.batching.passes, b.batching.passes);
  EXPECT_EQ(a.batching.ray_batches, b.batching.ray_batches);
  EXPECT_EQ(a.batching.max_batches_per_step, b.batching.max_batches_per_step);
  EXPECT_EQ(a.batching.face_sets, b.batching.face_sets);
  EXPECT_EQ(a.batching.face_set_uploads, b.batching.face_set_uploads);
  EXPECT_EQ(a.pci.bytes_to_board, b.pci.bytes_to_board);
  EXPECT_EQ(a.pci.bytes_to_host, b.pci.bytes_to_host);
  EXPECT_EQ(a.pci.dma_transfers, b.pci.dma_transfers);
  EXPECT_EQ(a.pci.pio_transfers, b.pci.pio_transfers);
  EXPECT_EQ(a.pci.register_accesses, b.pci.register_accesses);
  EXPECT_EQ(a.pci.bus_transactions, b.pci.bus_transactions);
  EXPECT_EQ(a.pci.bus_busy_seconds, b.pci.bus_busy_seconds);
  ASSERT_EQ(a.banks.size(), b.banks.size());
  for (std::size_t i = 0; i < a.banks.size(); ++i) {
    const BankUseReport &x = a.banks[i], &y = b.banks[i];
    EXPECT_EQ(x.bank, y.bank);
    EXPECT_EQ(x.role, y.role);
    EXPECT_EQ(x.reads, y.reads);
    EXPECT_EQ(x.writes, y.writes);
    EXPECT_EQ(x.bytes_read, y.bytes_read);
    EXPECT_EQ(x.bytes_written, y.bytes_written);
    EXPECT_EQ(x.busy_seconds, y.busy_seconds);
    EXPECT_EQ(x.bytes_per_second, y.bytes_per_second);
    EXPECT_EQ(x.bytes_per_second_while_fpga_busy, y.bytes_per_second_while_fpga_busy);
  }
  ASSERT_EQ(a.lanes.size(), b.lanes.size());
  for (std::size_t i = 0; i < a.lanes.size(); ++i) {
    EXPECT_EQ(a.lanes[i].lane, b.lanes[i].lane);
    EXPECT_EQ(a.lanes[i].rate, b.lanes[i].rate);
    EXPECT_EQ(a.lanes[i].rays, b.lanes[i].rays);
    EXPECT_EQ(a.lanes[i].utilisation, b.lanes[i].utilisation);
  }
  ASSERT_EQ(a.stream_limits.size(), b.stream_limits.size());
  for (std::size_t i = 0; i < a.stream_limits.size(); ++i) {
    EXPECT_EQ(a.stream_limits[i].limit, b.stream_limits[i].limit);
    EXPECT_EQ(a.stream_limits[i].passes, b.stream_limits[i].passes);
    EXPECT_EQ(a.stream_limits[i].fpga_busy_seconds, b.stream_limits[i].fpga_busy_seconds);
  }
  EXPECT_EQ(a.driver_model, b.driver_model);
  for (int k = 0; k < kDriverWorkKinds; ++k) expect_same(a.driver[k], b.driver[k]);
  EXPECT_EQ(a.cards.count, b.cards.count);
  EXPECT_EQ(a.cards.split, b.cards.split);
  EXPECT_EQ(a.cards.bus, b.cards.bus);
  ASSERT_EQ(a.cards.buses.size(), b.cards.buses.size());
  for (std::size_t i = 0; i < a.cards.buses.size(); ++i) {
    EXPECT_EQ(a.cards.buses[i].cards, b.cards.buses[i].cards);
    EXPECT_EQ(a.cards.buses[i].busy_seconds, b.cards.buses[i].busy_seconds);
    EXPECT_EQ(a.cards.buses[i].utilisation, b.cards.buses[i].utilisation);
  }
  ASSERT_EQ(a.cards.per_card.size(), b.cards.per_card.size());
  for (std::size_t i = 0; i < a.cards.per_card.size(); ++i) {
    const CardReport &x = a.cards.per_card[i], &y = b.cards.per_card[i];
    EXPECT_EQ(x.card, y.card);
    EXPECT_EQ(x.faces, y.faces);
    EXPECT_EQ(x.passes, y.passes);
    EXPECT_EQ(x.tests, y.tests);
    EXPECT_EQ(x.fpga_busy_seconds, y.fpga_busy_seconds);
    EXPECT_EQ(x.bytes_to_board, y.bytes_to_board);
    EXPECT_EQ(x.bytes_to_host, y.bytes_to_host);
    EXPECT_EQ(x.pci_bus_busy_seconds, y.pci_bus_busy_seconds);
    EXPECT_EQ(x.pci_bus_wait_seconds, y.pci_bus_wait_seconds);
    EXPECT_EQ(x.driver_cpu_seconds, y.driver_cpu_seconds);
    EXPECT_EQ(x.pci_transfer_seconds, y.pci_transfer_seconds);
    EXPECT_EQ(x.waiting_seconds, y.waiting_seconds);
    EXPECT_EQ(x.idle_seconds, y.idle_seconds);
  }
}

void expect_same_energy(const energy::EnergyReport& a, const energy::EnergyReport& b) {
  ASSERT_EQ(a.terms.size(), b.terms.size());
  for (std::size_t i = 0; i < a.terms.size(); ++i) {
    const energy::EnergyTerm &x = a.terms[i], &y = b.terms[i];
    EXPECT_EQ(x.component, y.component);
    EXPECT_EQ(x.counter, y.counter);
    EXPECT_EQ(x.count, y.count);
    EXPECT_EQ(x.figure.value, y.figure.value);
    EXPECT_EQ(x.figure.path, y.figure.path);
    EXPECT_EQ(x.figure.unit, y.figure.unit);
    EXPECT_EQ(x.figure.source, y.figure.source);
    EXPECT_EQ(x.is_static, y.is_static);
    EXPECT_EQ(x.joules, y.joules);
  }
  ASSERT_EQ(a.components.size(), b.components.size());
  for (std::size_t i = 0; i < a.components.size(); ++i) {
    EXPECT_EQ(a.components[i].name, b.components[i].name);
    EXPECT_EQ(a.components[i].static_joules, b.components[i].static_joules);
    EXPECT_EQ(a.components[i].dynamic_joules, b.components[i].dynamic_joules);
    EXPECT_EQ(a.components[i].average_watts, b.components[i].average_watts);
  }
  EXPECT_EQ(a.joules, b.joules);
  EXPECT_EQ(a.seconds, b.seconds);
  EXPECT_EQ(a.average_watts, b.average_watts);
  EXPECT_EQ(a.joules_per_step, b.joules_per_step);
  EXPECT_EQ(a.joules_per_intersection, b.joules_per_intersection);
  EXPECT_EQ(a.energy_delay_product, b.energy_delay_product);
  EXPECT_EQ(a.device_table, b.device_table);
  EXPECT_EQ(a.host_table, b.host_table);
}

void expect_same(const RunReport& a, const RunReport& b) {
  EXPECT_EQ(a.board_run, b.board_run);
  EXPECT_EQ(a.simulated_seconds, b.simulated_seconds);
  EXPECT_EQ(a.time.host_compute, b.time.host_compute);
  EXPECT_EQ(a.time.driver_cpu, b.time.driver_cpu);
  EXPECT_EQ(a.time.pci_transfer, b.time.pci_transfer);
  EXPECT_EQ(a.time.waiting, b.time.waiting);
  EXPECT_EQ(a.time.fpga_busy, b.time.fpga_busy);
  EXPECT_EQ(a.time.overlap, b.time.overlap);
  EXPECT_EQ(a.time.second_cpu, b.time.second_cpu);
  EXPECT_EQ(a.time.second_cpu_compute, b.time.second_cpu_compute);
  EXPECT_EQ(a.time.second_cpu_wait, b.time.second_cpu_wait);
  EXPECT_EQ(a.intersections.tests, b.intersections.tests);
  EXPECT_EQ(a.intersections.per_second, b.intersections.per_second);
  EXPECT_EQ(a.intersections.per_second_while_fpga_busy, b.intersections.per_second_while_fpga_busy);
  EXPECT_EQ(a.host_profile, b.host_profile);
  for (int k = 0; k < kHostWorkKinds; ++k) expect_same(a.work[k], b.work[k]);
  expect_same_board(a.board, b.board);
  EXPECT_EQ(a.has_wall, b.has_wall);
  EXPECT_EQ(a.wall_seconds, b.wall_seconds);
  EXPECT_EQ(a.wall_seconds_per_step, b.wall_seconds_per_step);
  ASSERT_EQ(a.energy.has_value(), b.energy.has_value());
  if (a.energy) expect_same_energy(*a.energy, *b.energy);
  EXPECT_EQ(a.energy_missing, b.energy_missing);
}

TEST(RunReport, CodecRoundTripKeepsEveryFieldExactly) {
  const RunReport report = every_field_set();
  expect_same(decode(encode(report)), report);
  RunReport without_energy = report;
  without_energy.energy.reset();
  without_energy.time.second_cpu = false;
  expect_same(decode(encode(without_energy)), without_energy);
}

TEST(RunReport, WriterAndCodecShareTheFieldNames) {
  RunReport report = every_field_set();
  report.board.stream_limits[0].limit = "lanes";  // the bound model (board.bounds) names a resource
  const nlohmann::ordered_json codec = nlohmann::ordered_json::parse(encode(report));
  const nlohmann::ordered_json doc = to_json(report);
  // The same member under the same name in both documents, wherever the report writes it.
  EXPECT_EQ(doc["time"]["second_cpu_wait_seconds"], codec["time"]["second_cpu_wait_seconds"]);
  EXPECT_EQ(doc["capacity"]["max_faces_per_set"], codec["board"]["max_faces_per_set"]);
  EXPECT_EQ(nlohmann::json::parse(doc["host"]["driver"].dump()), nlohmann::json::parse(codec["board"]["driver"].dump()));
  EXPECT_EQ(doc["energy"]["terms"][0]["figure"]["key"], codec["energy"]["terms"][0]["figure"]["key"]);
  EXPECT_EQ(doc["energy"]["terms"][0]["kind"], "static");
  EXPECT_EQ(doc["energy"]["terms"][1]["kind"], "dynamic");
  EXPECT_DOUBLE_EQ(doc["energy"]["components"][0]["joules"].get<double>(), report.energy->components[0].joules());
}

TEST(RunReport, DecodeNamesAWrongWord) {
  nlohmann::json j = nlohmann::json::parse(encode(every_field_set()));
  j["energy"]["terms"][0]["kind"] = "sometimes";
  try {
    decode(j.dump());
    FAIL() << "a wrong word was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"kind\" is \"sometimes\""), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rc::test
