#include "io/text_encoding.h"

#include <cstdio>

#include "io/input_file.h"

namespace rc::io {

namespace {

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

// The byte order marks of the encodings we name; UTF-32's are checked before UTF-16's, whose
// little-endian mark is their prefix.
std::string byte_order_mark_encoding(std::string_view text) {
  using namespace std::string_view_literals;
  if (starts_with(text, "\xFF\xFE\x00\x00"sv)) return "UTF-32 (little-endian byte order mark)";
  if (starts_with(text, "\x00\x00\xFE\xFF"sv)) return "UTF-32 (big-endian byte order mark)";
  if (starts_with(text, "\xFF\xFE"sv)) return "UTF-16 (little-endian byte order mark)";
  if (starts_with(text, "\xFE\xFF"sv)) return "UTF-16 (big-endian byte order mark)";
  return "";
}

// ASCII text saved as UTF-16 without a mark: every other byte of its first characters is NUL.
bool looks_like_utf16(std::string_view text) {
  if (text.size() < 4) return false;
  const auto ascii = [&](std::size_t i) { return text[i] > 0 && text[i] < 0x7F; };  // char may be signed
  const bool low = ascii(0) && text[1] == 0 && ascii(2) && text[3] == 0;
  const bool high = text[0] == 0 && ascii(1) && text[2] == 0 && ascii(3);
  return low || high;
}

// Length of the valid UTF-8 sequence starting at `i`, or 0.
std::size_t sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  if (b < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the range of the second byte (overlongs, surrogates, > U+10FFFF)
  if (b >= 0xC2 && b <= 0xDF) n = 2;
  else if (b == 0xE0) n = 3, lo = 0xA0;
  else if (b >= 0xE1 && b <= 0xEC) n = 3;
  else if (b == 0xED) n = 3, hi = 0x9F;
  else if (b >= 0xEE && b <= 0xEF) n = 3;
  else if (b == 0xF0) n = 4, lo = 0x90;
  else if (b >= 0xF1 && b <= 0xF3) n = 4;
  else if (b == 0xF4) n = 4, hi = 0x8F;
  else return 0;
  if (i + n > text.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

std::string hex_byte(unsigned char b) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02X", b);
  return text;
}

}  // namespace

std::size_t first_invalid_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = sequence_length(text, i);
    if (n == 0) return i;
    i += n;
  }
  return std::string_view::npos;
}

TextPosition position_of(std::string_view text, std::size_t offset) {
  TextPosition p;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

std::string wide_encoding(std::string_view text) {
  const std::string mark = byte_order_mark_encoding(text);
  if (!mark.empty()) return "is " + mark + ", not UTF-8";
  if (looks_like_utf16(text)) return "is UTF-16 without a byte order mark (NUL bytes between the characters), not UTF-8";
  return "";
}

std::string utf8_problem(std::string_view text) {
  if (std::string wide = wide_encoding(text); !wide.empty()) return wide;
  const std::size_t bad = first_invalid_utf8(text);
  if (bad == std::string_view::npos) return "";
  const TextPosition p = position_of(text, bad);
  return "is not UTF-8: byte " + hex_byte(static_cast<unsigned char>(text[bad])) + " at offset " +
         std::to_string(bad) + " (line " + std::to_string(p.line) + ", column " + std::to_string(p.column) +
         "; Latin-1 or another 8-bit encoding?)";
}

void check_utf8(std::string_view text, const std::string& path) {
  const std::string problem = utf8_problem(text);
  if (!problem.empty()) throw InputFileError(path + ": " + problem + "; save it as UTF-8");
}

std::string printable_utf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = sequence_length(text, i);
    if (n == 0) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", static_cast<unsigned char>(text[i]));
      out += escaped;
      ++i;
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
  }
  return out;
}

}  // namespace rc::io
