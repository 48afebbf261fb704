// Studies meet the same profile limits as runs (docs/board.md, "Validation"; docs/studies.md): a
// profile axis or fixed setting the device loader refuses fails the study before any work, naming the
// study, the profile with its settings, the key and the limit; shard arguments and study files are
// read strictly.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

#include "host_sw/studies/study_file.h"
#include "host_sw/studies/sweep_study.h"
#include "profiles/profile_json.h"

namespace rc {
namespace {

const std::string kSource = RC_SOURCE_DIR;
const std::string kInline = kSource + "/tests/host_sw/studies/data/inline.toml";
const std::string kDevice = profiles::default_config_dir() + "/devices/xc2v6000.json";

std::string error_of(const std::string& text) {
  try {
    (void)parse_study_text(text, kInline);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(StudyProfileLimits, ABankAxisBelowAFaceRecordFailsTheStudy) {
  EXPECT_EQ(error_of("[axes]\ndevices = [\"xc2v6000\"]\n\"banks.capacity_bytes\" = [4096, 16]\n"),
            kDevice + " with banks.capacity_bytes=16 (study " + kInline +
                "): banks.capacity_bytes = 16 is smaller than one face record and its own-face table entry (40 bytes: "
                "10 words of 4 bytes; a pass needs both in the face bank when no spare bank holds the table)");
  EXPECT_EQ(error_of("[axes]\ndevices = [\"xc2v6000\"]\n[fixed]\n\"banks.capacity_bytes\" = 4194306\n"),
            kDevice + " with banks.capacity_bytes=4194306 (study " + kInline +
                "): banks.capacity_bytes = 4194306 is not a whole number of 4-byte words");
  EXPECT_EQ(error_of("[axes]\ndevices = [\"xc2v6000\"]\n\"banks.word_bits\" = [64]\n[fixed]\n\"banks.capacity_bytes\" = 76\n"),
            kDevice + " with banks.capacity_bytes=76, banks.word_bits=64 (study " + kInline +
                "): banks.capacity_bytes = 76 is not a whole number of 8-byte words");
  // The smallest bank of each word width is a valid axis value.
  EXPECT_EQ(error_of("[axes]\ndevices = [\"xc2v6000\"]\nlanes = [1, 2]\n\"banks.capacity_bytes\" = [40, 4096]\n"),
            "(no error)");
}

TEST(StudyProfileLimits, ShardArgumentsAreWholeNumbers) {
  for (const char* bad : {"1x/3", "1/3x", "+1/3", "1/ 3", "1/3 ", "0x1/3", "1e0/3"}) {
    try {
      (void)parse_shard(bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), std::string("--shard: expected I/N (shard I of N, counted from 0), got '") + bad + "'");
    }
  }
  EXPECT_EQ(parse_shard("01/3").index, 1u);  // leading zeros are still the number
}

TEST(StudyProfileLimits, StudyFilesAreReadWithASizeLimit) {
  const std::string path = ::testing::TempDir() + "/large-study-" + std::to_string(::getpid()) + ".toml";
  {
    std::ofstream out(path);
    out << "name = \"large\"\n" << std::string(kMaxStudyFileBytes, '#') << "\n";
  }
  try {
    (void)load_study_file(path);
    ADD_FAILURE() << "accepted a study file over the limit";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(std::to_string(kMaxStudyFileBytes)), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace rc
