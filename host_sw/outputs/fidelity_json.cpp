#include "host_sw/outputs/fidelity_json.h"

namespace rc {

namespace {

nlohmann::ordered_json causes_json(const DifferenceCauses& c) {
  return {{"small_determinant", c.small_determinant}, {"neighbour", c.neighbour}, {"lost_face", c.lost_face}, {"near_end", c.near_end}, {"other", c.other}};
}

}  // namespace

nlohmann::ordered_json fidelity_json(const Fidelity& f, double warn_share, const std::string& warning) {
  nlohmann::ordered_json j;
  j["reference"] = "double-precision visibility (the float backend's test, the same own-surface rule)";
  j["arithmetic"] = f.arithmetic;
  j["segments"] = f.population;
  j["sampled"] = f.sampled;
  j["exact"] = f.exact;
  j["decisions_differ"] = f.differing();
  j["false_shadows"] = f.false_shadows;
  j["missing_shadows"] = f.missing_shadows;
  j["share_differ"] = f.share;
  j["confidence"] = 0.95;
  j["share_differ_low"] = f.share_low;
  j["share_differ_high"] = f.share_high;
  j["false_shadow_causes"] = causes_json(f.false_causes);
  j["missing_shadow_causes"] = causes_json(f.missing_causes);
  j["warn_share"] = warn_share;
  j["warning"] = warning.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(warning);
  return j;
}

}  // namespace rc
