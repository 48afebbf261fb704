#include "profiles/synthesis_table.h"

#include <algorithm>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/input_file.h"
#include "io/json_text.h"

namespace rc::profiles {

namespace {

using nlohmann::json;

[[noreturn]] void synthesis_fail(const std::string& origin, const std::string& what) {
  throw std::runtime_error("synthesis resources " + origin + ": " + what);
}

const json& synthesis_member(const json& j, const std::string& key, const std::string& where, const std::string& origin) {
  if (!j.is_object() || !j.contains(key)) synthesis_fail(origin, where + "missing \"" + key + "\"");
  return j.at(key);
}

std::string synthesis_text(const json& j, const std::string& key, const std::string& where, const std::string& origin) {
  const json& v = synthesis_member(j, key, where, origin);
  if (!v.is_string() || v.get<std::string>().empty()) synthesis_fail(origin, where + "\"" + key + "\" is not a non-empty string");
  return v.get<std::string>();
}

int synthesis_count(const json& j, const std::string& key, const std::string& where, const std::string& origin) {
  const json& v = synthesis_member(j, key, where, origin);
  if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 10'000'000) {
    synthesis_fail(origin, where + "\"" + key + "\" is not a whole number in 0..10000000");
  }
  return v.get<int>();
}

std::vector<SynthesisPoint> synthesis_rows(const json& family, const std::string& key, const std::string& where,
                                 const std::string& origin) {
  const json& list = synthesis_member(family, key, where, origin);
  if (!list.is_array()) synthesis_fail(origin, where + "\"" + key + "\" is not a list");
  std::vector<SynthesisPoint> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = where + key + "[" + std::to_string(i) + "]: ";
    SynthesisPoint p;
    p.frac_bits = synthesis_count(list[i], "frac_bits", at, origin);
    if (p.frac_bits < 7 || p.frac_bits > 31) synthesis_fail(origin, at + "frac_bits " + std::to_string(p.frac_bits) + " is outside 7..31");
    p.luts = synthesis_count(list[i], "luts", at, origin);
    p.srls = synthesis_count(list[i], "srls", at, origin);
    p.flip_flops = synthesis_count(list[i], "flip_flops", at, origin);
    p.block_multipliers = synthesis_count(list[i], "block_multipliers", at, origin);
    out.push_back(p);
  }
  std::sort(out.begin(), out.end(), [](const SynthesisPoint& a, const SynthesisPoint& b) { return a.frac_bits < b.frac_bits; });
  for (std::size_t i = 1; i < out.size(); ++i) {
    if (out[i].frac_bits == out[i - 1].frac_bits) synthesis_fail(origin, where + key + ": width " + std::to_string(out[i].frac_bits) + " twice");
  }
  return out;
}

}  // namespace

SynthesisTable parse_synthesis_table(const std::string& text_in, const std::string& origin) {
  json j;
  try {
    j = io::parse_json_text(text_in, origin);  // depth, duplicate keys, comments, UTF-8 (io/json_text.h)
  } catch (const io::InputFileError& e) {
    throw std::runtime_error(e.what());
  }
  SynthesisTable t;
  t.synthesizer = synthesis_text(j, "synthesizer", "", origin);
  t.command = synthesis_text(j, "command", "", origin);
  t.source = synthesis_text(j, "source", "", origin);
  const json& families = synthesis_member(j, "families", "", origin);
  if (!families.is_array() || families.empty()) synthesis_fail(origin, "\"families\" is not a non-empty list");
  for (std::size_t i = 0; i < families.size(); ++i) {
    const std::string at = "families[" + std::to_string(i) + "].";
    SynthesisFamily f;
    f.family = synthesis_text(families[i], "family", at, origin);
    f.part_prefix = synthesis_text(families[i], "part_prefix", at, origin);
    f.block = synthesis_rows(families[i], "block", at, origin);
    f.array = synthesis_rows(families[i], "array", at, origin);
    if (f.block.empty() && f.array.empty()) synthesis_fail(origin, at + "no synthesis rows");
    t.families.push_back(std::move(f));
  }
  return t;
}

SynthesisTable read_synthesis_table(const std::string& path) {
  try {
    return parse_synthesis_table(io::read_file(path, io::kProfileLimitBytes, "the synthesis resources"), path);
  } catch (const io::InputFileError& e) {
    throw std::runtime_error(e.what());
  }
}

}  // namespace rc::profiles
