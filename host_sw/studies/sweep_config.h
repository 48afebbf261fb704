// The configurations a sweep spans (`rc2000sim sweep`, docs/results/sweep.md): its axes, one
// configuration of them, and every configuration in a fixed order. Whether a configuration can
// exist is config_checker.h's job; what it measured is sweep_row.h's.
//
//   SweepAxes axes;  axes.devices = {"xc2v6000"};  axes.lanes = parse_int_list("1-4", "--lanes", 1, 255); ...
//   for (const SweepConfig& c : enumerate_configs(axes)) ...
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "host_sw/platform/card_options.h"
#include "host_sw/studies/profile_setting.h"

namespace rc {

// A value of a profile field, as a study gives it (profile_setting.h holds its type).
using ProfileValue = decltype(ProfileSetting::value);

// A profile field swept by its path (profile_setting.h), with its values in the order given.
struct ProfileAxis {
  ProfileField field;
  std::vector<ProfileValue> values;
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

// Every combination of the axes' values, the first axis varying slowest ({{}} without axes).
std::vector<std::vector<ProfileSetting>> profile_combinations(const std::vector<ProfileAxis>& axes);

// A sweep bigger than this is almost certainly a typo (and would take hours); narrow the lists.
constexpr std::size_t kMaxSweepConfigs = 20000;

// Device-major, then width, driver (serial first), host, cards, card split, card bus (one card: the
// first split and bus only, they do not apply), profile axes, lanes, banks: one lanes x banks block
// per device, width, driver, host, cards and profile values. Throws std::invalid_argument for an empty axis or more than kMaxSweepConfigs.
std::vector<SweepConfig> enumerate_configs(const SweepAxes& axes);

}  // namespace rc
