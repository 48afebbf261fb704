// The checks made on study files before toml++ parses them (io/toml_text.h).
#include <gtest/gtest.h>

#include <string>

#include "io/input_file.h"
#include "io/toml_text.h"

namespace rc::io {
namespace {

std::string error_of(const std::string& text) {
  try {
    check_toml_text(text, "s.toml");
  } catch (const InputFileError& e) {
    return e.what();
  }
  return "";
}

std::string dotted(int parts) {
  std::string key = "a";
  for (int i = 1; i < parts; ++i) key += ".a";
  return key;
}

// A 200,000-part key (400 KB) ended in SIGSEGV inside toml++ (measured: a table header and a dotted key).
TEST(TomlText, ALongDottedKeyIsRefusedAtTheLimitNamingTheLine) {
  const std::string limit = std::to_string(kTomlKeyDepthLimit);
  const std::string message = ": a dotted key of more than " + limit + " parts (io/toml_text.h, kTomlKeyDepthLimit)";
  EXPECT_EQ(error_of("name = \"x\"\n[" + dotted(200000) + "]\nx = 1\n"), "s.toml:2" + message);
  EXPECT_EQ(error_of("\n\n" + dotted(200000) + " = 1\n"), "s.toml:3" + message);
  EXPECT_EQ(error_of("[\"a\" . b. 'c'.d]\n" + dotted(kTomlKeyDepthLimit + 1) + " = 1"),
            "s.toml:2" + message);
  EXPECT_EQ(error_of(dotted(kTomlKeyDepthLimit) + " = 1\n"), "");
}

TEST(TomlText, StringsCommentsAndNumbersAreNotKeys) {
  const std::string many_dots = std::string(200, '.');
  EXPECT_EQ(error_of("name = \"" + dotted(200) + "\"\n"), "");
  EXPECT_EQ(error_of("name = '" + dotted(200) + "'\n"), "");
  EXPECT_EQ(error_of("d = \"\"\"\n" + dotted(200) + "\n\"\"\"\n"), "");
  EXPECT_EQ(error_of("# " + dotted(200) + "\nx = [1.5, 2.5, 3.5, 4.5]\n"), "");
  EXPECT_EQ(error_of("\"banks.clock_mhz\" = 1\n"), "");
  // After a multi-line string the lines still count.
  EXPECT_EQ(error_of("d = '''\n\n'''\n" + dotted(100) + " = 1").substr(0, 9), "s.toml:4:");
}

TEST(TomlText, OtherEncodingsAreNamed) {
  EXPECT_EQ(error_of("name = \"caf\xE9\"\n"),
            "s.toml: is not UTF-8: byte 0xE9 at offset 11 (line 1, column 12; Latin-1 or another 8-bit encoding?); save it "
            "as UTF-8");
  EXPECT_EQ(error_of(std::string("\xFF\xFEn\0a\0", 6)),
            "s.toml: is UTF-16 (little-endian byte order mark), not UTF-8; save it as UTF-8");
}

}  // namespace
}  // namespace rc::io
