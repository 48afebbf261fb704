// Device profiles are checked against the limits the model derives from them (docs/board.md,
// "Profiles"): a bank holds at least one face record and its own-face table entry and no more than the
// wrapper's 32-bit counts reach, in whole words; bank counts fit the wrapper (5) and its CONFIG
// register (255); lane-clock keys are whole lane counts; every key is one the loader reads. Each bad
// profile gets exactly one error naming the file, the key, the value and the limit. The same bank
// limits hold for a capacity chosen beside the profile (BoardChoices), through make_bank_layout.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "board/bank_layout.h"
#include "board/board_params.h"
#include "board/device_profile.h"
#include "profiles/profile_json.h"

namespace rc::board::test {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

nlohmann::ordered_json xc2v6000() { return rc::profiles::json_of(find_device_profile("xc2v6000").document); }

std::string device_error(const nlohmann::ordered_json& j) {
  return error_of([&] { (void)device_profile_from_document(rc::profiles::document_of(j), "configs/devices/x.json"); });
}

nlohmann::ordered_json sourced(const nlohmann::ordered_json& value) { return {{"value", value}, {"source", "test"}}; }

TEST(ProfileValidation, ShippedProfilesPass) {
  for (const char* name : {"xc2v6000", "virtex4-sx55", "spartan3-5000"}) EXPECT_NO_THROW(find_device_profile(name)) << name;
}

// A name that is not there says where it looked; a path that is there but not a file (a device, a
// folder) says that, not "no profile".
TEST(ProfileValidation, MissingAndNonFileProfilesAreNamed) {
  EXPECT_EQ(error_of([] { (void)find_device_profile("no-such-board"); }),
            "no devices profile 'no-such-board' (looked for " + profiles::default_config_dir() + "/devices/no-such-board.json)");
  EXPECT_EQ(error_of([] { (void)find_device_profile("/dev/null"); }),
            "/dev/null: is a character device, not a regular file (a device profile must be one)");
  EXPECT_EQ(error_of([] { (void)find_device_profile("/tmp/"); }), "/tmp/: is a directory, not a file");
}

// The crash of issue 15: 4..32-byte banks passed and the driver divided by a set of zero faces.
TEST(ProfileValidation, BankSmallerThanAFaceRecordAndItsTableEntry) {
  for (std::uint64_t bytes : {4, 16, 32, 36}) {
    nlohmann::ordered_json j = xc2v6000();
    j["banks"]["capacity_bytes"]["value"] = bytes;
    EXPECT_EQ(device_error(j), "configs/devices/x.json: banks.capacity_bytes = " + std::to_string(bytes) +
                                   " is smaller than one face record and its own-face table entry (40 bytes: 10 words "
                                   "of 4 bytes; a pass needs both in the face bank when no spare bank holds the table)");
  }
  nlohmann::ordered_json j = xc2v6000();
  j["banks"]["capacity_bytes"]["value"] = 40;
  EXPECT_EQ(device_profile_from_document(rc::profiles::document_of(j), "x.json").bank_capacity_bytes, 40u);
  j["banks"]["word_bits"]["value"] = 64;  // 10 words of 8 bytes
  EXPECT_EQ(device_error(j), "configs/devices/x.json: banks.capacity_bytes = 40 is smaller than one face record and "
                             "its own-face table entry (80 bytes: 10 words of 8 bytes; a pass needs both in the face "
                             "bank when no spare bank holds the table)");
}

TEST(ProfileValidation, BankOfPartWords) {
  nlohmann::ordered_json j = xc2v6000();
  j["banks"]["capacity_bytes"]["value"] = 4194305;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: banks.capacity_bytes = 4194305 is not a whole number of 4-byte words");
}

// 2^36 bytes and more ended in std::bad_alloc; the limit is what the 32-bit FACE_COUNT reaches.
TEST(ProfileValidation, BankLargerThanTheRegistersReach) {
  const std::uint64_t limit = kMaxBankWords * 4;  // 171798691800 bytes
  EXPECT_EQ(limit, 171798691800u);
  nlohmann::ordered_json j = xc2v6000();
  j["banks"]["capacity_bytes"]["value"] = limit + 4;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: banks.capacity_bytes = 171798691804 is larger than the wrapper "
                             "can address (171798691800 bytes: 42949672950 words of 4 bytes, 2^32 - 1 face records and "
                             "their own-face table entries, the most the 32-bit FACE_COUNT register reaches)");
  j["banks"]["capacity_bytes"]["value"] = limit;
  EXPECT_EQ(device_profile_from_document(rc::profiles::document_of(j), "x.json").bank_capacity_bytes, limit);
}

// A bank so large that it holds more faces or rays than the 32-bit registers count: the layout's
// limits stop at what RAY_COUNT and FACE_COUNT hold (the driver writes them as 32-bit words).
TEST(ProfileValidation, BatchAndSetLimitsStopAtTheRegisters) {
  const BankLayout L = make_bank_layout(2, 6, 15, 32, kMaxBankWords * 4);
  EXPECT_EQ(L.max_faces_per_set, kMaxRegisterCount);
  EXPECT_EQ(L.max_rays_per_batch, kMaxRegisterCount);
  const BankLayout small = make_bank_layout(1, 6, 15, 32, 4u << 20);
  EXPECT_EQ(small.max_faces_per_set, (1u << 20) / 9);  // one lane on six banks: the table has a spare bank
}

TEST(ProfileValidation, BankCountTheWrapperCanUse) {
  nlohmann::ordered_json j = xc2v6000();
  j["banks"]["count"]["value"] = 4;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: banks.count = 4 is fewer than the 5 banks the wrapper needs "
                             "(faces, X, Y, Z, results; paper sec 4.1)");
  j["banks"]["count"]["value"] = 256;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: banks.count = 256 is more than the wrapper's CONFIG register can "
                             "count (8 bits: at most 255)");
  EXPECT_EQ(error_of([] { (void)make_bank_layout(1, 256, 15, 32, 4u << 20); }),
            "256 banks: the wrapper's CONFIG register counts banks in 8 bits (at most 255)");
}

// "2abc" was read as lane 2 (std::stoi), " 2" too; 0 and 256 lanes are no design.
TEST(ProfileValidation, LaneClockKeysAreWholeLaneCounts) {
  for (const char* key : {"2abc", " 2", "2.0", "0", "256", "-1", ""}) {
    nlohmann::ordered_json j = xc2v6000();
    j["clock"]["mhz_by_lanes"][key] = sourced(50);
    EXPECT_EQ(device_error(j), std::string("configs/devices/x.json: clock.mhz_by_lanes.") + key +
                                   ": key must be a lane count, a whole number 1..255 (a design has at most 255 lanes: "
                                   "the CONFIG register holds 8 bits)")
        << key;
  }
  nlohmann::ordered_json j = xc2v6000();
  j["clock"]["mhz_by_lanes"]["255"] = sourced(50);
  EXPECT_EQ(device_profile_from_document(rc::profiles::document_of(j), "x.json").clock_mhz(255), 50);
}

TEST(ProfileValidation, ClocksArePositiveAndFinite) {
  nlohmann::ordered_json j = xc2v6000();
  j["banks"]["clock_mhz"]["value"] = 0;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: banks.clock_mhz: value 0 is outside [0.001, 10000]");
  j = xc2v6000();
  j["clock"]["mhz_by_lanes"]["1"]["value"] = -53.8;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: clock.mhz_by_lanes.1: value -53.8 is outside [0.001, 10000]");
  j = xc2v6000();
  j["clock"]["mhz_default"]["value"] = 1e300;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: clock.mhz_default: value 1e+300 is outside [0.001, 10000]");
  // Whole limits are printed in full (they were 1.04858e+06 and 4.29497e+09).
  j = xc2v6000();
  j["wrapper"]["pass_start_cycles"]["value"] = -3;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: wrapper.pass_start_cycles: value -3 is outside [0, 1048576]");
  j = xc2v6000();
  j["pci"]["max_burst_bytes"]["value"] = 3;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: pci.max_burst_bytes: value 3 is outside [8, 4294967295]");
  // A burst is one TLM transaction, whose length is 32-bit: exactly 2^32 passed this check and then
  // failed inside the DMA engine, naming neither file nor key (issue 27).
  j["pci"]["max_burst_bytes"]["value"] = 4294967296.0;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: pci.max_burst_bytes: value 4294967296 is outside [8, 4294967295]");
  j["pci"]["max_burst_bytes"]["value"] = 4294967295.0;
  EXPECT_EQ(device_error(j), "(no error)");
}

// A value without its source, or with a source that is not text, is named (it once reached
// nlohmann's const operator[] on the missing key: fuzz/regressions/device).
TEST(ProfileValidation, EveryValueNeedsItsSource) {
  nlohmann::ordered_json j = xc2v6000();
  j["pci"]["clock_mhz"].erase("source");
  EXPECT_EQ(device_error(j), "configs/devices/x.json: pci.clock_mhz: has no \"source\" string (every number must "
                             "say where it came from)");
  j = xc2v6000();
  j["pci"]["clock_mhz"]["source"] = 7;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: pci.clock_mhz: has no \"source\" string (every number must "
                             "say where it came from)");
  j = xc2v6000();
  j["wrapper"]["results"].erase("source");
  EXPECT_EQ(device_error(j).rfind("configs/devices/x.json: wrapper.results: has no \"source\" string", 0), 0u)
      << device_error(j);
}

TEST(ProfileValidation, DesignBitsAreAPipelineWidth) {
  nlohmann::ordered_json j = xc2v6000();
  j["clock"]["design_bits"]["value"] = 40;
  EXPECT_EQ(device_error(j),
            "configs/devices/x.json: clock.design_bits = 40 is not a fractional width the pipeline has (7..31)");
}

TEST(ProfileValidation, UnknownKeysAreRefused) {
  nlohmann::ordered_json j = xc2v6000();
  j["banks"]["clock_mhzz"] = sourced(100);
  EXPECT_EQ(device_error(j), "configs/devices/x.json: banks.clock_mhzz: unknown key (known in banks: capacity_bytes, "
                             "clock_mhz, count, read_latency_cycles, word_bits, write_latency_cycles)");
  j = xc2v6000();
  j["bogus"] = 1;
  EXPECT_EQ(device_error(j), "configs/devices/x.json: bogus: unknown key (known at the top: banks, clock, description, energy, "
                             "fpga, name, pci, pipeline, schema, wrapper)");
  j = xc2v6000();
  j["pci"]["clock_mhz"]["unit"] = "MHz";
  EXPECT_EQ(device_error(j), "configs/devices/x.json: pci.clock_mhz.unit: unknown key (a sourced field has only "
                             "\"value\" and \"source\")");
  j = xc2v6000();
  j["schema"] = "rc2000sim.host/1";
  EXPECT_EQ(device_error(j),
            "configs/devices/x.json: schema: is \"rc2000sim.host/1\"; this reader takes \"rc2000sim.device/1\"");
}

// A capacity chosen beside the profile (tests, studies' compact banks) meets the same limits.
TEST(ProfileValidation, ChosenCapacityMeetsTheSameLimits) {
  BoardChoices c;
  c.bank_capacity_bytes = 16;
  const BoardParams p = make_board_params(find_device_profile("xc2v6000"), c);
  EXPECT_EQ(error_of([&] { (void)make_bank_layout(p); }),
            "a bank capacity of 16 bytes is smaller than one face record and its own-face table entry (40 bytes: 10 "
            "words of 4 bytes; a pass needs both in the face bank when no spare bank holds the table)");
  // The smallest bank works in every layout: one face and its table entry, one packet of one ray.
  for (unsigned banks : {5u, 6u, 7u, 12u}) {
    const BankLayout L = make_bank_layout(2, banks, 15, 32, 40);
    EXPECT_EQ(L.max_faces_per_set, 1u) << banks;
    EXPECT_GE(L.max_rays_per_batch, 1u) << banks;
  }
}

}  // namespace
}  // namespace rc::board::test
