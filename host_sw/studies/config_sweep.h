// What-if sweeps over board configurations (`rc2000sim sweep`, docs/results/sweep.md): the option
// lists a sweep takes, the configurations they span in a fixed order, which of them can exist, and
// one row per configuration made from its board report. Nothing here elaborates SystemC; the
// command runs the configurations that can exist through run_timing_study (timing_study.h).
//
//   SweepAxes axes;  axes.devices = {"xc2v6000"};  axes.lanes = parse_int_list("1-4", "--lanes", 1, 255); ...
//   ConfigChecker checker(axes.devices, "athlon-mp-2600-calibrated");
//   for (const SweepConfig& c : enumerate_configs(axes)) {
//     ConfigCheck check = checker.check(c);   // ok, does_not_fit, too_few_banks (reason: the message)
//     ...
//   }
#pragma once

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "board/device_profile.h"
#include "host_sw/platform/board_run.h"
#include "pipeline/resource_model.h"
#include "host_sw/studies/profile_setting.h"

namespace rc {

// ---- option lists -----------------------------------------------------------------------------------

// "1-16", "5,6,8-12", "15": the values listed, ascending and distinct (so the sweep's order never
// depends on how the list was spelt). Throws std::invalid_argument naming `option` for an empty
// list or item, a non-number, a reversed range and a value outside [min, max].
std::vector<int> parse_int_list(const std::string& text, const std::string& option, int min, int max);

// "a,b,c": the names in the order given, repeats dropped. Throws for an empty list or name.
std::vector<std::string> parse_name_list(const std::string& text, const std::string& option);
// "rays,faces" -> the choices (io/choice.h); an unknown name is an error naming `option`.
template <class E>
std::vector<E> parse_choice_list(const std::string& text, const std::string& option) {
  try {
    return parse_choices<E>(parse_name_list(text, option));
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    throw std::invalid_argument(what.rfind(option, 0) == 0 ? what : option + ": " + what);
  }
}

// "off" (serial driver), "on" (concurrent driver, paper sec 4.3) or "both" (serial first).
std::vector<bool> parse_concurrency(const std::string& text);

// How many shooting steps every configuration replays.
struct StepsChoice {
  enum class Kind {
    paper,     // the paper's Table 2 count for a paper scene (its faces and patches); else converge
    converge,  // the steps our solver needs to reach the convergence target (per width)
    fixed,     // exactly `steps`
  };
  Kind kind = Kind::paper;
  int steps = 0;
};
// "paper", "converge" or a positive step count: the one parser of a steps policy (the command line,
// study files and the resolved study's JSON all read it here); to_string gives the text back.
StepsChoice parse_steps(const std::string& text);
std::string to_string(const StepsChoice& steps);

// ---- configurations ---------------------------------------------------------------------------------

// A profile field swept by its path (profile_setting.h), with its values in the order given.
struct ProfileAxis {
  ProfileField field;
  std::vector<nlohmann::ordered_json> values;
};

struct SweepAxes {
  std::vector<std::string> devices;  // profile names or paths, in the order given
  std::vector<int> bits;
  std::vector<bool> concurrent;
  std::vector<std::string> hosts = {"athlon-mp-2600-calibrated"};  // host profiles, in the order given
  // Several cards (docs/board.md, "Several cards"): card counts 1..16, and for more than one card how a
  // step is split and how they sit on PCI (ChoiceNames<CardSplit>, ChoiceNames<CardBus>).
  std::vector<int> cards = {1};
  std::vector<CardSplit> card_splits = {CardSplit::rays};
  std::vector<CardBus> card_buses = {CardBus::shared};
  std::vector<ProfileAxis> profile;  // profile fields, in the order given (the first varies slowest)
  std::vector<int> lanes;
  std::vector<int> banks;
};

struct SweepConfig {
  std::string device;
  int bits = 15;
  bool concurrent = false;
  unsigned lanes = 1;
  unsigned banks = 6;
  std::string host;                      // empty: the checker's first host
  unsigned cards = 1;
  CardSplit card_split = CardSplit::rays;  // with one card: the axis's first (it does not apply)
  CardBus card_bus = CardBus::shared;
  std::vector<ProfileSetting> settings;  // this configuration's value of each profile axis, in axis order
  // "xc2v6000 15-bit concurrent 2 lanes 6 banks", then each setting ("banks.clock_mhz=133").
  std::string label() const;
};

// The software-only time a configuration's speedup is taken against depends on its width, its host
// profile and the host settings among its profile axes: this names that combination.
std::string software_key(int bits, const std::string& host, const std::vector<ProfileSetting>& settings);
std::string software_key(const SweepConfig& config);

// A sweep bigger than this is almost certainly a typo (and would take hours); narrow the lists.
constexpr std::size_t kMaxSweepConfigs = 20000;

// Device-major, then width, driver (serial first), host, cards, card split, card bus (one card: the
// first split and bus only, they do not apply), profile axes, lanes, banks: one lanes x banks block
// per device, width, driver, host, cards and profile values. Throws std::invalid_argument for an empty axis or more than kMaxSweepConfigs.
std::vector<SweepConfig> enumerate_configs(const SweepAxes& axes);

enum class Validity {
  ok,             // can exist: simulated
  does_not_fit,   // the lanes need more slices or block multipliers than the device has (design_fit.h)
  too_few_banks,  // the bank layout cannot feed the lanes (bank_layout.h)
  other,          // make_board_setup rejected it for another reason
};
std::string to_string(Validity v);  // "ok", "does_not_fit", "too_few_banks", "other"

struct ConfigCheck {
  Validity validity = Validity::ok;
  std::string reason;      // the exception's message when not ok
  double clock_mhz = 0;    // the design clock when the lanes fit the device (0 when they do not)
  BoardRunOptions options; // the board to simulate (validity ok): its device_profile and host_profile
                           // are the profiles with the study's settings applied
};

// Says whether configurations can exist, exactly as make_board_setup (the function every board run
// and timing case goes through) accepts or rejects them: the lanes must fit the device first, then
// the banks must feed them. Profiles are loaded once.
class ConfigChecker {
 public:
  // Throws std::invalid_argument for an unknown device or host profile, or a fixed setting the
  // profiles reject: that is a bad option, not a configuration that cannot exist. `fixed` applies
  // to every configuration before its own settings; `study` names the study in errors and sources.
  ConfigChecker(const std::vector<std::string>& devices, const std::vector<std::string>& hosts,
                const std::vector<ProfileSetting>& fixed = {}, const std::string& study = "command line");
  ConfigChecker(const std::vector<std::string>& devices, const std::string& host)
      : ConfigChecker(devices, std::vector<std::string>{host}) {}

  // A setting the profiles reject (a value out of range) is a bad study, not a configuration that
  // cannot exist: it throws std::invalid_argument.
  ConfigCheck check(const SweepConfig& config) const;

  // A bank capacity that changes nothing for a run whose steps have at most `max_rays` segments
  // and whose scene has `faces` faces, or 0 (keep the profile's). See config_sweep.cpp.
  static std::uint64_t compact_bank_capacity(const board::DeviceProfile& device, std::uint64_t max_rays,
                                             std::uint64_t faces);
  std::uint64_t compact_bank_capacity(const SweepConfig& config, std::uint64_t max_rays, std::uint64_t faces) const {
    return compact_bank_capacity(device(config), max_rays, faces);
  }

  const board::DeviceProfile& device(const std::string& name) const;  // as loaded, with the fixed settings
  board::DeviceProfile device(const SweepConfig& config) const;       // with the configuration's settings too
  HostProfile host(const SweepConfig& config) const;
  const std::string& first_host() const { return host_order_.front(); }

 private:
  std::map<std::string, board::DeviceProfile> devices_;
  std::map<std::string, HostProfile> hosts_;
  std::vector<std::string> host_order_;
  pipeline::ResourceModel resources_;
  std::string study_;
};

// ---- results ----------------------------------------------------------------------------------------

// One configuration's outcome: the CSV row and the JSON record (docs/results/sweep.md defines
// every column). Numbers of an invalid row are NaN (empty in the CSV, null in the JSON).
struct SweepRow {
  SweepConfig config;
  Validity validity = Validity::ok;
  std::string reason;
  int steps = 0;
  double clock_mhz = 0;  // NaN when the lanes do not fit
  double nominal_rays_per_cycle = 0;
  double simulated_seconds = 0, fpga_busy_seconds = 0;
  double host_compute_seconds = 0, driver_cpu_seconds = 0, pci_transfer_seconds = 0, waiting_seconds = 0;
  double pci_utilisation = 0;       // PCI bus busy / simulated
  double max_bank_utilisation = 0;  // busiest bank's busy time / FPGA busy time
  int busiest_bank = -1;
  std::string busiest_bank_role;
  double mean_lane_utilisation = 0;
  double intersections_per_second_while_busy = 0;
  std::string fpga_limit;        // the stream limit that took the most FPGA time ("lanes", "bank 4 (results)")
  double fpga_limit_share = 0;   // its share of the FPGA busy time
  std::string bottleneck;        // bottleneck() below
  double speedup_vs_one_lane = 0;  // NaN when 1 lane was not swept at the same device, width, driver, banks
  double speedup_vs_software = 0;  // NaN without a software time for the width
  // Energy (docs/energy.md), NaN when the row is invalid or a profile has no energy table (then
  // energy_missing says which).
  double energy_joules = 0, energy_per_step_joules = 0, energy_per_intersection_nanojoules = 0;
  double average_watts = 0, energy_delay_product_joule_seconds = 0;
  double fpga_joules = 0, sram_joules = 0, pci_joules = 0, host_joules = 0;
  std::string energy_missing;
  // On the Pareto front of time against energy (pareto_time_energy below); false off it, and for rows
  // without both.
  bool pareto_time_energy = false;
};

SweepRow invalid_row(const SweepConfig& config, const ConfigCheck& check, int steps);
// From a board report (rc2000sim.board/1 with stream_limits); speedups are filled by fill_speedups.
SweepRow row_from_report(const SweepConfig& config, const RunReport& report, int steps);

// "lanes" -> "fpga_lanes"; "bank N (results)" -> "fpga_result_bank"; "bank N (rays ...)" ->
// "fpga_ray_bank"; anything else -> "fpga_other".
std::string fpga_limit_kind(const std::string& limit);

// The largest part of the host thread's timeline (host compute, driver CPU, PCI transfers, waiting
// for the FPGA's interrupt): the part whose removal would save the most. Waiting means the FPGA
// bounds the run, and then what bounded its stream is named (fpga_limit_kind). Values:
// host_compute, host_driver, pci, fpga_lanes, fpga_result_bank, fpga_ray_bank, fpga_other.
std::string bottleneck(const SweepRow& row);

// speedup_vs_one_lane from the 1-lane rows of the same configuration but lanes; speedup_vs_software
// from software seconds by software_key (keys missing from the map: NaN).
void fill_speedups(std::vector<SweepRow>& rows, const std::map<std::string, double>& software_seconds);

// Marks pareto_time_energy: a valid row with energy is on the front when no other such row with the
// same width and the same profile-axis values is at least as fast and as frugal and better in one.
// The front chooses among designs (device, lanes, banks, driver, host, cards); a width makes another
// picture and a profile setting assumes another world (a clock, an SRAM's standby power), so each of
// those has a front of its own.
void mark_pareto_time_energy(std::vector<SweepRow>& rows);

// The columns beyond the classic ones that a sweep over `axes` adds: "host" when more than one
// host is swept, "cards", "card_split" and "card_bus" when more than one card is, then each profile
// axis's path. They follow "concurrent".
std::vector<std::string> extra_columns(const SweepAxes& axes);

// The CSV header and rows (stable column names; numbers with enough digits to round-trip).
void write_sweep_csv(std::ostream& out, const std::vector<SweepRow>& rows, const std::vector<std::string>& extra = {});
nlohmann::ordered_json sweep_row_json(const SweepRow& row, const std::vector<std::string>& extra = {});
// The longest simulated time a row read back may hold: 1e12 s (31,700 years). No configuration the
// model finishes simulating comes near it (the slowest shipped study row takes minutes of simulated
// time); a figure there is a damaged or edited shard, and 1e308 would overflow every sum over rows.
constexpr double kMaxRowSeconds = 1e12;

// The numbers and texts of a row back from sweep_row_json; the configuration is `config` (the
// plan's), and the row's own config columns must agree with it (std::invalid_argument otherwise), as
// must its figures: finite, not negative, a simulated row's time in (0, kMaxRowSeconds], shares at
// most 1 (std::invalid_argument naming the row and the key).
SweepRow sweep_row_from_json(const nlohmann::ordered_json& json, const SweepConfig& config);

}  // namespace rc
