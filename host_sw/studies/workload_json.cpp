#include "host_sw/studies/workload_json.h"

namespace rc {

nlohmann::ordered_json workload_json(const Workload& w, std::uint64_t faces, std::uint64_t patches, int steps) {
  using nlohmann::ordered_json;
  const ConstructionCheck c = check_construction(w, faces, patches);
  ordered_json scene = {{"source", w.source},
                        {"faces", faces},
                        {"patches", patches},
                        {"construction", construction_text(w.scene)},
                        {"paper_construction", to_string(c.kind)}};
  if (c.kind == Construction::other) {
    scene["paper_options"] = construction_text(c.paper);
    scene["note"] = c.note;
  }
  ordered_json j;
  j["scene"] = scene;
  const bool fixed = w.steps.kind == StepsChoice::Kind::fixed;
  j["steps"] = {{"policy", fixed ? "fixed" : to_string(w.steps)},  // paper, converge or fixed
                {"count", fixed ? ordered_json(w.steps.steps) : ordered_json()},
                {"convergence", w.convergence},
                {"solved", steps > 0 ? ordered_json(steps) : ordered_json()}};
  j["segments"] = w.paper_faithful ? "paper-faithful" : "culled";
  j["form_factor"] = to_string(w.form_factor);
  return j;
}

}  // namespace rc
