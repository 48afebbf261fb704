// The study-side readers go through the strict text edges (io/json_text.h, io/toml_text.h): the
// Table 2 file and the variants file refuse a key given twice, a comment, deep nesting and other
// encodings naming the file and the line; a study file refuses a dotted key toml++ would crash on
// and names another encoding; a FIFO given as --study, --table or --variants is refused by name
// at once (each used to block forever).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "host_sw/studies/calibration_variants.h"
#include "host_sw/studies/paper_workload.h"
#include "host_sw/studies/study_file.h"
#include "tests/common/temp_folder.h"

namespace rc {
namespace {

namespace fs = std::filesystem;

class TextInputs : public ::rc::test::TempFolderTest {
 protected:
  TextInputs() : TempFolderTest("rc_text_inputs") {}
  static std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  static std::string error_of(const std::function<void()>& f) {
    try {
      f();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(no error)";
  }
};

TEST_F(TextInputs, TheTable2FileRefusesKeysTwiceCommentsDepthAndEncodings) {
  const std::string shipped = read(default_paper_table_path());
  ASSERT_EQ(shipped.find("\"schema\""), shipped.find('{') + 4);  // `{\n  "schema"`: the edit below goes before it
  const std::string twice = write("twice.json", "{\n  \"scenes\": [],\n" + shipped.substr(shipped.find('{') + 2));
  const std::string e = error_of([&] { (void)load_paper_table(twice); });
  EXPECT_EQ(e, twice + ": line 6: key \"scenes\" given twice in the top level (first on line 2); JSON readers keep only "
                       "one, so remove the other");
  const std::string commented = write("c.json", "# Table 2\n" + shipped);
  EXPECT_EQ(error_of([&] { (void)load_paper_table(commented); }),
            commented + ": line 1: JSON has no comments ('#' here); remove it");
  const std::string deep = write("d.json", std::string(100000, '[') + std::string(100000, ']'));
  EXPECT_NE(error_of([&] { (void)load_paper_table(deep); }).find("nested deeper than the limit of 64"), std::string::npos);
  const std::string latin1 = write("l.json", "{\"description\": \"Tabelle f\xFCr\"}");
  EXPECT_EQ(error_of([&] { (void)load_paper_table(latin1); }),
            latin1 + ": is not UTF-8: byte 0xFC at offset 26 (line 1, column 27; Latin-1 or another 8-bit encoding?); "
                     "save it as UTF-8");
}

TEST_F(TextInputs, TheVariantsFileRefusesAKeyTwice) {
  const std::string shipped = read(default_variants_path());
  ASSERT_NE(shipped.find("\"chosen\": "), std::string::npos);
  std::string text = shipped;
  const std::size_t at = text.find("\"chosen\": ");
  text.insert(at, "\"chosen\": true, ");
  const std::string path = write("v.json", text);
  EXPECT_NE(error_of([&] { (void)load_calibrated_variants(path); }).find(": key \"chosen\" given twice in variants[0]"),
            std::string::npos)
      << error_of([&] { (void)load_calibrated_variants(path); });
  EXPECT_EQ(error_of([&] { (void)load_calibrated_variants(write("ok.json", shipped)); }), "(no error)");
}

TEST_F(TextInputs, AStudyFileWithADeepKeyOrAnotherEncodingIsNamed) {
  std::string key = "a";
  for (int i = 0; i < 200000; ++i) key += ".a";
  const std::string deep = write("deep.toml", "name = \"x\"\n[" + key + "]\n");
  EXPECT_EQ(error_of([&] { (void)load_study_file(deep); }),
            deep + ":2: a dotted key of more than 64 parts (io/toml_text.h, kTomlKeyDepthLimit)");
  const std::string latin1 = write("l.toml", "name = \"Gr\xF6\xDF" "e\"\n");
  EXPECT_EQ(error_of([&] { (void)load_study_file(latin1); }),
            latin1 + ": is not UTF-8: byte 0xF6 at offset 10 (line 1, column 11; Latin-1 or another 8-bit encoding?); "
                     "save it as UTF-8");
  // toml++'s own errors name the file and the line.
  const std::string bad = write("bad.toml", "name = \"x\"\nname = \"y\"\n");
  EXPECT_EQ(error_of([&] { (void)load_study_file(bad); }).substr(0, bad.size() + 3), bad + ":2:");
}

TEST_F(TextInputs, AFifoIsRefusedByNameAsStudyTableOrVariants) {
  const std::string fifo = (dir_ / "input.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  const std::string kind = fifo + ": is a named pipe (FIFO), not a regular file (";
  EXPECT_EQ(error_of([&] { (void)load_study_file(fifo); }), kind + "a study file must be one)");
  EXPECT_EQ(error_of([&] { (void)load_paper_table(fifo); }), kind + "the paper's Table 2 data must be one)");
  EXPECT_EQ(error_of([&] { (void)load_calibrated_variants(fifo); }), kind + "a variants file must be one)");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

}  // namespace
}  // namespace rc
