#include "apps/sweep_lanes_fit.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "board/device_profile.h"
#include "host_sw/studies/profile_setting.h"
#include "host_sw/studies/sweep_config.h"

namespace rc {

std::vector<SweptFit> swept_fits(const Study& s) {
  const std::string study = s.name;  // as run_study_shard names it
  const HostProfile host = with_settings(find_host_profile(s.axes.hosts.front()), s.fixed, study);
  std::vector<ProfileAxis> device_axes;
  for (const ProfileAxis& a : s.axes.profile)
    if (a.field.kind == ProfileKind::device) device_axes.push_back(a);
  std::vector<SweptFit> fits;
  for (const std::string& device : s.axes.devices) {
    const board::DeviceProfile base = board::find_device_profile(device);
    for (const std::vector<ProfileSetting>& combination : profile_combinations(device_axes)) {
      std::vector<ProfileSetting> settings = s.fixed;
      settings.insert(settings.end(), combination.begin(), combination.end());
      std::optional<board::DeviceProfile> d;
      std::string why;
      try {
        d = with_settings(base, settings, study);
      } catch (const std::invalid_argument& e) {  // a combination of values no device has: its rows say so too
        why = e.what();
      }
      for (int bits : s.axes.bits) {
        SweptFit fit{device, bits, combination, {}, why};
        if (d) fit.estimates = lanes_that_fit(*d, host, bits, s.resources);
        fits.push_back(fit);
      }
    }
  }
  return fits;
}

bool sweeps_device_fields(const Study& s) {
  return std::any_of(s.axes.profile.begin(), s.axes.profile.end(),
                     [](const ProfileAxis& a) { return a.field.kind == ProfileKind::device; });
}

}  // namespace rc
