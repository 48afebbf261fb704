// The checks toml++ (3.3, the study files' parser) lacks, made on the text before it parses:
//  - UTF-8, with other encodings named (toml++ says only "Encountered invalid utf-8 sequence");
//  - the length of a dotted key (`a.b.c = 1`, `[a.b.c]`): each component is a level of tables, and
//    toml++ builds and frees them recursively: a 200,000-component key (400 KB) ends in SIGSEGV.
//    Arrays and inline tables toml++ bounds itself (TOML_MAX_NESTED_VALUES, 256).
// Errors are InputFileErrors that start with the path and name the line and the limit.
#pragma once

#include <string>
#include <string_view>

namespace rc::io {

// The longest dotted key allowed; our study keys have 3 components at most.
inline constexpr int kTomlKeyDepthLimit = 64;

void check_toml_text(std::string_view text, const std::string& path);

}  // namespace rc::io
