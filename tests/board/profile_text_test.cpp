// Device profiles (and the energy tables inside them) are read through the strict JSON edge
// (io/json_text.h): a key given twice, a comment, deep nesting, another encoding and a special file
// are refused naming the file, the line and the limit, instead of a silent last-key-wins, a crash or
// a hang.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "board/device_profile.h"
#include "profiles/profile_json.h"
#include "tests/common/temp_folder.h"

namespace rc::board::test {
namespace {

namespace fs = std::filesystem;

class ProfileText : public ::rc::test::TempFolderTest {
 protected:
  ProfileText() : TempFolderTest("rc_profile_text") {}

  void SetUp() override {
    TempFolderTest::SetUp();
    std::ifstream in(profiles::default_config_dir() + "/devices/xc2v6000.json", std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    shipped_ = text.str();
  }
  std::string write(const std::string& bytes) const { return TempFolderTest::write("p.json", bytes); }
  static std::string error_of(const std::string& path) {
    try {
      (void)find_device_profile(path);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  }
  // The shipped profile with `insert` put right after the first occurrence of `after`.
  std::string edited(const std::string& after, const std::string& insert) const {
    std::string text = shipped_;
    const std::size_t at = text.find(after);
    EXPECT_NE(at, std::string::npos) << after;
    return text.insert(at + after.size(), insert);
  }
  static std::size_t line_of(const std::string& text, const std::string& what) {
    const std::size_t at = text.find(what);
    return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
  }

  std::string shipped_;
};

TEST_F(ProfileText, TheShippedProfileReadsFromACopy) { EXPECT_EQ(error_of(write(shipped_)), "(no error)"); }

// banks.count given twice: nlohmann kept the last silently. Also inside the energy table.
TEST_F(ProfileText, AKeyGivenTwiceIsRefusedNamingBothLines) {
  const std::string text = edited("\"banks\": {", "\n    \"count\": {\"value\": 4, \"source\": \"a second count\"},");
  const std::size_t first = line_of(text, "a second count");
  const std::size_t second = line_of(text, "\"count\": {\"value\": 6");
  const std::string path = write(text);
  EXPECT_EQ(error_of(path), path + ": line " + std::to_string(second) + ": key \"count\" given twice in banks (first on line " +
                                std::to_string(first) + "); JSON readers keep only one, so remove the other");
  const std::string energy = write(edited("\"energy\": {", "\n \"x\": 1,\n \"x\": 2,"));
  EXPECT_NE(error_of(energy).find(": key \"x\" given twice in energy (first on line "), std::string::npos) << error_of(energy);
}

TEST_F(ProfileText, CommentsDeepNestingAndEncodingsAreNamed) {
  const std::string commented = write("{\n  // the board\n" + shipped_.substr(shipped_.find('{') + 1));
  EXPECT_EQ(error_of(commented), commented + ": line 2: JSON has no comments ('//' here); remove it");
  const std::string deep = write("{\"schema\": " + std::string(200000, '[') + std::string(200000, ']') + "}");
  EXPECT_EQ(error_of(deep), deep + ": line 1: nested deeper than the limit of 64 arrays and objects (io/json_text.h, "
                                   "kJsonDepthLimit)");
  const std::string wide = write(std::string("\xFF\xFE{\0}\0", 6));
  EXPECT_EQ(error_of(wide), wide + ": is UTF-16 (little-endian byte order mark), not UTF-8; save it as UTF-8");
}

TEST_F(ProfileText, AFifoIsRefusedByNameWithoutWaiting) {
  const std::string fifo = (dir_ / "board.json").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(error_of(fifo), fifo + ": is a named pipe (FIFO), not a regular file (a device profile must be one)");
}

}  // namespace
}  // namespace rc::board::test
