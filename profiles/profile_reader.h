// The one field-checking dialect of the profile files of configs/ (devices, hosts, energy sections):
// every number is an object {"value": x, "source": "where it came from"}, and a missing, mistyped,
// out-of-range or unsourced number is an error that names the file and the field path (e.g.
// "xc2v6000.json: banks.clock_mhz: missing"). Reads a ProfileDocument (profile_document.h) into the
// typed values the models take; no JSON crosses this header.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "profiles/profile_document.h"

namespace rc::profiles {

// Every path a loader reads is remembered, so that refuse_unknown_keys() can refuse the keys it never
// read: a misspelt field ("banks.clock_mhzz") is an error, not a silent default.
class ProfileReader {
 public:
  ProfileReader(const ProfileDocument& document, std::string file) : document_(document), file_(std::move(file)) {}

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
  bool has(const std::string& path) const;
  // The keys of the object at `path`, in file order; fails with `problem` if it is not an object.
  std::vector<std::string> keys(const std::string& path, const std::string& problem) const;

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
  friend struct ReaderAccess;  // profile_reader.cpp: the lookups on the document's tree
  bool was_read(const std::string& path) const { return read_.count(path) > 0; }

  const ProfileDocument& document_;
  std::string file_;
  mutable std::set<std::string> read_;  // every path looked up
};

}  // namespace rc::profiles
