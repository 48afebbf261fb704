// Text that users give us must be UTF-8: every reader checks it at the edge, so a file saved as
// UTF-16 or Latin-1 is refused naming its encoding (or the first byte that is not UTF-8) instead of
// failing later with a message about something else. Names that reach our outputs (report.json,
// stderr, the trace) pass through printable_utf8 so that no byte that is not UTF-8 leaves as an
// exception after the work is done (docs/reliability.md, "Round three").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rc::io {

// "" when `text` is UTF-8 (a leading UTF-8 byte order mark allowed); otherwise what it is instead:
// "UTF-16 (little-endian byte order mark)", "UTF-32 ...", "UTF-16 without a byte order mark (NUL
// bytes between the characters)", or "not UTF-8: byte 0xE9 at offset 1234 (line 5, column 7)".
std::string utf8_problem(std::string_view text);

// The UTF-16 or UTF-32 encoding `text` is in, by its byte order mark or (UTF-16 without one) NUL
// bytes between its first ASCII characters: "is UTF-16 (little-endian byte order mark), not UTF-8";
// "" for anything else. A binary file (a mesh) has neither start.
std::string wide_encoding(std::string_view text);

// Throws InputFileError "<path>: <utf8_problem>; save it as UTF-8" unless `text` is UTF-8.
void check_utf8(std::string_view text, const std::string& path);

// The offset of the first byte of `text` that does not start or continue a valid UTF-8 sequence
// (overlong forms, surrogates and code points above U+10FFFF are invalid), or npos.
std::size_t first_invalid_utf8(std::string_view text);

// `text` with every byte that is not part of valid UTF-8 shown as \xNN, so that a Latin-1 name
// reaches JSON and the terminal readable and valid. Valid UTF-8 is returned unchanged.
std::string printable_utf8(std::string_view text);

// 1-based line and column (in bytes) of `offset` in `text`.
struct TextPosition {
  std::size_t line = 1, column = 1;
};
TextPosition position_of(std::string_view text, std::size_t offset);

}  // namespace rc::io
