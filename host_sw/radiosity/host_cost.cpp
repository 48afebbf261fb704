#include "host_sw/radiosity/host_cost.h"

namespace rc {

std::string to_string(HostWork work) {
  switch (work) {
    case HostWork::Step: return "step";
    case HostWork::PatchScan: return "patch_scan";
    case HostWork::FormFactor: return "form_factor";
    case HostWork::EnergyUpdate: return "energy_update";
    case HostWork::SegmentSetup: return "segment_setup";
    case HostWork::IntersectionTest: return "intersection_test";
    case HostWork::Count: break;
  }
  return "unknown";
}

}  // namespace rc
