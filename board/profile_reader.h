// Reads the profile files of configs/ (devices, hosts): every number is an object
// {"value": x, "source": "where it came from"}, and a missing, mistyped, out-of-range or unsourced
// number is an error that names the file and the field path (e.g. "xc2v6000.json: banks.clock_mhz:
// missing"). Also finds a profile by name in the source tree's configs/ folder.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rc::board {

// configs/ of the source tree this library was built from.
std::string default_config_dir();

// A path (contains '/' or ends in ".json") is returned unchanged; a bare name becomes
// <config dir>/<kind>/<name>.json ("devices", "hosts"). Throws std::invalid_argument if the file does
// not exist, naming what was looked for.
std::string resolve_profile_path(const std::string& name_or_path, const std::string& kind);

// Parses a JSON file; throws std::invalid_argument with the file name on I/O or syntax errors.
nlohmann::ordered_json read_json_file(const std::string& path);

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

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const;
  const std::string& file() const { return file_; }

 private:
  const nlohmann::ordered_json& sourced(const std::string& path) const;

  const nlohmann::ordered_json& root_;
  std::string file_;
};

}  // namespace rc::board
