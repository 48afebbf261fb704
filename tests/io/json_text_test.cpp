// The JSON reading edge (io/json_text.h) and the UTF-8 checks under it (io/text_encoding.h): what
// nlohmann's parser crashes on or accepts silently is refused naming the file, the line and the
// limit; syntax errors say where.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "io/json_text.h"
#include "io/text_encoding.h"

namespace rc::io {
namespace {

std::string error_of(const std::string& text) {
  try {
    (void)parse_json_text(text, "p.json");
  } catch (const JsonTextError& e) {
    return e.what();
  }
  return "";
}

std::string nested(int depth, char open, char close, const std::string& inner = "") {
  std::string s;
  for (int i = 0; i < depth; ++i) s += open == '{' ? "{\"a\":" : std::string(1, open);
  s += inner.empty() ? "1" : inner;
  for (int i = 0; i < depth; ++i) s += close;
  return s;
}

// 200,000 nested arrays (400 KB) ended in SIGSEGV inside nlohmann; now the scan stops at the limit.
TEST(JsonText, DeepNestingIsRefusedAtTheLimitNamingTheLine) {
  const std::string limit = std::to_string(kJsonDepthLimit);
  EXPECT_EQ(error_of(std::string(200000, '[') + std::string(200000, ']')),
            "p.json: line 1: nested deeper than the limit of " + limit + " arrays and objects (io/json_text.h, kJsonDepthLimit)");
  EXPECT_EQ(error_of(nested(200000, '{', '}')),
            "p.json: line 1: nested deeper than the limit of " + limit + " arrays and objects (io/json_text.h, kJsonDepthLimit)");
  // At the limit it parses, one more does not: the bound is the documented one.
  EXPECT_EQ(error_of(std::string(kJsonDepthLimit, '[') + std::string(kJsonDepthLimit, ']')), "");
  EXPECT_NE(error_of(std::string(kJsonDepthLimit + 1, '[') + std::string(kJsonDepthLimit + 1, ']')), "");
  EXPECT_EQ(error_of("[\n[\n" + nested(kJsonDepthLimit, '[', ']') + "\n]\n]").substr(0, 15), "p.json: line 3:");
}

TEST(JsonText, ADuplicateKeyIsRefusedNamingBothLinesAndWhere) {
  EXPECT_EQ(error_of("{\n  \"meshes\": [],\n  \"meshes\": [{\"file\": \"a.obj\"}]\n}"),
            "p.json: line 3: key \"meshes\" given twice in the top level (first on line 2); JSON readers keep only one, "
            "so remove the other");
  EXPECT_EQ(error_of("{\"banks\": {\n \"count\": {\"value\": 8},\n \"x\": [1, 2],\n \"count\": {\"value\": 4}}}"),
            "p.json: line 4: key \"count\" given twice in banks (first on line 2); JSON readers keep only one, so "
            "remove the other");
  EXPECT_EQ(error_of("{\"meshes\": [{\"file\": \"a\"}, {\"file\": \"b\",\n\"file\": \"c\"}]}").substr(0, 69),
            "p.json: line 2: key \"file\" given twice in meshes[1] (first on line 1)");
  // The same key written with an escape is the same key, as the parser reads it.
  EXPECT_NE(error_of(R"({"a": 1, "\u0061": 2})"), "");
  // The same key in different objects, or as a value, is fine.
  EXPECT_EQ(error_of(R"([{"a": 1}, {"a": 2}, {"b": {"a": 3}, "a": "a"}])"), "");
  EXPECT_EQ(error_of(R"({"a": "b", "b": "a", "c": ["a", "a"]})"), "");
}

TEST(JsonText, CommentsAreNamedAsComments) {
  EXPECT_EQ(error_of("{\n  // the box\n  \"a\": 1\n}"), "p.json: line 2: JSON has no comments ('//' here); remove it");
  EXPECT_EQ(error_of("{\"a\": 1 /* one */}"), "p.json: line 1: JSON has no comments ('/*' here); remove it");
  EXPECT_EQ(error_of("# a profile\n{}"), "p.json: line 1: JSON has no comments ('#' here); remove it");
  EXPECT_EQ(error_of(R"({"url": "http://x/#y", "a": "/*"})"), "");  // inside strings they are text
}

TEST(JsonText, SyntaxErrorsSayLineAndColumn) {
  const std::string e = error_of("{\n  \"a\": 1,\n  \"b\": ]\n}");
  EXPECT_EQ(e.substr(0, 43), "p.json: line 3, column 8: not valid JSON: s") << e;
  EXPECT_EQ(error_of(""), "p.json: empty (no JSON value)");
  EXPECT_EQ(error_of(" \n "), "p.json: empty (no JSON value)");
  EXPECT_NE(error_of("{\"a\": \"unterminated}"), "");
}

// nlohmann throws out_of_range.406 for a number beyond a double (the fuzzer's composition with
// "2e308" ended in std::terminate): named with its line like any other error.
TEST(JsonText, ANumberBeyondADoubleIsNamedWithItsLine) {
  EXPECT_EQ(error_of("{\n  \"min\": [0, 2e308, 0]\n}"),
            "p.json: line 2: the number '2e308' is beyond the range of a double (numbers must be finite)");
  EXPECT_EQ(error_of("[-1e400]"), "p.json: line 1: the number '-1e400' is beyond the range of a double (numbers must be finite)");
}

TEST(JsonText, OtherEncodingsAreNamed) {
  EXPECT_EQ(error_of(std::string("\xFF\xFE{\0}\0", 6)),
            "p.json: is UTF-16 (little-endian byte order mark), not UTF-8; save it as UTF-8");
  EXPECT_EQ(error_of(std::string("\xFE\xFF\0{\0}", 6)),
            "p.json: is UTF-16 (big-endian byte order mark), not UTF-8; save it as UTF-8");
  EXPECT_EQ(error_of(std::string("\xFF\xFE\0\0{\0\0\0", 8)),
            "p.json: is UTF-32 (little-endian byte order mark), not UTF-8; save it as UTF-8");
  EXPECT_EQ(error_of(std::string("{\0\"\0a\0\"\0", 8)),
            "p.json: is UTF-16 without a byte order mark (NUL bytes between the characters), not UTF-8; save it as UTF-8");
  EXPECT_EQ(error_of("{\n  \"name\": \"caf\xE9\"\n}"),
            "p.json: is not UTF-8: byte 0xE9 at offset 16 (line 2, column 15; Latin-1 or another 8-bit encoding?); "
            "save it as UTF-8");
  // A UTF-8 byte order mark is skipped; UTF-8 text of every length passes.
  EXPECT_EQ(error_of("\xEF\xBB\xBF{\"name\": \"caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80\"}"), "");
}

TEST(TextEncoding, InvalidUtf8IsFoundAtItsFirstByte) {
  EXPECT_EQ(first_invalid_utf8("abc"), std::string::npos);
  EXPECT_EQ(first_invalid_utf8("a\xC3\xA9"), std::string::npos);
  EXPECT_EQ(first_invalid_utf8("a\xC0\xAF"), 1u);          // overlong '/'
  EXPECT_EQ(first_invalid_utf8("ab\xED\xA0\x80"), 2u);     // a UTF-16 surrogate
  EXPECT_EQ(first_invalid_utf8("\xF4\x90\x80\x80"), 0u);   // above U+10FFFF
  EXPECT_EQ(first_invalid_utf8("ab\xE2\x82"), 2u);         // cut short
  EXPECT_EQ(first_invalid_utf8("\x80"), 0u);               // a lone continuation byte
}

TEST(TextEncoding, PrintableUtf8EscapesOnlyTheForeignBytes) {
  EXPECT_EQ(printable_utf8("caf\xE9 \xC3\xA9"), "caf\\xE9 \xC3\xA9");
  EXPECT_EQ(printable_utf8("plain"), "plain");
  EXPECT_EQ(first_invalid_utf8(printable_utf8("\xFF\xFE\x80\xC3")), std::string::npos);
}

}  // namespace
}  // namespace rc::io
