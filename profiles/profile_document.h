// A profile file (configs/devices, configs/hosts, calibrated profiles) as the profile-reading edge
// holds it: the document as written, sources included, in file order. The models never see its
// text: they read their typed values from it once, through ProfileReader (profile_reader.h), and
// reports copy it whole through the edge's writer (profile_json.h). A study's setting of a field by
// its dotted path is applied here, on the document, before the model's loader reads it again.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace rc::profiles {

// A value a study or a variant writes into a sourced field: a whole number, a number or a name
// (a whole number stays one in the document: 133, not 133.0).
using FieldValue = std::variant<std::int64_t, double, std::string>;

class ProfileDocument {
 public:
  struct Tree;  // the parsed file (profile_json.h)

  ProfileDocument();  // an empty document
  explicit ProfileDocument(std::shared_ptr<const Tree> tree) : tree_(std::move(tree)) {}

  // Every sourced field ({"value", "source"}), as dotted paths in file order.
  std::vector<std::string> sourced_fields() const;
  bool is_sourced(const std::string& path) const;
  bool holds_number(const std::string& path) const;  // a sourced field whose value is a number
  // The top-level keys, in file order.
  std::vector<std::string> top_keys() const;
  // The same document with `path`'s {"value", "source"} set (the field need not exist yet; objects on
  // the way are made).
  ProfileDocument with_field(const std::string& path, const FieldValue& value, const std::string& source) const;
  // The value's text as JSON writes it ("133", "\"bank\""), for messages.
  std::string value_text(const std::string& path) const;

  bool operator==(const ProfileDocument& other) const;
  bool operator!=(const ProfileDocument& other) const { return !(*this == other); }
  const Tree& tree() const { return *tree_; }

 private:
  std::shared_ptr<const Tree> tree_;
};

// Where profiles are found by name: io::config_dir() (RC2000SIM_CONFIGS, else this source tree's
// configs/, else the installed share folder; io/config_dir.h).
std::string default_config_dir();

// A path (contains '/' or ends in ".json") is returned unchanged; a bare name becomes
// <config dir>/<kind>/<name>.json ("devices", "hosts"). Throws std::invalid_argument if the file does
// not exist, naming what was looked for.
std::string resolve_profile_path(const std::string& name_or_path, const std::string& kind);

// Reads and parses a profile file of at most `limit_bytes` (io/input_file.h; `what` names the kind of
// file in errors) through io/json_text.h (depth, duplicate keys, comments, UTF-8); throws
// std::invalid_argument with the file name on I/O, text or syntax errors.
ProfileDocument read_profile_document(const std::string& path, const std::string& what = "a profile");

}  // namespace rc::profiles
