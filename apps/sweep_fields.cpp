#include "apps/sweep_fields.h"

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "board/profile_reader.h"

namespace rc {

namespace {

void list_fields(const std::string& title, const std::string& prefix, const nlohmann::ordered_json& profile) {
  std::printf("%s\n", title.c_str());
  for (const std::string& f : sourced_fields(profile)) {
    const nlohmann::ordered_json* node = &profile;
    for (std::size_t from = 0, dot = 0; dot != std::string::npos; from = dot + 1) {
      dot = f.find('.', from);
      node = &(*node)[f.substr(from, dot == std::string::npos ? std::string::npos : dot - from)];
    }
    std::printf("  %-48s %s\n", (prefix + f).c_str(), (*node)["value"].dump().c_str());
  }
}


}  // namespace

int run_list_fields(const Study& s) {
  for (const std::string& d : s.axes.devices) {
    const board::DeviceProfile p = board::find_device_profile(d);
    list_fields("device profile " + p.file + " (paths as written in [axes] or [fixed]):", "", p.json);
  }
  for (const std::string& h : s.axes.hosts) {
    const HostProfile p = find_host_profile(h);
    list_fields("host profile " + p.file + ":", "host.", p.json);
  }
  std::printf("A leaf name that is unique within its profile may stand for its path (host.segment_pack).\n");
  return 0;
}

}  // namespace rc
