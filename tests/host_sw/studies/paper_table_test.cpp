// The Table 2 file (configs/paper-table2.json) is the only timing the host model is calibrated on,
// and users edit copies of it to calibrate on their own measurements (`calibrate --table`,
// `paper --table`). Every value is checked where it is read: a negative or zero time, a step count
// that is not whole, a row that is not a paper-like scene, a repeated row, a misspelt key and a
// wrong schema each get one error naming the file, the row and the key (they used to be read as
// given, or end in nlohmann's "type must be number").
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "host_sw/studies/paper_prediction.h"
#include "host_sw/studies/paper_workload.h"

namespace rc {
namespace {

nlohmann::json shipped_table() {
  std::ifstream in(default_paper_table_path());
  return nlohmann::json::parse(in);
}

// The error of loading `table` from a file named t.json ("(no error)" when it loads).
std::string table_error(const nlohmann::json& table) {
  const std::string path = ::testing::TempDir() + "t.json";
  std::ofstream(path) << table.dump();
  std::string error = "(no error)";
  try {
    (void)load_paper_table(path);
  } catch (const std::runtime_error& e) {
    error = e.what();
    const std::string prefix = path + ": ";
    if (error.rfind(prefix, 0) == 0) error = "t.json: " + error.substr(prefix.size());
  }
  std::remove(path.c_str());
  return error;
}

std::string error_with(const std::function<void(nlohmann::json&)>& change) {
  nlohmann::json table = shipped_table();
  change(table);
  return table_error(table);
}

TEST(PaperTable, TheShippedTableLoads) {
  const std::vector<PaperRow> rows = load_paper_table(default_paper_table_path());
  ASSERT_EQ(rows.size(), 8u);
  EXPECT_EQ(rows[0].label(), "70/280");
  EXPECT_EQ(rows[0].steps, 385);
  EXPECT_DOUBLE_EQ(rows[7].software_seconds, 1459.8);
  EXPECT_EQ(table_error(shipped_table()), "(no error)");
}

TEST(PaperTable, TimesMustBeMeasuredPositiveSeconds) {
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][0]["software_seconds"] = -1; }),
            "t.json: scenes[0].software_seconds: must be a measured time, seconds above 0 and at most a year, got -1");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][2]["one_pipe_seconds"] = 0; }),
            "t.json: scenes[2].one_pipe_seconds: must be a measured time, seconds above 0 and at most a year, got 0");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][0]["software_seconds"] = 1e300; }),
            "t.json: scenes[0].software_seconds: must be a measured time, seconds above 0 and at most a year, got 1e+300");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][0]["software_seconds"] = "0.9"; }),
            "t.json: scenes[0].software_seconds: must be a measured time, seconds above 0 and at most a year, got \"0.9\"");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][0].erase("one_pipe_seconds"); }),
            "t.json: scenes[0].one_pipe_seconds: missing");
}

TEST(PaperTable, CountsMustBeWholeAndPaperLike) {
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][0]["steps"] = 385.5; }),
            "t.json: scenes[0].steps: must be a whole number 1..10000000, got 385.5");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][0]["steps"] = 0; }),
            "t.json: scenes[0].steps: must be a whole number 1..10000000, got 0");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][0]["steps"] = "385"; }),
            "t.json: scenes[0].steps: must be a whole number 1..10000000, got \"385\"");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][1]["faces"] = 71; }),
            "t.json: scenes[1]: no paper-like scene has 71 faces and 1120 patches (70 x 4^k faces, faces x 4^m patches)");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][0]["patches"] = 1e12; }),
            "t.json: scenes[0].patches: must be a whole number 1..16777216, got 1000000000000.0");
}

TEST(PaperTable, OneRowPerSceneAndOnlyKnownKeys) {
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"].push_back(t["scenes"][3]); }),
            "t.json: scenes[8]: 280/280 is already scenes[3]; one row per scene");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][4]["stepz"] = 3; }),
            "t.json: scenes[4].stepz: unknown key (known: faces, patches, steps, software_seconds, one_pipe_seconds)");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scene"] = t["scenes"]; }),
            "t.json: scene: unknown key (known: schema, description, source, scenes)");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["schema"] = "x"; }),
            "t.json: schema: must be \"rc2000sim.paper-table2/1\"");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"] = nlohmann::json::array(); }),
            "t.json: scenes: must be a list of at least one scene");
  EXPECT_EQ(error_with([](nlohmann::json& t) { t["scenes"][0] = 5; }),
            "t.json: scenes[0]: must be an object {faces, patches, steps, software_seconds, one_pipe_seconds}");
  EXPECT_EQ(table_error(nlohmann::json::array()), "t.json: must be a JSON object with \"schema\" and \"scenes\"");
}

// The summary's "largest scene" and the bank variants follow the work, not the table's last row.
TEST(PaperTable, TheLargestSceneIsTheOneWithTheMostWork) {
  std::vector<PaperScene> scenes(4);
  scenes[0].row = {1120, 4480, 5889, 1, 1};
  scenes[1].row = {70, 280, 385, 1, 1};
  scenes[2].row = {280, 4480, 5889, 1, 1};
  scenes[3].row = {1120, 1120, 1488, 1, 1};
  EXPECT_EQ(largest_scene_index(scenes), 0u);
  std::swap(scenes[0], scenes[2]);
  EXPECT_EQ(largest_scene_index(scenes), 2u);
  scenes.resize(2);  // a subset: 280/4480 (1254400 pairs) against 70/280 (19600)
  EXPECT_EQ(largest_scene_index(scenes), 0u);
}

}  // namespace
}  // namespace rc
