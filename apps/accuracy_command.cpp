// `rc2000sim accuracy`: what the pipeline's arithmetic does to the picture. For each fixed-point
// width and each floating-point format (paper sec 6: "a narrower total bitwidth, saving
// bandwidth"), the radiosity solved with that bit-exact pipeline arithmetic is compared with the
// double-precision solution (RMSE and max error of patch radiosity), and the visibility decisions
// that differ are counted along the double solver's own trajectory (same shooters, same segments).
// Each row also gives the bytes one intersection moves (sec 5.6(a)'s count: three coordinates
// read, one result bit written), so error can be set against bandwidth.
#include <cstdio>
#include <memory>
#include <sstream>

#include "apps/cli_options.h"
#include "apps/outputs.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "pipeline/float_format.h"
#include "host_sw/studies/fidelity.h"

namespace rc {

namespace {

struct AccuracyOptions {
  SceneOptions scene;
  SolverOptions solver;
  std::vector<int> widths{7, 11, 15, 19, 23, 27, 31};
  // Single, half, and narrower formats of about the fixed widths' sizes (docs/results/accuracy.md).
  std::vector<std::string> formats{"float:8,23", "float:6,13", "float:5,10", "float:5,7", "float:4,5"};
  std::string out_dir = "out/accuracy";
  bool quiet = false;
};

struct WidthResult {
  std::string arithmetic;          // "fixed:15", "float:5,10"
  int bits = 0;                    // fixed: fractional bits; float: 0
  int coordinate_bits = 0;         // bits of one coordinate value (fixed: N; float: 1 + E + M)
  double bytes_per_intersection = 0;
  int steps = 0;
  SolutionError error;
  std::uint64_t segments_compared = 0, fixed_only_blocks = 0, float_only_blocks = 0;
};

// One row of the table from the fidelity study's (host_sw/studies/fidelity.h).
WidthResult width_result(const ArithmeticFidelity& f) {
  WidthResult r;
  const bool is_float = f.arithmetic.is_float();
  r.arithmetic = f.arithmetic.label();
  r.bits = is_float ? 0 : f.arithmetic.bits;
  r.coordinate_bits = is_float ? pipeline::parse_float_format(f.arithmetic.backend).bits_per_value() : f.arithmetic.bits;
  // As the banks store them: floor(32 / b) coordinates to a 32-bit word, so each takes 32 / floor(32 / b)
  // bits (for fixed point exactly the bank layout's field, board/bank_layout.h); sec 5.6(a)'s count:
  // three coordinates read, one result bit written.
  const int packed_bits = 32 / (32 / r.coordinate_bits);
  r.bytes_per_intersection = 3.0 * packed_bits / 8.0 + 1.0 / 8.0;
  r.steps = f.run.result.steps;
  r.error = f.error;
  r.segments_compared = f.decisions.compared;
  r.fixed_only_blocks = f.decisions.arithmetic_only;
  r.float_only_blocks = f.decisions.double_only;
  return r;
}

std::string width_rows_csv(const std::vector<WidthResult>& rows, int float_steps) {
  std::ostringstream out;
  out << "arithmetic,bits,coordinate_bits,bytes_per_intersection,steps,float_steps,rmse,max_abs_error,relative_rmse,"
         "relative_max_error,segments,decisions_differ,fixed_blocks_float_clear,float_blocks_fixed_clear\n";
  for (const WidthResult& r : rows) {
    out << '"' << r.arithmetic << '"' << ',' << (r.bits > 0 ? std::to_string(r.bits) : std::string()) << ',' << r.coordinate_bits
        << ',' << r.bytes_per_intersection << ',' << r.steps << ',' << float_steps << ',' << r.error.rmse << ',' << r.error.max_abs << ','
        << r.error.relative_rmse() << ',' << r.error.relative_max() << ',' << r.segments_compared << ','
        << r.fixed_only_blocks + r.float_only_blocks << ',' << r.fixed_only_blocks << ',' << r.float_only_blocks
        << "\n";
  }
  return out.str();
}

int run_accuracy(const AccuracyOptions& o) {
  const std::string csv = o.out_dir + "/accuracy.csv", png = o.out_dir + "/accuracy.png";
  Outputs outputs;
  outputs.own_folder(o.out_dir, "accuracy");
  outputs.expect(csv);
  outputs.expect(png);
  ProgressLine progress(!o.quiet);
  const Scene scene = prepare_scene(o.scene, [&](const std::string& what) { progress.update("%-60s", what.c_str()); }).scene;
  std::vector<Arithmetic> arithmetics;
  for (int bits : o.widths) arithmetics.push_back(Arithmetic::fixed(bits));
  for (const std::string& format : o.formats) arithmetics.push_back(Arithmetic::floating(format));
  FidelityOptions fidelity;
  fidelity.progress = [&](const std::string& what) { progress.update("%-60s", what.c_str()); };
  const FidelityResult measured = measure_fidelity(scene, o.solver, arithmetics, fidelity);
  const SolverResult& reference = measured.reference;
  std::vector<WidthResult> rows;
  for (const ArithmeticFidelity& f : measured.rows) rows.push_back(width_result(f));
  progress.finish();
  outputs.add(csv, width_rows_csv(rows, reference.steps));
  outputs.write();
  const bool drawn = plot("accuracy.py", csv, png);

  std::printf("rc2000sim accuracy: %zu faces, %zu patches, float reference %d steps\n", scene.faces.size(),
              scene.patches.size(), reference.steps);
  std::printf("%-11s %6s %6s %12s %12s %14s %12s\n", "arithmetic", "B/int", "steps", "rel. RMSE", "rel. max",
              "decisions", "differ %");
  for (const WidthResult& r : rows) {
    const std::uint64_t differ = r.fixed_only_blocks + r.float_only_blocks;
    std::printf("%-11s %6.3f %6d %12.3e %12.3e %14llu %12.4f\n", r.arithmetic.c_str(), r.bytes_per_intersection, r.steps,
                r.error.relative_rmse(),
                r.error.relative_max(), static_cast<unsigned long long>(differ),
                100.0 * double(differ) / double(r.segments_compared ? r.segments_compared : 1));
  }
  std::printf("errors relative to the mean float radiosity; decisions compared on %llu segments per width\n",
              static_cast<unsigned long long>(rows.empty() ? 0 : rows.front().segments_compared));
  std::printf("wrote %s%s (%.1f s)\n", csv.c_str(), drawn ? (" and " + png).c_str() : "", progress.seconds());
  return 0;
}

}  // namespace

void add_accuracy_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<AccuracyOptions>();
  auto solver = std::make_shared<SolverCli>();
  CLI::App* cmd = app.add_subcommand("accuracy", "Radiosity error and visibility decisions per fixed-point width and floating-point format, against double precision");
  add_scene_options(*cmd, options->scene);
  add_solver_options(*cmd, *solver);
  cmd->add_option("--widths", options->widths, "Fractional widths of the fixed-point pipeline to measure")
      ->check(CLI::Range(7, 31))->delimiter(',')->capture_default_str();
  cmd->add_option("--formats", options->formats,
                  "Floating-point formats to measure (float:E,M; space- or ';'-separated; 'none' for none)")
      ->delimiter(';')->capture_default_str();
  cmd->add_option("--out", options->out_dir, "Output folder")->check(output_path())->capture_default_str();
  cmd->add_flag("--quiet", options->quiet, "No progress output");
  add_jobs_option(*cmd, "threads of the reference's answers and solves run at once");
  cmd->callback([options, solver, cmd, &exit_code] {
    options->solver = solver->resolved(*cmd);
    if (options->formats == std::vector<std::string>{"none"}) options->formats.clear();
    check_float_formats("--formats", options->formats);  // before any work
    exit_code = run_guarded("accuracy", options->out_dir + "/", [&] { return run_accuracy(*options); });
  });
}

}  // namespace rc
