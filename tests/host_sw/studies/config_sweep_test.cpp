#include <gtest/gtest.h>

#include <tuple>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "board/bank_layout.h"
#include "host_sw/studies/config_sweep.h"

namespace rc {
namespace {

const char* const kHost = "athlon-mp-2600-calibrated";

// ---- option lists -----------------------------------------------------------------------------------

TEST(ConfigSweep, ParsesListsAndRangesAscendingAndDistinct) {
  EXPECT_EQ(parse_int_list("1-16", "--lanes", 1, 255), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}));
  EXPECT_EQ(parse_int_list("15", "--bits", 7, 31), (std::vector<int>{15}));
  EXPECT_EQ(parse_int_list("8, 5-6 ,6,12", "--banks", 1, 255), (std::vector<int>{5, 6, 8, 12}));
  EXPECT_EQ(parse_int_list("3-3", "--lanes", 1, 255), (std::vector<int>{3}));
}

TEST(ConfigSweep, RejectsBadListsNamingTheOption) {
  for (const char* bad : {"", " ", "1,,2", "x", "1-", "-3", "4-2", "1-2-3", "1.5", "0", "256", "2-300", "1e3", "+4"}) {
    try {
      parse_int_list(bad, "--lanes", 1, 255);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--lanes"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(parse_int_list("6", "--bits", 7, 31), std::invalid_argument);
}

TEST(ConfigSweep, ParsesNamesDriversAndSteps) {
  EXPECT_EQ(parse_name_list("xc2v6000, virtex4-sx55,xc2v6000", "--devices"),
            (std::vector<std::string>{"xc2v6000", "virtex4-sx55"}));
  EXPECT_THROW(parse_name_list("a,,b", "--devices"), std::invalid_argument);
  EXPECT_THROW(parse_name_list("", "--devices"), std::invalid_argument);
  EXPECT_EQ(parse_concurrency("both"), (std::vector<bool>{false, true}));
  EXPECT_EQ(parse_concurrency("on"), (std::vector<bool>{true}));
  EXPECT_THROW(parse_concurrency("yes"), std::invalid_argument);
  EXPECT_EQ(parse_steps("paper").kind, StepsChoice::Kind::paper);
  EXPECT_EQ(parse_steps("converge").kind, StepsChoice::Kind::converge);
  EXPECT_EQ(parse_steps("1488").kind, StepsChoice::Kind::fixed);
  EXPECT_EQ(parse_steps("1488").steps, 1488);
  for (const char* bad : {"0", "-5", "many", "", "12x"}) EXPECT_THROW(parse_steps(bad), std::invalid_argument) << bad;
}

// ---- enumeration ------------------------------------------------------------------------------------

TEST(ConfigSweep, EnumeratesDeviceWidthDriverLanesBanksInOrder) {
  SweepAxes a;
  a.devices = {"virtex4-sx55", "xc2v6000"};  // as given, not sorted
  a.bits = {15, 19};
  a.concurrent = {false, true};
  a.lanes = {1, 2};
  a.banks = {5, 6, 7};
  const std::vector<SweepConfig> c = enumerate_configs(a);
  ASSERT_EQ(c.size(), 2u * 2 * 2 * 2 * 3);
  EXPECT_EQ(c[0].label(), "virtex4-sx55 15-bit serial 1 lane 5 banks");
  EXPECT_EQ(c[1].label(), "virtex4-sx55 15-bit serial 1 lane 6 banks");
  EXPECT_EQ(c[3].label(), "virtex4-sx55 15-bit serial 2 lanes 5 banks");
  EXPECT_EQ(c[6].label(), "virtex4-sx55 15-bit concurrent 1 lane 5 banks");
  EXPECT_EQ(c[12].label(), "virtex4-sx55 19-bit serial 1 lane 5 banks");
  EXPECT_EQ(c[24].label(), "xc2v6000 15-bit serial 1 lane 5 banks");
  EXPECT_EQ(c.back().label(), "xc2v6000 19-bit concurrent 2 lanes 7 banks");
  // The same axes give the same list.
  const std::vector<SweepConfig> again = enumerate_configs(a);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_EQ(c[i].label(), again[i].label());
}

TEST(ConfigSweep, RefusesEmptyAxesAndRunawaySweeps) {
  SweepAxes a;
  a.devices = {"xc2v6000"};
  a.bits = {15};
  a.concurrent = {true};
  a.lanes = {};
  a.banks = {6};
  EXPECT_THROW(enumerate_configs(a), std::invalid_argument);
  a.lanes = parse_int_list("1-255", "--lanes", 1, 255);
  a.banks = parse_int_list("1-255", "--banks", 1, 255);
  EXPECT_THROW(enumerate_configs(a), std::invalid_argument);
}

// ---- validity ---------------------------------------------------------------------------------------

SweepConfig config(const std::string& device, unsigned lanes, unsigned banks, int bits = 15) {
  SweepConfig c;
  c.device = device;
  c.bits = bits;
  c.concurrent = true;
  c.lanes = lanes;
  c.banks = banks;
  return c;
}

TEST(ConfigSweep, TheRc2000ConfigurationsThePaperBuiltAreValid) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  for (unsigned lanes : {1u, 2u}) {
    const ConfigCheck c = checker.check(config("xc2v6000", lanes, 6));
    EXPECT_EQ(c.validity, Validity::ok) << c.reason;
    EXPECT_TRUE(c.reason.empty());
    EXPECT_EQ(c.options.lanes, lanes);
    EXPECT_EQ(c.options.banks, 6u);
    EXPECT_EQ(c.options.host, kHost);
    EXPECT_TRUE(c.options.concurrent);
    EXPECT_NO_THROW(make_board_setup(c.options));
  }
  EXPECT_NEAR(checker.check(config("xc2v6000", 1, 6)).clock_mhz, 53.833, 1e-9);  // sec 5.4
  EXPECT_NEAR(checker.check(config("xc2v6000", 2, 6)).clock_mhz, 52.5, 1e-9);    // sec 5.5
}

TEST(ConfigSweep, LanesThatDoNotFitTheDeviceAreReportedWithTheFitMessage) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  for (unsigned banks : {6u, 20u}) {  // enough banks or not: the fit is checked first
    const ConfigCheck c = checker.check(config("xc2v6000", 12, banks));
    EXPECT_EQ(c.validity, Validity::does_not_fit);
    EXPECT_NE(c.reason.find("does not fit"), std::string::npos) << c.reason;
    EXPECT_NE(c.reason.find("xc2v6000"), std::string::npos) << c.reason;
    EXPECT_EQ(c.clock_mhz, 0);
    BoardRunOptions o;
    o.lanes = 12;
    o.banks = banks;
    EXPECT_THROW(make_board_setup(o), std::invalid_argument);  // the same verdict as a run
  }
}

TEST(ConfigSweep, TooFewBanksIsReportedWhenTheLanesFit) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  // 15 bits: two lanes per word, so 8 lanes are 4 ray groups: 14 banks at full rate, 12 at least.
  const ConfigCheck six = checker.check(config("xc2v6000", 8, 6));
  EXPECT_EQ(six.validity, Validity::too_few_banks) << six.reason;
  EXPECT_NE(six.reason.find("the board has 6"), std::string::npos) << six.reason;
  EXPECT_GT(six.clock_mhz, 0);  // the design fits; only the banks are missing
  EXPECT_EQ(checker.check(config("xc2v6000", 8, 11)).validity, Validity::too_few_banks);
  EXPECT_EQ(checker.check(config("xc2v6000", 8, 12)).validity, Validity::ok);
  // Fewer than the basic architecture's five banks (sec 4.1).
  const ConfigCheck four = checker.check(config("xc2v6000", 1, 4));
  EXPECT_EQ(four.validity, Validity::too_few_banks);
  EXPECT_NE(four.reason.find("at least 5 banks"), std::string::npos) << four.reason;
  // 19 bits: one coordinate per word, so the 6-bank board feeds a second lane at 1/3 rate only.
  EXPECT_EQ(checker.check(config("xc2v6000", 2, 6, 19)).validity, Validity::ok);
  EXPECT_EQ(checker.check(config("xc2v6000", 3, 6, 19)).validity, Validity::too_few_banks);
}

// A device as large as needed: 16 lanes fit, so only the banks decide.
std::string big_device_profile() {
  std::ifstream in(std::string(RC_SOURCE_DIR) + "/configs/devices/virtex4-sx55.json");
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(in);
  j["name"] = "test-big-device";
  j["fpga"]["slices"]["value"] = 1000000;
  j["fpga"]["block_multipliers"]["value"] = 10000;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("rc_sweep_big_device_" + std::to_string(::getpid()) + ".json")).string();
  std::ofstream(path) << j.dump(2);
  return path;
}

TEST(ConfigSweep, SixteenLanesAtFifteenBitsOnSixBanksAreTooFewBanks) {
  const std::string big = big_device_profile();
  const ConfigChecker checker({big, "virtex4-sx55"}, kHost);
  const ConfigCheck c = checker.check(config(big, 16, 6));
  EXPECT_EQ(c.validity, Validity::too_few_banks) << c.reason;
  EXPECT_NE(c.reason.find("16 lanes"), std::string::npos) << c.reason;
  EXPECT_EQ(checker.check(config(big, 16, 26)).validity, Validity::ok);  // 8 groups x 3 + 2: full rate
  EXPECT_EQ(checker.check(config(big, 16, 24)).validity, Validity::ok);  // last group at 1/3 rate
  EXPECT_EQ(checker.check(config(big, 16, 23)).validity, Validity::too_few_banks);
  // On the real Virtex-4 the design itself is too big, and that is what is reported.
  EXPECT_EQ(checker.check(config("virtex4-sx55", 16, 26)).validity, Validity::does_not_fit);
  std::filesystem::remove(big);
}

TEST(ConfigSweep, UnknownProfilesAreBadOptionsNotInvalidConfigurations) {
  EXPECT_THROW(ConfigChecker({"no-such-device"}, kHost), std::invalid_argument);
  EXPECT_THROW(ConfigChecker({"xc2v6000"}, "no-such-host"), std::invalid_argument);
}

TEST(ConfigSweep, CompactBanksHoldTheWholeStepAndEveryFaceWithoutCappingAGroup) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  const SweepConfig c = config("xc2v6000", 2, 6);
  const std::uint64_t bytes = checker.compact_bank_capacity(c, 1120, 280);
  ASSERT_GT(bytes, 0u);
  EXPECT_LT(bytes, 4u << 20);
  EXPECT_EQ(bytes & (bytes - 1), 0u);  // a power of two
  EXPECT_GE(bytes / 4, 3u * 1120);
  const board::BankLayout small = board::make_bank_layout(c.lanes, c.banks, c.bits, 32, bytes);
  const board::BankLayout full = board::make_bank_layout(c.lanes, c.banks, c.bits, 32, 4u << 20);
  EXPECT_GE(small.max_rays_per_batch, 1120u);
  EXPECT_GE(small.max_faces_per_set, 280u);
  for (std::uint64_t rays : {1u, 37u, 1119u, 1120u}) {
    EXPECT_EQ(board::split_rays(small, rays).rays, board::split_rays(full, rays).rays) << rays;
  }
  // A scene the profile's banks must batch keeps the profile's banks.
  EXPECT_EQ(checker.compact_bank_capacity(c, 1u << 21, 280), 0u);
}

// ---- rows ---------------------------------------------------------------------------------------------

RunReport synthetic_report(double waiting, double host) {
  RunReport r;
  r.board_run = true;
  r.simulated_seconds = waiting + host + 1.0 + 0.5;
  r.time.host_compute = host;
  r.time.driver_cpu = 1.0;
  r.time.pci_transfer = 0.5;
  r.time.waiting = waiting;
  r.time.fpga_busy = 4.0;
  r.board.device.clock_hz = 52.5e6;
  r.board.layout.nominal_rays_per_cycle = 2.0;
  r.board.pci.bus_busy_seconds = 0.25;
  for (const auto& [bank, role, busy] : {std::tuple<unsigned, const char*, double>{0, "faces", 0.1},
                                         {4, "results", 3.0},
                                         {1, "rays g0 X", 2.0}}) {
    BankUseReport b;
    b.bank = bank;
    b.role = role;
    b.busy_seconds = busy;
    r.board.banks.push_back(b);
  }
  r.board.lanes = {{0, 1.0, 0, 0.9}, {1, 1.0, 0, 0.8}};
  r.intersections.per_second_while_fpga_busy = 1e8;
  r.board.stream_limits = {{"bank 4 (results)", 10, 3.0}, {"lanes", 20, 1.0}};
  return r;
}

TEST(ConfigSweep, RowsComeFromTheReportAndNameTheBottleneck) {
  const SweepRow r = row_from_report(config("xc2v6000", 2, 6), synthetic_report(3.0, 2.0), 385);
  EXPECT_EQ(r.validity, Validity::ok);
  EXPECT_EQ(r.steps, 385);
  EXPECT_DOUBLE_EQ(r.clock_mhz, 52.5);
  EXPECT_DOUBLE_EQ(r.simulated_seconds, 6.5);
  EXPECT_DOUBLE_EQ(r.pci_utilisation, 0.25 / 6.5);
  EXPECT_EQ(r.busiest_bank, 4);
  EXPECT_EQ(r.busiest_bank_role, "results");
  EXPECT_DOUBLE_EQ(r.max_bank_utilisation, 0.75);
  EXPECT_DOUBLE_EQ(r.mean_lane_utilisation, 0.85);
  EXPECT_EQ(r.fpga_limit, "bank 4 (results)");
  EXPECT_DOUBLE_EQ(r.fpga_limit_share, 0.75);
  EXPECT_EQ(r.bottleneck, "fpga_result_bank");  // waiting is the largest part of the host's timeline
  EXPECT_EQ(row_from_report(config("xc2v6000", 2, 6), synthetic_report(1.0, 2.0), 385).bottleneck, "host_compute");

  EXPECT_EQ(fpga_limit_kind("lanes"), "fpga_lanes");
  EXPECT_EQ(fpga_limit_kind("bank 7 (results)"), "fpga_result_bank");
  EXPECT_EQ(fpga_limit_kind("bank 2 (rays g0 Y)"), "fpga_ray_bank");
  EXPECT_EQ(fpga_limit_kind("bank 4 (rays g1 XYZ)"), "fpga_ray_bank");
  EXPECT_EQ(fpga_limit_kind(""), "fpga_other");
}

TEST(ConfigSweep, SpeedupsAndCsvAreStable) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  std::vector<SweepRow> rows;
  rows.push_back(row_from_report(config("xc2v6000", 1, 6), synthetic_report(6.0, 2.0), 10));
  rows.push_back(row_from_report(config("xc2v6000", 2, 6), synthetic_report(3.0, 2.0), 10));
  rows.push_back(row_from_report(config("xc2v6000", 2, 7), synthetic_report(3.0, 2.0), 10));  // no 1-lane row at 7 banks
  rows.push_back(invalid_row(config("xc2v6000", 12, 6), checker.check(config("xc2v6000", 12, 6)), 10));
  fill_speedups(rows, {{software_key(rows[0].config), 19.0}});
  EXPECT_DOUBLE_EQ(rows[0].speedup_vs_one_lane, 1.0);
  EXPECT_DOUBLE_EQ(rows[1].speedup_vs_one_lane, 9.5 / 6.5);
  EXPECT_TRUE(std::isnan(rows[2].speedup_vs_one_lane));
  EXPECT_DOUBLE_EQ(rows[1].speedup_vs_software, 19.0 / 6.5);
  EXPECT_TRUE(std::isnan(rows[3].speedup_vs_software));

  std::ostringstream csv;
  write_sweep_csv(csv, rows);
  std::istringstream lines(csv.str());
  std::string header, first, second, third, invalid;
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  std::getline(lines, third);
  std::getline(lines, invalid);
  EXPECT_EQ(header,
            "device,lanes,banks,bits,concurrent,status,invalid_kind,reason,steps,clock_mhz,nominal_rays_per_cycle,"
            "simulated_seconds,fpga_busy_seconds,host_compute_seconds,driver_cpu_seconds,pci_transfer_seconds,"
            "waiting_seconds,pci_utilisation,max_bank_utilisation,busiest_bank,busiest_bank_role,"
            "mean_lane_utilisation,intersections_per_second_while_busy,fpga_limit,fpga_limit_share,bottleneck,"
            "speedup_vs_one_lane,speedup_vs_software,energy_joules,energy_per_step_joules,"
            "energy_per_intersection_nanojoules,average_watts,energy_delay_product_joule_seconds,fpga_joules,"
            "sram_joules,pci_joules,host_joules,energy_missing,pareto_time_energy");
  EXPECT_EQ(second.rfind("xc2v6000,2,6,15,1,ok,,,10,52.5,2,6.5,4,2,1,0.5,3,", 0), 0u) << second;
  // The reason holds commas, so it is quoted; the numbers of an invalid row are empty.
  EXPECT_EQ(invalid.rfind("xc2v6000,12,6,15,1,invalid,does_not_fit,\"12 lane(s)", 0), 0u) << invalid;
  EXPECT_NE(invalid.find(",,,,,,,,,,,"), std::string::npos) << invalid;
  const nlohmann::ordered_json j = sweep_row_json(rows[3]);
  EXPECT_EQ(j["status"], "invalid");
  EXPECT_TRUE(j["simulated_seconds"].is_null());
  EXPECT_EQ(j["concurrent"], true);
}

// A report with an energy estimate of `joules` (fpga 1, sram 2, pci 3, the rest host) over its time.
RunReport report_with_energy(double waiting, double joules) {
  RunReport r = synthetic_report(waiting, 2.0);
  energy::EnergyReport e;
  const double host = joules - 6;
  for (const auto& [name, j] : {std::pair<const char*, double>{"fpga", 1}, {"sram", 2}, {"pci", 3}, {"host", host}}) {
    energy::ComponentEnergy c;
    c.name = name;
    c.dynamic_joules = j;
    e.components.push_back(c);
  }
  e.joules = joules;
  e.seconds = r.simulated_seconds;
  e.average_watts = joules / e.seconds;
  e.joules_per_step = joules / 10;
  e.joules_per_intersection = joules / 1e9;
  e.energy_delay_product = joules * e.seconds;
  r.energy = e;
  return r;
}

TEST(ConfigSweep, EnergyColumnsComeFromTheReportOrSayWhyNot) {
  const SweepRow r = row_from_report(config("xc2v6000", 2, 6), report_with_energy(3.0, 100.0), 10);
  EXPECT_DOUBLE_EQ(r.energy_joules, 100.0);
  EXPECT_DOUBLE_EQ(r.energy_per_step_joules, 10.0);
  EXPECT_DOUBLE_EQ(r.energy_per_intersection_nanojoules, 100.0);
  EXPECT_DOUBLE_EQ(r.average_watts, 100.0 / 6.5);
  EXPECT_DOUBLE_EQ(r.energy_delay_product_joule_seconds, 650.0);
  EXPECT_DOUBLE_EQ(r.fpga_joules, 1.0);
  EXPECT_DOUBLE_EQ(r.sram_joules, 2.0);
  EXPECT_DOUBLE_EQ(r.pci_joules, 3.0);
  EXPECT_DOUBLE_EQ(r.host_joules, 94.0);
  EXPECT_EQ(r.energy_missing, "");

  RunReport without = synthetic_report(3.0, 2.0);
  without.energy_missing = "device profile x.json has no energy table";
  const SweepRow m = row_from_report(config("xc2v6000", 2, 6), without, 10);
  EXPECT_TRUE(std::isnan(m.energy_joules));
  EXPECT_TRUE(std::isnan(m.host_joules));
  EXPECT_EQ(m.energy_missing, "device profile x.json has no energy table");
  const nlohmann::ordered_json j = sweep_row_json(m);
  EXPECT_TRUE(j["energy_joules"].is_null());
  EXPECT_TRUE(j["pareto_time_energy"].is_null());  // not "off the front": there is no energy to compare

  // The shard round trip keeps every energy column.
  std::vector<SweepRow> rows = {r};
  mark_pareto_time_energy(rows);
  const SweepRow back = sweep_row_from_json(sweep_row_json(rows[0]), rows[0].config);
  EXPECT_DOUBLE_EQ(back.energy_joules, 100.0);
  EXPECT_DOUBLE_EQ(back.energy_per_intersection_nanojoules, 100.0);
  EXPECT_DOUBLE_EQ(back.host_joules, 94.0);
  EXPECT_TRUE(back.pareto_time_energy);
}

// A row read back from a shard must hold figures a run can produce (issue 27: merge accepted
// negative and 1e308 simulated seconds): each edit below is refused naming the row and the key; the
// row as written, and an invalid row's nulls, pass.
TEST(ConfigSweep, RowsReadBackMustHoldFiguresARunProduces) {
  const SweepRow r = row_from_report(config("xc2v6000", 2, 6), report_with_energy(3.0, 100.0), 10);
  const nlohmann::ordered_json good = sweep_row_json(r);
  EXPECT_NO_THROW((void)sweep_row_from_json(good, r.config));
  auto error_with = [&](const char* key, const nlohmann::ordered_json& value) {
    nlohmann::ordered_json j = good;
    j[key] = value;
    try {
      (void)sweep_row_from_json(j, r.config);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  const std::string row = "row " + r.config.label() + ": ";
  EXPECT_EQ(error_with("simulated_seconds", -1.0),
            row + "simulated_seconds = -1.0 is not a figure a run produces (a finite number, not negative, or null)");
  EXPECT_EQ(error_with("simulated_seconds", 1e308),
            row + "simulated_seconds = 1e+308 is outside (0, 1e+12] for a simulated row (kMaxRowSeconds)");
  EXPECT_EQ(error_with("simulated_seconds", 0.0),
            row + "simulated_seconds = 0 is outside (0, 1e+12] for a simulated row (kMaxRowSeconds)");
  EXPECT_EQ(error_with("simulated_seconds", nullptr),
            row + "simulated_seconds = nan is outside (0, 1e+12] for a simulated row (kMaxRowSeconds)");
  EXPECT_EQ(error_with("energy_joules", -100.0),
            row + "energy_joules = -100.0 is not a figure a run produces (a finite number, not negative, or null)");
  EXPECT_EQ(error_with("waiting_seconds", "3"),
            row + "waiting_seconds = \"3\" is not a figure a run produces (a finite number, not negative, or null)");
  EXPECT_EQ(error_with("mean_lane_utilisation", 1.5), row + "mean_lane_utilisation = 1.5 is above 1 (a share)");
  EXPECT_EQ(error_with("energy_joules", nullptr), "(accepted)");  // energy not estimated

  const ConfigChecker checker({"xc2v6000"}, kHost);
  const SweepRow invalid = invalid_row(config("xc2v6000", 12, 6), checker.check(config("xc2v6000", 12, 6)), 10);
  EXPECT_NO_THROW((void)sweep_row_from_json(sweep_row_json(invalid), invalid.config));
}

// Time against energy: a row is on the front unless another of the same width and profile settings
// is no slower, no costlier and better in one. Rows without energy are never on it.
TEST(ConfigSweep, ParetoFrontOfTimeAgainstEnergy) {
  std::vector<SweepRow> rows;
  rows.push_back(row_from_report(config("xc2v6000", 1, 6), report_with_energy(6.0, 100.0), 10));  // slow, frugal
  rows.push_back(row_from_report(config("xc2v6000", 2, 6), report_with_energy(3.0, 120.0), 10));  // fast, costly
  rows.push_back(row_from_report(config("xc2v6000", 2, 7), report_with_energy(3.0, 130.0), 10));  // as fast, costlier
  rows.push_back(row_from_report(config("xc2v6000", 4, 6), report_with_energy(3.0, 120.0), 10));  // a tie: both stay
  RunReport none = synthetic_report(1.0, 2.0);  // the fastest, but without energy
  none.energy_missing = "no table";
  rows.push_back(row_from_report(config("xc2v6000", 4, 7), none, 10));
  SweepConfig other_width = config("xc2v6000", 1, 7);
  other_width.bits = 23;  // its own front, however costly
  rows.push_back(row_from_report(other_width, report_with_energy(9.0, 500.0), 10));
  mark_pareto_time_energy(rows);
  EXPECT_TRUE(rows[0].pareto_time_energy);
  EXPECT_TRUE(rows[1].pareto_time_energy);
  EXPECT_FALSE(rows[2].pareto_time_energy);
  EXPECT_TRUE(rows[3].pareto_time_energy);
  EXPECT_FALSE(rows[4].pareto_time_energy);
  EXPECT_TRUE(rows[5].pareto_time_energy);
}

}  // namespace
}  // namespace rc
