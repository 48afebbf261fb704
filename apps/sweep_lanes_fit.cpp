#include "apps/sweep_lanes_fit.h"

#include <algorithm>

#include "board/device_profile.h"
#include "host_sw/studies/profile_setting.h"

namespace rc {


std::vector<SweptFit> swept_fits(const Study& s) {
  const std::string study = s.name;  // as run_study_shard names it
  const HostProfile host = with_settings(find_host_profile(s.axes.hosts.front()), s.fixed, study);
  std::vector<SweptFit> fits;
  for (const std::string& device : s.axes.devices) {
    const board::DeviceProfile d = with_settings(board::find_device_profile(device), s.fixed, study);
    for (int bits : s.axes.bits) fits.push_back({bits, lanes_that_fit(d, host, bits)});
  }
  return fits;
}

bool sweeps_device_fields(const Study& s) {
  return std::any_of(s.axes.profile.begin(), s.axes.profile.end(),
                     [](const ProfileAxis& a) { return a.field.kind == ProfileKind::device; });
}

}  // namespace rc
