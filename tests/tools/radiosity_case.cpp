// Writes one solved case for the independent reference solver (tests/reference/radiosity_reference.py,
// docs/radiosity.md "How the solver is checked"): the prepared scene (normalised faces with their
// materials, surfaces and sheets; patches with vertices, centres, normals and areas) and what the C++
// solver made of it with double-precision visibility (FloatVisibility): radiosity per patch, steps,
// segments, blocked segments, skipped receivers, segment-face tests and the energy balance; or, when
// the solver's energy guard stops the solve (SolveDiverged), its message.
// A test helper, not a user-facing format: JSON because Python reads it without a parser of ours,
// with every double written to round-trip exactly.
//
//   radiosity_case [--scene FILE] [--patch-levels N] [--form-factor point|disc|analytic]
//                  [--convergence C] --out CASE.json
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/radiosity/form_factor.h"
#include "host_sw/radiosity/radiosity.h"
#include "scenes/prepare.h"

namespace {

using nlohmann::json;

json vec(const rc::Vec3& v) { return json::array({v.x, v.y, v.z}); }
json spectrum(const rc::Spectrum& s) { return json(s.band); }
json triangle(const rc::Triangle& t) { return json::array({vec(t.v0), vec(t.v1), vec(t.v2)}); }

struct Arguments {
  rc::SceneOptions scene;
  rc::SolverOptions solver;
  std::string out;
};

Arguments parse(int argc, char** argv) {
  Arguments a;
  a.scene.patch_levels = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (i + 1 >= argc) throw std::invalid_argument(key + " needs a value");
    const std::string value = argv[++i];
    if (key == "--scene") {
      a.scene.file = value;
    } else if (key == "--patch-levels") {
      a.scene.patch_levels = std::stoi(value);
    } else if (key == "--form-factor") {
      a.solver.form_factor = rc::parse_form_factor_kind(value);
    } else if (key == "--convergence") {
      a.solver.convergence = std::stod(value);
    } else if (key == "--out") {
      a.out = value;
    } else {
      throw std::invalid_argument("unknown option " + key +
                                  " (expected --scene, --patch-levels, --form-factor, --convergence, --out)");
    }
  }
  if (a.out.empty()) throw std::invalid_argument("--out CASE.json is required");
  return a;
}

json scene_json(const rc::Scene& scene) {
  json materials = json::array();
  for (const rc::Material& m : scene.materials) {
    materials.push_back({{"name", m.name}, {"reflectance", spectrum(m.reflectance)}, {"emission", spectrum(m.emission)}});
  }
  json faces = json::array();
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    const rc::Face& face = scene.faces[f];
    faces.push_back({{"vertices", triangle(face.tri)},
                     {"material", face.material},
                     {"surface", face.surface},
                     {"sheet", scene.sheets.first(static_cast<int>(f))}});
  }
  json patches = json::array();
  for (const rc::Patch& p : scene.patches) {
    patches.push_back({{"vertices", triangle(p.tri)},
                       {"face", p.face},
                       {"centre", vec(p.centre)},
                       {"normal", vec(p.normal)},
                       {"area", p.area}});
  }
  return {{"name", scene.name}, {"materials", materials}, {"faces", faces}, {"patches", patches}};
}

json result_json(const rc::SolverResult& r, std::uint64_t tests) {
  json radiosity = json::array();
  for (const rc::Spectrum& b : r.radiosity) radiosity.push_back(spectrum(b));
  return {{"radiosity", radiosity},
          {"steps", r.steps},
          {"converged", r.converged},
          {"segments", r.segments},
          {"blocked_segments", r.blocked_segments},
          {"receivers_skipped", r.receivers_skipped},
          {"tests_performed", tests},
          {"steps_above_one", r.form_factor_sums.steps_above_one},
          {"energy",
           {{"emitted", r.energy.emitted},
            {"absorbed", r.energy.absorbed},
            {"escaping", r.energy.escaping},
            {"unshot", r.energy.unshot}}}};
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Arguments a = parse(argc, argv);
    const rc::Scene scene = rc::prepare_scene(a.scene).scene;
    rc::FloatVisibility visibility;
    json out = {{"scene", scene_json(scene)},
                {"solver",
                 {{"form_factor", rc::to_string(a.solver.form_factor)},
                  {"convergence", a.solver.convergence},
                  {"cull_receivers", a.solver.cull_receivers},
                  {"visibility", visibility.name()}}}};
    try {
      const rc::SolverResult result = rc::ProgressiveRadiosity(scene, visibility, a.solver).run();
      out["result"] = result_json(result, visibility.tests_performed());
    } catch (const rc::SolveDiverged& e) {
      // The energy guard refused the solve (docs/radiosity.md, Guards): the reference must find the
      // same step creating energy.
      out["result"] = {{"diverged", e.what()}};
    }
    std::ofstream file(a.out);
    file << out.dump();
    file.close();
    if (!file) throw std::runtime_error("cannot write " + a.out);
  } catch (const std::exception& e) {
    std::cerr << "radiosity_case: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
