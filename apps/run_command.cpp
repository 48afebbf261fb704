#include "apps/run_command.h"

#include <cstdio>
#include <filesystem>

#include "apps/cli_options.h"
#include "apps/progress.h"
#include "apps/report.h"
#include "host_sw/png_writer.h"
#include "host_sw/visibility_factory.h"

namespace rc {

namespace {

void print_summary(const RunOptions& o, const Scene& scene, const SolverResult& r,
                   const VisibilityBackend& vis, double wall) {
  std::printf("rc2000sim run: %s\n", scene.name.c_str());
  std::printf("  scene        %zu faces, %zu patches\n", scene.faces.size(), scene.patches.size());
  std::printf("  solver       %d steps, %.2f%% converged (target %.2f%%), form factor %s\n", r.steps,
              100.0 * r.convergence_reached, 100.0 * o.solver.convergence, to_string(o.solver.form_factor).c_str());
  std::printf("  visibility   %s: %llu segments (%llu blocked), %llu segment-face tests\n", vis.name().c_str(),
              static_cast<unsigned long long>(r.segments), static_cast<unsigned long long>(r.blocked_segments),
              static_cast<unsigned long long>(vis.tests_performed()));
  std::printf("  energy       emitted %.6g = absorbed %.6g + escaping %.6g + unshot %.6g\n", r.energy.emitted,
              r.energy.absorbed, r.energy.escaping, r.energy.unshot);
  std::printf("  wall time    %.2f s\n", wall);
  std::printf("  outputs      %s/report.json, patches.csv, image.png\n", o.out_dir.c_str());
}

}  // namespace

int run_simulation(const RunOptions& o) {
  ProgressLine progress(!o.quiet);
  PreparedScene prepared = prepare_scene(o.scene);
  for (const std::string& w : prepared.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  const Scene& scene = prepared.scene;

  auto visibility = make_software_visibility(o.visibility, o.bits);
  HostWorkCounter work;
  ProgressiveRadiosity solver(scene, *visibility, o.solver, &work);
  solver.on_progress([&](const StepProgress& p) {
    progress.update("step %d, %.2f%% converged", p.step, 100.0 * p.convergence_reached);
  });
  const SolverResult result = solver.run();
  progress.finish();

  std::filesystem::create_directories(o.out_dir);
  const std::string source = o.scene.file.empty() ? "embedded:cornell-box" : o.scene.file;
  nlohmann::ordered_json report;
  report["schema"] = "rc2000sim.run/1";
  report["faces"] = scene.faces.size();
  report["patches"] = scene.patches.size();
  report["steps"] = result.steps;
  report["scene"] = scene_json(scene, source, prepared.warnings);
  report["settings"] = {{"convergence", o.solver.convergence},
                        {"fixed_steps", o.solver.fixed_steps},
                        {"form_factor", to_string(o.solver.form_factor)},
                        {"visibility", o.visibility},
                        {"bits", o.bits},
                        {"face_target", o.scene.face_target},
                        {"face_levels", o.scene.face_levels},
                        {"patch_levels", o.scene.patch_levels}};
  report["solver"] = solver_json(result);
  nlohmann::ordered_json host;
  for (int k = 0; k < kHostWorkKinds; ++k) host[to_string(HostWork(k))] = work.count(HostWork(k));
  report["host_work"] = host;
  report["visibility_tests"] = visibility->tests_performed();
  report["wall_seconds"] = progress.seconds();
  write_json(o.out_dir + "/report.json", report);
  write_patches_csv(o.out_dir + "/patches.csv", scene, result.radiosity);
  write_png(o.out_dir + "/image.png", tone_map(render_radiosity(scene, result.radiosity, o.render), o.render.key));
  print_summary(o, scene, result, *visibility, progress.seconds());
  return 0;
}

}  // namespace rc

namespace rc {

void add_run_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RunOptions>();
  auto solver = std::make_shared<SolverCli>();
  CLI::App* cmd = app.add_subcommand("run", "Solve radiosity for one scene; write report.json, patches.csv, image.png");
  add_scene_options(*cmd, options->scene);
  add_solver_options(*cmd, *solver);
  cmd->add_option("--visibility", options->visibility, "Visibility backend: float or fixed")
      ->check(CLI::IsMember({"float", "fixed"}))->capture_default_str();
  add_bits_option(*cmd, options->bits);
  cmd->add_option("--out", options->out_dir, "Output folder")->capture_default_str();
  cmd->add_option("--image-size", options->render.width, "Image width and height in pixels")
      ->check(CLI::Range(16, 8192))->capture_default_str();
  cmd->add_flag("--quiet", options->quiet, "No progress output");
  cmd->callback([options, solver, &exit_code] {
    options->solver = solver->resolved();
    options->render.height = options->render.width;
    exit_code = run_simulation(*options);
  });
}

}  // namespace rc
