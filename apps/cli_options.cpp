#include "apps/cli_options.h"

namespace rc {

SolverOptions SolverCli::resolved() const {
  SolverOptions o = options;
  o.form_factor = parse_form_factor_kind(form_factor);
  return o;
}

void add_scene_options(CLI::App& cmd, SceneOptions& scene) {
  cmd.add_option("--scene", scene.file, "Scene file (docs/scenes.md); default: the embedded Cornell Box")
      ->check(CLI::ExistingFile);
  cmd.add_option("--faces", scene.face_target, "Refine to exactly this many faces first (70: the paper's count)")
      ->check(CLI::NonNegativeNumber);
  cmd.add_option("--face-levels", scene.face_levels, "Split every face into 4^k faces")->check(CLI::Range(0, 8));
  CLI::Option* levels = cmd.add_option("--patch-levels", scene.patch_levels, "Split every face into 4^m patches")
                            ->check(CLI::Range(0, 8))->capture_default_str();
  cmd.add_option("--patch-size", scene.patch_size,
                 "Instead of --patch-levels: split each face until its patches' edges are at most this long "
                 "(normalised units, the scene scaled into [0,1)^3; for meshes that are not grids)")
      ->check(CLI::PositiveNumber)->excludes(levels);
}

void add_solver_options(CLI::App& cmd, SolverCli& solver) {
  cmd.add_option("--convergence", solver.options.convergence,
                 "Stop when max unshot power < (1 - c) x max emitted power")
      ->check(CLI::Range(0.0, 1.0))->capture_default_str();
  cmd.add_option("--steps", solver.options.fixed_steps, "Run exactly this many shooting steps instead")
      ->check(CLI::NonNegativeNumber);
  cmd.add_option("--form-factor", solver.form_factor, "point (paper) or disc")
      ->check(CLI::IsMember({"point", "disc"}))->capture_default_str();
}

void add_bits_option(CLI::App& cmd, int& bits) {
  cmd.add_option("--bits", bits, "Fractional bits of the fixed-point pipeline (7..31)")->check(CLI::Range(7, 31))
      ->capture_default_str();
}

}  // namespace rc
