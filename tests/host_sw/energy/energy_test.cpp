// The energy tables (host_sw/energy/energy_table.h) and the estimate (host_sw/energy/energy_model.h): a known
// activity gives the hand-computed sum, static energy follows the simulated time, and a profile
// without a table says so instead of giving zeros.
#include <gtest/gtest.h>

#include "board/device_profile.h"
#include "profiles/profile_json.h"
#include "board/design_fit.h"
#include "host_sw/energy/energy_model.h"
#include "host_sw/energy/full_rate_energy.h"
#include "pipeline/resource_model.h"

namespace rc::energy {
namespace {

nlohmann::ordered_json sourced(double v) { return {{"value", v}, {"source", "test figure"}}; }

nlohmann::ordered_json device_json_with_energy() {
  nlohmann::ordered_json j = profiles::read_json_file(profiles::resolve_profile_path("xc2v6000", "devices"));
  j["energy"] = {{"fpga",
                  {{"static_w", sourced(1.5)},
                   {"slice_pj_per_cycle", sourced(2.0)},
                   {"multiplier_pj_per_cycle", sourced(30.0)},
                   {"clock_pj_per_slice_cycle", sourced(0.5)}}},
                 {"sram", {{"read_nj", sourced(3.0)}, {"write_nj", sourced(4.0)}, {"standby_mw", sourced(20.0)}}},
                 {"pci", {{"data_phase_nj", sourced(6.0)}, {"transaction_nj", sourced(50.0)}, {"bridge_w", sourced(1.0)}}}};
  return j;
}

nlohmann::ordered_json host_json_with_energy() {
  nlohmann::ordered_json j = profiles::read_json_file(profiles::resolve_profile_path("athlon-mp-2600", "hosts"));
  j["energy"] = {{"busy_w", sourced(60.0)}, {"wait_w", sourced(10.0)}};
  return j;
}

EnergyTables tables() {
  const board::DeviceProfile device = board::device_profile_from_document(rc::profiles::document_of(device_json_with_energy()), "dev.json");
  return load_energy_tables(&device, rc::profiles::document_of(host_json_with_energy()), "host.json");
}

Activity board_activity() {
  Activity a;
  a.seconds = 2.0;
  a.steps = 4;
  a.intersections = 1000;
  a.host_busy_cpu_seconds = 1.5;
  a.host_cpus = 1;
  a.cards = 1;
  a.lanes = 2;
  a.device_clock_hz = 50e6;
  a.slices_per_lane = 2000;
  a.multipliers_per_lane = 25;
  a.lane_active_cycles = 1000;
  a.banks = 6;
  a.bank_word_reads = 1500;
  a.bank_word_writes = 40;
  a.pci_data_phases = 800;
  a.pci_transactions = 3;
  return a;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// Every term by hand, in the estimate's order (per component: static, then the actions' sum).
TEST(Energy, KnownActivityGivesTheHandComputedSum) {
  const EnergyReport r = estimate(tables(), board_activity());
  const double lane_cycles = 1.0 * 2 * 50e6 * 2.0;
  const double fpga_static = 2.0 * 1.5;
  const double fpga_dynamic = lane_cycles * 2000 * (0.5 * 1e-12) + 1000.0 * 2000 * (2.0 * 1e-12) + 1000.0 * 25 * (30.0 * 1e-12);
  const double sram_static = 1.0 * 6 * 2.0 * (20.0 * 1e-3);
  const double sram_dynamic = 1500 * (3.0 * 1e-9) + 40 * (4.0 * 1e-9);
  const double pci_static = 2.0 * 1.0;
  const double pci_dynamic = 800 * (6.0 * 1e-9) + 3 * (50.0 * 1e-9);
  const double host_dynamic = 1.5 * 60.0, host_static = 0.5 * 10.0;
  ASSERT_EQ(r.components.size(), 4u);
  EXPECT_EQ(r.components[0].name, "fpga");
  EXPECT_EQ(r.components[0].static_joules, fpga_static);
  EXPECT_EQ(r.components[0].dynamic_joules, fpga_dynamic);
  EXPECT_EQ(r.components[1].static_joules, sram_static);
  EXPECT_EQ(r.components[1].dynamic_joules, sram_dynamic);
  EXPECT_EQ(r.components[2].static_joules, pci_static);
  EXPECT_EQ(r.components[2].dynamic_joules, pci_dynamic);
  EXPECT_EQ(r.components[3].name, "host");
  EXPECT_EQ(r.components[3].static_joules, host_static);
  EXPECT_EQ(r.components[3].dynamic_joules, host_dynamic);
  const double total = (fpga_static + fpga_dynamic) + (sram_static + sram_dynamic) + (pci_static + pci_dynamic) +
                       (host_static + host_dynamic);
  EXPECT_EQ(r.joules, 0.0 + (fpga_static + fpga_dynamic) + (sram_static + sram_dynamic) + (pci_static + pci_dynamic) +
                          (host_static + host_dynamic));
  EXPECT_DOUBLE_EQ(r.joules, total);
  EXPECT_EQ(r.joules_per_step, r.joules / 4);
  EXPECT_EQ(r.joules_per_intersection, r.joules / 1000);
  EXPECT_EQ(r.average_watts, r.joules / 2.0);
  EXPECT_EQ(r.energy_delay_product, r.joules * 2.0);
  EXPECT_EQ(r.components[3].average_watts, (host_static + host_dynamic) / 2.0);
}

// Static terms are power x time: twice the time with the same actions doubles them exactly and
// leaves every action's energy as it was.
TEST(Energy, StaticEnergyScalesWithSimulatedTime) {
  Activity a = board_activity();
  a.host_busy_cpu_seconds = 0;
  const EnergyReport once = estimate(tables(), a);
  a.seconds *= 2;
  const EnergyReport twice = estimate(tables(), a);
  ASSERT_EQ(once.terms.size(), twice.terms.size());
  for (std::size_t i = 0; i < once.terms.size(); ++i) {
    const bool clocked = once.terms[i].figure.path == "energy.fpga.clock_pj_per_slice_cycle";
    if (once.terms[i].is_static || clocked || once.terms[i].component == "host") {
      EXPECT_EQ(twice.terms[i].joules, 2 * once.terms[i].joules) << once.terms[i].counter;  // the clock runs too
    } else {
      EXPECT_EQ(twice.terms[i].joules, once.terms[i].joules) << once.terms[i].counter;
    }
  }
}

// Every term names its counter, its profile key and that key's source.
TEST(Energy, EveryTermTracesToAProfileFigureAndACounter) {
  const EnergyReport r = estimate(tables(), board_activity());
  EXPECT_EQ(r.terms.size(), 12u);
  for (const EnergyTerm& t : r.terms) {
    EXPECT_FALSE(t.counter.empty());
    EXPECT_EQ(t.figure.path.rfind("energy.", 0), 0u) << t.figure.path;
    EXPECT_EQ(t.figure.source, "test figure");
    EXPECT_EQ(t.joules, t.count * t.figure.si());
  }
  EXPECT_EQ(r.device_table, "dev.json");
  EXPECT_EQ(r.host_table, "host.json");
}

TEST(Energy, SoftwareRunsCountOnlyTheHost) {
  Activity a;
  a.seconds = 3;
  a.host_busy_cpu_seconds = 3;
  a.steps = 3;
  const nlohmann::ordered_json host = host_json_with_energy();
  const EnergyReport r = estimate(load_energy_tables(nullptr, rc::profiles::document_of(host), "host.json"), a);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.joules, 3 * 60.0 + 0 * 10.0);
  EXPECT_EQ(r.joules_per_intersection, 0.0);  // none were made
}

// A profile without an energy section: a clear message, never zeros.
TEST(Energy, AProfileWithoutATableSaysSo) {
  const board::DeviceProfile bare = board::find_device_profile("xc2v6000");
  nlohmann::ordered_json host = host_json_with_energy();
  host.erase("energy");
  EXPECT_EQ(error_of([&] { (void)host_energy_table(rc::profiles::document_of(host), "h.json"); }),
            "h.json has no energy table (an \"energy\" section: docs/energy.md), so the host has no energy figures; "
            "its times are unaffected");
  nlohmann::ordered_json device = device_json_with_energy();
  device.erase("energy");
  const board::DeviceProfile no_table = board::device_profile_from_document(rc::profiles::document_of(device), "d.json");
  const EnergyTables t = load_energy_tables(&no_table, rc::profiles::document_of(host_json_with_energy()), "host.json");
  EXPECT_FALSE(t.device.has_value());
  EXPECT_TRUE(t.host.has_value());
  EXPECT_EQ(t.missing, "d.json has no energy table (an \"energy\" section: docs/energy.md), so the board has no "
                       "energy figures; its times are unaffected");
  EXPECT_EQ(error_of([&] { (void)estimate(t, board_activity()); }), "energy: no device energy table (" + t.missing + ")");
  (void)bare;
}

TEST(Energy, ABrokenTableNamesTheKey) {
  nlohmann::ordered_json j = device_json_with_energy();
  j["energy"]["sram"]["read_nj"]["value"] = -1;
  auto device_error = [](const nlohmann::ordered_json& json) {
    return error_of([&] { (void)device_energy_table(board::device_profile_from_document(rc::profiles::document_of(json), "d.json")); });
  };
  EXPECT_EQ(device_error(j), "d.json: energy.sram.read_nj: value -1 is outside [0, 1000000]");
  j = device_json_with_energy();
  j["energy"]["pci"].erase("bridge_w");
  EXPECT_EQ(device_error(j), "d.json: energy.pci.bridge_w: missing");
  j = device_json_with_energy();
  j["energy"]["sram"]["erase_nj"] = sourced(1);
  EXPECT_EQ(device_error(j).rfind("d.json: energy.sram.erase_nj: unknown key", 0), 0u) << device_error(j);
  j = device_json_with_energy();
  j["energy"]["fpga"]["static_w"].erase("source");
  EXPECT_EQ(device_error(j).rfind("d.json: energy.fpga.static_w: has no \"source\"", 0), 0u) << device_error(j);
}

TEST(Energy, AnActivityTheLanesCouldNotDoIsRefused) {
  Activity a = board_activity();
  a.lane_active_cycles = 300'000'000;  // 2 lanes x 50 MHz x 2 s = 2e8
  EXPECT_NE(error_of([&] { (void)estimate(tables(), a); }).find("active lane-cycles exceed"), std::string::npos);
  a = board_activity();
  a.host_busy_cpu_seconds = 2.5;
  EXPECT_NE(error_of([&] { (void)estimate(tables(), a); }).find("busy CPU-seconds exceed"), std::string::npos);
}

}  // namespace
}  // namespace rc::energy

namespace rc::energy {
namespace {

// Every shipped profile has a whole energy table, every figure sourced (configs/devices, configs/hosts).
TEST(Energy, ShippedProfilesHaveSourcedTables) {
  for (const char* name : {"xc2v6000", "virtex4-sx55", "spartan3-5000"}) {
    const DeviceEnergyTable t = device_energy_table(board::find_device_profile(name));
    for (const Figure* f : {&t.fpga.static_w, &t.fpga.slice_pj_per_cycle, &t.fpga.multiplier_pj_per_cycle,
                            &t.fpga.clock_pj_per_slice_cycle, &t.sram.read_nj, &t.sram.write_nj, &t.sram.standby_mw,
                            &t.pci.data_phase_nj, &t.pci.transaction_nj, &t.pci.bridge_w}) {
      EXPECT_GT(f->value, 0) << name << " " << f->path;
      EXPECT_GT(f->source.size(), 20u) << name << " " << f->path;
    }
  }
  for (const char* name : {"athlon-mp-2600", "athlon-mp-2600-calibrated"}) {
    const std::string path = profiles::resolve_profile_path(name, "hosts");
    const HostEnergyTable t = host_energy_table(rc::profiles::read_profile_document(path), path);
    EXPECT_GT(t.busy_w.value, t.wait_w.value) << name;
  }
}

}  // namespace
}  // namespace rc::energy

namespace rc::energy {
namespace {

// Sec 5.6 in joules: one second at full rate, by hand with the test tables above. 2 lanes at 50 MHz,
// 1e8 intersections a second moving 8 bytes each (2e8 words, half priced as reads, half as writes).
TEST(FullRateEnergy, OneSecondAtFullRateByHand) {
  const board::DeviceProfile device = board::device_profile_from_document(rc::profiles::document_of(device_json_with_energy()), "dev.json");
  board::PaperEstimate e;
  e.estimate = "a test design";
  e.rule = board::EstimateRule::Model;
  e.device = device.name;
  e.lanes = 2;
  e.clock_mhz = 50;
  e.intersections_per_s = 1e8;
  e.bytes_per_intersection = 8;
  e.software_rate = 2e7;
  const FullRateEnergy f = full_rate_energy(e, device, tables(), 15);
  const board::DesignFit fit = board::fit_design(device, pipeline::ResourceModel::load_default(), 2, 15);
  const double slices = fit.slices / 2.0, multipliers = fit.block_multipliers / 2.0;
  EXPECT_EQ(f.banks, std::max(device.bank_count, board::banks_for_full_rate(device, 2, 15)));
  const double fpga = 1.5 + 2 * 50e6 * slices * 0.5e-12 + 1e8 * slices * 2.0e-12 + 1e8 * multipliers * 30e-12;
  const double sram = 1e8 * 3.0e-9 + 1e8 * 4.0e-9 + f.banks * 20e-3;
  const double pci = 1.0;  // the bridge only: a pass streams out of the banks
  EXPECT_NEAR(f.fpga_nj, fpga * 10, 1e-9);  // joules in a second / 1e8 intersections, in nJ
  EXPECT_NEAR(f.sram_nj, sram * 10, 1e-9);
  EXPECT_NEAR(f.pci_nj, pci * 10, 1e-12);
  EXPECT_NEAR(f.card_nj, (fpga + sram + pci) * 10, 1e-9);
  EXPECT_NEAR(f.card_watts, fpga + sram + pci, 1e-9);
  EXPECT_NEAR(f.host_waiting_nj, 10.0 * 10, 1e-9);       // 10 W waiting
  EXPECT_NEAR(f.system_nj, (fpga + sram + pci + 10) * 10, 1e-9);
  EXPECT_NEAR(f.software_nj, 60.0 / 2e7 * 1e9, 1e-9);  // 60 W computing at 2e7 tests a second
}

TEST(FullRateEnergy, AProfileWithoutATableGivesNoFiguresAndSaysWhy) {
  nlohmann::ordered_json j = device_json_with_energy();
  j.erase("energy");
  const board::DeviceProfile device = board::device_profile_from_document(rc::profiles::document_of(j), "bare.json");
  board::PaperEstimate e;
  e.estimate = "lanes that fit";
  e.device = device.name;
  e.lanes = 2;
  e.clock_mhz = 50;
  e.intersections_per_s = 1e8;
  e.bytes_per_intersection = 8;
  const FullRateEnergy f = full_rate_energy(e, device, load_energy_tables(&device, rc::profiles::document_of(host_json_with_energy()), "h.json"), 15);
  EXPECT_NE(f.missing.find("bare.json has no energy table"), std::string::npos) << f.missing;
  EXPECT_TRUE(std::isnan(f.card_nj));
  EXPECT_TRUE(std::isnan(f.software_nj));
  e.lanes = 0;  // the bandwidth limit: no design to price
  EXPECT_NE(error_of([&] { (void)full_rate_energy(e, device, tables(), 15); }).find("no lanes streaming"), std::string::npos);
}

}  // namespace
}  // namespace rc::energy
