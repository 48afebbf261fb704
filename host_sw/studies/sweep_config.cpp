#include "host_sw/studies/sweep_config.h"

#include <algorithm>
#include <stdexcept>

namespace rc {

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

std::vector<std::vector<ProfileSetting>> profile_combinations(const std::vector<ProfileAxis>& axes) {
  std::vector<std::vector<ProfileSetting>> combos = {{}};
  for (const ProfileAxis& axis : axes) {
    std::vector<std::vector<ProfileSetting>> next;
    for (const std::vector<ProfileSetting>& before : combos) {
      for (const ProfileValue& value : axis.values) {
        next.push_back(before);
        next.back().push_back({axis.field, value});
      }
    }
    combos = std::move(next);
  }
  return combos;
}

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

}  // namespace rc
