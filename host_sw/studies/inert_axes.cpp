#include "host_sw/studies/inert_axes.h"

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "host_sw/studies/profile_setting.h"
#include "host_sw/studies/sweep_config.h"

namespace rc {

namespace {

// Everything that identifies a row but the profile axis `skip`.
std::string key_without(const SweepConfig& c, std::size_t skip) {
  std::string key = c.device + "|" + std::to_string(c.bits) + "|" + (c.concurrent ? "c" : "s") + "|" +
                    std::to_string(c.lanes) + "|" + std::to_string(c.banks) + "|" + c.host + "|" + std::to_string(c.cards) + "|" +
                    std::to_string(static_cast<int>(c.card_split)) + "|" + std::to_string(static_cast<int>(c.card_bus));
  for (std::size_t i = 0; i < c.settings.size(); ++i)
    if (i != skip) key += "|" + c.settings[i].text();
  return key;
}

bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// The figures an axis could move: whether the row exists, its clock, times and energy.
bool same_figures(const SweepRow& a, const SweepRow& b) {
  return a.validity == b.validity && same(a.clock_mhz, b.clock_mhz) && same(a.simulated_seconds, b.simulated_seconds) &&
         same(a.fpga_busy_seconds, b.fpga_busy_seconds) && same(a.energy_joules, b.energy_joules);
}

}  // namespace

std::vector<std::string> inert_axis_warnings(const std::vector<SweepRow>& rows) {
  std::vector<std::string> warnings;
  if (rows.empty()) return warnings;
  const std::size_t axes = rows.front().config.settings.size();
  for (std::size_t axis = 0; axis < axes; ++axis) {
    std::map<std::string, std::vector<const SweepRow*>> groups;
    std::map<std::string, bool> values;  // the axis's distinct values, as text
    for (const SweepRow& r : rows) {
      if (r.config.settings.size() != axes) return warnings;  // rows of different studies: nothing to compare
      groups[key_without(r.config, axis)].push_back(&r);
      values[r.config.settings[axis].text()] = true;
    }
    if (values.size() < 2) continue;
    bool compared = false, moved = false;
    for (const auto& [key, group] : groups) {
      if (group.size() < 2) continue;
      compared = true;
      for (const SweepRow* r : group) moved = moved || !same_figures(*group.front(), *r);
    }
    if (!compared || moved) continue;
    const std::string& path = rows.front().config.settings[axis].field.path;
    warnings.push_back("profile axis " + path + " changed no figure: in every configuration, the rows that differ only in " +
                       path + " (" + std::to_string(values.size()) +
                       " values) have the same clock, times and energy. Either the timing never reads it in these "
                       "configurations (e.g. host.cpu_cores applies only with a CPU/FPGA split, host.cpu_share above 0; "
                       "a device's clock_mhz_default only for lane counts its profile does not list), or it does not "
                       "bound anything here; drop the axis or add the configurations where it applies");
  }
  return warnings;
}

}  // namespace rc
