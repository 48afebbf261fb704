#include "apps/sweep_fields.h"

#include <cstdio>
#include <string>

#include "profiles/profile_json.h"

namespace rc {

namespace {

void list_fields(const std::string& title, const std::string& prefix, const profiles::ProfileDocument& profile) {
  std::printf("%s\n", title.c_str());
  for (const std::string& f : profile.sourced_fields())
    std::printf("  %-48s %s\n", (prefix + f).c_str(), profile.value_text(f).c_str());
}


}  // namespace

int run_list_fields(const Study& s) {
  for (const std::string& d : s.axes.devices) {
    const board::DeviceProfile p = board::find_device_profile(d);
    list_fields("device profile " + p.file + " (paths as written in [axes] or [fixed]):", "", p.document);
  }
  for (const std::string& h : s.axes.hosts) {
    const HostProfile p = find_host_profile(h);
    list_fields("host profile " + p.file + ":", "host.", p.document);
  }
  std::printf("A leaf name that is unique within its profile may stand for its path (host.segment_pack).\n");
  return 0;
}

}  // namespace rc
