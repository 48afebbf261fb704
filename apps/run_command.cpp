#include "apps/run_command.h"

#include <array>
#include <optional>
#include <string>
#include <vector>
#include <cstdio>
#include <stdexcept>

#include <systemc>

#include "apps/cli_options.h"
#include "apps/outputs.h"
#include "apps/progress.h"
#include "apps/report.h"
#include "io/parse_number.h"
#include "host_sw/studies/timing_interval.h"
#include "host_sw/platform/run_bounds.h"
#include "host_sw/radiosity/png_writer.h"
#include "host_sw/studies/workload.h"
#include "host_sw/studies/workload_json.h"
#include "pipeline/float_format.h"
#include "rtl/lanes/rtl_lanes.h"
#include "rtl/sim/rtl_pipeline.h"
#include "host_sw/radiosity/energy_plausibility.h"
#include "host_sw/visibility/fixed_visibility.h"
#include "host_sw/visibility/visibility_factory.h"
#include "host_sw/outputs/fidelity_json.h"
#include "apps/segment_fix_options.h"
#include "host_sw/outputs/run_report_json.h"
#include "host_sw/outputs/trace_json.h"

namespace rc {

namespace {

// What one run produced, whichever implementation answered visibility.
struct RunOutcome {
  SolverResult solver;
  std::string visibility_name;
  std::uint64_t visibility_tests = 0;
  // Board runs on the calibrated host: the simulated time's interval and the workload's range warnings
  // (host_sw/studies/timing_interval.h); empty elsewhere, with why in interval_absent.
  std::optional<TimingInterval> interval;
  std::string interval_absent;
  std::array<std::uint64_t, kHostWorkKinds> work_counts{};  // software runs
  std::optional<RunReport> board;                           // board runs
  std::optional<LanesThatFit> lanes_that_fit;               // board runs: sec 5.6 on the run's device
  std::string trace_json;                                   // board runs with --trace
  std::optional<Fidelity> fidelity;                         // runs in the pipeline's arithmetic, sampled
  std::string fidelity_warning;                             // "" when within --fidelity-warn
};

bool float_arith(const RunOptions& o) { return o.arith.is_float(); }
// Whether the run's visibility has a fractional width (--bits): the board's fixed lanes and the
// bit-exact software backends do; float formats and double precision do not.
bool uses_fixed_width(const RunOptions& o) { return !float_arith(o) && (o.impl == Impl::board || o.visibility != SoftwareVisibility::float_double); }

// A warning when faces have no area on the width's grid (a silent wrong answer otherwise: they
// block nothing); nothing for a scene whose faces all survive quantisation.
std::optional<std::string> faces_lost_at_width(const Scene& scene, int bits) {
  const std::vector<std::size_t> lost = faces_without_area(scene.faces, bits);
  if (lost.empty()) return std::nullopt;
  const int surface = scene.faces[lost.front()].surface;
  const std::string surface_name = scene.surface_name(surface);
  return "at " + std::to_string(bits) + " fractional bits " + std::to_string(lost.size()) + " of " +
         std::to_string(scene.faces.size()) + " faces (the first: face " + std::to_string(lost.front()) + " of surface '" +
         (surface_name.empty() ? std::to_string(surface) : surface_name) + "') have no area on the 2^-" + std::to_string(bits) +
         " grid of the normalised scene, so the fixed-point visibility never finds them blocking and their "
         "shadows are missing; raise --bits, or bring the scene's parts closer together";
}

// Whether the run answers in the pipeline's arithmetic (fixed at --bits or float:E,M), whose decisions
// the fidelity sample checks; double precision is the reference itself.
bool in_pipeline_arithmetic(const RunOptions& o) { return o.impl == Impl::board || float_arith(o) || o.visibility != SoftwareVisibility::float_double; }

// The run's fidelity from its sample (decision_sample.h), and its warning; progress says it is checking.
void measure_fidelity(const RunOptions& o, const Scene& scene, const DecisionSampler& sampler, RunOutcome& out,
                      ProgressLine& progress) {
  if (!in_pipeline_arithmetic(o) || o.fidelity_sample == 0) return;
  progress.update("checking %zu sampled segments against double precision", sampler.sample().size());
  out.fidelity = estimate_fidelity(scene, sampler.sample(), sampler.population(), o.arith, o.bits, 0, o.solver.fixes.t_guard);
  out.fidelity_warning = fidelity_warning(*out.fidelity, o.fidelity_warn, o.bits);
}

RunOutcome run_software(const RunOptions& o, const Scene& scene, ProgressLine& progress, const RunHooks& hooks) {
  // A float pipeline (--arith float:E,M) answers as the backend of that name (pipeline/float_mt.h).
  auto visibility = make_software_visibility(float_arith(o) ? o.arith.name() : choice_name(o.visibility), o.bits, 0,
                                             o.solver.fixes.t_guard);
  HostWorkCounter work;
  ProgressiveRadiosity solver(scene, *visibility, o.solver, &work);
  solver.on_progress([&](const StepProgress& p) {
    progress.update("step %d, %.2f%% converged", p.step, 100.0 * p.convergence_reached);
    if (hooks.on_step) hooks.on_step(p, 0.0);
  });
  DecisionSampler sampler(in_pipeline_arithmetic(o) ? o.fidelity_sample : 0);
  solver.on_answers(sampler.observer());
  RunOutcome out;
  progress.update("solving %zu patches against %zu faces (%s visibility), step 1", scene.patches.size(), scene.faces.size(),
                  visibility->name().c_str());
  out.solver = solver.run();
  measure_fidelity(o, scene, sampler, out, progress);
  out.visibility_name =
      visibility->name() + (o.visibility != SoftwareVisibility::float_double && !float_arith(o) ? " " + std::to_string(o.bits) + "-bit" : "");
  out.visibility_tests = visibility->tests_performed();
  for (int k = 0; k < kHostWorkKinds; ++k) out.work_counts[k] = work.count(HostWork(k));
  return out;
}

// "A:B" -> first and last step (1-based, inclusive); each side whole ("1x:3" is refused).
void parse_trace_steps(const std::string& text, BoardRunOptions& board) {
  const auto colon = text.find(':');
  const std::optional<std::uint64_t> first = colon == std::string::npos ? std::nullopt : io::parse_unsigned(text.substr(0, colon));
  const std::optional<std::uint64_t> last = colon == std::string::npos ? std::nullopt : io::parse_unsigned(text.substr(colon + 1));
  if (!first || !last) refuse_option("--trace-steps", "expects FIRST:LAST, e.g. 1:3, got '" + text + "'");
  if (*first < 1 || *last < *first || *last > static_cast<std::uint64_t>(SolverOptions{}.max_steps)) {
    refuse_option("--trace-steps",
                  "needs 1 <= FIRST <= LAST <= " + std::to_string(SolverOptions{}.max_steps) + ", got '" + text + "'");
  }
  board.trace_first_step = static_cast<int>(*first);
  board.trace_last_step = static_cast<int>(*last);
}

// `vcd` is where SystemC writes the VCD while it simulates (a temporary file), or empty.
// The board run's options as the command line gives them (no oracle, progress or VCD yet).
BoardRunOptions board_options(const RunOptions& o) {
  BoardRunOptions board = o.board;
  board.vcd_path.clear();  // --vcd: the final path; SystemC writes a temporary file (run_board)
  board.trace = !o.trace_path.empty();
  board.bits = o.bits;
  if (!o.cpu_share.empty()) board.cpu_split = parse_cpu_split(o.cpu_share, o.cpu_cores);
  board.ray_split = board::parse_ray_split(o.ray_split);
  if (float_arith(o)) board.float_format = o.arith.float_format();  // float lanes
  if (o.lanes_impl == LanesImpl::rtl) {  // the Verilated RTL in the cycle-level wrapper; it computes
    board.model = board::WrapperModel::cycle;
    board.clocked_lanes = rtl::rtl_lanes_factory();
  }
  return board;
}

RunOutcome run_board(const RunOptions& o, const Scene& scene, ProgressLine& progress, const std::string& vcd,
                     const RunHooks& hooks) {
  BoardRunOptions board = board_options(o);
  board.vcd_path = vcd;
  // The lanes copy the culled kernel's answer, proven bit-identical (tests BoardOracle.*, FastVisibility.*);
  // float lanes copy the `float:E,M` software backend's (tests BoardSystem.FloatLanes*).
  std::unique_ptr<VisibilityBackend> oracle;
  if (!o.lanes_compute && o.lanes_impl == LanesImpl::cpp) {
    oracle = make_functional_answer(float_arith(o) ? o.arith.name() : "fast", o.bits, 0, o.solver.fixes.t_guard);
    board.oracle = oracle.get();
  }
  if (board.trace) parse_trace_steps(o.trace_steps, board);
  board.on_progress = [&](const StepProgress& p) {
    progress.update("step %d, %.2f%% converged", p.step, 100.0 * p.convergence_reached);
    if (hooks.on_step) hooks.on_step(p, sc_core::sc_time_stamp().to_seconds());  // when the step ended
  };
  // Sec 5.6 on the run's device, from the profiles the run uses (loaded once, by run_simulation).
  // Estimated before the simulation: a profile that cannot give the estimate is said so by an
  // exception caught here, and once SystemC has switched stacks AddressSanitizer cannot follow a
  // throw (docs/reliability.md, "Sanitizers").
  LanesThatFit fit = float_arith(o) ? lanes_that_fit(*board.device_profile, *board.host_profile, o.arith.float_format())
                                    : lanes_that_fit(*board.device_profile, *board.host_profile, o.bits, board.resources);
  DecisionSampler sampler(o.fidelity_sample);
  board.on_answers = sampler.observer();
  progress.update("solving %zu patches against %zu faces on the board, step 1", scene.patches.size(), scene.faces.size());
  BoardRunResult r = run_radiosity_on_board(scene, o.solver, board);
  RunOutcome out;
  out.solver = std::move(r.solver);
  measure_fidelity(o, scene, sampler, out, progress);
  out.visibility_name = "board " + board.device + ", " + std::to_string(board.lanes.value()) + " lane(s), " +
                        (float_arith(o) ? o.arith.name() : std::to_string(o.bits) + "-bit") +
                        (o.lanes_impl == LanesImpl::rtl ? " RTL lanes" : "") + (board.concurrent ? ", concurrent" : ", serial") +
                        (board.cpu_split.on() ? ", cpu share " + board.cpu_split.name() : "") +
                        (board.chunk_rays != 0 ? ", chunks of " + std::to_string(board.chunk_rays) : "") +
                        (o.board.cards > 1 ? ", " + std::to_string(o.board.cards) + " cards (split " + choice_name(o.board.card_split) + ", " +
                                           choice_name(o.board.card_bus) + " bus)"
                                     : "");
  // The board's tests and, with a CPU/FPGA split, the host's (0 otherwise).
  out.visibility_tests = r.report.intersections.tests + r.report.work[static_cast<int>(HostWork::IntersectionTest)].count;
  out.board = std::move(r.report);
  // The calibration's error applies to the profile it was fitted as (docs/calibration.md).
  if (board.host == BoardRunOptions{}.host) {
    out.interval = timing_interval(out.board->simulated_seconds, scene.faces.size(), scene.patches.size());
    for (const std::string& w : out.interval->warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  } else {
    out.interval_absent = "host " + board.host + " is not the calibrated profile " + BoardRunOptions{}.host +
                          ": the calibration's error does not apply";
  }
  if (r.trace) out.trace_json = trace_json(*r.trace);
  out.lanes_that_fit = std::move(fit);
  return out;
}

// Joules, not the light's energy above (docs/energy.md): the total, per step and per intersection,
// and each component's share; or why there are none.
void print_electrical_energy(const RunReport& b) {
  if (!b.energy) {
    std::printf("  electricity  not estimated: %s\n", b.energy_missing.c_str());
    return;
  }
  const energy::EnergyReport& e = *b.energy;
  std::string parts;
  for (const energy::ComponentEnergy& c : e.components) {
    char part[96];
    std::snprintf(part, sizeof part, "%s%s %.4g J", parts.empty() ? "" : ", ", c.name.c_str(), c.joules());
    parts += part;
  }
  std::printf("  electricity  %.4g J (%.4g J per step, %.4g nJ per intersection, %.4g W average): %s\n", e.joules,
              e.joules_per_step, e.joules_per_intersection * 1e9, e.average_watts, parts.c_str());
}

void print_board_summary(const RunReport& b) {
  const RunTime& t = b.time;
  std::printf("  simulated    %.6f s = host compute %.6f + driver %.6f + PCI %.6f + waiting %.6f\n", b.simulated_seconds,
              t.host_compute, t.driver_cpu, t.pci_transfer, t.waiting);
  if (t.second_cpu) {
    std::printf("  second cpu   computes %.6f s beside the first, which waits %.6f s for it (in simulated above)\n",
                t.second_cpu_compute, t.second_cpu_wait);
  }
  const WorkTally& software_tests = b.work[static_cast<int>(HostWork::IntersectionTest)];
  if (software_tests.count > 0) {  // the CPU/FPGA split (docs/board.md)
    std::printf("  cpu split    %llu software segment-face tests (%.6f s), %llu board segment-face pairs streamed\n",
                static_cast<unsigned long long>(software_tests.count), software_tests.seconds,
                static_cast<unsigned long long>(b.intersections.tests));
  }
  std::printf("  FPGA         busy %.6f s (overlapping host compute %.6f s), %.4g intersections/s while busy\n",
              t.fpga_busy, t.overlap, b.intersections.per_second_while_fpga_busy);
  std::printf("  board        %s at %.3f MHz, %u banks (rays split: %s), %llu passes, %.4g MB over PCI\n",
              b.board.device.profile.c_str(), b.board.device.clock_hz / 1e6, b.board.device.banks,
              b.board.layout.ray_split.c_str(),
              static_cast<unsigned long long>(b.board.batching.passes),
              (static_cast<double>(b.board.pci.bytes_to_board) + static_cast<double>(b.board.pci.bytes_to_host)) / 1e6);
  // What bounds the run and its FPGA stream, and the bandwidth each resource gave (docs/board.md,
  // "What bounds a run"), instead of one utilisation line per lane.
  const RunBounds bounds = run_bounds(b);
  std::printf("  bound        %s\n", bounds.summary().c_str());
  std::printf("  bandwidth    %s\n", bounds.bandwidth_line().c_str());
  for (const CardReport& c : b.board.cards.per_card) {
    std::printf("  card %-7u %llu passes, FPGA busy %.6f s, PCI bus busy %.6f s (waited %.6f s), driver idle %.6f s\n",
                c.card, static_cast<unsigned long long>(c.passes), c.fpga_busy_seconds, c.pci_bus_busy_seconds,
                c.pci_bus_wait_seconds, c.idle_seconds);
  }
  for (std::size_t i = 0; i < b.board.cards.buses.size(); ++i) {
    std::printf("  PCI bus %-4zu %zu card(s), utilisation %.1f%%\n", i, b.board.cards.buses[i].cards.size(),
                100.0 * b.board.cards.buses[i].utilisation);
  }
  print_electrical_energy(b);
}

void print_summary(const RunOptions& o, const Scene& scene, const RunOutcome& out, double wall,
                   const std::vector<std::string>& written) {
  const SolverResult& r = out.solver;
  std::printf("rc2000sim run: %s\n", scene.name.c_str());
  std::printf("  scene        %zu faces, %zu patches\n", scene.faces.size(), scene.patches.size());
  std::printf("  solver       %d steps%s, %.2f%% converged (target %.2f%%), form factor %s\n", r.steps,
              r.exhausted ? " (stopped: nothing left to shoot is a normal number)" : "", 100.0 * r.convergence_reached,
              100.0 * o.solver.convergence, to_string(o.solver.form_factor).c_str());
  // Each count under its own name (docs/outputs.md, "Counts of visibility work"): software tests are
  // the pairs a software backend tested, board pairs the pairs the lanes streamed.
  if (out.board) {
    std::printf("  visibility   %s: %llu segments (%llu blocked), %llu board segment-face pairs streamed\n",
                out.visibility_name.c_str(), static_cast<unsigned long long>(r.segments),
                static_cast<unsigned long long>(r.blocked_segments),
                static_cast<unsigned long long>(out.board->intersections.tests));
  } else {
    std::printf("  visibility   %s: %llu segments (%llu blocked), %llu software segment-face tests\n",
                out.visibility_name.c_str(), static_cast<unsigned long long>(r.segments),
                static_cast<unsigned long long>(r.blocked_segments), static_cast<unsigned long long>(out.visibility_tests));
  }
  if (out.fidelity) std::printf("  fidelity     %s\n", fidelity_line(*out.fidelity).c_str());
  if (const std::string fixes = segment_fix_summary(o.solver.fixes, r); !fixes.empty()) std::printf("  fixes        %s\n", fixes.c_str());
  std::printf("  energy       emitted %.6g = absorbed %.6g + escaping %.6g + unshot %.6g\n", r.energy.emitted,
              r.energy.absorbed, r.energy.escaping, r.energy.unshot);
  if (out.board) {
    print_board_summary(*out.board);
    if (out.interval) {
      std::printf("  interval     %s\n", out.interval->text().c_str());
      for (const std::string& w : out.interval->warnings) std::printf("  warning      %s\n", w.c_str());
    } else {
      std::printf("  interval     none: %s\n", out.interval_absent.c_str());
    }
    std::printf("  sec 5.6      lanes that fit on %s\n", lanes_that_fit_line(*out.lanes_that_fit).c_str());
  }
  std::printf("  wall time    %.2f s\n", wall);
  if (!written.empty()) std::printf("  wrote        %s\n", listed(written).c_str());
}

nlohmann::ordered_json make_report(const RunOptions& o, const PreparedScene& prepared, const RunOutcome& out,
                                   const std::vector<std::string>& solver_warnings, const std::string& image_warning,
                                   double wall) {
  const Scene& scene = prepared.scene;
  nlohmann::ordered_json report;
  report["schema"] = "rc2000sim.run/1";
  report["faces"] = scene.faces.size();
  report["patches"] = scene.patches.size();
  report["steps"] = out.solver.steps;
  if (out.board) {
    report["simulated_seconds"] = out.board->simulated_seconds;
    if (out.interval) {
      report["timing_interval"] = {{"low_seconds", out.interval->low_seconds},
                                   {"high_seconds", out.interval->high_seconds},
                                   {"left_out_error_low", out.interval->error_low},
                                   {"left_out_error_high", out.interval->error_high},
                                   {"left_out_errors", out.interval->errors},
                                   {"how", "simulated seconds / (1 + e), e the 10% and 90% quantiles of the calibration's "
                                           "left-out relative errors (docs/calibration.md, Prediction intervals)"},
                                   {"range_warnings", out.interval->warnings}};
    } else {
      report["timing_interval"] = {{"none", out.interval_absent}};
    }
  }
  report["scene"] = scene_json(scene, o.scene.file.empty() ? "embedded:cornell-box" : o.scene.file, prepared.warnings);
  report["workload"] = workload_json(run_workload(o.scene, o.solver), scene.faces.size(), scene.patches.size(),
                                     out.solver.steps);
  report["settings"] = {{"impl", choice_name(o.impl)},
                        {"convergence", o.solver.convergence},
                        {"fixed_steps", o.solver.fixed_steps},
                        {"form_factor", to_string(o.solver.form_factor)},
                        {"visibility", o.impl == Impl::board ? "board" : float_arith(o) ? o.arith.name() : choice_name(o.visibility)},
                        {"arith", o.arith.name()},
                        {"cards", o.impl == Impl::board ? nlohmann::ordered_json(o.board.cards.value()) : nlohmann::ordered_json()},
                        {"card_split", o.impl == Impl::board && o.board.cards > 1 ? nlohmann::ordered_json(choice_name(o.board.card_split))
                                                                        : nlohmann::ordered_json()},
                        {"card_bus", o.impl == Impl::board && o.board.cards > 1 ? nlohmann::ordered_json(choice_name(o.board.card_bus))
                                                                      : nlohmann::ordered_json()},
                        {"bits", uses_fixed_width(o) ? nlohmann::ordered_json(o.bits) : nlohmann::ordered_json()},
                        {"face_target", o.scene.face_target},
                        {"face_levels", o.scene.face_levels},
                        {"patch_levels", o.scene.patch_size > 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(o.scene.patch_levels)},
                        {"patch_size", o.scene.patch_size > 0 ? nlohmann::ordered_json(o.scene.patch_size) : nlohmann::ordered_json()}};
  // Every other option that can change a figure, as used (the profile's value where the option was not
  // given); null where it does not apply (a software run has no board). Tested by walking `run --help`
  // (tests/scripts/report_settings_test.sh): an option missing here fails it.
  const bool board = o.impl == Impl::board;
  const auto on_board = [&](nlohmann::ordered_json v) { return board ? std::move(v) : nlohmann::ordered_json(); };
  nlohmann::ordered_json& settings = report["settings"];
  settings["scene"] = o.scene.file.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(o.scene.file);
  settings["paper_faithful"] = !o.solver.cull_receivers;
  settings["image_size"] = o.render.width;
  settings["offset_lsb"] = o.solver.fixes.offset_lsb;
  settings["neighbour_rings"] = o.solver.fixes.neighbour_rings;
  settings["coordinate_bits"] = o.solver.fixes.coordinate_bits;
  settings["t_guard"] = o.solver.fixes.t_guard;
  settings["fidelity_sample"] = o.fidelity_sample;
  settings["fidelity_warn"] = o.fidelity_warn;
  settings["device"] = on_board(o.board.device);
  settings["host"] = on_board(o.board.host);
  settings["lanes"] = on_board(o.board.lanes.value());
  settings["banks"] = on_board(o.board.banks != 0 || !o.board.device_profile ? o.board.banks : o.board.device_profile->bank_count);
  settings["concurrent"] = on_board(o.board.concurrent);
  settings["lanes_impl"] = on_board(choice_name(o.lanes_impl));
  settings["lanes_compute"] = on_board(o.lanes_compute);
  settings["resources"] = on_board(choice_name(o.board.resources));
  settings["ray_split"] = on_board(o.ray_split);
  if (board && o.board.host_profile) {
    const DriverModel& driver = o.board.host_profile->driver_model;
    const CpuSplit split = o.cpu_share.empty() ? driver.cpu_split : parse_cpu_split(o.cpu_share, o.cpu_cores);
    settings["cpu_share"] = !split.on()                                ? nlohmann::ordered_json()
                            : split.mode == CpuSplit::Mode::balanced ? nlohmann::ordered_json("balanced")
                                                                     : nlohmann::ordered_json(split.share);
    settings["cpu_cores"] = split.on() ? nlohmann::ordered_json(split.cores) : nlohmann::ordered_json();
    settings["chunk_rays"] = o.board.chunk_rays != 0 ? o.board.chunk_rays : driver.chunk_rays;
  } else {
    settings["cpu_share"] = settings["cpu_cores"] = settings["chunk_rays"] = nullptr;
  }
  report["solver"] = solver_json(out.solver);
  report["solver"]["warnings"] = solver_warnings;
  if (out.board) {
    report["host_work"] = work_json(out.board->work);
  } else {
    nlohmann::ordered_json counts;
    for (int k = 0; k < kHostWorkKinds; ++k) counts[to_string(HostWork(k))] = out.work_counts[k];
    report["host_work"] = counts;
  }
  report["visibility_tests"] = out.visibility_tests;
  if (out.fidelity) report["fidelity"] = fidelity_json(*out.fidelity, o.fidelity_warn, out.fidelity_warning);
  if (o.solver.fixes.any()) report["segment_fixes"] = segment_fix_json(o.solver.fixes, out.solver);
  if (out.board) {
    report["board"] = to_json(*out.board);
    report["lanes_that_fit"] = lanes_that_fit_json(*out.lanes_that_fit);
  }
  report["image_warning"] = image_warning.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(image_warning);
  report["wall_seconds"] = wall;
  return report;
}

// The files a run writes, in the order written: report.json last, so that its presence means a
// complete run.
std::vector<std::string> output_paths(const RunOptions& o) {
  std::vector<std::string> paths = {o.out_dir + "/patches.csv", o.out_dir + "/image.png"};
  if (!o.trace_path.empty()) paths.push_back(o.trace_path);
  if (!o.board.vcd_path.empty()) paths.push_back(o.board.vcd_path);
  paths.push_back(o.out_dir + "/report.json");
  return paths;
}

}  // namespace

pipeline::Arithmetic parse_arith_option(const std::string& text) {
  try {
    return pipeline::Arithmetic::parse(text);  // a bad format names the value and the limits
  } catch (const std::invalid_argument& e) {
    refuse_option("--arith", text + ": " + e.what());
  }
}

void check_run_options(const CLI::App& cmd, const RunOptions& o) {
  if (o.impl != Impl::board) {
    refuse_given(cmd, {"--device", "--lanes", "--banks", "--concurrent", "--cards", "--card-split", "--card-bus",
                       "--lanes-compute", "--lanes-impl", "--resources", "--host", "--trace", "--trace-steps", "--vcd", "--cpu-share", "--cpu-cores", "--chunk-rays",
                       "--ray-split"},
                 "applies to --impl board only (the simulated RC2000); this run answers visibility in software");
  } else {
    refuse_given(cmd, {"--visibility"}, "applies to --impl software only: with --impl board the board's lanes answer "
                                        "visibility (bit-exact at --bits, or --arith float:E,M)");
  }
  if (o.board.cards == 1) refuse_given(cmd, {"--card-split", "--card-bus"}, "applies only with more than one card (--cards)");
  if (o.board.chunk_rays != 0 && o.board.cards > 1) {
    refuse_option("--chunk-rays", "the pipelined driver drives one card (--cards " + std::to_string(o.board.cards.value()) + ")");
  }
  if (o.cpu_share.empty()) refuse_given(cmd, {"--cpu-cores"}, "applies only with --cpu-share (the CPU/FPGA split)");
  if (!o.cpu_share.empty()) {
    if (o.board.cards > 1) refuse_option("--cpu-share", "a CPU/FPGA split drives one card (--cards " + std::to_string(o.board.cards.value()) + ")");
    CpuSplit split;
    try {
      split = parse_cpu_split(o.cpu_share, o.cpu_cores);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError(e.what());  // names --cpu-share or --cpu-cores and the limits
    }
    if (!split.on() || (split.mode == CpuSplit::Mode::fixed && split.share == 0))  // a share of 0 is no split: the host tests nothing, on any number of processors
      refuse_given(cmd, {"--cpu-cores"}, "does not apply with --cpu-share " + o.cpu_share + " (no CPU/FPGA split: the host tests no segments)");
  }
  if (o.arith.is_float()) {
    refuse_given(cmd, {"--resources"}, "applies to fixed-point lanes only: the float lanes (--arith " + o.arith.name() +
                                           ") have no RTL to synthesise; their costs are counting-rule estimates");
    refuse_given(cmd, {"--bits", "--visibility"},
                 "does not apply with --arith " + o.arith.name() +
                     " (the float pipeline has no fractional width and is its own backend)");
  } else if (o.impl != Impl::board && o.visibility == SoftwareVisibility::float_double) {
    refuse_given(cmd, {"--bits"}, "does not apply with --visibility float (double precision has no fractional width); "
                                  "--visibility fixed or fast, or --impl board, use it");
  }
  // The fast backend is the only part of a run with threads of its own: the software run's with
  // --visibility fast, the board's answer unless its lanes compute (--lanes-compute, --lanes-impl rtl)
  // or --arith float:E,M.
  const bool fast = !float_arith(o) && (o.impl == Impl::board ? !o.lanes_compute && o.lanes_impl != LanesImpl::rtl
                                                              : o.visibility == SoftwareVisibility::fast);
  if (!fast) {
    refuse_given(cmd, {"--jobs"}, "applies only where the fast backend runs (--impl software --visibility fast, or --impl "
                                  "board without --lanes-compute, --lanes-impl rtl or --arith float:E,M): this run has no threads of its own");
  }
  if (o.lanes_impl == LanesImpl::rtl) {
    if (o.impl != Impl::board) refuse_option("--lanes-impl", "applies to --impl board only (the simulated RC2000's lanes)");
    if (o.arith.is_float())
      refuse_option("--lanes-impl", "rtl: the RTL pipeline is fixed-point; it does not apply with --arith " + o.arith.name());
    refuse_given(cmd, {"--lanes-compute"}, "does not apply with --lanes-impl rtl (the RTL lanes always compute)");
    if (const std::string why = rtl::rtl_unavailable_reason(o.bits); !why.empty())
      refuse_option("--lanes-impl", "rtl: " + why);
  }
  if (!in_pipeline_arithmetic(o)) {
    refuse_given(cmd, {"--fidelity-sample", "--fidelity-warn"},
                 "does not apply with --visibility float: double precision is the reference the fidelity sample "
                 "checks against (it applies to --visibility fixed or fast, --arith float:E,M and --impl board)");
  } else if (o.fidelity_sample == 0) {
    refuse_given(cmd, {"--fidelity-warn"}, "does not apply with --fidelity-sample 0 (no fidelity is measured)");
  }
  check_segment_fix_options(cmd, o.arith.is_float(), o.arith.name(), o.impl != Impl::board && o.visibility == SoftwareVisibility::float_double,
                            o.bits, o.solver.fixes.coordinate_bits);
  if (o.trace_path.empty()) {
    refuse_given(cmd, {"--trace-steps"}, "applies only with --trace (the steps it records)");
  } else {
    BoardRunOptions steps;
    parse_trace_steps(o.trace_steps, steps);  // refuses a malformed range before any work
  }
}

int run_simulation(const RunOptions& given, const RunHooks& hooks) {
  Outputs outputs;
  if (hooks.write_outputs) {
    outputs.own_folder(given.out_dir, "run");
    for (const std::string& path : output_paths(given)) outputs.expect(path);  // before any work
  }
  // The profiles, each read once, here, and handed down; the board they make (lanes, banks,
  // layout) checked before the scene is prepared.
  RunOptions o = given;
  if (o.impl == Impl::board) {
    if (!o.board.device_profile) o.board.device_profile = board::find_device_profile(o.board.device);
    if (!o.board.host_profile) o.board.host_profile = find_host_profile(o.board.host);
    (void)make_board_setup(board_options(o));
  }
  ProgressLine progress(!o.quiet);
  PreparedScene prepared = prepare_scene(o.scene, [&](const std::string& what) { progress.update("%-60s", what.c_str()); });
  if (uses_fixed_width(o)) {
    if (std::optional<std::string> lost = faces_lost_at_width(prepared.scene, o.bits)) prepared.warnings.push_back(*lost);
  }
  for (const std::string& w : prepared.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  const Scene& scene = prepared.scene;
  // Once: counts of a paper scene built another way (report.json's workload says it too).
  const ConstructionCheck construction =
      check_construction(run_workload(o.scene, o.solver), scene.faces.size(), scene.patches.size());
  if (construction.kind == Construction::other) std::fprintf(stderr, "note: %s\n", construction.note.c_str());

  std::optional<TemporaryFile> vcd;  // SystemC writes it while simulating; moved into place at the end
  if (!o.board.vcd_path.empty()) vcd.emplace(".vcd");
  const RunOutcome out = o.impl == Impl::board ? run_board(o, scene, progress, vcd ? vcd->path() : std::string(), hooks)
                                               : run_software(o, scene, progress, hooks);
  // A scene of subnormal emission: drawn from the solve's scaled radiosity, where nothing underflowed
  // (the picture does not depend on the scene's units).
  const std::vector<Spectrum>& drawn = out.solver.radiosity_solved.empty() ? out.solver.radiosity : out.solver.radiosity_solved;
  const RgbImage image = tone_map(render_radiosity(scene, drawn, o.render), o.render.key);
  progress.update("checking the energy accounting against the scene's geometry");
  const std::vector<std::string> end_notes = solver_end_notes(scene, out.solver, o.solver.fixed_steps);
  progress.finish();
  // Point and disc: steps that created energy, said once (docs/radiosity.md, Form-factor sums).
  std::vector<std::string> solver_warnings;
  const std::string dark = dark_picture_warning(image);
  if (!dark.empty()) std::fprintf(stderr, "warning: %s\n", dark.c_str());
  if (!out.fidelity_warning.empty()) {
    std::fprintf(stderr, "warning: %s\n", out.fidelity_warning.c_str());
    solver_warnings.push_back(out.fidelity_warning);
  }
  if (std::string w = form_factor_sum_warning(scene, out.solver, o.solver.form_factor); !w.empty()) {
    std::fprintf(stderr, "warning: %s\n", w.c_str());
    solver_warnings.push_back(std::move(w));
  }
  // How the solve ended: stopped for want of normal powers, underflow in the scene's units, an
  // energy accounting the geometry does not allow (host_sw/radiosity/energy_plausibility.h).
  for (const std::string& w : end_notes) {
    std::fprintf(stderr, "warning: %s\n", w.c_str());
    solver_warnings.push_back(w);
  }

  if (!hooks.write_outputs) {
    if (hooks.on_report) hooks.on_report(make_report(o, prepared, out, solver_warnings, dark, progress.seconds()));
    if (hooks.print_summary) print_summary(o, scene, out, progress.seconds(), {});
    return 0;
  }
  outputs.add(o.out_dir + "/patches.csv", patches_csv(scene, out.solver.radiosity));
  outputs.add(o.out_dir + "/image.png", encode_png(image));
  if (!o.trace_path.empty()) outputs.add(o.trace_path, out.trace_json);
  if (vcd) outputs.move_in(o.board.vcd_path, vcd->path());
  std::optional<nlohmann::ordered_json> report;  // made once: written, and handed to on_report
  outputs.add_made(o.out_dir + "/report.json", [&] {
    report = make_report(o, prepared, out, solver_warnings, dark, progress.seconds());
    return pretty_json(*report);
  });
  outputs.write();
  if (hooks.on_report && report) hooks.on_report(*report);
  if (hooks.print_summary) print_summary(o, scene, out, progress.seconds(), outputs.paths());
  return 0;
}

void add_run_command(CLI::App& app, int& exit_code) {
  CLI::App* cmd = app.add_subcommand("run", "Solve radiosity for one scene; write report.json, patches.csv, image.png");
  const RunOptionsResolver resolve = add_run_options(*cmd);
  cmd->callback([resolve, &exit_code] {
    const RunOptions options = resolve();
    std::vector<std::string> where = {options.out_dir + "/"};
    if (!options.trace_path.empty()) where.push_back(options.trace_path);
    if (!options.board.vcd_path.empty()) where.push_back(options.board.vcd_path);
    exit_code = run_guarded("run", listed(where), [&] { return run_simulation(options); });
  });
}

RunOptionsResolver add_run_options(CLI::App& command) {
  auto options = std::make_shared<RunOptions>();
  auto solver = std::make_shared<SolverCli>();
  auto paper_faithful = std::make_shared<bool>(false);
  auto fixes = std::make_shared<SegmentFixOptions>();
  CLI::App* cmd = &command;
  add_scene_options(*cmd, options->scene);
  add_solver_options(*cmd, *solver);
  cmd->add_flag("--paper-faithful", *paper_faithful,
                "Send every segment to every other patch, as the paper did (sweep, paper and design replay this "
                "workload), instead of culling receivers that cannot see the shooter");
  add_choice_option(*cmd, "--impl", options->impl, "Who answers visibility: software or board (the SystemC RC2000 model)");
  add_choice_option(*cmd, "--visibility", options->visibility,
                    "Software backend: float, fixed (bit-exact, brute force) or fast (bit-exact, culled, all cores)");
  add_bits_option(*cmd, options->bits);
  auto arith = std::make_shared<std::string>(options->arith.name());  // parsed once, in the callback
  cmd->add_option("--arith", *arith,
                  "The pipeline's arithmetic: fixed (fractional bits: --bits) or float:E,M (exponent and fraction bits, "
                  "e.g. float:8,23 single, float:5,10 half; round to nearest even per operation, no subnormals; "
                  "docs/pipeline.md; with --impl board, float lanes: docs/board.md, Float lanes)")
      ->capture_default_str();
  BoardRunOptions& b = options->board;
  cmd->add_option("--device", b.device, "Board: device profile, configs/devices/NAME.json or a path")->capture_default_str();
  add_count_option(*cmd, "--lanes", b.lanes, "Board: pipeline lanes");
  // 0 is the setup's "the profile's"; given, it would mean "not given": refused like any count below 1.
  cmd->add_option("--banks", b.banks, "Board: memory banks, 1..64 (default: the profile's)")->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd->add_flag("--concurrent", b.concurrent, "Board: form factors while the FPGA works (paper sec 4.3)");
  cmd->add_option("--ray-split", options->ray_split,
                  "Board: how a pass's rays are divided over the ray groups: limit (by what limits each group's "
                  "stream, result bank included) or nominal (the paper's: by the lanes' nominal rates); docs/board.md, "
                  "Ray split")
      ->check(CLI::IsMember({"limit", "nominal"}))
      ->capture_default_str();
  cmd->add_option("--chunk-rays", b.chunk_rays,
                  "Board: the pipelined driver, rays per chunk (chunks go to alternating halves of the banks, so "
                  "transfers overlap the passes; docs/board.md, Pipelined passes); default: the host profile's, "
                  "usually the unpipelined driver")
      ->check(CLI::Range(std::size_t{1}, std::size_t{4294967295u}));
  cmd->add_option("--cpu-share", options->cpu_share,
                  "Board: the CPU/FPGA split, the fraction 0..1 of each step's segments the host CPU tests in software "
                  "while the board tests the rest, or 'balanced' (per step, both finish together; docs/board.md, "
                  "CPU/FPGA split)");
  cmd->add_option("--cpu-cores", options->cpu_cores,
                  "Board, with --cpu-share: 1 (the solver's processor, while the board works) or 2 (the second Athlon)")
      ->capture_default_str();
  add_count_option(*cmd, "--cards", b.cards,
                   "Board: identical RC2000 cards working on the scene at once (paper sec 6; docs/board.md, Several cards)");
  add_choice_option(*cmd, "--card-split", b.card_split,
                    "Board, several cards: rays (each card a share of a step's segments, every face) or faces (each "
                    "card a share of the faces, every segment)");
  add_choice_option(*cmd, "--card-bus", b.card_bus,
                    "Board, several cards: shared (one PCI bus, transfers contend) or separate (each card on its own bus)");
  add_choice_option(*cmd, "--lanes-impl", options->lanes_impl,
                    "Board: the lanes' implementation: cpp (the C++ pipeline) or rtl (the Verilog pipeline rtl/mt_pipeline.v, "
                    "Verilated, one model per lane, clocked cycle by cycle in the cycle-level wrapper: slow, small scenes; "
                    "docs/board.md, RTL lanes)");
  add_resources_option(*cmd, b.resources, "Board: ");
  cmd->add_flag("--lanes-compute", options->lanes_compute,
                "Board: the lanes test every ray against every face (slow) instead of copying the bit-identical "
                "culled answer; timing and results are the same");
  cmd->add_option("--host", b.host, "Board: host CPU profile, configs/hosts/NAME.json or a path")->capture_default_str();
  cmd->add_option("--trace", options->trace_path, "Board: write a Chrome/Perfetto trace.json of --trace-steps")
      ->check(output_path());
  cmd->add_option("--trace-steps", options->trace_steps, "Board: steps to trace, FIRST:LAST")->capture_default_str();
  cmd->add_option("--vcd", b.vcd_path, "Board: write a VCD of start/busy/done/irq")->check(output_path());
  cmd->add_option("--out", options->out_dir, "Output folder")->check(output_path())->capture_default_str();
  cmd->add_option("--image-size", options->render.width, "Image width and height in pixels")
      ->check(CLI::Range(16, 8192))->capture_default_str();
  cmd->add_option("--fidelity-sample", options->fidelity_sample,
                  "Segments of the run checked against double-precision visibility for the share of decisions that "
                  "differ, 0..10000000 (0: none; docs/radiosity.md, Fidelity in every run)")
      ->check(CLI::Range(std::size_t{0}, static_cast<std::size_t>(kMaxFidelitySample)))->capture_default_str();
  cmd->add_option("--fidelity-warn", options->fidelity_warn,
                  "Warn when more than this share 0..1 of the sampled decisions differ from double precision")
      ->check(finite_in_range(0.0, 1.0))->capture_default_str();
  cmd->add_flag("--quiet", options->quiet, "No progress output");
  add_jobs_option(*cmd, "the fast backend's threads (--visibility fast, or the board's answers)");
  add_segment_fix_options(*cmd, *fixes);
  return [options, solver, arith, paper_faithful, fixes, cmd] {
    options->solver = solver->resolved(*cmd);
    options->solver.cull_receivers = !*paper_faithful;
    options->arith = parse_arith_option(*arith);
    options->solver.fixes = resolve_segment_fixes(*fixes, uses_fixed_width(*options), options->bits);
    options->render.height = options->render.width;
    check_run_options(*cmd, *options);
    return *options;
  };
}

}  // namespace rc
