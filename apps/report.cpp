#include "apps/report.h"

#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace rc {

namespace {

std::ofstream open_output(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  return out;
}

}  // namespace

nlohmann::ordered_json scene_json(const Scene& scene, const std::string& source,
                                  const std::vector<std::string>& warnings) {
  nlohmann::ordered_json j;
  j["name"] = scene.name;
  j["source"] = source;
  j["surfaces"] = scene.surface_names.size();
  j["faces"] = scene.faces.size();
  j["patches"] = scene.patches.size();
  j["normalisation"] = {{"offset", {scene.normalisation.offset.x, scene.normalisation.offset.y,
                                    scene.normalisation.offset.z}},
                        {"scale", scene.normalisation.scale}};
  j["warnings"] = warnings;
  return j;
}

nlohmann::ordered_json solver_json(const SolverResult& r) {
  nlohmann::ordered_json j;
  j["steps"] = r.steps;
  j["converged"] = r.converged;
  j["convergence_reached"] = r.convergence_reached;
  j["max_initial_power"] = r.max_initial_power;
  j["max_unshot_power"] = r.max_unshot_power;
  j["energy"] = {{"emitted", r.energy.emitted},
                 {"absorbed", r.energy.absorbed},
                 {"escaping", r.energy.escaping},
                 {"unshot", r.energy.unshot}};
  j["segments"] = r.segments;
  j["blocked_segments"] = r.blocked_segments;
  j["receivers_skipped"] = r.receivers_skipped;
  return j;
}

void write_json(const std::string& path, const nlohmann::ordered_json& json) {
  std::ofstream out = open_output(path);
  out << json.dump(2) << "\n";
}

void write_patches_csv(const std::string& path, const Scene& scene, const std::vector<Spectrum>& radiosity) {
  std::ofstream out = open_output(path);
  out << "patch,face,centre_x,centre_y,centre_z,area";
  const char* band_names[] = {"r", "g", "b"};
  for (std::size_t b = 0; b < kBands; ++b) {
    out << ",radiosity_" << (kBands == 3 ? band_names[b] : std::to_string(b).c_str());
  }
  out << "\n" << std::setprecision(17);
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const Patch& p = scene.patches[i];
    out << i << ',' << p.face << ',' << p.centre.x << ',' << p.centre.y << ',' << p.centre.z << ',' << p.area;
    for (std::size_t b = 0; b < kBands; ++b) out << ',' << radiosity[i][b];
    out << "\n";
  }
}

}  // namespace rc
