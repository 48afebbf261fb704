#include "host_sw/studies/sweep_options.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>

#include "io/parse_number.h"

namespace rc {

namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> items;
  std::size_t from = 0;
  while (true) {
    const std::size_t to = text.find(separator, from);
    items.push_back(trim(text.substr(from, to == std::string::npos ? std::string::npos : to - from)));
    if (to == std::string::npos) return items;
    from = to + 1;
  }
}

// A whole item of decimal digits; no sign (a '-' separates a range), no trailing characters.
bool parse_number(const std::string& s, long& value) {
  const std::optional<std::uint64_t> v = io::parse_unsigned(s);
  if (!v || *v > 999999999) return false;  // far beyond any axis's range, and no overflow below
  value = static_cast<long>(*v);
  return true;
}

}  // namespace

std::vector<int> parse_int_list(const std::string& text, const std::string& option, int min, int max) {
  const std::string range = std::to_string(min) + ".." + std::to_string(max);
  if (trim(text).empty()) throw std::invalid_argument(option + ": empty list (expected e.g. 1-4,8 within " + range + ")");
  std::set<int> values;
  for (const std::string& item : split(text, ',')) {
    const std::size_t dash = item.find('-');
    long low = 0, high = 0;
    const bool ok = dash == std::string::npos
                        ? parse_number(item, low) && (high = low, true)
                        : parse_number(trim(item.substr(0, dash)), low) && parse_number(trim(item.substr(dash + 1)), high);
    if (!ok) {
      throw std::invalid_argument(option + ": '" + item + "' is not a number or a range LOW-HIGH (e.g. 1-4,8 within " +
                                  range + ")");
    }
    if (low > high) throw std::invalid_argument(option + ": '" + item + "' is a reversed range (write LOW-HIGH)");
    if (low < min || high > max) {
      throw std::invalid_argument(option + ": '" + item + "' is outside " + range);
    }
    for (long v = low; v <= high; ++v) values.insert(static_cast<int>(v));
  }
  return {values.begin(), values.end()};
}

std::vector<std::string> parse_name_list(const std::string& text, const std::string& option) {
  if (trim(text).empty()) throw std::invalid_argument(option + ": empty list");
  std::vector<std::string> names;
  for (const std::string& name : split(text, ',')) {
    if (name.empty()) throw std::invalid_argument(option + ": empty name in '" + text + "'");
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

std::vector<bool> parse_concurrency(const std::string& text) {
  if (text == "off") return {false};
  if (text == "on") return {true};
  if (text == "both") return {false, true};
  throw std::invalid_argument("--concurrent: expected on, off or both, got '" + text + "'");
}

std::string to_string(const StepsChoice& steps) {
  switch (steps.kind) {
    case StepsChoice::Kind::paper: return "paper";
    case StepsChoice::Kind::converge: return "converge";
    case StepsChoice::Kind::fixed: return std::to_string(steps.steps);
  }
  throw std::logic_error("to_string: not a StepsChoice");
}

StepsChoice parse_steps(const std::string& text) {
  StepsChoice c;
  if (text == "paper") return c;
  if (text == "converge") {
    c.kind = StepsChoice::Kind::converge;
    return c;
  }
  long steps = 0;
  if (!parse_number(text, steps) || steps < 1) {
    throw std::invalid_argument("--steps: expected paper, converge or a positive step count, got '" + text + "'");
  }
  c.kind = StepsChoice::Kind::fixed;
  c.steps = static_cast<int>(steps);
  return c;
}

}  // namespace rc
