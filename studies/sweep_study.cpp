#include "studies/sweep_study.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "studies/paper_workload.h"

namespace rc {

namespace {

// ---- the workload ---------------------------------------------------------------------------------

// Table 2's step count when the scene is one of the paper's (our Cornell Box refined to 70 faces,
// then split); 0 otherwise.
int paper_steps(const SweepSpec& o, const Scene& scene) {
  if (!o.scene.file.empty() || o.scene.face_target != 70) return 0;
  for (const PaperRow& row : load_paper_table(default_paper_table_path())) {
    if (static_cast<std::size_t>(row.faces) == scene.faces.size() &&
        static_cast<std::size_t>(row.patches) == scene.patches.size())
      return row.steps;
  }
  return 0;
}

SolverOptions base_solver(const SweepSpec& o) {
  SolverOptions s;
  s.cull_receivers = !o.paper_faithful;
  s.convergence = o.convergence;
  return s;
}

WidthRun record_width(const SweepSpec& o, const Scene& scene, int bits, int fixed_steps) {
  SolverOptions solver = base_solver(o);
  solver.fixed_steps = fixed_steps;  // 0: to convergence
  WidthRun w;
  w.functional = record_functional_run(scene, solver, o.visibility, bits);
  w.steps = w.functional.result.steps;
  for (int s = 0; s < w.steps; ++s)
    w.max_segments = std::max<std::uint64_t>(w.max_segments, w.functional.recording.segments(static_cast<std::size_t>(s)));
  return w;
}

// ---- the study ------------------------------------------------------------------------------------

TimingCase base_case(const Scene& scene, const SweepSpec& o, const WidthRun& w) {
  TimingCase c;
  c.scene = &scene;
  c.solver = base_solver(o);
  c.solver.fixed_steps = w.steps;
  c.recording = &w.functional.recording;
  return c;
}

TimingCase software_case(const Scene& scene, const SweepSpec& o, int bits, const WidthRun& w) {
  TimingCase c = base_case(scene, o, w);
  c.label = "software " + std::to_string(bits) + "-bit";
  c.software = true;
  c.host = o.host;
  return c;
}

TimingCase board_case(const Scene& scene, const SweepSpec& o, const Planned& p, const WidthRun& w) {
  TimingCase c = base_case(scene, o, w);
  c.label = p.config.label();
  c.board = p.check.options;
  c.board.bank_capacity_bytes = p.bank_capacity;
  return c;
}

// Compact banks promise identical passes; a batched or split step would break that promise.
void check_compact_banks(const Planned& p, const TimingOutcome& out) {
  if (p.bank_capacity == 0) return;
  const BatchingReport& b = out.report.board.batching;
  if (b.max_batches_per_step > 1 || b.face_sets > 1) {
    throw std::logic_error("compact banks batched " + p.config.label() + "; rerun with --full-banks");
  }
}

// Every combination with its verdict, in enumeration order.
std::vector<Planned> plan_sweep(const SweepAxes& axes, const ConfigChecker& checker) {
  std::vector<Planned> plan;
  for (const SweepConfig& c : enumerate_configs(axes)) plan.push_back({c, checker.check(c)});
  return plan;
}

std::map<int, WidthRun> record_widths(const SweepSpec& o, const Scene& scene, const std::vector<int>& bits,
                                      const std::function<void(const std::string&)>& progress) {
  const StepsChoice steps = parse_steps(o.steps);
  int fixed_steps = steps.kind == StepsChoice::Kind::fixed ? steps.steps : 0;
  if (steps.kind == StepsChoice::Kind::paper) {
    fixed_steps = paper_steps(o, scene);
    if (fixed_steps == 0 && !o.quiet)
      std::fprintf(stderr, "note: the scene is not one of Table 2's; --steps paper falls back to converge\n");
  }
  std::map<int, WidthRun> widths;
  for (int b : bits) {
    progress("solving " + std::to_string(scene.patches.size()) + " patches at " + std::to_string(b) + " bits");
    widths.emplace(b, record_width(o, scene, b, fixed_steps));
  }
  return widths;
}

// One software case per width first (in width order), then every combination that can exist;
// each planned combination learns its case's index.
std::vector<TimingCase> make_cases(const SweepSpec& o, const Scene& scene, const ConfigChecker& checker,
                                   const std::map<int, WidthRun>& widths, std::vector<Planned>& plan) {
  std::vector<TimingCase> cases;
  for (const auto& [bits, w] : widths) cases.push_back(software_case(scene, o, bits, w));
  for (Planned& p : plan) {
    if (p.check.validity != Validity::ok) continue;
    const WidthRun& w = widths.at(p.config.bits);
    if (!o.full_banks) p.bank_capacity = checker.compact_bank_capacity(p.config, w.max_segments, scene.faces.size());
    p.outcome = cases.size();
    cases.push_back(board_case(scene, o, p, w));
  }
  return cases;
}

std::vector<SweepRow> collect_rows(const std::vector<Planned>& plan, const ConfigChecker& checker,
                                   const std::map<int, WidthRun>& widths, const std::map<int, double>& software,
                                   const std::vector<TimingOutcome>& outcomes) {
  std::vector<SweepRow> rows;
  for (const Planned& p : plan) {
    const int replayed = widths.at(p.config.bits).steps;
    if (p.check.validity == Validity::ok) check_compact_banks(p, outcomes[p.outcome]);
    rows.push_back(p.check.validity == Validity::ok ? row_from_report(p.config, outcomes[p.outcome].report, replayed)
                                                    : invalid_row(p.config, p.check, replayed));
    rows.back().config.device = checker.device(p.config.device).name;  // a profile given by path shows its name
  }
  fill_speedups(rows, software);
  return rows;
}

std::map<std::string, std::uint64_t> bank_capacities(const std::vector<Planned>& plan, const ConfigChecker& checker) {
  std::map<std::string, std::uint64_t> capacity;
  for (const Planned& p : plan) {
    if (p.check.validity != Validity::ok) continue;
    std::uint64_t& bytes = capacity[checker.device(p.config.device).name];
    bytes = std::max(bytes, p.bank_capacity);
  }
  return capacity;
}

}  // namespace

SweepResult run_sweep_study(const SweepSpec& spec, const std::function<void(const std::string&)>& progress) {
  (void)parse_steps(spec.steps);                              // a bad --steps fails before any work
  const ConfigChecker checker(spec.axes.devices, spec.host);  // and so do unknown profiles
  SweepResult r;
  r.scene = prepare_scene(spec.scene, progress).scene;
  const Scene& scene = r.scene;
  r.plan = plan_sweep(spec.axes, checker);
  r.valid = static_cast<std::size_t>(
      std::count_if(r.plan.begin(), r.plan.end(), [](const Planned& p) { return p.check.validity == Validity::ok; }));
  r.widths = record_widths(spec, scene, spec.axes.bits, progress);
  const std::vector<TimingCase> cases = make_cases(spec, scene, checker, r.widths, r.plan);
  progress("simulating " + std::to_string(r.valid) + " configurations (" + std::to_string(r.plan.size() - r.valid) +
           " cannot exist)");
  const std::vector<TimingOutcome> outcomes = run_timing_study(cases);
  // The software cases come first, one per width in width order.
  for (const auto& [bits, w] : r.widths) r.software_seconds[bits] = outcomes[r.software_seconds.size()].simulated_seconds;
  r.rows = collect_rows(r.plan, checker, r.widths, r.software_seconds, outcomes);
  r.bank_capacities = bank_capacities(r.plan, checker);
  return r;
}

}  // namespace rc
