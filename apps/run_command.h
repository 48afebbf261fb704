// `rc2000sim run`: one radiosity simulation from scene to report, patch table and image.
#pragma once

#include <string>

#include "host_sw/radiosity.h"
#include "host_sw/render.h"
#include "scenes/prepare.h"

namespace rc {

struct RunOptions {
  SceneOptions scene;
  SolverOptions solver;  // resolved from SolverCli
  std::string visibility = "float";  // float | fixed
  int bits = 15;                     // fractional bits of the fixed-point pipeline
  std::string out_dir = "out";
  RenderOptions render;
  bool quiet = false;
};

// Returns the process exit code.
int run_simulation(const RunOptions& options);

}  // namespace rc
