// The combined table of a study over several scenes (host_sw/studies/study_table.h): read back with
// a CSV reader of its own (RFC 4180: quotes, doubled quotes, line breaks inside quotes), it is one
// header, `scene` then the per-scene columns, and each scene's rows in the study's order, each the
// per-scene table's record with the scene in front.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "host_sw/studies/sweep_columns.h"
#include "host_sw/studies/sweep_csv.h"
#include "host_sw/studies/study_table.h"

namespace rc {
namespace {

using Record = std::vector<std::string>;

// A CSV reader independent of the writers: fields of every record, quotes undone.
std::vector<Record> read_csv(const std::string& text) {
  std::vector<Record> records;
  Record record;
  std::string field;
  bool quoted = false, any = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    any = true;
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') field += '"', ++i;
      else if (c == '"') quoted = false;
      else field += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      record.push_back(field), field.clear();
    } else if (c == '\n') {
      record.push_back(field), field.clear();
      records.push_back(record), record.clear();
      any = false;
    } else {
      field += c;
    }
  }
  if (any) record.push_back(field), records.push_back(record);
  return records;
}

SweepRow row(const std::string& device, unsigned lanes, const std::string& reason) {
  SweepRow r;
  r.config.device = device;
  r.config.lanes = lanes;
  r.validity = reason.empty() ? Validity::ok : Validity::does_not_fit;
  r.reason = reason;
  r.simulated_seconds = 0.25 * lanes;
  return r;
}

StudyResult two_scenes() {
  StudyResult r;
  r.study.scenes = {{"box-70", {}, "", ""}, {"odd, \"name\"", {}, "", ""}};
  r.scenes.resize(2);
  r.scenes[0].rows = {row("xc2v6000", 1, ""), row("xc2v6000", 2, "")};
  r.scenes[1].rows = {row("xc2v6000", 1, ""), row("xc2v8000", 3, "too big,\nsee \"fit\""), row("xc2v6000", 4, "")};
  return r;
}

TEST(StudyTable, EachSceneRowsBehindItsNameUnderOneHeader) {
  const StudyResult r = two_scenes();
  std::ostringstream combined;
  write_study_table_csv(combined, r);
  const std::vector<Record> table = read_csv(combined.str());
  ASSERT_EQ(table.size(), 1u + 2 + 3);

  std::vector<std::vector<Record>> per_scene;
  for (const SceneSweep& s : r.scenes) {
    std::ostringstream csv;
    write_sweep_csv(csv, s.rows);
    per_scene.push_back(read_csv(csv.str()));
  }
  Record header = {"scene"};
  header.insert(header.end(), per_scene[0][0].begin(), per_scene[0][0].end());
  EXPECT_EQ(table[0], header);
  std::size_t at = 1;
  for (std::size_t s = 0; s < per_scene.size(); ++s)
    for (std::size_t i = 1; i < per_scene[s].size(); ++i, ++at) {
      Record want = {r.study.scenes[s].name};
      want.insert(want.end(), per_scene[s][i].begin(), per_scene[s][i].end());
      EXPECT_EQ(table[at], want) << "row " << at;
    }
  EXPECT_EQ(table[4][0], "odd, \"name\"");  // quoted and read back whole
}

// An extra axis column (here the host axis) is in the combined header and in every row.
TEST(StudyTable, ExtraAxisColumnsAreKept) {
  StudyResult r = two_scenes();
  for (SceneSweep& s : r.scenes)
    for (SweepRow& each : s.rows) each.config.host = "athlon-mp-2600";
  std::ostringstream combined, first;
  write_study_table_csv(combined, r, {"host"});
  write_sweep_csv(first, r.scenes[0].rows, {"host"});
  const std::vector<Record> table = read_csv(combined.str());
  const Record first_header = read_csv(first.str())[0];
  ASSERT_EQ(table[0].size(), first_header.size() + 1);
  for (const Record& line : table) EXPECT_EQ(line.size(), table[0].size());
  EXPECT_NE(std::find(table[0].begin(), table[0].end(), "host"), table[0].end());
}

}  // namespace
}  // namespace rc
