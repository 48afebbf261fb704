// What the guard tests share: a float-visibility solve with a chosen form factor, and the message of
// the SolveDiverged it throws ("" when it converges).
#pragma once

#include <string>

#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/radiosity/radiosity.h"

namespace rc::test {

inline SolverResult solve(const Scene& scene, FormFactorKind kind, bool cull = true) {
  FloatVisibility visibility;
  SolverOptions options;
  options.form_factor = kind;
  options.cull_receivers = cull;
  return ProgressiveRadiosity(scene, visibility, options).run();
}

inline std::string divergence_of(const Scene& scene, FormFactorKind kind) {
  try {
    solve(scene, kind);
  } catch (const SolveDiverged& e) {
    return e.what();
  }
  return "";
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace rc::test
