#include "host_sw/studies/design_options.h"

#include "host_sw/radiosity/segment_fix_names.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <utility>

#include "board/lane_count.h"
#include "host_sw/platform/card_options.h"
#include "host_sw/radiosity/form_factor.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/studies/sweep_options.h"

namespace rc {

namespace {

template <class T, class Name>
std::string joined_names(const std::vector<T>& values, Name name) {
  std::string text;
  for (const T& v : values) text += (text.empty() ? "" : ",") + name(v);
  return text;
}

std::string concurrency_text(const std::vector<bool>& c) {
  if (c.size() == 2 && !c[0] && c[1]) return "both";
  if (c.size() == 1) return c[0] ? "on" : "off";
  throw std::logic_error("DesignSpace::concurrent: not one of on, off, both");
}

// The words of the command line's range check (CLI11's Range), so both front ends say the same.
[[noreturn]] void out_of_range(const std::string& option, long long value, long long min, long long max) {
  throw std::invalid_argument(option + ": Value " + std::to_string(value) + " not in range " + std::to_string(min) +
                              " to " + std::to_string(max));
}

void check_range(const std::string& option, long long value, long long min, long long max) {
  if (value < min || value > max) out_of_range(option, value, min, max);
}

std::string readable(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

// As the command line's positive_finite check words it.
void check_positive_finite(const std::string& option, double value) {
  if (!std::isfinite(value)) throw std::invalid_argument(option + ": '" + readable(value) + "' is not a finite number");
  if (!(value > 0)) throw std::invalid_argument(option + ": " + readable(value) + " must be positive");
}

std::vector<double> parse_clocks(const std::string& text) {
  std::vector<double> clocks;
  for (const std::string& item : parse_name_list(text, "--bank-clocks")) {
    std::size_t used = 0;
    double mhz = 0;
    try {
      mhz = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !std::isfinite(mhz) || mhz <= 0)
      throw std::invalid_argument("--bank-clocks: '" + item + "' is not a clock in MHz above 0");
    clocks.push_back(mhz);
  }
  return clocks;
}

std::vector<board::ResultStore> parse_results(const std::string& text) {
  std::vector<board::ResultStore> results;
  for (const std::string& r : parse_name_list(text, "--results")) {
    if (r == "bank") results.push_back(board::ResultStore::bank);
    else if (r == "on_chip") results.push_back(board::ResultStore::on_chip);
    else throw std::invalid_argument("--results: '" + r + "' is not one of bank, on_chip");
  }
  return results;
}

}  // namespace

DesignOptions::DesignOptions()
    : results(joined_names(space.results, [](board::ResultStore r) { return std::string(board::to_string(r)); })),
      bits(joined_names(space.bits, [](int b) { return std::to_string(b); })),
      multipliers(joined_names(space.multipliers, [](Multipliers m) { return std::string(to_string(m)); })),
      cards(joined_names(space.cards, [](int c) { return std::to_string(c); })),
      concurrent(concurrency_text(space.concurrent)),
      offset_lsb(joined_names(space.offset_lsb, [](int k) { return std::to_string(k); })),
      neighbour_rings(joined_names(space.neighbour_rings, [](int r) { return std::to_string(r); })),
      coordinate_bits(joined_names(space.coordinate_bits, [](int c) { return std::to_string(c); })) {}

void check_design_steps(long long steps) { check_range("--steps", steps, 1, SolverOptions{}.max_steps); }

StepsChoice design_steps(long long steps) {
  check_design_steps(steps);
  return {StepsChoice::Kind::fixed, static_cast<int>(steps)};
}

void check_design_max_banks(long long banks) { check_range("--max-banks", banks, board::kMinBanks, 255); }
void check_design_min_bits(long long bits) { check_range("--min-bits", bits, 7, 31); }
void check_design_cap(const std::string& option, double value) { check_positive_finite(option, value); }

void check_design_axis(const std::string& option, const std::string& text) {
  if (text.empty()) parse_name_list(text, option);  // throws, naming the option
}

void check_scene_option(const std::string& option, long long value) {
  if (option == "--faces") {
    if (value < 1)
      throw std::invalid_argument("--faces: must be at least 1 (the number of faces to refine to); omit it for the scene's "
                                  "own faces (sweep without --scene: the paper's 70)");
    check_range(option, value, 1, std::numeric_limits<int>::max());
  } else if (option == "--face-levels" || option == "--patch-levels") {
    check_range(option, value, 0, 8);
  } else {
    throw std::logic_error("check_scene_option: " + option + " is not a counted scene option");
  }
}

void check_patch_size(double size) { check_positive_finite("--patch-size", size); }

void check_scene_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw std::invalid_argument("--scene: File is actually a directory: " + path);
  if (!std::filesystem::exists(path, ec)) throw std::invalid_argument("--scene: File does not exist: " + path);
}

void check_form_factor(const std::string& name) {
  const std::vector<std::string> names = form_factor_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw std::invalid_argument("--form-factor: " + name + " not in {" + joined_names(names, [](const std::string& n) { return n; }) +
                                "}");
}

FormFactorKind design_form_factor(const std::string& name) {
  check_form_factor(name);
  return parse_form_factor_kind(name);
}

void resolve_design_options(DesignOptions& o) {
  DesignSpace& s = o.space;
  if (!o.lanes.empty()) s.lanes = parse_int_list(o.lanes, "--lanes", board::LaneCount::kMin, board::LaneCount::kMax);
  if (!o.banks.empty()) s.banks = parse_int_list(o.banks, "--banks", board::kMinBanks, kMaxRunBanks);
  if (!o.bank_clocks.empty()) s.bank_clocks_mhz = parse_clocks(o.bank_clocks);
  s.results = parse_results(o.results);
  s.bits = parse_int_list(o.bits, "--bits", 7, 31);
  if (std::none_of(s.bits.begin(), s.bits.end(), [&](int b) { return b >= o.constraints.min_bits; }))
    throw std::invalid_argument("--min-bits: " + std::to_string(o.constraints.min_bits) + " leaves no width of --bits " +
                                o.bits + " to search; give --bits with a width of at least " +
                                std::to_string(o.constraints.min_bits));
  s.multipliers.clear();
  for (const std::string& m : parse_name_list(o.multipliers, "--multipliers")) s.multipliers.push_back(parse_multipliers(m));
  s.cards = parse_int_list(o.cards, "--cards", CardCount::kMin, CardCount::kMax);
  s.concurrent = parse_concurrency(o.concurrent);
  // The fixes' limits are run's (--offset-lsb 1..2^20, --neighbour-rings 1..2, --coordinate-bits 7..30), with 0 for off.
  s.offset_lsb = parse_int_list(o.offset_lsb, "--offset-lsb", 0, 1 << 20);
  s.neighbour_rings = parse_int_list(o.neighbour_rings, "--neighbour-rings", 0, 2);
  s.coordinate_bits = parse_int_list(o.coordinate_bits, "--coordinate-bits", 0, 30);
  for (int c : s.coordinate_bits)
    if (c != 0 && c < 7)
      throw std::invalid_argument("--coordinate-bits: '" + std::to_string(c) + "' is outside 7..30 (0: off)");
  for (int b : s.bits)
    if (b >= o.constraints.min_bits)
      for (int c : s.coordinate_bits)
        if (!coordinate_bits_problem(b, c).empty()) throw std::invalid_argument("--coordinate-bits: " + coordinate_bits_problem(b, c));
  o.workload.source = scene_source(o.workload.scene);
  o.workload.paper_faithful = !o.culled;
  if (o.fidelity != "on" && o.fidelity != "off")
    throw std::invalid_argument("--fidelity: '" + o.fidelity + "' is not one of on, off");
  s.measure_fidelity = o.fidelity == "on";
  for (const auto& [option, bound] : {std::pair<const char*, double>{"--max-error", o.constraints.max_error},
                                      {"--max-error-max", o.constraints.max_error_max}})
    if (!s.measure_fidelity && std::isfinite(bound))
      throw std::invalid_argument(std::string(option) + ": an error bound needs the picture's error measured; it does not "
                                  "apply with --fidelity off");
  if (o.constraints.max_banks > kMaxRunBanks)
    throw std::invalid_argument("--max-banks: " + std::to_string(o.constraints.max_banks) + " is above " +
                                std::to_string(kMaxRunBanks) + ", the most `rc2000sim run --banks` takes");
}

}  // namespace rc
