// The one reading edge for JSON text (compositions, device and host profiles with their energy
// tables, the Table 2 file, the variants file, the pipeline resources): every reader calls
// parse_json_text instead of nlohmann's parse. Before nlohmann sees the text it is checked for what
// nlohmann would accept silently or crash on:
//  - text that is not UTF-8 (UTF-16/32 named by their byte order mark, else the first invalid byte);
//  - nesting deeper than kJsonDepthLimit (nlohmann copies and destroys values recursively: 200,000
//    nested arrays, 400 KB, ended in SIGSEGV);
//  - a key given twice in one object (nlohmann keeps the last: a composition's second "meshes"
//    dropped the first), named with both lines;
//  - comments, which JSON does not have ("JSON has no comments: line N").
// Syntax errors are reported with the line and column. Every error is a JsonTextError (an
// InputFileError) whose message starts with the path.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/input_file.h"

namespace rc::io {

// Our JSON files nest 5 levels at most; a generous bound that no real input reaches.
inline constexpr int kJsonDepthLimit = 64;

class JsonTextError : public InputFileError {
 public:
  using InputFileError::InputFileError;
};

// Throws JsonTextError for the problems above (not for syntax errors, which the parser finds);
// returns `text` without a leading UTF-8 byte order mark.
std::string_view check_json_text(std::string_view text, const std::string& path);

// "<path>: line L, column C: not valid JSON: <what the parser says>".
[[noreturn]] void throw_json_syntax_error(const nlohmann::json::parse_error& e, std::string_view text,
                                          const std::string& path);

// "<path>: line L: a number beyond the range of a double ('2e308')": nlohmann's out_of_range.406,
// which has no position of its own (the line is that of the number's first occurrence).
[[noreturn]] void throw_json_number_error(const nlohmann::json::out_of_range& e, std::string_view text,
                                          const std::string& path);

// `text` parsed as JSON (nlohmann::json or nlohmann::ordered_json), or a JsonTextError naming `path`.
template <class Json = nlohmann::json>
Json parse_json_text(std::string_view text, const std::string& path) {
  const std::string_view body = check_json_text(text, path);
  try {
    return Json::parse(body.begin(), body.end());
  } catch (const nlohmann::json::parse_error& e) {
    throw_json_syntax_error(e, body, path);
  } catch (const nlohmann::json::out_of_range& e) {  // a number that overflows a double
    throw_json_number_error(e, body, path);
  }
}

}  // namespace rc::io
