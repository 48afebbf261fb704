// The profile edge: every shipped config file reads through it (the one field-checking dialect for
// device and host profiles, the resource table, the variants file), its document is the file as
// written, and each kind of mistake is named once, with the file and the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "profiles/profile_json.h"
#include "profiles/composition_file.h"
#include "profiles/paper_table.h"
#include "profiles/profile_reader.h"
#include "profiles/resource_table.h"
#include "profiles/variants_file.h"

namespace rc::profiles {
namespace {

const std::string kConfigs = std::string(RC_SOURCE_DIR) + "/configs";

std::vector<std::string> files_in(const std::string& folder) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(kConfigs + "/" + folder))
    if (e.path().extension() == ".json") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string text_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Reads every sourced field the dialect's way (a number or a name), then refuses unknown keys: a
// file that passes has no field outside the dialect.
void read_every_field(const ProfileDocument& d, const std::string& file) {
  const ProfileReader r(d, file);
  if (r.has("schema")) (void)r.text("schema");
  (void)r.text("name");
  for (const std::string& f : d.sourced_fields()) {
    if (d.holds_number(f)) {
      (void)r.number(f, -1e300, 1e300);
      EXPECT_FALSE(r.source(f).empty()) << file << ": " << f;
    } else {
      (void)r.text(f + ".value");
      EXPECT_FALSE(r.text(f + ".source").empty()) << file << ": " << f;
    }
  }
  r.refuse_unknown_keys({"description", "calibration", "fpga.part"});
}

TEST(ProfileEdge, EveryShippedProfileRoundTrips) {
  std::size_t files = 0;
  for (const char* kind : {"devices", "hosts"}) {
    for (const std::string& path : files_in(kind)) {
      SCOPED_TRACE(path);
      const ProfileDocument d = read_profile_document(path);
      EXPECT_NO_THROW(read_every_field(d, path));
      // The document is the file: parsed again from its own text it is equal, field for field.
      EXPECT_TRUE(document_of(nlohmann::ordered_json::parse(text_of(path))) == d);
      EXPECT_EQ(json_of(document_of(nlohmann::ordered_json::parse(json_of(d).dump(2)))).dump(), json_of(d).dump());
      EXPECT_GT(d.sourced_fields().size(), 10u);
      ++files;
    }
  }
  EXPECT_EQ(files, 5u);  // three devices, two hosts (configs/devices, configs/hosts)
}

TEST(ProfileEdge, ShippedResourceTableAndVariantsRead) {
  const ResourceTable t = read_resource_table(kConfigs + "/pipeline_resources.json");
  EXPECT_EQ(t.device_name, "XC2V6000");
  EXPECT_EQ(t.soft.size(), 4u);  // Table 1: 7, 15, 23 and 31 bits without block multipliers
  EXPECT_EQ(t.hard.size(), 2u);  // 7 and 15 bits with them
  for (const ResourcePoint& p : t.soft) EXPECT_FALSE(p.source.empty());
  EXPECT_FALSE(t.families.empty());
  const std::vector<VariantRecord> v = read_variants_file(kConfigs + "/calibration/athlon-mp-2600-variants.json");
  ASSERT_FALSE(v.empty());
  std::size_t chosen = 0;
  for (const VariantRecord& r : v) {
    chosen += r.chosen ? 1 : 0;
    EXPECT_NO_THROW(read_every_field(r.profile, r.driver_model));
  }
  EXPECT_EQ(chosen, 1u);
}

TEST(ProfileEdge, ShippedPaperTableAndCompositionsRead) {
  const std::vector<PaperTableRow> rows = read_paper_table(kConfigs + "/paper-table2.json", {1 << 20, 1 << 24, 1 << 20});
  ASSERT_FALSE(rows.empty());
  for (const PaperTableRow& r : rows) EXPECT_GE(r.software_seconds, r.one_pipe_seconds);  // the board was never slower
  for (const std::string& path : files_in("scenes")) {
    SCOPED_TRACE(path);
    ASSERT_TRUE(has_composition_schema(text_of(path), path));
    const CompositionFile c = parse_composition(text_of(path), path);
    ASSERT_FALSE(c.meshes.empty());
    for (const CompositionMesh& m : c.meshes) EXPECT_TRUE(std::filesystem::path(m.file).is_absolute()) << m.file;
  }
  // The same mistakes in a composition: named once, with the file and the key.
  const std::string text = R"({"schema": "rc2000sim.composition/1", "meshes": [{"file": "a.obj", "sclae": 2}]})";
  try {
    (void)parse_composition(text, "c.json");
    FAIL() << "accepted an unknown key";
  } catch (const CompositionError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("c.json: meshes[0].sclae: unknown key", 0), 0u) << e.what();
  }
}

// How many times `needle` occurs in `hay`.
std::size_t occurrences(const std::string& hay, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = hay.find(needle); at != std::string::npos; at = hay.find(needle, at + needle.size())) ++n;
  return n;
}

std::string error_reading(const nlohmann::ordered_json& j, const char* path) {
  const ProfileDocument d = document_of(j);
  const ProfileReader r(d, "dev.json");
  try {
    (void)r.number(path, 0, 1e6);
    r.refuse_unknown_keys({});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ProfileEdge, EachMistakeIsNamedOnceWithFileAndKey) {
  const nlohmann::ordered_json good = {{"banks", {{"clock_mhz", {{"value", 100}, {"source", "datasheet"}}}}}};
  EXPECT_EQ(error_reading(good, "banks.clock_mhz"), "(no error)");

  nlohmann::ordered_json unknown = good;
  unknown["banks"]["clock_mhzz"] = {{"value", 1}, {"source", "typo"}};
  const std::string e1 = error_reading(unknown, "banks.clock_mhz");
  EXPECT_EQ(e1.rfind("dev.json: banks.clock_mhzz: unknown key", 0), 0u) << e1;
  EXPECT_EQ(occurrences(e1, "dev.json"), 1u) << e1;
  EXPECT_EQ(occurrences(e1, "clock_mhzz"), 1u) << e1;

  nlohmann::ordered_json wrong = good;
  wrong["banks"]["clock_mhz"]["value"] = "fast";
  const std::string e2 = error_reading(wrong, "banks.clock_mhz");
  EXPECT_EQ(e2, "dev.json: banks.clock_mhz: \"value\" must be a number");
  EXPECT_EQ(occurrences(e2, "banks.clock_mhz"), 1u);

  nlohmann::ordered_json unsourced = good;
  unsourced["banks"]["clock_mhz"].erase("source");
  const std::string e3 = error_reading(unsourced, "banks.clock_mhz");
  EXPECT_EQ(e3, "dev.json: banks.clock_mhz: has no \"source\" string (every number must say where it came from)");
  EXPECT_EQ(occurrences(e3, "dev.json"), 1u);
}

TEST(ProfileEdge, ASettingIsWrittenOnTheDocumentWithItsSource) {
  const ProfileDocument d = read_profile_document(kConfigs + "/devices/xc2v6000.json");
  const ProfileDocument set = d.with_field("banks.clock_mhz", std::int64_t{133}, "study s: banks.clock_mhz=133");
  EXPECT_EQ(set.value_text("banks.clock_mhz"), "133");  // a whole number stays whole
  EXPECT_EQ(ProfileReader(set, "x").source("banks.clock_mhz"), "study s: banks.clock_mhz=133");
  EXPECT_TRUE(d != set);
  EXPECT_EQ(d.sourced_fields(), set.sourced_fields());  // in place, order kept
  // Setting the profile's own value and source back gives the document that was read.
  const nlohmann::ordered_json& was = json_of(d).at("banks").at("clock_mhz");
  EXPECT_TRUE(set.with_field("banks.clock_mhz", was.at("value").get<std::int64_t>(), was.at("source").get<std::string>()) == d);
  const ProfileDocument name = d.with_field("wrapper.results", std::string("on_chip"), "study s");
  EXPECT_EQ(ProfileReader(name, "x").choice("wrapper.results", {"bank", "on_chip"}), 1u);
}

}  // namespace
}  // namespace rc::profiles
