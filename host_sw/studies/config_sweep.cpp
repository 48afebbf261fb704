#include "host_sw/studies/config_sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>

#include "board/bank_layout.h"
#include "io/parse_number.h"
#include "board/design_fit.h"

namespace rc {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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

// ---- option lists -----------------------------------------------------------------------------------

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

// ---- configurations ---------------------------------------------------------------------------------

std::string SweepConfig::label() const {
  std::string text = device + " " + std::to_string(bits) + "-bit " + (concurrent ? "concurrent " : "serial ") +
                     std::to_string(lanes) + (lanes == 1 ? " lane " : " lanes ") + std::to_string(banks) + " banks";
  if (cards > 1) text += " " + std::to_string(cards) + " cards (" + choice_name(card_split) + ", " + choice_name(card_bus) + " bus)";
  for (const ProfileSetting& s : settings) text += " " + s.text();
  return text;
}

std::string software_key(int bits, const std::string& host, const std::vector<ProfileSetting>& settings) {
  std::string key = std::to_string(bits) + "-bit " + host;
  for (const ProfileSetting& s : settings)
    if (s.field.kind == ProfileKind::host) key += " " + s.text();
  return key;
}

std::string software_key(const SweepConfig& c) { return software_key(c.bits, c.host, c.settings); }

namespace {

// Every combination of the profile axes' values, the first axis varying slowest.
std::vector<std::vector<ProfileSetting>> profile_combinations(const std::vector<ProfileAxis>& axes) {
  std::vector<std::vector<ProfileSetting>> combos = {{}};
  for (const ProfileAxis& axis : axes) {
    std::vector<std::vector<ProfileSetting>> next;
    for (const std::vector<ProfileSetting>& before : combos) {
      for (const nlohmann::ordered_json& value : axis.values) {
        next.push_back(before);
        next.back().push_back({axis.field, value});
      }
    }
    combos = std::move(next);
  }
  return combos;
}

}  // namespace

std::vector<SweepConfig> enumerate_configs(const SweepAxes& a) {
  if (a.devices.empty() || a.bits.empty() || a.concurrent.empty() || a.hosts.empty() || a.lanes.empty() ||
      a.banks.empty()) {
    throw std::invalid_argument("a sweep needs at least one device, width, driver, host, lane count and bank count");
  }
  if (a.cards.empty() || a.card_splits.empty() || a.card_buses.empty())
    throw std::invalid_argument("a sweep needs at least one card count, card split and card bus");
  const double one_card = static_cast<double>(std::count(a.cards.begin(), a.cards.end(), 1));
  const double card_choices =
      one_card + (static_cast<double>(a.cards.size()) - one_card) * a.card_splits.size() * a.card_buses.size();
  double count = static_cast<double>(a.devices.size()) * a.bits.size() * a.concurrent.size() * a.hosts.size() *
                 card_choices * a.lanes.size() * a.banks.size();
  for (const ProfileAxis& axis : a.profile) {
    if (axis.values.empty()) throw std::invalid_argument("profile axis '" + axis.field.path + "' has no values");
    count *= static_cast<double>(axis.values.size());
  }
  if (count > kMaxSweepConfigs) {
    throw std::invalid_argument("the sweep spans " + std::to_string(static_cast<long long>(count)) +
                                " configurations (at most " + std::to_string(kMaxSweepConfigs) + "); narrow the lists");
  }
  const std::vector<std::vector<ProfileSetting>> combos = profile_combinations(a.profile);
  std::vector<SweepConfig> configs;
  for (const std::string& device : a.devices)
    for (int bits : a.bits)
      for (bool concurrent : a.concurrent)
        for (const std::string& host : a.hosts)
          for (int cards : a.cards)
            for (std::size_t s = 0; s < (cards == 1 ? 1 : a.card_splits.size()); ++s)
              for (std::size_t b = 0; b < (cards == 1 ? 1 : a.card_buses.size()); ++b)
                for (const std::vector<ProfileSetting>& settings : combos)
                  for (int lanes : a.lanes)
                    for (int banks : a.banks)
                      configs.push_back({device, bits, concurrent, static_cast<unsigned>(lanes),
                                         static_cast<unsigned>(banks), host, static_cast<unsigned>(cards),
                                         a.card_splits[s], a.card_buses[b], settings});
  return configs;
}

std::string to_string(Validity v) {
  switch (v) {
    case Validity::ok: return "ok";
    case Validity::does_not_fit: return "does_not_fit";
    case Validity::too_few_banks: return "too_few_banks";
    case Validity::other: return "other";
  }
  return "other";
}

ConfigChecker::ConfigChecker(const std::vector<std::string>& devices, const std::vector<std::string>& hosts,
                             const std::vector<ProfileSetting>& fixed, const std::string& study)
    : host_order_(hosts), resources_(pipeline::ResourceModel::load_default()), study_(study) {
  if (hosts.empty()) throw std::invalid_argument("a sweep needs at least one host profile");
  // An unknown profile or a rejected fixed setting fails here, not as every configuration's reason.
  for (const std::string& h : hosts) hosts_.emplace(h, with_settings(find_host_profile(h), fixed, study));
  for (const std::string& d : devices) devices_.emplace(d, with_settings(board::find_device_profile(d), fixed, study));
}

const board::DeviceProfile& ConfigChecker::device(const std::string& name) const {
  const auto it = devices_.find(name);
  if (it == devices_.end()) throw std::invalid_argument("device '" + name + "' was not loaded by the checker");
  return it->second;
}

board::DeviceProfile ConfigChecker::device(const SweepConfig& c) const {
  return c.settings.empty() ? device(c.device) : with_settings(device(c.device), c.settings, study_);
}

HostProfile ConfigChecker::host(const SweepConfig& c) const {
  const auto it = hosts_.find(c.host.empty() ? first_host() : c.host);
  if (it == hosts_.end()) throw std::invalid_argument("host '" + c.host + "' was not loaded by the checker");
  return c.settings.empty() ? it->second : with_settings(it->second, c.settings, study_);
}

// The two checks of make_board_setup, in its order, so that each rejection gets its kind; then
// make_board_setup itself, so that "ok" means what a timing case will accept.
ConfigCheck ConfigChecker::check(const SweepConfig& c) const {
  ConfigCheck out;
  const board::DeviceProfile d = device(c);  // a setting the profile rejects throws: a bad study
  const HostProfile h = host(c);
  try {
    const board::DesignFit fit = board::fit_design(d, resources_, static_cast<int>(c.lanes), c.bits);
    if (!fit.fits) {
      out.validity = Validity::does_not_fit;
      out.reason = fit.describe();
      return out;
    }
    out.clock_mhz = fit.clock_mhz;
    try {
      (void)board::make_bank_layout(c.lanes, c.banks, c.bits, d.bank_word_bits, d.bank_capacity_bytes);
    } catch (const std::invalid_argument& e) {
      out.validity = Validity::too_few_banks;
      out.reason = e.what();
      return out;
    }
    out.options.device = c.device;
    out.options.lanes = c.lanes;
    out.options.banks = c.banks;
    out.options.bits = c.bits;
    out.options.concurrent = c.concurrent;
    out.options.host = c.host.empty() ? first_host() : c.host;
    out.options.host_profile = h;
    out.options.device_profile = d;
    out.options.cards = c.cards;
    out.options.card_split = c.card_split;
    out.options.card_bus = c.card_bus;
    (void)make_board_setup(out.options);
  } catch (const std::invalid_argument& e) {
    out.validity = Validity::other;
    out.reason = e.what();
  }
  return out;
}

// Bank capacity enters the timing only through batching: it bounds the rays of a batch, the faces of
// a set, and each ray group's packets, which can move rays between groups (split_rays). A bank of
// W >= 3 R words never caps a group's packets for R rays or fewer (a group's stream needs at most
// 3 R cycles, and a group of k banks holds W k / 3 packets), holds their R result words, and with
// W >= 10 F words holds F face records and their own-face table. When the profile's banks satisfy
// both and a smaller power of two does too, passes, splits, transfers and times are identical with
// the smaller banks; only the host memory the model allocates (every bank's bytes) shrinks.
std::uint64_t ConfigChecker::compact_bank_capacity(const board::DeviceProfile& d, std::uint64_t max_rays,
                                                   std::uint64_t faces) {
  const std::uint64_t word_bytes = d.bank_word_bits / 8;
  const std::uint64_t words = std::max<std::uint64_t>({3 * max_rays, 10 * faces, 1});
  if (words * word_bytes > d.bank_capacity_bytes) return 0;  // the profile's banks batch: keep them
  std::uint64_t bytes = 4096;
  while (bytes < words * word_bytes) bytes *= 2;
  return bytes < d.bank_capacity_bytes ? bytes : 0;
}

// ---- results ----------------------------------------------------------------------------------------

namespace {

void set_no_energy(SweepRow& r) {
  for (double* x : {&r.energy_joules, &r.energy_per_step_joules, &r.energy_per_intersection_nanojoules, &r.average_watts,
                    &r.energy_delay_product_joule_seconds, &r.fpga_joules, &r.sram_joules, &r.pci_joules, &r.host_joules})
    *x = kNaN;
  r.pareto_time_energy = false;
}

double component_joules(const energy::EnergyReport& e, const char* name) {
  for (const energy::ComponentEnergy& c : e.components)
    if (c.name == name) return c.joules();
  return kNaN;
}

void energy_columns(const RunReport& report, SweepRow& r) {
  set_no_energy(r);
  r.energy_missing = report.energy_missing;
  if (!report.energy) return;
  const energy::EnergyReport& e = *report.energy;
  r.energy_joules = e.joules;
  r.energy_per_step_joules = e.joules_per_step > 0 ? e.joules_per_step : kNaN;
  r.energy_per_intersection_nanojoules = e.joules_per_intersection > 0 ? e.joules_per_intersection * 1e9 : kNaN;
  r.average_watts = e.average_watts;
  r.energy_delay_product_joule_seconds = e.energy_delay_product;
  r.fpga_joules = component_joules(e, "fpga");
  r.sram_joules = component_joules(e, "sram");
  r.pci_joules = component_joules(e, "pci");
  r.host_joules = component_joules(e, "host");
}

}  // namespace

SweepRow invalid_row(const SweepConfig& config, const ConfigCheck& check, int steps) {
  SweepRow r;
  r.config = config;
  r.validity = check.validity;
  r.reason = check.reason;
  r.steps = steps;
  r.clock_mhz = check.clock_mhz > 0 ? check.clock_mhz : kNaN;
  for (double* x : {&r.nominal_rays_per_cycle, &r.simulated_seconds, &r.fpga_busy_seconds, &r.host_compute_seconds,
                    &r.driver_cpu_seconds, &r.pci_transfer_seconds, &r.waiting_seconds, &r.pci_utilisation,
                    &r.max_bank_utilisation, &r.mean_lane_utilisation, &r.intersections_per_second_while_busy,
                    &r.fpga_limit_share, &r.speedup_vs_one_lane, &r.speedup_vs_software})
    *x = kNaN;
  set_no_energy(r);
  return r;
}

namespace {

double ratio(double a, double b) { return b > 0 ? a / b : kNaN; }

void busiest_bank(const std::vector<BankUseReport>& banks, double fpga_busy, SweepRow& r) {
  double most = -1;
  for (const BankUseReport& b : banks) {
    if (b.busy_seconds <= most) continue;  // the first of equal banks wins
    most = b.busy_seconds;
    r.busiest_bank = static_cast<int>(b.bank);
    r.busiest_bank_role = b.role;
  }
  r.max_bank_utilisation = most >= 0 ? ratio(most, fpga_busy) : kNaN;
}

void dominant_limit(const std::vector<StreamLimitReport>& limits, SweepRow& r) {
  double most = -1, total = 0;
  for (const StreamLimitReport& l : limits) {
    total += l.fpga_busy_seconds;
    if (l.fpga_busy_seconds <= most) continue;
    most = l.fpga_busy_seconds;
    r.fpga_limit = l.limit;
  }
  r.fpga_limit_share = most >= 0 ? ratio(most, total) : kNaN;
}

}  // namespace

SweepRow row_from_report(const SweepConfig& config, const RunReport& report, int steps) {
  SweepRow r;
  r.config = config;
  r.steps = steps;
  const RunTime& t = report.time;
  r.clock_mhz = report.board.device.clock_hz / 1e6;
  r.nominal_rays_per_cycle = report.board.layout.nominal_rays_per_cycle;
  r.simulated_seconds = report.simulated_seconds;
  r.fpga_busy_seconds = t.fpga_busy;
  r.host_compute_seconds = t.host_compute;
  r.driver_cpu_seconds = t.driver_cpu;
  r.pci_transfer_seconds = t.pci_transfer;
  r.waiting_seconds = t.waiting;
  r.pci_utilisation = ratio(report.board.pci.bus_busy_seconds, r.simulated_seconds);
  busiest_bank(report.board.banks, r.fpga_busy_seconds, r);
  double lanes = 0;
  for (const LaneReport& l : report.board.lanes) lanes += l.utilisation;
  r.mean_lane_utilisation = report.board.lanes.empty() ? kNaN : lanes / report.board.lanes.size();
  r.intersections_per_second_while_busy = report.intersections.per_second_while_fpga_busy;
  dominant_limit(report.board.stream_limits, r);
  r.bottleneck = bottleneck(r);
  r.speedup_vs_one_lane = r.speedup_vs_software = kNaN;
  energy_columns(report, r);
  return r;
}

std::string fpga_limit_kind(const std::string& limit) {
  if (limit == "lanes") return "fpga_lanes";
  if (limit.rfind("bank ", 0) == 0 && limit.find("(results)") != std::string::npos) return "fpga_result_bank";
  if (limit.rfind("bank ", 0) == 0 && limit.find("(rays") != std::string::npos) return "fpga_ray_bank";
  return "fpga_other";
}

std::string bottleneck(const SweepRow& r) {
  // In this order the first of equal parts wins: the FPGA, then the host's own parts.
  const std::pair<const char*, double> parts[] = {{"fpga", r.waiting_seconds},
                                                  {"host_compute", r.host_compute_seconds},
                                                  {"host_driver", r.driver_cpu_seconds},
                                                  {"pci", r.pci_transfer_seconds}};
  const auto* top = &parts[0];
  for (const auto& p : parts)
    if (p.second > top->second) top = &p;
  return top == &parts[0] ? fpga_limit_kind(r.fpga_limit) : top->first;
}

void fill_speedups(std::vector<SweepRow>& rows, const std::map<std::string, double>& software_seconds) {
  // The same configuration but its lane count (the settings' texts stand for their values).
  auto base_key = [](const SweepConfig& c) {
    std::string key = c.device + "|" + std::to_string(c.bits) + "|" + (c.concurrent ? "1" : "0") + "|" +
                      std::to_string(c.banks) + "|" + c.host + "|" + std::to_string(c.cards) + "|" + choice_name(c.card_split) +
                      "|" + choice_name(c.card_bus);
    for (const ProfileSetting& s : c.settings) key += "|" + s.text();
    return key;
  };
  std::map<std::string, double> one_lane;
  for (const SweepRow& r : rows)
    if (r.validity == Validity::ok && r.config.lanes == 1) one_lane[base_key(r.config)] = r.simulated_seconds;
  for (SweepRow& r : rows) {
    if (r.validity != Validity::ok) continue;
    const auto base = one_lane.find(base_key(r.config));
    r.speedup_vs_one_lane = base != one_lane.end() ? ratio(base->second, r.simulated_seconds) : kNaN;
    const auto sw = software_seconds.find(software_key(r.config));
    r.speedup_vs_software = sw != software_seconds.end() ? ratio(sw->second, r.simulated_seconds) : kNaN;
  }
}

void mark_pareto_time_energy(std::vector<SweepRow>& rows) {
  auto world = [](const SweepConfig& c) {
    std::string key = std::to_string(c.bits);
    for (const ProfileSetting& s : c.settings) key += "|" + s.text();
    return key;
  };
  auto has_both = [](const SweepRow& r) {
    return r.validity == Validity::ok && std::isfinite(r.simulated_seconds) && std::isfinite(r.energy_joules);
  };
  for (SweepRow& r : rows) {
    r.pareto_time_energy = false;
    if (!has_both(r)) continue;
    bool dominated = false;
    for (const SweepRow& o : rows) {
      if (&o == &r || !has_both(o) || world(o.config) != world(r.config)) continue;
      const bool no_worse = o.simulated_seconds <= r.simulated_seconds && o.energy_joules <= r.energy_joules;
      const bool better = o.simulated_seconds < r.simulated_seconds || o.energy_joules < r.energy_joules;
      if (no_worse && better) {
        dominated = true;
        break;
      }
    }
    r.pareto_time_energy = !dominated;
  }
}

std::vector<std::string> extra_columns(const SweepAxes& axes) {
  std::vector<std::string> columns;
  if (axes.hosts.size() > 1) columns.push_back("host");
  if (axes.cards != std::vector<int>{1}) {
    for (const char* c : {"cards", "card_split", "card_bus"}) columns.push_back(c);
  }
  for (const ProfileAxis& a : axes.profile) columns.push_back(a.field.path);
  return columns;
}

// ---- output -----------------------------------------------------------------------------------------

namespace {

const char* const kColumns[] = {"device",
                                "lanes",
                                "banks",
                                "bits",
                                "concurrent",
                                "status",
                                "invalid_kind",
                                "reason",
                                "steps",
                                "clock_mhz",
                                "nominal_rays_per_cycle",
                                "simulated_seconds",
                                "fpga_busy_seconds",
                                "host_compute_seconds",
                                "driver_cpu_seconds",
                                "pci_transfer_seconds",
                                "waiting_seconds",
                                "pci_utilisation",
                                "max_bank_utilisation",
                                "busiest_bank",
                                "busiest_bank_role",
                                "mean_lane_utilisation",
                                "intersections_per_second_while_busy",
                                "fpga_limit",
                                "fpga_limit_share",
                                "bottleneck",
                                "speedup_vs_one_lane",
                                "speedup_vs_software",
                                "energy_joules",
                                "energy_per_step_joules",
                                "energy_per_intersection_nanojoules",
                                "average_watts",
                                "energy_delay_product_joule_seconds",
                                "fpga_joules",
                                "sram_joules",
                                "pci_joules",
                                "host_joules",
                                "energy_missing",
                                "pareto_time_energy"};

std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

std::string csv_number(double x) {
  if (std::isnan(x)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

nlohmann::ordered_json json_number(double x) { return std::isnan(x) ? nlohmann::ordered_json() : nlohmann::ordered_json(x); }

constexpr std::size_t kConfigColumns = 5;  // device .. concurrent: the extra columns follow them

std::vector<std::string> columns(const std::vector<std::string>& extra) {
  std::vector<std::string> names(std::begin(kColumns), std::end(kColumns));
  names.insert(names.begin() + kConfigColumns, extra.begin(), extra.end());
  return names;
}

// The value of an extra column: the host, or the setting of the profile axis with that path.
nlohmann::ordered_json extra_value(const SweepConfig& c, const std::string& column) {
  if (column == "host") return c.host;
  if (column == "cards") return c.cards;
  if (column == "card_split") return c.cards > 1 ? nlohmann::ordered_json(choice_name(c.card_split)) : nlohmann::ordered_json();
  if (column == "card_bus") return c.cards > 1 ? nlohmann::ordered_json(choice_name(c.card_bus)) : nlohmann::ordered_json();
  for (const ProfileSetting& s : c.settings)
    if (s.field.path == column) return s.value;
  throw std::logic_error("sweep column '" + column + "' has no value in " + c.label());
}

// Every column's value as a JSON value (strings, integers, numbers or null), in column order.
std::vector<nlohmann::ordered_json> row_values(const SweepRow& r, const std::vector<std::string>& extra) {
  const bool ok = r.validity == Validity::ok;
  const nlohmann::ordered_json none;
  std::vector<nlohmann::ordered_json> values = {r.config.device, r.config.lanes, r.config.banks, r.config.bits,
                                                r.config.concurrent ? 1 : 0};
  for (const std::string& column : extra) values.push_back(extra_value(r.config, column));
  std::vector<nlohmann::ordered_json> rest = {
          ok ? "ok" : "invalid",
          ok ? std::string() : to_string(r.validity),
          r.reason,
          r.steps,
          json_number(r.clock_mhz),
          json_number(r.nominal_rays_per_cycle),
          json_number(r.simulated_seconds),
          json_number(r.fpga_busy_seconds),
          json_number(r.host_compute_seconds),
          json_number(r.driver_cpu_seconds),
          json_number(r.pci_transfer_seconds),
          json_number(r.waiting_seconds),
          json_number(r.pci_utilisation),
          json_number(r.max_bank_utilisation),
          ok && r.busiest_bank >= 0 ? nlohmann::ordered_json(r.busiest_bank) : none,
          r.busiest_bank_role,
          json_number(r.mean_lane_utilisation),
          json_number(r.intersections_per_second_while_busy),
          r.fpga_limit,
          json_number(r.fpga_limit_share),
          r.bottleneck,
          json_number(r.speedup_vs_one_lane),
          json_number(r.speedup_vs_software),
          json_number(r.energy_joules),
          json_number(r.energy_per_step_joules),
          json_number(r.energy_per_intersection_nanojoules),
          json_number(r.average_watts),
          json_number(r.energy_delay_product_joule_seconds),
          json_number(r.fpga_joules),
          json_number(r.sram_joules),
          json_number(r.pci_joules),
          json_number(r.host_joules),
          r.energy_missing,
          ok && std::isfinite(r.energy_joules) ? nlohmann::ordered_json(r.pareto_time_energy ? 1 : 0) : none};
  values.insert(values.end(), rest.begin(), rest.end());
  return values;
}

std::string csv_field(const nlohmann::ordered_json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return csv_text(v.get<std::string>());
  if (v.is_number_float()) return csv_number(v.get<double>());
  return v.dump();
}

}  // namespace

void write_sweep_csv(std::ostream& out, const std::vector<SweepRow>& rows, const std::vector<std::string>& extra) {
  const std::vector<std::string> names = columns(extra);
  for (std::size_t i = 0; i < names.size(); ++i) out << (i ? "," : "") << csv_text(names[i]);
  out << "\n";
  for (const SweepRow& r : rows) {
    const std::vector<nlohmann::ordered_json> values = row_values(r, extra);
    for (std::size_t i = 0; i < values.size(); ++i) out << (i ? "," : "") << csv_field(values[i]);
    out << "\n";
  }
}

nlohmann::ordered_json sweep_row_json(const SweepRow& r, const std::vector<std::string>& extra) {
  const std::vector<std::string> names = columns(extra);
  const std::vector<nlohmann::ordered_json> values = row_values(r, extra);
  nlohmann::ordered_json j;
  for (std::size_t i = 0; i < values.size(); ++i) j[names[i]] = values[i];
  j["concurrent"] = r.config.concurrent;  // a JSON boolean; the CSV writes 1 or 0
  return j;
}

namespace {

double number_from(const nlohmann::ordered_json& j, const char* key) {
  const nlohmann::ordered_json& v = j.at(key);
  return v.is_null() ? kNaN : v.get<double>();
}

Validity validity_from(const std::string& status, const std::string& kind) {
  if (status == "ok") return Validity::ok;
  for (Validity v : {Validity::does_not_fit, Validity::too_few_banks, Validity::other})
    if (kind == to_string(v)) return v;
  throw std::invalid_argument("sweep row: unknown invalid_kind '" + kind + "'");
}

const char* const kRowFigures[] = {"steps", "clock_mhz", "nominal_rays_per_cycle", "simulated_seconds",
                                   "fpga_busy_seconds", "host_compute_seconds", "driver_cpu_seconds",
                                   "pci_transfer_seconds", "waiting_seconds", "pci_utilisation", "max_bank_utilisation",
                                   "busiest_bank", "mean_lane_utilisation", "intersections_per_second_while_busy",
                                   "fpga_limit_share", "speedup_vs_one_lane", "speedup_vs_software", "energy_joules",
                                   "energy_per_step_joules", "energy_per_intersection_nanojoules", "average_watts",
                                   "energy_delay_product_joule_seconds", "fpga_joules", "sram_joules", "pci_joules",
                                   "host_joules"};

// A row read back (a shard file, hand-edited or damaged) must hold figures a run can produce: every
// number finite and non-negative (null: not measured), a simulated row's time positive and at most
// kMaxRowSeconds, shares and utilisations at most 1. Otherwise merge would write the number as a
// result (negative or 1e308 simulated seconds were accepted).
void check_row_figures(const nlohmann::ordered_json& j, const SweepRow& r) {
  const std::string row = "row " + r.config.label() + ": ";
  for (const char* key : kRowFigures) {
    const nlohmann::ordered_json& v = j.at(key);
    if (v.is_null()) continue;
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0) {
      throw std::invalid_argument(row + key + " = " + v.dump() +
                                  " is not a figure a run produces (a finite number, not negative, or null)");
    }
  }
  if (r.validity != Validity::ok) return;
  const double seconds = number_from(j, "simulated_seconds");
  if (!(seconds > 0 && seconds <= kMaxRowSeconds)) {
    char text[96];
    std::snprintf(text, sizeof text, "%g is outside (0, %g]", seconds, kMaxRowSeconds);
    throw std::invalid_argument(row + "simulated_seconds = " + text + " for a simulated row (kMaxRowSeconds)");
  }
  for (const char* key : {"pci_utilisation", "max_bank_utilisation", "mean_lane_utilisation", "fpga_limit_share"}) {
    const double x = number_from(j, key);
    if (x > 1 + 1e-9) throw std::invalid_argument(row + key + " = " + j.at(key).dump() + " is above 1 (a share)");
  }
}

}  // namespace

SweepRow sweep_row_from_json(const nlohmann::ordered_json& j, const SweepConfig& config) {
  SweepRow r;
  r.config = config;
  const bool same = j.at("lanes").get<unsigned>() == config.lanes && j.at("banks").get<unsigned>() == config.banks &&
                    j.at("bits").get<int>() == config.bits && j.at("concurrent").get<bool>() == config.concurrent;
  if (!same) throw std::invalid_argument("sweep row " + j.dump() + " is not the plan's " + config.label());
  r.config.device = j.at("device").get<std::string>();  // the profile's name (the plan may hold a path)
  r.validity = validity_from(j.at("status").get<std::string>(), j.at("invalid_kind").get<std::string>());
  check_row_figures(j, r);  // before any figure is read as a number
  r.reason = j.at("reason").get<std::string>();
  r.steps = j.at("steps").get<int>();
  r.clock_mhz = number_from(j, "clock_mhz");
  r.nominal_rays_per_cycle = number_from(j, "nominal_rays_per_cycle");
  r.simulated_seconds = number_from(j, "simulated_seconds");
  r.fpga_busy_seconds = number_from(j, "fpga_busy_seconds");
  r.host_compute_seconds = number_from(j, "host_compute_seconds");
  r.driver_cpu_seconds = number_from(j, "driver_cpu_seconds");
  r.pci_transfer_seconds = number_from(j, "pci_transfer_seconds");
  r.waiting_seconds = number_from(j, "waiting_seconds");
  r.pci_utilisation = number_from(j, "pci_utilisation");
  r.max_bank_utilisation = number_from(j, "max_bank_utilisation");
  r.busiest_bank = j.at("busiest_bank").is_null() ? -1 : j.at("busiest_bank").get<int>();
  r.busiest_bank_role = j.at("busiest_bank_role").get<std::string>();
  r.mean_lane_utilisation = number_from(j, "mean_lane_utilisation");
  r.intersections_per_second_while_busy = number_from(j, "intersections_per_second_while_busy");
  r.fpga_limit = j.at("fpga_limit").get<std::string>();
  r.fpga_limit_share = number_from(j, "fpga_limit_share");
  r.bottleneck = j.at("bottleneck").get<std::string>();
  r.speedup_vs_one_lane = number_from(j, "speedup_vs_one_lane");
  r.speedup_vs_software = number_from(j, "speedup_vs_software");
  r.energy_joules = number_from(j, "energy_joules");
  r.energy_per_step_joules = number_from(j, "energy_per_step_joules");
  r.energy_per_intersection_nanojoules = number_from(j, "energy_per_intersection_nanojoules");
  r.average_watts = number_from(j, "average_watts");
  r.energy_delay_product_joule_seconds = number_from(j, "energy_delay_product_joule_seconds");
  r.fpga_joules = number_from(j, "fpga_joules");
  r.sram_joules = number_from(j, "sram_joules");
  r.pci_joules = number_from(j, "pci_joules");
  r.host_joules = number_from(j, "host_joules");
  r.energy_missing = j.at("energy_missing").get<std::string>();
  r.pareto_time_energy = !j.at("pareto_time_energy").is_null() && j.at("pareto_time_energy").get<int>() == 1;
  return r;
}

}  // namespace rc
