// Command-line options shared by several rc2000sim commands, and the command registry.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "radiosity/radiosity.h"
#include "scenes/prepare.h"

namespace rc {

// Solver options as parsed; the form factor arrives as a name and is resolved after parsing.
struct SolverCli {
  SolverOptions options;
  std::string form_factor = "point";
  SolverOptions resolved() const;
};

void add_scene_options(CLI::App& cmd, SceneOptions& scene);
void add_solver_options(CLI::App& cmd, SolverCli& solver);
void add_bits_option(CLI::App& cmd, int& bits);

// Each command registers itself and, when chosen, stores its exit code in `exit_code`.
void add_run_command(CLI::App& app, int& exit_code);
void add_accuracy_command(CLI::App& app, int& exit_code);
void add_calibrate_command(CLI::App& app, int& exit_code);
void add_paper_command(CLI::App& app, int& exit_code);
void add_sweep_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_adaptive_command(CLI::App& app, int& exit_code);

}  // namespace rc
