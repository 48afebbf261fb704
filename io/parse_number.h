// Strict number parsing: the whole text must be the number. "2abc", " 2", "2.5" as an integer,
// "1e999" or "nan" as a finite value are all refused (std::nullopt), where std::stoi/stod and atoi
// would read a prefix, skip spaces or return infinity. Callers turn nullopt into an error that names
// their file, key or option.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rc::io {

// Decimal digits only (no sign, no spaces), within the type's range.
std::optional<std::uint64_t> parse_unsigned(std::string_view text);
// An optional '-' then decimal digits, within the type's range.
std::optional<std::int64_t> parse_integer(std::string_view text);
// A decimal or scientific number (as strtod reads it, all of the text), finite.
std::optional<double> parse_finite(std::string_view text);

// The inverse, for numbers people read and paste back (printed commands: docs/outputs.md): the
// shortest %g text that reads back as exactly `value` (0.2, not 0.20000000000000001; 1e-09; at
// most 17 digits). "nan", "inf" and "-inf" for the values that are not finite.
std::string shortest_text(double value);

}  // namespace rc::io
