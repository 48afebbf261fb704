// Machine-readable outputs of a run: report.json (keys documented in docs/outputs.md) and
// patches.csv (one row per patch).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "radiosity/radiosity.h"
#include "scenes/scene.h"

namespace rc {

nlohmann::ordered_json scene_json(const Scene& scene, const std::string& source,
                                  const std::vector<std::string>& warnings);
nlohmann::ordered_json solver_json(const SolverResult& result);
void write_json(const std::string& path, const nlohmann::ordered_json& json);
void write_patches_csv(const std::string& path, const Scene& scene, const std::vector<Spectrum>& radiosity);

}  // namespace rc
