#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "host_sw/studies/study_file.h"
#include "host_sw/studies/study_json.h"
#include "host_sw/studies/sweep_columns.h"

namespace rc {
namespace {

const std::string kSource = RC_SOURCE_DIR;

Study parse(const std::string& text) { return parse_study_text(text, kSource + "/tests/host_sw/studies/data/inline.toml"); }

// The error of parsing `text`, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    (void)parse(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(StudyFile, TheDefaultStudyFileIsWhatSweepRunsWithoutOptions) {
  const Study file = load_study_file(kSource + "/configs/studies/default.toml");
  nlohmann::ordered_json a = study_json(file), b = study_json(default_study());
  for (const char* key : {"description", "file"}) a.erase(key), b.erase(key);
  EXPECT_EQ(a.dump(2), b.dump(2));
  ASSERT_EQ(file.scenes.size(), 1u);
  EXPECT_EQ(file.scenes[0].name, "paper-280-1120");
}

TEST(StudyFile, ProfileFieldsAreAxesByPathInTheFileOrder) {
  const Study s = parse(R"(
[axes]
devices = ["xc2v6000"]
"pci.clock_mhz" = [33.333, 66.667]
banks.clock_mhz = { from = 100, to = 200, step = 50 }
host.segment_pack = [1e-7]
"host.driver_model.transfer" = ["dma", "pio"]
pipeline = { latency_cycles = { from = 30, to = 31 } }
[fixed]
"device.wrapper.face_setup_cycles" = 2
)");
  ASSERT_EQ(s.axes.profile.size(), 5u);
  const ProfileAxis& pci = s.axes.profile[0];
  EXPECT_EQ(pci.field.field, "pci.clock_mhz");
  EXPECT_EQ(pci.field.kind, ProfileKind::device);
  const ProfileAxis& banks = s.axes.profile[1];
  EXPECT_EQ(banks.field.path, "banks.clock_mhz");
  EXPECT_EQ(banks.values, (std::vector<ProfileValue>{std::int64_t{100}, std::int64_t{150}, std::int64_t{200}}));  // a whole range stays whole
  const ProfileAxis& pack = s.axes.profile[2];
  EXPECT_EQ(pack.field.kind, ProfileKind::host);
  EXPECT_EQ(pack.field.field, "driver_seconds.segment_pack");  // the leaf name is unique
  EXPECT_EQ(s.axes.profile[3].field.field, "driver_model.transfer");
  EXPECT_FALSE(s.axes.profile[3].field.numeric);
  EXPECT_EQ(s.axes.profile[4].values, (std::vector<ProfileValue>{std::int64_t{30}, std::int64_t{31}}));
  ASSERT_EQ(s.fixed.size(), 1u);
  EXPECT_EQ(s.fixed[0].field.field, "wrapper.face_setup_cycles");
  // The resolved record reads back to the same study.
  EXPECT_EQ(study_json(study_from_json(study_json(s))).dump(), study_json(s).dump());
}

TEST(StudyFile, ClassicAxesTakeListsRangesAndTheCommandLineSpelling) {
  const Study s = parse(R"(
name = "spelled"
[[scenes]]
file = "../../../../scenes/examples/two-rooms.scene"
patch_levels = 1
[solver]
steps = 12
[axes]
devices = "xc2v6000, virtex4-sx55"
bits = [19, 15, 19]
lanes = "1-3,8"
banks = { from = 6, to = 12, step = 3 }
concurrent = "both"
)");
  EXPECT_EQ(s.name, "spelled");
  EXPECT_EQ(to_string(s.steps), "12");
  EXPECT_EQ(s.axes.devices, (std::vector<std::string>{"xc2v6000", "virtex4-sx55"}));
  EXPECT_EQ(s.axes.bits, (std::vector<int>{15, 19}));  // ascending and distinct, as on the command line
  EXPECT_EQ(s.axes.lanes, (std::vector<int>{1, 2, 3, 8}));
  EXPECT_EQ(s.axes.banks, (std::vector<int>{6, 9, 12}));
  EXPECT_EQ(s.axes.concurrent, (std::vector<bool>{false, true}));
  ASSERT_EQ(s.scenes.size(), 1u);
  EXPECT_EQ(s.scenes[0].options.file, kSource + "/scenes/examples/two-rooms.scene");  // relative to the study file
  EXPECT_EQ(s.scenes[0].name, "two-rooms");
}

// The source of resources (docs/pipeline.md, "Two sources of resources"): a top-level key, recorded in
// study.json only when not the paper fit (so earlier records read as before), read back the same.
TEST(StudyFile, ResourcesAreTheStudysSourceOfSlicesAndBlockMultipliers) {
  EXPECT_EQ(parse("").resources, pipeline::ResourceSource::paper_fit);
  EXPECT_FALSE(study_json(parse("")).contains("resources"));
  const Study s = parse("resources = \"synthesis\"\n");
  EXPECT_EQ(s.resources, pipeline::ResourceSource::synthesis);
  EXPECT_EQ(study_json(s).at("resources"), "synthesis");
  EXPECT_EQ(study_from_json(study_json(s)).resources, pipeline::ResourceSource::synthesis);
}

TEST(StudyFile, BadStudiesNameTheFileTheLineTheKeyAndTheLimit) {
  struct Case {
    const char* text;
    std::vector<const char*> expected;
  };
  const Case cases[] = {
      {"[axes]\n\"banks.clok_mhz\" = [1]\n", {"inline.toml:2", "banks.clok_mhz", "no sourced field", "banks.clock_mhz"}},
      {"[axes]\nclock_mhz = [1]\n", {"inline.toml:2", "names several fields", "pci.clock_mhz"}},
      {"[axes]\nbanks.clock_mhz = [0]\n", {"banks.clock_mhz=0", "banks.clock_mhz", "outside"}},
      {"[axes]\nbanks.clock_mhz = [\"fast\"]\n", {"inline.toml:2: axes.banks.clock_mhz: expected a number (the profile's banks.clock_mhz is a number), got \"fast\""}},
      {"[axes]\n\"host.transfer\" = [\"usb\"]\n", {"host.transfer=usb", "not one of dma, pio"}},
      {"[axes]\n\"host.transfer\" = [3]\n", {"inline.toml:2", "expected a name"}},
      {"[axes]\nlanes = \"0-3\"\n", {"inline.toml:2", "axes.lanes", "1..255"}},
      {"[axes]\nbits = [40]\n", {"inline.toml:2", "axes.bits", "7..31"}},
      {"[axes]\nlanes = []\n", {"inline.toml:2", "empty list"}},
      {"[axes]\nconcurrent = \"maybe\"\n", {"inline.toml:2", "axes.concurrent", "on, off or both"}},
      {"[axes]\ndevices = [\"no-such-device\"]\n", {"no devices profile 'no-such-device'"}},
      {"[axes]\nhosts = [\"no-such-host\"]\n", {"no hosts profile 'no-such-host'"}},
      {"[axes]\nbanks.clock_mhz = { from = 200, to = 100 }\n", {"inline.toml:2", "below from"}},
      {"[axes]\nbanks.clock_mhz = { from = 1, to = 1e9, step = 1 }\n", {"at most 10000"}},
      {"[axes]\nbanks.clock_mhz = { from = 0, to = 1e308, step = 1e-308 }\n", {"spans more than 10^18", "at most 10000"}},
      {"[axes]\n\"banks.clock_mhz\" = [100]\n[fixed]\n\"banks.clock_mhz\" = 90\n", {"both an axis and fixed"}},
      {"[solver]\nsteps = 0\n", {"inline.toml:2", "solver.steps", "1..10000000"}},
      {"resources = \"yosys\"\n", {"inline.toml:1", "resources", "'yosys' is not one of: paper, synthesis"}},
      {"[solver]\nsteps = \"often\"\n", {"inline.toml:2", "solver.steps"}},
      {"[solver]\nconvergence = 1.5\n", {"inline.toml:2", "strictly between 0 and 1"}},
      {"[solver]\nvisibility = \"exact\"\n", {"inline.toml:2", "is not one of: fixed, fast"}},
      {"[solver]\nspeed = 3\n", {"inline.toml:2", "solver.speed", "unknown key"}},
      {"colour = 3\n", {"inline.toml:1", "colour", "unknown key"}},
      {"[[scenes]]\npaper = { faces = 280, patches = 1000 }\n", {"inline.toml:2", "no paper-like scene"}},
      {"[[scenes]]\npaper = { faces = 70, patches = 280 }\nfaces = 70\n", {"does not apply to a paper scene"}},
      {"[[scenes]]\npaper = { faces = 70, patches = 280 }\n[[scenes]]\npaper = { faces = 70, patches = 280 }\n",
       {"two scenes are named 'paper-70-280'"}},
      {"[[scenes]]\nname = \"../x\"\n", {"cannot name a folder"}},
      {"[axes]\nlanes = \"1-255\"\nbanks = \"1-255\"\n", {"configurations (at most 20000)"}},
      {"[axes\n", {"inline.toml:1", "not valid TOML"}},
      {"[axes]\ncards = [1, 17]\n", {"inline.toml:2", "axes.cards", "1..16"}},
      {"[axes]\ncard_split = [\"faces\"]\n", {"apply only with more than one card"}},
      {"[axes]\ncards = [2]\ncard_bus = [\"ethernet\"]\n", {"card bus 'ethernet'", "shared, separate"}},
      {"[axes]\nbanks = [6]\nbanks.clock_mhz = [1]\n", {"inline.toml:3", "not valid TOML", "must be quoted"}},
      {"[axes]\n\"banks.count\" = [6, 8]\n", {"banks.count changes nothing", "use the banks axis"}},
      {"[axes]\ndevices = [\"xc2v6000\"]\nlanes = [1]\n\"clock.mhz_by_lanes.2\" = [50]\n", {"no configuration with 2 lane(s)"}},
      {"[axes]\n\"host.word_store\" = [1e-9]\n", {"host.word_store changes nothing", "per_word"}},
      {"[axes]\n\"host.clock_mhz\" = [1000, 3000]\n", {"host.clock_mhz changes nothing", "not used in timing"}},
      {"[fixed]\n\"clock.design_bits\" = 19\n", {"clock.design_bits changes nothing", "sweep bits"}},
      {"[fixed]\n\"host.driver_model.transfer\" = \"dma\"\n\"host.pio_read_round_trip_seconds\" = 1e-6\n",
       {"changes nothing", "programmed I/O"}},
  };
  for (const Case& c : cases) {
    const std::string e = error_of(c.text);
    ASSERT_FALSE(e.empty()) << "accepted:\n" << c.text;
    for (const char* part : c.expected) EXPECT_NE(e.find(part), std::string::npos) << "'" << part << "' not in: " << e;
  }
}

TEST(StudyFile, CardsAreAnAxisWhoseSplitAndBusApplyToSeveralCardsOnly) {
  const Study s = parse(R"(
[axes]
devices = ["xc2v6000"]
lanes = [2]
banks = [6]
cards = "1-2,4"
card_split = ["rays", "faces"]
card_bus = "shared,separate"
)");
  EXPECT_EQ(s.axes.cards, (std::vector<int>{1, 2, 4}));
  const std::vector<SweepConfig> configs = enumerate_configs(s.axes);
  ASSERT_EQ(configs.size(), 1u + 2u * 2u * 2u);  // one card once; 2 and 4 cards by split and bus
  EXPECT_EQ(configs[0].cards, 1u);
  EXPECT_EQ(configs[1].label(), "xc2v6000 15-bit concurrent 2 lanes 6 banks 2 cards (rays, shared bus)");
  EXPECT_EQ(configs[2].card_bus, CardBus::separate);
  EXPECT_EQ(configs[3].card_split, CardSplit::faces);
  EXPECT_EQ(extra_columns(s.axes), (std::vector<std::string>{"cards", "card_split", "card_bus"}));
  EXPECT_EQ(study_json(study_from_json(study_json(s))).dump(), study_json(s).dump());
}

// A copy of a shipped device profile at `path`, renamed `name`.
void write_device_copy(const std::string& path, const std::string& name) {
  std::ifstream in(kSource + "/configs/devices/xc2v6000.json");
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(in);
  j["name"] = name;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << j.dump(2);
}

// Device and host paths in a study lie relative to the study file's folder, as its scene files do
// (issue 27: they resolved against the working folder). A bare name is a profile of configs/.
TEST(StudyFile, ProfilePathsLieBesideTheStudyFile) {
  const std::string dir = ::testing::TempDir() + "relative-study";
  write_device_copy(dir + "/profiles/mine.json", "mine");
  std::ofstream(dir + "/s.toml") << "[[scenes]]\npaper = { faces = 70, patches = 280 }\n[axes]\n"
                                    "devices = [\"profiles/mine.json\", \"xc2v6000\"]\nlanes = [1]\nbanks = [6]\n";
  const Study s = load_study_file(dir + "/s.toml");
  ASSERT_EQ(s.axes.devices.size(), 2u);
  EXPECT_EQ(s.axes.devices[0], dir + "/profiles/mine.json");
  EXPECT_EQ(s.axes.devices[1], "xc2v6000");
  std::filesystem::remove_all(dir);
}

// Rows, sweep keys and plots name a device by its profile's "name": two files of one name (a copy
// of a profile edited but not renamed) gave duplicate sweep keys and a plot-script traceback, exit 0.
TEST(StudyFile, TwoProfilesOfOneNameAreRefusedNamingBothFiles) {
  const std::string dir = ::testing::TempDir() + "same-name-study";
  write_device_copy(dir + "/edited.json", "xc2v6000");
  std::ofstream(dir + "/s.toml") << "[[scenes]]\npaper = { faces = 70, patches = 280 }\n[axes]\n"
                                    "devices = [\"xc2v6000\", \"edited.json\"]\nlanes = [1]\nbanks = [6]\n";
  try {
    (void)load_study_file(dir + "/s.toml");
    ADD_FAILURE() << "two devices named xc2v6000 were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "study " + dir + "/s.toml: two device profiles are named 'xc2v6000': " + kSource +
                                         "/configs/devices/xc2v6000.json and " + dir +
                                         "/edited.json; rows and plots are keyed by the name: give each its own \"name\"");
  }
  std::filesystem::remove_all(dir);
}

TEST(StudyFile, FilesThatAreNotStudiesAreRefusedBeforeReading) {
  EXPECT_THROW(load_study_file("/no/such/study.toml"), std::invalid_argument);
  try {
    load_study_file("/dev/zero");  // not a regular file: never read
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/zero"), std::string::npos) << e.what();
  }
}

// [solver] form_factor: the paper's point rule unless the study says otherwise; a name of
// form_factor_names(), else an error naming the key, the line and the names. Recorded (and read back)
// only when not point, so point studies' records are what they were before the setting existed.
TEST(StudyFile, TheFormFactorIsAFixedSolverSettingPointByDefault) {
  EXPECT_EQ(parse("").form_factor, "point");
  const Study analytic = parse("[solver]\nform_factor = \"analytic\"\n");
  EXPECT_EQ(analytic.form_factor, "analytic");
  const nlohmann::ordered_json record = study_json(analytic);
  EXPECT_EQ(record.at("solver").at("form_factor"), "analytic");
  EXPECT_EQ(study_from_json(record).form_factor, "analytic");
  EXPECT_FALSE(study_json(parse("")).at("solver").contains("form_factor"));
  EXPECT_EQ(study_from_json(study_json(parse(""))).form_factor, "point");
  const std::string e = error_of("[solver]\nform_factor = \"exact\"\n");
  EXPECT_NE(e.find("inline.toml:2: solver.form_factor: form factor 'exact' is not one of: point, disc, analytic"),
            std::string::npos) << e;
}

// [axes] form_factors: each scene once per form factor, named for it, recorded per scene in the
// resolved study (so shards and merges keep it); excludes [solver] form_factor.
TEST(StudyFile, FormFactorsAreAnAxisOfScenes) {
  const Study s = parse(R"([[scenes]]
paper = { faces = 70, patches = 280 }
[[scenes]]
file = "../../../../scenes/examples/two-rooms.scene"
patch_levels = 0
[axes]
form_factors = ["point", "analytic"]
)");
  ASSERT_EQ(s.scenes.size(), 4u);
  EXPECT_EQ(s.scenes[0].name, "paper-70-280-point");
  EXPECT_EQ(s.scenes[1].name, "paper-70-280-analytic");
  EXPECT_EQ(s.scenes[3].name, "two-rooms-analytic");
  EXPECT_EQ(s.form_factor_of(s.scenes[0]), "point");
  EXPECT_EQ(s.form_factor_of(s.scenes[3]), "analytic");
  const Study back = study_from_json(study_json(s));
  ASSERT_EQ(back.scenes.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(back.scenes[i].form_factor, s.scenes[i].form_factor) << i;
  EXPECT_EQ(study_json(back), study_json(s));
  // One scene's record without the axis has no form_factor key (records read as before).
  EXPECT_FALSE(study_json(parse("")).at("scenes").at(0).contains("form_factor"));

  EXPECT_NE(error_of("[solver]\nform_factor = \"disc\"\n[axes]\nform_factors = [\"point\"]\n")
                .find("inline.toml:4: axes.form_factors: excludes solver.form_factor"),
            std::string::npos);
  EXPECT_NE(error_of("[axes]\nform_factors = [\"point\", \"exact\"]\n")
                .find("axes.form_factors: form factor 'exact' is not one of: point, disc, analytic"),
            std::string::npos);
  EXPECT_NE(error_of("[axes]\nform_factors = []\n").find("axes.form_factors: expected a non-empty list of names"),
            std::string::npos);
}

}  // namespace
}  // namespace rc
