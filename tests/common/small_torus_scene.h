// A small smooth mesh in the Cornell Box for the segment-fix tests (host_sw/radiosity/segment_fixes.h):
// a torus of 2 x nu x nv triangles sharing their vertices, written as an OBJ beside a composition in a
// temporary folder and prepared as `run` prepares a scene.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include <unistd.h>

#include "scenes/prepare.h"

namespace rc::test {

inline Scene small_torus_scene(int nu = 12, int nv = 6, int patch_levels = 0) {
  // Named by the process: tests run in parallel processes, each writing its own files.
  const std::string stem = ::testing::TempDir() + "/small_torus_" + std::to_string(nu) + "x" + std::to_string(nv) + "_" +
                           std::to_string(static_cast<long>(::getpid()));
  const std::string obj = stem + ".obj";
  {
    std::ofstream out(obj);
    const double pi = std::acos(-1.0);
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; j < nv; ++j) {
        const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
        out << "v " << (1 + 0.4 * std::cos(v)) * std::cos(u) << ' ' << 0.4 * std::sin(v) << ' ' << (1 + 0.4 * std::cos(v)) * std::sin(u) << '\n';
      }
    }
    const auto idx = [&](int i, int j) { return (i % nu) * nv + (j % nv) + 1; };
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; j < nv; ++j) {
        out << "f " << idx(i, j) << ' ' << idx(i, j + 1) << ' ' << idx(i + 1, j + 1) << '\n';
        out << "f " << idx(i, j) << ' ' << idx(i + 1, j + 1) << ' ' << idx(i + 1, j) << '\n';
      }
    }
  }
  const std::string json = stem + ".json";
  {
    std::ofstream out(json);
    out << R"({"schema": "rc2000sim.composition/1", "room": "cornell-box", "meshes": [{"file": ")" << obj
        << R"(", "rotate": {"axis": [1, 0, 0], "degrees": 30}, "fit_into": {"min": [300, 0, 100], "max": [520, 200, 320]},)"
        << R"( "material": {"reflectance": [0.75, 0.75, 0.75]}}]})";
  }
  SceneOptions o;
  o.file = json;
  o.patch_levels = patch_levels;
  return prepare_scene(o).scene;
}

}  // namespace rc::test
