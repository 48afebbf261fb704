// Reads the profile files of configs/ (devices, hosts): every number is an object
// {"value": x, "source": "where it came from"}, and a missing, mistyped, out-of-range or unsourced
// number is an error that names the file and the field path (e.g. "xc2v6000.json: banks.clock_mhz:
// missing"). Also finds a profile by name in the source tree's configs/ folder.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/input_file.h"

namespace rc::board {

// The config folder: $RC2000SIM_CONFIGS (a command's --configs sets it), else configs/ of the source
// tree this library was built from (io/config_dir.h).
std::string default_config_dir();

// A path (contains '/' or ends in ".json") is returned unchanged; a bare name becomes
// <config dir>/<kind>/<name>.json ("devices", "hosts"). Throws std::invalid_argument if the file does
// not exist, naming what was looked for.
std::string resolve_profile_path(const std::string& name_or_path, const std::string& kind);

// Parses a JSON file of at most `limit_bytes` (io/input_file.h; `what` names the kind of file in the
// error) through io/json_text.h (depth limit, duplicate keys, comments, UTF-8); throws
// std::invalid_argument with the file name on I/O, text or syntax errors.
nlohmann::ordered_json read_json_file(const std::string& path, std::uint64_t limit_bytes = io::kProfileLimitBytes,
                                      const std::string& what = "a profile");

// Every path a loader reads is remembered, so that refuse_unknown_keys() can refuse the keys it never
// read: a misspelt field ("banks.clock_mhzz") is an error, not a silent default.
class ProfileReader {
 public:
  ProfileReader(const nlohmann::ordered_json& root, std::string file) : root_(root), file_(std::move(file)) {}

  // A sourced number at a dotted path ("banks.clock_mhz"), checked to lie in [min, max] and, if
  // `integer`, to be a whole number.
  double number(const std::string& path, double min, double max, bool integer = false) const;
  std::uint64_t integer(const std::string& path, std::uint64_t min, std::uint64_t max) const;
  std::optional<double> optional_number(const std::string& path, double min, double max) const;
  std::string source(const std::string& path) const;  // the "source" string next to a number
  std::string text(const std::string& path) const;    // a plain string field
  // A sourced name {"value": "bank", "source": "..."} that must be one of `allowed`; returns its index.
  // Errors name the file, the field and the allowed names.
  std::size_t choice(const std::string& path, const std::vector<std::string>& allowed) const;
  bool has(const std::string& path) const { return find(path) != nullptr; }
  const nlohmann::ordered_json* find(const std::string& path) const;

  // The profile's "schema" string, when present, must be `expected` ("rc2000sim.device/1").
  void schema(const std::string& expected) const;
  // Throws (naming the file, the key and the keys read beside it) for any key the loader has not read:
  // outside a sourced field, or inside one beyond "value" and "source". Subtrees under `free_form`
  // paths (a description, a calibration record) are not checked. Call after reading everything.
  void refuse_unknown_keys(const std::vector<std::string>& free_form) const;

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const;
  // "<file>: <path> = <value> <problem>", for a value outside a limit the model derives
  // ("banks.capacity_bytes = 16 is smaller than one face record ...").
  [[noreturn]] void refuse(const std::string& path, const std::string& value, const std::string& problem) const;
  const std::string& file() const { return file_; }

 private:
  const nlohmann::ordered_json& sourced(const std::string& path) const;
  bool was_read(const std::string& path) const { return read_.count(path) > 0; }
  void check_known(const nlohmann::ordered_json& node, const std::string& path,
                   const std::vector<std::string>& free_form) const;

  const nlohmann::ordered_json& root_;
  std::string file_;
  mutable std::set<std::string> read_;  // every path looked up
};

}  // namespace rc::board
