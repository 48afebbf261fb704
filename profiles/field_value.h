// A value a study writes into a profile field (profiles::FieldValue, profile_document.h) as the
// model code reads it: its kind and its text, without JSON (field_value_json.h converts at the edge).
#pragma once

#include <string>
#include <variant>

#include "profiles/profile_document.h"

namespace rc::profiles {

inline bool is_number(const FieldValue& v) { return !std::holds_alternative<std::string>(v); }
inline bool is_whole(const FieldValue& v) { return std::holds_alternative<std::int64_t>(v); }

// As JSON writes it: 133, 133.0, 1.5e-05, "bank" (quoted: a name among numbers in a message).
std::string json_text(const FieldValue& v);
// A name as it is, a number as json_text writes it: the "banks.clock_mhz=133" of a setting's text.
std::string plain_text(const FieldValue& v);

}  // namespace rc::profiles
