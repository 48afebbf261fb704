#include "profiles/resource_table.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/input_file.h"
#include "io/json_text.h"

namespace rc::profiles {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& origin, const std::string& what) {
  throw std::runtime_error("pipeline resources " + origin + ": " + what);
}

const json& field(const json& j, const char* key, const std::string& origin) {
  if (!j.is_object() || !j.contains(key)) fail(origin, std::string("missing \"") + key + "\"");
  return j.at(key);
}

double number(const json& j, const char* key, const std::string& origin) {
  const json& v = field(j, key, origin);
  if (!v.is_number()) fail(origin, std::string("\"") + key + "\" is not a number");
  return v.get<double>();
}

int integer(const json& j, const char* key, const std::string& origin) {
  const json& v = field(j, key, origin);
  if (!v.is_number_integer()) fail(origin, std::string("\"") + key + "\" is not an integer");
  return v.get<int>();
}

std::string text(const json& j, const char* key, const std::string& origin) {
  const json& v = field(j, key, origin);
  if (!v.is_string()) fail(origin, std::string("\"") + key + "\" is not a string");
  return v.get<std::string>();
}

bool flag(const json& j, const char* key, const std::string& origin) {
  const json& v = field(j, key, origin);
  if (!v.is_boolean()) fail(origin, std::string("\"") + key + "\" is not true or false");
  return v.get<bool>();
}

// Every figure must say where it comes from.
std::string source_of(const json& j, const std::string& origin) {
  const json& s = field(j, "source", origin);
  if (!s.is_string() || s.get<std::string>().empty()) fail(origin, "empty \"source\"");
  return s.get<std::string>();
}

const json& list(const json& j, const char* key, const std::string& origin) {
  const json& v = field(j, key, origin);
  if (!v.is_array()) fail(origin, std::string("\"") + key + "\" is not a list");
  return v;
}

std::vector<ResourcePoint> points(const json& j, const char* key, bool with_blocks, const std::string& origin) {
  std::vector<ResourcePoint> out;
  for (const json& p : list(j, key, origin)) {
    ResourcePoint r;
    r.source = source_of(p, origin);
    r.frac_bits = integer(p, "frac_bits", origin);
    r.clock_mhz = number(p, "clock_mhz", origin);
    r.slices = number(p, "slices", origin);
    if (with_blocks) r.block_multipliers = integer(p, "block_multipliers", origin);
    out.push_back(r);
  }
  return out;
}

SourcedCount sourced_count(const json& fp, const char* key, const std::string& origin) {
  const json& v = field(fp, key, origin);
  SourcedCount c;
  c.source = source_of(v, origin);
  c.value = integer(v, "value", origin);
  if (c.value < 0) fail(origin, std::string("float_pipeline.") + key + " is negative");
  return c;
}

}  // namespace

ResourceTable parse_resource_table(const std::string& text_in, const std::string& origin) {
  json j;
  try {
    j = io::parse_json_text(text_in, origin);  // depth, duplicate keys, comments, UTF-8 (io/json_text.h)
  } catch (const io::InputFileError& e) {
    throw std::runtime_error(e.what());
  }
  ResourceTable t;
  const json& device = field(j, "device", origin);
  t.device_source = source_of(device, origin);
  t.device_name = text(device, "name", origin);
  t.device_slices = integer(device, "slices", origin);
  t.device_block_multipliers = integer(device, "block_multipliers", origin);
  const json& block = field(j, "block_multiplier", origin);
  t.block_source = source_of(block, origin);
  t.block_operand_bits = integer(block, "operand_bits", origin);
  const json& limit = field(j, "block_multiplier_synthesis_limit", origin);
  t.synthesis_limit_source = source_of(limit, origin);
  t.synthesis_limit_bits = integer(limit, "max_frac_bits", origin);
  t.soft = points(j, "pipeline_without_block_multipliers", false, origin);
  t.hard = points(j, "pipeline_with_block_multipliers", true, origin);
  for (const json& d : list(j, "designs", origin)) {
    ResourceDesign r;
    r.source = source_of(d, origin);
    r.lanes = integer(d, "lanes", origin);
    if (r.lanes == 1 || r.lanes == 2) {  // the two the wrapper model is solved from
      r.frac_bits = integer(d, "frac_bits", origin);
      r.block_multipliers_used = flag(d, "block_multipliers_used", origin);
      r.slices = integer(d, "slices", origin);
      r.block_multipliers = integer(d, "block_multipliers", origin);
      r.clock_mhz = number(d, "clock_mhz", origin);
    }
    t.designs.push_back(r);
  }
  const json& fp = field(j, "float_pipeline", origin);
  t.multipliers = sourced_count(fp, "multipliers", origin);
  t.sign_flips = sourced_count(fp, "sign_flips", origin);
  t.add_subs = sourced_count(fp, "add_subs", origin);
  t.comparators = sourced_count(fp, "comparators", origin);
  t.guard_bits = sourced_count(fp, "guard_bits", origin);
  t.luts_per_slice = sourced_count(fp, "luts_per_slice", origin);
  t.flip_flops_per_slice = sourced_count(fp, "flip_flops_per_slice", origin);
  for (const json& f : list(fp, "families", origin)) {
    FloatFamilyRow r;
    r.source = source_of(f, origin);
    r.name = text(f, "name", origin);
    r.part_prefix = text(f, "part_prefix", origin);
    r.block_multiplier = text(f, "block_multiplier", origin);
    r.operand_bits = integer(f, "operand_bits", origin);
    t.families.push_back(r);
  }
  return t;
}

ResourceTable read_resource_table(const std::string& path) {
  try {
    return parse_resource_table(io::read_file(path, io::kProfileLimitBytes, "the pipeline resources"), path);
  } catch (const io::InputFileError& e) {
    throw std::runtime_error(e.what());
  }
}

}  // namespace rc::profiles
