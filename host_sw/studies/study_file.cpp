#include "host_sw/studies/study_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>

#include <toml++/toml.h>

#include "io/input_file.h"
#include "io/toml_text.h"

#include "host_sw/studies/paper_workload.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {

namespace {

// Errors name the file, the line and the key.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const toml::node& node, const std::string& key, const std::string& problem) const {
    throw std::invalid_argument(file_ + ":" + std::to_string(node.source().begin.line) + ": " + key + ": " + problem);
  }

  // For messages that already name the key (parse_int_list and friends name their option).
  [[noreturn]] void fail_with(const toml::node& node, const std::string& message) const {
    throw std::invalid_argument(file_ + ":" + std::to_string(node.source().begin.line) + ": " + message);
  }

  // Every key of `table` must be one of `known`.
  void only(const toml::table& table, const std::string& prefix, std::initializer_list<const char*> known) const {
    for (auto&& [key, node] : table) {
      const std::string name(key.str());
      if (std::find_if(known.begin(), known.end(), [&](const char* k) { return name == k; }) != known.end()) continue;
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(node, prefix + name, "unknown key (expected one of: " + list + ")");
    }
  }

  std::string text(const toml::node& node, const std::string& key) const {
    if (!node.is_string()) fail(node, key, "expected a string");
    return *node.value<std::string>();
  }
  bool boolean(const toml::node& node, const std::string& key) const {
    if (!node.is_boolean()) fail(node, key, "expected true or false");
    return *node.value<bool>();
  }
  double number(const toml::node& node, const std::string& key) const {
    if (!node.is_number()) fail(node, key, "expected a number");
    const double x = *node.value<double>();
    if (!std::isfinite(x)) fail(node, key, "expected a finite number");
    return x;
  }
  int integer(const toml::node& node, const std::string& key, int min, int max) const {
    if (!node.is_integer()) fail(node, key, "expected a whole number");
    const std::int64_t x = *node.value<std::int64_t>();
    if (x < min || x > max) fail(node, key, std::to_string(x) + " is outside " + std::to_string(min) + ".." + std::to_string(max));
    return static_cast<int>(x);
  }
  // A number or a name with the TOML node's type (integers stay integers).
  profiles::FieldValue value(const toml::node& node, const std::string& key) const {
    if (node.is_integer()) return *node.value<std::int64_t>();
    if (node.is_floating_point()) return number(node, key);
    if (node.is_string()) return *node.value<std::string>();
    fail(node, key, "expected a number or a name");
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

bool is_range_table(const toml::node& node) {
  const toml::table* t = node.as_table();
  return t && t->contains("from") && t->contains("to");
}

// {from, to, step}: from, from + step, ... up to `to` (each from + i step, not a running sum).
// Whole numbers stay whole.
std::vector<profiles::FieldValue> range_values(const Reader& r, const toml::table& t, const std::string& key) {
  r.only(t, key + ".", {"from", "to", "step"});
  const toml::node& from = *t.get("from");
  const toml::node& to = *t.get("to");
  const toml::node* step = t.get("step");
  const bool whole = from.is_integer() && to.is_integer() && (!step || step->is_integer());
  const double a = r.number(from, key + ".from"), b = r.number(to, key + ".to");
  const double d = step ? r.number(*step, key + ".step") : 1.0;
  if (!(d > 0)) r.fail(step ? *step : from, key + ".step", "must be positive");
  if (b < a) r.fail(to, key + ".to", "is below from");
  const double count = std::floor((b - a) / d + 1e-9) + 1;
  // Written so that an infinite count (a huge span over a tiny step) fails here before any cast.
  if (!(count <= 10000)) {
    r.fail(t, key, (std::isfinite(count) && count < 1e18 ? "spans " + std::to_string(static_cast<long long>(count))
                                                          : std::string("spans more than 10^18")) +
                       " values (at most 10000)");
  }
  std::vector<profiles::FieldValue> values;
  for (long long i = 0; i < static_cast<long long>(count); ++i) {
    const double x = a + static_cast<double>(i) * d;
    if (whole) {
      values.push_back(static_cast<std::int64_t>(std::llround(x)));
    } else {
      values.push_back(x);
    }
  }
  return values;
}

// A list of values: an array, a {from, to, step} table, or one value.
std::vector<profiles::FieldValue> values_of(const Reader& r, const toml::node& node, const std::string& key) {
  std::vector<profiles::FieldValue> values;
  if (is_range_table(node)) return range_values(r, *node.as_table(), key);
  if (const toml::array* a = node.as_array()) {
    if (a->empty()) r.fail(node, key, "empty list");
    for (const toml::node& item : *a) values.push_back(r.value(item, key));
  } else {
    values.push_back(r.value(node, key));
  }
  return values;
}

// Lanes, banks and widths: "1-4,8" as on the command line, a list, a {from, to, step} table or one
// number; ascending and distinct, as parse_int_list makes them.
std::vector<int> int_axis(const Reader& r, const toml::node& node, const std::string& key, int min, int max) {
  if (node.is_string()) {
    try {
      return parse_int_list(*node.value<std::string>(), key, min, max);
    } catch (const std::invalid_argument& e) {
      r.fail_with(node, e.what());
    }
  }
  std::vector<int> values;
  for (const profiles::FieldValue& v : values_of(r, node, key)) {
    if (!profiles::is_whole(v)) r.fail(node, key, "expected whole numbers, got " + profiles::json_text(v));
    const std::int64_t x = std::get<std::int64_t>(v);
    if (x < min || x > max) r.fail(node, key, std::to_string(x) + " is outside " + std::to_string(min) + ".." + std::to_string(max));
    values.push_back(static_cast<int>(x));
  }
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

std::vector<std::string> name_axis(const Reader& r, const toml::node& node, const std::string& key) {
  std::vector<std::string> names;
  if (node.is_string()) {
    try {
      return parse_name_list(*node.value<std::string>(), key);
    } catch (const std::invalid_argument& e) {
      r.fail_with(node, e.what());
    }
  }
  const toml::array* a = node.as_array();
  if (!a || a->empty()) r.fail(node, key, "expected a non-empty list of names");
  for (const toml::node& item : *a) {
    const std::string name = r.text(item, key);
    if (name.empty()) r.fail(item, key, "empty name");
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

// A list of names of one choice (io/choice.h): an unknown name is an error at its line.
template <class E>
std::vector<E> choice_axis(const Reader& r, const toml::node& node, const std::string& key) {
  const std::vector<std::string> names = name_axis(r, node, key);
  try {
    return parse_choices<E>(names);
  } catch (const std::invalid_argument& e) {
    r.fail(node, key, e.what());
  }
}

std::vector<bool> concurrency_axis(const Reader& r, const toml::node& node) {
  if (node.is_boolean()) return {*node.value<bool>()};
  const std::string text = r.text(node, "axes.concurrent");
  try {
    return parse_concurrency(text);
  } catch (const std::invalid_argument& e) {
    r.fail_with(node, "axes.concurrent: " + std::string(e.what()).substr(std::string("--concurrent: ").size()));
  }
}

std::string relative_to(const std::string& study_file, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute()) return path;
  return (std::filesystem::path(study_file).parent_path() / p).lexically_normal().string();
}

// A device or host named by a path (as board::resolve_profile_path tells a path from a name) lies,
// like a scene file, relative to the study file's folder; a bare name is a profile of configs/.
std::vector<std::string> profiles_relative_to(const std::string& study_file, std::vector<std::string> names) {
  for (std::string& n : names) {
    const bool is_path = n.find('/') != std::string::npos || (n.size() > 5 && n.compare(n.size() - 5, 5, ".json") == 0);
    if (is_path) n = relative_to(study_file, n);
  }
  return names;
}

StudyScene read_scene(const Reader& r, const toml::table& t, const std::string& key) {
  r.only(t, key + ".", {"name", "paper", "file", "faces", "face_levels", "patch_levels", "patch_size"});
  StudyScene s;
  if (const toml::node* paper = t.get("paper")) {
    const toml::table* p = paper->as_table();
    if (!p) r.fail(*paper, key + ".paper", "expected { faces = F, patches = P } (a Table 2 scene)");
    r.only(*p, key + ".paper.", {"faces", "patches"});
    for (const char* k : {"file", "faces", "face_levels", "patch_levels", "patch_size"})
      if (t.contains(k)) r.fail(*t.get(k), key + "." + k, "does not apply to a paper scene (paper sets the refinement)");
    if (!p->contains("faces") || !p->contains("patches")) r.fail(*paper, key + ".paper", "needs faces and patches");
    try {
      s.options = paper_scene_options(r.integer(*p->get("faces"), key + ".paper.faces", 1, 1 << 24),
                                      r.integer(*p->get("patches"), key + ".paper.patches", 1, 1 << 24));
    } catch (const std::invalid_argument& e) {
      r.fail(*paper, key + ".paper", e.what());
    }
  } else {
    if (const toml::node* f = t.get("file")) {
      s.source = r.text(*f, key + ".file");
      s.options.file = relative_to(r.file(), s.source);
    }
    if (const toml::node* n = t.get("faces")) s.options.face_target = r.integer(*n, key + ".faces", 0, 1 << 24);
    if (const toml::node* n = t.get("face_levels")) s.options.face_levels = r.integer(*n, key + ".face_levels", 0, 8);
    if (const toml::node* n = t.get("patch_levels")) s.options.patch_levels = r.integer(*n, key + ".patch_levels", 0, 8);
    if (const toml::node* n = t.get("patch_size")) {
      s.options.patch_size = r.number(*n, key + ".patch_size");
      if (!(s.options.patch_size > 0)) r.fail(*n, key + ".patch_size", "must be positive");
    }
  }
  s.name = t.contains("name") ? r.text(*t.get("name"), key + ".name") : default_scene_name(s.options);
  return s;
}

void read_scenes(const Reader& r, const toml::node& node, Study& s) {
  const toml::array* a = node.as_array();
  if (!a || a->empty()) r.fail(node, "scenes", "expected one or more [[scenes]] tables");
  s.scenes.clear();
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table* t = a->get(i)->as_table();
    const std::string key = "scenes[" + std::to_string(i) + "]";
    if (!t) r.fail(*a->get(i), key, "expected a table");
    s.scenes.push_back(read_scene(r, *t, key));
  }
}

void read_solver(const Reader& r, const toml::table& t, Study& s) {
  r.only(t, "solver.", {"steps", "convergence", "paper_faithful", "visibility", "full_banks", "form_factor"});
  if (const toml::node* n = t.get("steps")) {
    const std::string text =
        n->is_integer() ? std::to_string(r.integer(*n, "solver.steps", 1, 10000000)) : r.text(*n, "solver.steps");
    try {
      s.steps = parse_steps(text);
    } catch (const std::invalid_argument& e) {
      r.fail(*n, "solver.steps", e.what());
    }
  }
  if (const toml::node* n = t.get("convergence")) {
    s.convergence = r.number(*n, "solver.convergence");
    if (!(s.convergence > 0 && s.convergence < 1)) r.fail(*n, "solver.convergence", "must lie strictly between 0 and 1");
  }
  if (const toml::node* n = t.get("paper_faithful")) s.paper_faithful = r.boolean(*n, "solver.paper_faithful");
  if (const toml::node* n = t.get("visibility")) {
    try {
      s.visibility = parse_choice<BitExactVisibility>(r.text(*n, "solver.visibility"));
    } catch (const std::invalid_argument& e) {
      r.fail(*n, "solver.visibility", e.what());
    }
  }
  if (const toml::node* n = t.get("full_banks")) s.full_banks = r.boolean(*n, "solver.full_banks");
  if (const toml::node* n = t.get("form_factor")) {
    s.form_factor = r.text(*n, "solver.form_factor");
    try {
      (void)parse_form_factor_kind(s.form_factor);
    } catch (const std::invalid_argument& e) {
      r.fail(*n, "solver.form_factor", e.what());
    }
  }
}

// A profile path and where it was written: TOML tables are sorted by key, so the file's order
// (the order axes enumerate in) is recovered from the lines.
struct PathNode {
  std::string path;
  const toml::node* node;
};

// Dotted keys (banks.clock_mhz = ...) arrive as nested tables; quoted keys ("banks.clock_mhz") as one
// key. Both become the same paths. A {from, to} table is a range, not a level.
void collect_paths(const toml::table& t, const std::string& prefix, std::vector<PathNode>& out) {
  for (auto&& [key, node] : t) {
    const std::string path = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (node.is_table() && !is_range_table(node)) {
      collect_paths(*node.as_table(), path, out);
    } else {
      out.push_back({path, &node});
    }
  }
}

std::vector<PathNode> in_file_order(std::vector<PathNode> paths) {
  std::stable_sort(paths.begin(), paths.end(), [](const PathNode& a, const PathNode& b) {
    const auto& x = a.node->source().begin;
    const auto& y = b.node->source().begin;
    return x.line != y.line ? x.line < y.line : x.column < y.column;
  });
  return paths;
}

ProfileField resolve(const Reader& r, const PathNode& p, const std::string& key, const Study& s) {
  try {
    return resolve_study_field(p.path, s.axes.devices, s.axes.hosts);
  } catch (const std::invalid_argument& e) {
    r.fail(*p.node, key, e.what());
  }
}

// [axes] form_factors: every scene once per form factor (expand_form_factors). Excludes
// [solver] form_factor, the same choice fixed.
void read_form_factor_axis(const Reader& r, const toml::node& node, bool fixed_too, Study& s) {
  if (fixed_too) r.fail(node, "axes.form_factors", "excludes solver.form_factor (one form factor: write that alone)");
  const std::vector<std::string> names = name_axis(r, node, "axes.form_factors");
  try {
    expand_form_factors(s, names);
  } catch (const std::invalid_argument& e) {
    r.fail(node, "axes.form_factors", e.what());
  }
}

void read_axes(const Reader& r, const toml::table& t, Study& s, bool form_factor_fixed) {
  std::vector<PathNode> profile_paths;
  for (auto&& [key, node] : t) {
    const std::string name(key.str());
    const std::string k = "axes." + name;
    if (node.is_table() && !is_range_table(node)) {
      // A section of profile fields (banks.clock_mhz = ... written unquoted is the table "banks").
      collect_paths(*node.as_table(), name, profile_paths);
    } else if (name == "devices") {
      s.axes.devices = profiles_relative_to(r.file(), name_axis(r, node, k));
    } else if (name == "hosts") {
      s.axes.hosts = profiles_relative_to(r.file(), name_axis(r, node, k));
    } else if (name == "bits") {
      s.axes.bits = int_axis(r, node, k, 7, 31);
    } else if (name == "lanes") {
      s.axes.lanes = int_axis(r, node, k, board::LaneCount::kMin, board::LaneCount::kMax);
    } else if (name == "banks") {
      s.axes.banks = int_axis(r, node, k, 1, 255);
    } else if (name == "concurrent") {
      s.axes.concurrent = concurrency_axis(r, node);
    } else if (name == "cards") {
      s.axes.cards = int_axis(r, node, k, CardCount::kMin, CardCount::kMax);
    } else if (name == "card_split") {
      s.axes.card_splits = choice_axis<CardSplit>(r, node, k);
    } else if (name == "card_bus") {
      s.axes.card_buses = choice_axis<CardBus>(r, node, k);
    } else if (name == "form_factors") {
      read_form_factor_axis(r, node, form_factor_fixed, s);
    } else {
      profile_paths.push_back({name, &node});
    }
  }
  s.axes.profile.clear();
  for (const PathNode& p : in_file_order(profile_paths)) {
    const std::string key = "axes." + p.path;
    ProfileAxis axis{resolve(r, p, key, s), values_of(r, *p.node, key)};
    for (const profiles::FieldValue& v : axis.values) {
      try {
        check_setting_value(axis.field, v, "");  // r.fail names the file, line and key
      } catch (const std::invalid_argument& e) {
        r.fail(*p.node, key, e.what());
      }
    }
    s.axes.profile.push_back(axis);
  }
}

void read_fixed(const Reader& r, const toml::table& t, Study& s) {
  std::vector<PathNode> paths;
  collect_paths(t, "", paths);
  for (const PathNode& p : in_file_order(paths)) {
    const std::string key = "fixed." + p.path;
    ProfileSetting setting{resolve(r, p, key, s), r.value(*p.node, key)};
    try {
      check_setting_value(setting.field, setting.value, "");
    } catch (const std::invalid_argument& e) {
      r.fail(*p.node, key, e.what());
    }
    s.fixed.push_back(setting);
  }
}

const toml::table& table_at(const Reader& r, const toml::table& root, const char* key) {
  const toml::table* t = root.get(key)->as_table();
  if (!t) r.fail(*root.get(key), key, "expected a table ([" + std::string(key) + "])");
  return *t;
}

}  // namespace

Study default_study() {
  Study s = default_study_settings();
  s.scenes.front().name = default_scene_name(s.scenes.front().options);
  return s;
}

Study default_study_settings() {
  Study s;
  s.name = "default";
  s.scenes = {{"", paper_scene_options(280, 1120), "", ""}};
  s.axes.devices = {"xc2v6000", "virtex4-sx55", "spartan3-5000"};
  s.axes.bits = {15};
  s.axes.concurrent = {true};
  s.axes.hosts = {"athlon-mp-2600-calibrated"};
  for (int l = 1; l <= 16; ++l) s.axes.lanes.push_back(l);
  for (int b = 5; b <= 12; ++b) s.axes.banks.push_back(b);
  return s;
}

Study parse_study_text(const std::string& text, const std::string& path) {
  try {
    io::check_toml_text(text, path);  // UTF-8 and the length of dotted keys, which toml++ lacks
  } catch (const io::InputFileError& e) {
    throw std::invalid_argument(e.what());
  }
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const std::string what(e.description());
    const bool redefined = what.find("redefine") != std::string::npos;
    throw std::invalid_argument(path + ":" + std::to_string(e.source().begin.line) + ": not valid TOML: " + what +
                                (redefined ? " (a profile path that starts like another key, such as banks.clock_mhz "
                                             "beside banks, must be quoted: \"banks.clock_mhz\" = ...)"
                                           : ""));
  }
  const Reader r(path);
  r.only(root, "", {"name", "description", "resources", "ray_split", "scenes", "solver", "axes", "fixed"});
  Study s = default_study();
  s.file = path;
  s.name = std::filesystem::path(path).stem().string();
  if (const toml::node* n = root.get("name")) s.name = r.text(*n, "name");
  if (const toml::node* n = root.get("description")) s.description = r.text(*n, "description");
  if (const toml::node* n = root.get("resources")) {
    try {
      s.resources = parse_choice<pipeline::ResourceSource>(r.text(*n, "resources"));
    } catch (const std::invalid_argument& e) {
      r.fail(*n, "resources", e.what());
    }
  }
  if (const toml::node* n = root.get("ray_split")) {
    try {
      s.ray_split = board::parse_ray_split(r.text(*n, "ray_split"));
    } catch (const std::invalid_argument& e) {
      r.fail(*n, "ray_split", e.what());
    }
  }
  if (root.contains("scenes")) read_scenes(r, *root.get("scenes"), s);
  if (root.contains("solver")) read_solver(r, table_at(r, root, "solver"), s);
  // Axes before fixed settings: profile paths resolve against the devices and hosts swept.
  if (root.contains("axes")) {
    const bool form_factor_fixed = root.contains("solver") && table_at(r, root, "solver").contains("form_factor");
    read_axes(r, table_at(r, root, "axes"), s, form_factor_fixed);
  }
  if (root.contains("fixed")) read_fixed(r, table_at(r, root, "fixed"), s);
  check_study(s);
  return s;
}

Study load_study_file(const std::string& path) {
  try {
    return parse_study_text(io::read_file(path, kMaxStudyFileBytes, "a study file"), path);
  } catch (const io::InputFileError& e) {
    throw std::invalid_argument(e.what());
  }
}

}  // namespace rc
