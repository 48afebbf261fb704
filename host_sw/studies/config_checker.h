// Which sweep configurations can exist (sweep_config.h), decided exactly as make_board_setup (the
// function every board run and timing case goes through) decides: the lanes must fit the device
// first, then the banks must feed them. Nothing here elaborates SystemC.
//
//   ConfigChecker checker(axes.devices, "athlon-mp-2600-calibrated");
//   for (const SweepConfig& c : enumerate_configs(axes)) {
//     ConfigCheck check = checker.check(c);   // ok, does_not_fit, too_few_banks (reason: the message)
//     ...
//   }
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "board/device_profile.h"
#include "host_sw/platform/board_run.h"
#include "pipeline/resource_model.h"
#include "host_sw/studies/profile_setting.h"
#include "host_sw/studies/sweep_config.h"

namespace rc {

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
  // `resources`: where the lanes' slices and block multipliers come from (pipeline/resource_source.h);
  // the boards it passes carry it.
  ConfigChecker(const std::vector<std::string>& devices, const std::vector<std::string>& hosts,
                const std::vector<ProfileSetting>& fixed = {}, const std::string& study = "command line",
                pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit,
                board::RaySplitRule ray_split = board::RaySplitRule::limit);
  ConfigChecker(const std::vector<std::string>& devices, const std::string& host)
      : ConfigChecker(devices, std::vector<std::string>{host}) {}

  // A setting the profiles reject (a value out of range) is a bad study, not a configuration that
  // cannot exist: it throws std::invalid_argument.
  ConfigCheck check(const SweepConfig& config) const;

  // A bank capacity that changes nothing for a run whose steps have at most `max_rays` segments
  // and whose scene has `faces` faces, or 0 (keep the profile's). See config_checker.cpp.
  static std::uint64_t compact_bank_capacity(const board::DeviceProfile& device, std::uint64_t max_rays,
                                             std::uint64_t faces);
  std::uint64_t compact_bank_capacity(const SweepConfig& config, std::uint64_t max_rays, std::uint64_t faces) const {
    return compact_bank_capacity(device(config), max_rays, faces);
  }

  const board::DeviceProfile& device(const std::string& name) const;  // as loaded, with the fixed settings
  board::DeviceProfile device(const SweepConfig& config) const;       // with the configuration's settings too
  HostProfile host(const SweepConfig& config) const;
  const std::string& first_host() const { return host_order_.front(); }
  const pipeline::ResourceModel& resources() const { return resources_; }  // of the source it was made with

 private:
  std::map<std::string, board::DeviceProfile> devices_;
  std::map<std::string, HostProfile> hosts_;
  std::vector<std::string> host_order_;
  pipeline::ResourceModel resources_;
  std::string study_;
  board::RaySplitRule ray_split_;
};

}  // namespace rc
