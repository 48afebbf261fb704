#include "host_sw/studies/sweep_pareto.h"

#include <cmath>
#include <string>

namespace rc {

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

}  // namespace rc
