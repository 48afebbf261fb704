// rc2000tlm.design(): the options of `rc2000sim design` by their snake_case names, applied to the
// search's own options (host_sw/studies/design_options.h: their defaults, checks and resolution, the
// command line's too), the search run, and design.json's document returned (host_sw/studies/
// design_json.h, the writer the command uses). Only the options given are applied and checked, as on
// the command line; an option that is not one of the command's is a TypeError naming it.
#include "design_module_json.h"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "host_sw/radiosity/jobs.h"
#include "io/config_dir.h"
#include "io/input_file.h"
#include "host_sw/studies/design_json.h"
#include "host_sw/studies/design_options.h"
#include "host_sw/studies/paper_workload.h"
#include "profiles/profile_json.h"

namespace rc {

namespace {

using nlohmann::ordered_json;

std::string flag(const std::string& name) {
  std::string f = "--" + name;
  for (char& c : f) c = c == '_' ? '-' : c;
  return f;
}

[[noreturn]] void wrong_type(const std::string& name, const ordered_json& v, const char* expected) {
  throw std::invalid_argument(flag(name) + ": expected " + expected + ", got " + v.dump());
}

long long whole(const std::string& name, const ordered_json& v) {
  if (v.is_number_integer()) {
    if (v.is_number_unsigned() && v.get<unsigned long long>() > static_cast<unsigned long long>(std::numeric_limits<long long>::max()))
      wrong_type(name, v, "a whole number below 2^63");
    return v.get<long long>();
  }
  wrong_type(name, v, "a whole number");
}

double real(const std::string& name, const ordered_json& v) {
  if (v.is_number()) return v.get<double>();
  if (v.is_string()) {  // JSON has no NaN or infinity: the Python side sends them as text, to be refused by name
    const std::string t = v.get<std::string>();
    if (t == "nan" || t == "inf" || t == "-inf") return std::stod(t);
  }
  wrong_type(name, v, "a number");
}

std::string text(const std::string& name, const ordered_json& v) {
  if (!v.is_string()) wrong_type(name, v, "text");
  return v.get<std::string>();
}

// An axis as the command line spells it ("1-4", "bank,on_chip"); one number stands for itself and, for
// --concurrent, true and false for on and off (the Python side joins a list into the text).
std::string axis_text(const std::string& name, const ordered_json& v) {
  if (v.is_number_integer()) return std::to_string(whole(name, v));
  if (v.is_number_float()) {
    char t[32];
    std::snprintf(t, sizeof t, "%.17g", v.get<double>());
    return t;
  }
  if (v.is_boolean() && name == "concurrent") return v.get<bool>() ? "on" : "off";
  return text(name, v);
}

bool yes_no(const std::string& name, const ordered_json& v) {
  if (!v.is_boolean()) wrong_type(name, v, "true or false");
  return v.get<bool>();
}

// One option: how a value given applies (checked as the command line checks it) and the default it
// shows (null: the command's rule, which the option's help says).
struct Option {
  const char* name;
  std::function<void(DesignOptions&, const ordered_json&)> apply;
  std::function<ordered_json(const DesignOptions&)> shown;
};

ordered_json or_null(const std::string& s) { return s.empty() ? ordered_json() : ordered_json(s); }
ordered_json positive_or_null(double v) { return std::isfinite(v) && v > 0 ? ordered_json(v) : ordered_json(); }

#define RC_TEXT_AXIS(field) \
  {#field, [](DesignOptions& o, const ordered_json& v) { check_design_axis(flag(#field), o.field = axis_text(#field, v)); }, \
   [](const DesignOptions& o) { return or_null(o.field); }}

const std::vector<Option>& options() {
  static const std::vector<Option> table = {
      {"scene", [](DesignOptions& o, const ordered_json& v) { check_scene_file(o.workload.scene.file = text("scene", v)); },
       [](const DesignOptions& o) { return or_null(o.workload.scene.file); }},
      {"faces", [](DesignOptions& o, const ordered_json& v) {
         const long long n = whole("faces", v);
         check_scene_option("--faces", n);
         o.workload.scene.face_target = static_cast<int>(n);
       }, [](const DesignOptions& o) { return o.workload.scene.face_target > 0 ? ordered_json(o.workload.scene.face_target) : ordered_json(); }},
      {"face_levels", [](DesignOptions& o, const ordered_json& v) {
         const long long n = whole("face_levels", v);
         check_scene_option("--face-levels", n);
         o.workload.scene.face_levels = static_cast<int>(n);
       }, [](const DesignOptions& o) { return ordered_json(o.workload.scene.face_levels); }},
      {"patch_levels", [](DesignOptions& o, const ordered_json& v) {
         const long long n = whole("patch_levels", v);
         check_scene_option("--patch-levels", n);
         o.workload.scene.patch_levels = static_cast<int>(n);
       }, [](const DesignOptions& o) { return ordered_json(o.workload.scene.patch_levels); }},
      {"patch_size", [](DesignOptions& o, const ordered_json& v) { check_patch_size(o.workload.scene.patch_size = real("patch_size", v)); },
       [](const DesignOptions& o) { return positive_or_null(o.workload.scene.patch_size); }},
      {"steps", [](DesignOptions& o, const ordered_json& v) { o.workload.steps = design_steps(whole("steps", v)); },
       [](const DesignOptions& o) {
         return o.workload.steps.kind == StepsChoice::Kind::fixed ? ordered_json(o.workload.steps.steps) : ordered_json();
       }},
      {"culled", [](DesignOptions& o, const ordered_json& v) { o.culled = yes_no("culled", v); },
       [](const DesignOptions& o) { return ordered_json(o.culled); }},
      {"form_factor", [](DesignOptions& o, const ordered_json& v) { o.workload.form_factor = design_form_factor(text("form_factor", v)); },
       [](const DesignOptions& o) { return ordered_json(to_string(o.workload.form_factor)); }},
      {"device", [](DesignOptions& o, const ordered_json& v) { o.space.device = text("device", v); },
       [](const DesignOptions& o) { return ordered_json(o.space.device); }},
      {"host", [](DesignOptions& o, const ordered_json& v) { o.space.host = text("host", v); },
       [](const DesignOptions& o) { return ordered_json(o.space.host); }},
      RC_TEXT_AXIS(lanes), RC_TEXT_AXIS(banks), RC_TEXT_AXIS(bank_clocks), RC_TEXT_AXIS(results), RC_TEXT_AXIS(bits),
      RC_TEXT_AXIS(multipliers),
      {"resources", [](DesignOptions& o, const ordered_json& v) {
         o.space.resources = parse_choice_option<pipeline::ResourceSource>("--resources", text("resources", v));
       }, [](const DesignOptions& o) { return ordered_json(choice_name(o.space.resources)); }},
      RC_TEXT_AXIS(cards), RC_TEXT_AXIS(concurrent),
      {"ray_split", [](DesignOptions& o, const ordered_json& v) {
         const std::string rule = text("ray_split", v);
         if (rule != "limit" && rule != "nominal")  // the command line's IsMember check, in its words
           throw std::invalid_argument("--ray-split: " + rule + " not in {limit,nominal}");
         o.space.ray_split = board::parse_ray_split(rule);
       }, [](const DesignOptions& o) { return ordered_json(o.space.ray_split == board::RaySplitRule::limit ? "limit" : "nominal"); }},
      RC_TEXT_AXIS(offset_lsb), RC_TEXT_AXIS(neighbour_rings),
      RC_TEXT_AXIS(coordinate_bits),
      {"max_banks", [](DesignOptions& o, const ordered_json& v) {
         const long long n = whole("max_banks", v);
         check_design_max_banks(n);
         o.constraints.max_banks = static_cast<unsigned>(n);
       }, [](const DesignOptions& o) { return o.constraints.max_banks ? ordered_json(o.constraints.max_banks) : ordered_json(); }},
      {"min_bits", [](DesignOptions& o, const ordered_json& v) {
         const long long n = whole("min_bits", v);
         check_design_min_bits(n);
         o.constraints.min_bits = static_cast<int>(n);
       }, [](const DesignOptions& o) { return ordered_json(o.constraints.min_bits); }},
      {"max_energy", [](DesignOptions& o, const ordered_json& v) { check_design_cap("--max-energy", o.constraints.max_energy_joules = real("max_energy", v)); },
       [](const DesignOptions& o) { return positive_or_null(o.constraints.max_energy_joules); }},
      {"max_power", [](DesignOptions& o, const ordered_json& v) { check_design_cap("--max-power", o.constraints.max_watts = real("max_power", v)); },
       [](const DesignOptions& o) { return positive_or_null(o.constraints.max_watts); }},
      {"max_error", [](DesignOptions& o, const ordered_json& v) { check_design_cap("--max-error", o.constraints.max_error = real("max_error", v)); },
       [](const DesignOptions& o) { return positive_or_null(o.constraints.max_error); }},
      {"max_error_max", [](DesignOptions& o, const ordered_json& v) {
         check_design_cap("--max-error-max", o.constraints.max_error_max = real("max_error_max", v));
       }, [](const DesignOptions& o) { return positive_or_null(o.constraints.max_error_max); }},
      {"fidelity", [](DesignOptions& o, const ordered_json& v) {
         o.fidelity = v.is_boolean() ? (v.get<bool>() ? "on" : "off") : text("fidelity", v);
       }, [](const DesignOptions& o) { return ordered_json(o.fidelity); }},
      {"exhaustive", [](DesignOptions& o, const ordered_json& v) { o.exhaustive = yes_no("exhaustive", v); },
       [](const DesignOptions& o) { return ordered_json(o.exhaustive); }},
      // The folder of config files (io/config_dir.h), as every command's --configs; the process's own.
      {"configs", [](DesignOptions&, const ordered_json& v) {
         try {
           io::use_config_dir(text("configs", v));
         } catch (const io::InputFileError& e) {
           throw std::invalid_argument(std::string("--configs ") + e.what());  // the command line's words
         }
       }, [](const DesignOptions&) { return ordered_json(); }},
      // The process's job count, not a search option (host_sw/radiosity/jobs.h: the command line's --jobs,
      // its check and message); each call is a process of its own. Default: the rule's (null).
      {"jobs", [](DesignOptions&, const ordered_json& v) { set_jobs(whole("jobs", v), "--jobs"); },
       [](const DesignOptions&) { return ordered_json(); }},
  };
  return table;
}

#undef RC_TEXT_AXIS

std::string names() {
  std::string all;
  for (const Option& opt : options()) all += (all.empty() ? "" : ", ") + std::string(opt.name);
  return all;
}

DesignOptions given_options(const ordered_json& given) {
  if (!given.is_object()) throw std::invalid_argument("rc2000tlm.design: the options must be a JSON object");
  // The command line refuses both (CLI11's excludes, --patch-levels defined first): the same words.
  if (given.contains("patch_levels") && given.contains("patch_size"))
    throw std::invalid_argument("--patch-levels excludes --patch-size");
  DesignOptions o;
  for (const auto& item : given.items()) {
    const std::string& name = item.key();  // not a structured binding: C++17 lambdas cannot capture one (clang refuses)
    const auto& table = options();
    const auto opt = std::find_if(table.begin(), table.end(), [&](const Option& x) { return name == x.name; });
    if (opt == table.end())
      throw pybind11::type_error("rc2000tlm.design() got an unexpected keyword argument '" + name +
                                 "' (the options of `rc2000sim design`: " + names() + ")");
    opt->apply(o, item.value());
  }
  // A scene file as it is, solved with run's form factor, unless told otherwise (the command's rule).
  const std::map<std::string, const char*> keys = {{"--faces", "faces"}, {"--face-levels", "face_levels"}, {"--patch-levels", "patch_levels"}};
  take_scene_as_given(o.workload.scene, [&](const std::string& option) { return given.contains(keys.at(option)); });
  if (!o.workload.scene.file.empty() && !given.contains("form_factor")) o.workload.form_factor = kSceneFileFormFactor;
  resolve_design_options(o);
  return o;
}

}  // namespace

std::string design_defaults() {
  const DesignOptions o;
  ordered_json out;
  for (const Option& opt : options()) out[opt.name] = opt.shown(o);
  return out.dump();
}

std::string design_search(const std::string& options_json, bool progress) {
  const DesignOptions o = given_options(ordered_json::parse(options_json));
  (void)jobs();  // without jobs=, a bad RC2000SIM_JOBS is refused here, before any work
  const DesignSearchResult r = search_designs(o.workload, o.visibility, o.space, o.constraints, o.exhaustive, [&](const std::string& what) {
    if (progress) std::fprintf(stderr, "\r%-78s", what.c_str());
  });
  if (progress) std::fprintf(stderr, "\r%-78s\r", "");
  const Roofline roofline = design_roofline(r, measured_peak_software_rate(default_paper_table()));
  const DesignDocument doc{r, o.space, o.constraints, roofline, "", "rc2000tlm.design()"};
  ordered_json out;
  out["design"] = design_json(doc);
  // The run command names the files of a command's output folder; a call writes none.
  if (out["design"]["best"].is_object()) out["design"]["best"].erase("run_command");
  out["best_device"] = r.best ? profiles::json_of(r.points[*r.best].profile.document) : ordered_json();
  return out.dump();
}

}  // namespace rc
