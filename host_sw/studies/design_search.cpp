#include "host_sw/studies/design_search.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "board/design_fit.h"
#include "board/throughput_estimates.h"
#include "host_sw/platform/run_bounds.h"
#include "host_sw/studies/fidelity.h"
#include "host_sw/studies/workload.h"
#include "host_sw/studies/study.h"

namespace rc {

namespace {

using Progress = std::function<void(const std::string&)>;

// Banks of the whole design: every card has the configuration's banks.
unsigned total_banks(const DesignPoint& p) { return p.design.config.banks * p.design.config.cards; }

double energy_or_worst(const SweepRow& r) {
  return std::isfinite(r.energy_joules) ? r.energy_joules : std::numeric_limits<double>::infinity();
}

double error_or_worst(const DesignPoint& p) {
  return p.fidelity.measured() ? p.fidelity.relative_rmse : std::numeric_limits<double>::infinity();
}

ProfileSetting setting(const std::string& path, const profiles::FieldValue& value, const DesignSpace& space) {
  ProfileSetting s{resolve_study_field(path, {space.device}, {space.host}), value};
  check_setting_value(s.field, s.value, "design search");
  return s;
}

// The settings that make a design's profile: where results accumulate, the bank clock, and the
// multipliers (slice: no block multipliers left to the design).
std::vector<ProfileSetting> design_settings(const DesignSpace& space, const board::DeviceProfile& device,
                                            board::ResultStore results, double bank_clock, Multipliers m) {
  std::vector<ProfileSetting> s;
  s.push_back(setting("wrapper.results", std::string(board::to_string(results)), space));
  s.push_back(setting("banks.clock_mhz", bank_clock, space));
  s.push_back(setting("fpga.block_multipliers", std::int64_t{m == Multipliers::block ? device.block_multipliers : 0}, space));
  return s;
}

bool spare_banks(const DesignConfig& d, const board::DeviceProfile& device) {
  const board::BankLayout layout = board::make_bank_layout(static_cast<int>(d.config.lanes), d.config.banks, d.config.bits,
                                                           device.bank_word_bits, device.bank_capacity_bytes);
  return !layout.spare_banks.empty();
}

template <class T>
void require(const std::vector<T>& axis, const char* option) {
  if (axis.empty()) throw std::invalid_argument(std::string(option) + ": the design space needs at least one value");
}

}  // namespace

const char* to_string(Multipliers m) { return m == Multipliers::block ? "block" : "slice"; }

Multipliers parse_multipliers(const std::string& text) {
  if (text == "block") return Multipliers::block;
  if (text == "slice") return Multipliers::slice;
  throw std::invalid_argument("--multipliers: '" + text + "' is not one of block, slice");
}

DesignBound design_bound(const RunReport& report) {
  const RunBounds b = run_bounds(report);
  return {b.run.front().name, b.stream_bound_name(), b.stream_bound_share, b.stream_next_name(), b.summary()};
}

std::string describe(const DesignConfig& d) {
  const SweepConfig& c = d.config;
  char clock[32];
  std::snprintf(clock, sizeof clock, "%g", d.bank_clock_mhz);
  return c.device + ", " + std::to_string(c.lanes) + (c.lanes == 1 ? " lane, " : " lanes, ") + std::to_string(c.banks) +
         " banks at " + clock + " MHz, results " + (d.results == board::ResultStore::bank ? "in the bank" : "on chip") +
         ", " + std::to_string(c.bits) + "-bit, " + to_string(d.multipliers) + " multipliers, " + std::to_string(c.cards) +
         (c.cards == 1 ? " card, " : " cards, ") + (c.concurrent ? "concurrent" : "serial") + " driver";
}

std::vector<DesignCandidate> enumerate_designs(const DesignSpace& space, const DesignConstraints& constraints,
                                               const ConfigChecker& checker) {
  require(space.results, "--results");
  require(space.bits, "--bits");
  require(space.multipliers, "--multipliers");
  require(space.cards, "--cards");
  require(space.concurrent, "--concurrent");
  const board::DeviceProfile& device = checker.device(space.device);
  const unsigned max_banks = constraints.max_banks ? constraints.max_banks : device.bank_count;
  const std::vector<double> clocks = space.bank_clocks_mhz.empty() ? std::vector<double>{device.bank_clock_mhz}
                                                                   : space.bank_clocks_mhz;
  std::vector<int> banks = space.banks;
  if (banks.empty())
    for (unsigned b = board::kMinBanks; b <= max_banks; ++b) banks.push_back(static_cast<int>(b));
  const pipeline::ResourceModel resources = pipeline::ResourceModel::load_default(space.resources);
  std::vector<DesignCandidate> out;
  for (int bits : space.bits) {
    if (bits < constraints.min_bits) continue;
    for (bool concurrent : space.concurrent)
      for (int cards : space.cards)
        for (board::ResultStore results : space.results)
          for (double clock : clocks)
            for (Multipliers m : space.multipliers) {
              DesignConfig d;
              d.results = results;
              d.bank_clock_mhz = clock;
              d.multipliers = m;
              d.config.device = space.device;
              d.config.host = space.host;
              d.config.bits = bits;
              d.config.concurrent = concurrent;
              d.config.cards = static_cast<unsigned>(cards);
              d.config.settings = design_settings(space, device, results, clock, m);
              const board::DeviceProfile profile = checker.device(d.config);
              std::vector<int> lanes = space.lanes;
              if (lanes.empty())
                for (int l = 1; l <= board::max_lanes(profile, resources, bits); ++l) lanes.push_back(l);
              for (int l : lanes)
                for (int b : banks) {
                  if (static_cast<unsigned>(b) > max_banks) continue;
                  DesignCandidate c{d, {}, false};
                  c.design.config.lanes = static_cast<unsigned>(l);
                  c.design.config.banks = static_cast<unsigned>(b);
                  c.check = checker.check(c.design.config);
                  c.spare_banks = c.check.validity == Validity::ok && spare_banks(c.design, profile);
                  out.push_back(std::move(c));
                }
            }
  }
  return out;
}

std::optional<std::size_t> fastest(const std::vector<DesignPoint>& points) {
  std::optional<std::size_t> best;
  auto key = [&](const DesignPoint& p) {
    return std::make_tuple(p.row.simulated_seconds, total_banks(p), energy_or_worst(p.row), p.design.config.lanes,
                           p.design.config.cards, p.row.config.label());
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].meets_constraints) continue;
    if (!best || key(points[i]) < key(points[*best])) best = i;
  }
  return best;
}

void mark_front(std::vector<DesignPoint>& points) {
  for (DesignPoint& p : points) {
    p.on_front = false;
    if (!p.meets_constraints) continue;
    const double t = p.row.simulated_seconds, e = energy_or_worst(p.row), err = error_or_worst(p);
    const unsigned b = total_banks(p);
    bool dominated = false;
    for (const DesignPoint& q : points) {
      if (&q == &p || !q.meets_constraints) continue;
      const double qt = q.row.simulated_seconds, qe = energy_or_worst(q.row), qerr = error_or_worst(q);
      const unsigned qb = total_banks(q);
      if (qt <= t && qe <= e && qb <= b && qerr <= err && (qt < t || qe < e || qb < b || qerr < err)) {
        dominated = true;
        break;
      }
    }
    p.on_front = !dominated;
  }
}

void apply_caps(std::vector<DesignPoint>& points, const DesignConstraints& c) {
  for (DesignPoint& p : points) {
    const bool energy_ok = std::isinf(c.max_energy_joules) || p.row.energy_joules <= c.max_energy_joules;
    const bool power_ok = std::isinf(c.max_watts) || p.row.average_watts <= c.max_watts;
    // Not measured (NaN) fails an error cap that is set, as NaN fails any comparison.
    const bool rmse_ok = std::isinf(c.max_error) || p.fidelity.relative_rmse <= c.max_error;
    const bool max_ok = std::isinf(c.max_error_max) || p.fidelity.relative_max <= c.max_error_max;
    p.meets_constraints = energy_ok && power_ok && rmse_ok && max_ok;  // a NaN energy or power fails a cap that is set
  }
}

DesignConfig paper_two_lane_design(const ConfigChecker& checker) {
  DesignSpace space;
  space.device = "xc2v6000";
  space.host = checker.first_host();
  const board::DeviceProfile& device = checker.device(space.device);
  DesignConfig d;
  d.results = board::ResultStore::bank;
  d.bank_clock_mhz = device.bank_clock_mhz;
  d.multipliers = Multipliers::block;
  d.config.device = space.device;
  d.config.host = space.host;
  d.config.bits = 15;
  d.config.concurrent = true;
  d.config.lanes = 2;
  d.config.banks = 6;
  d.config.settings = design_settings(space, device, d.results, d.bank_clock_mhz, d.multipliers);
  return d;
}

DesignCases design_cases(const std::vector<DesignCandidate>& candidates, const Scene& scene, const SolverOptions& solver,
                         const VisibilityRecording& recording, std::uint64_t max_segments, bool exhaustive) {
  DesignCases out;
  for (const DesignCandidate& c : candidates) {
    if (c.check.validity != Validity::ok || (c.spare_banks && !exhaustive)) {
      out.index.push_back(~std::size_t{0});
      continue;
    }
    TimingCase t;
    t.label = c.design.config.label();
    t.scene = &scene;
    t.solver = solver;
    t.recording = &recording;
    t.board = c.check.options;
    t.board.bank_capacity_bytes =
        ConfigChecker::compact_bank_capacity(*c.check.options.device_profile, max_segments, scene.faces.size());
    out.index.push_back(out.cases.size());
    out.cases.push_back(std::move(t));
  }
  return out;
}

DesignPoint design_point(const DesignConfig& design, const TimingOutcome& outcome, int steps) {
  DesignPoint p;
  p.design = design;
  p.row = row_from_report(design.config, outcome.report, steps);
  p.bound = design_bound(outcome.report);
  const RunReport& r = outcome.report;
  p.tests = r.intersections.tests;
  double bank_bytes = 0;
  for (const BankUseReport& b : r.board.banks) bank_bytes += static_cast<double>(b.bytes_read + b.bytes_written);
  const double tests = static_cast<double>(p.tests);
  p.bank_bytes_per_test = tests > 0 ? bank_bytes / tests : 0;
  p.pci_bytes_per_test = tests > 0 ? static_cast<double>(r.board.pci.bytes_to_board + r.board.pci.bytes_to_host) / tests : 0;
  p.tests_per_second = r.simulated_seconds > 0 ? tests / r.simulated_seconds : 0;
  p.meets_constraints = true;
  return p;
}

double speedup_over_software(const DesignPoint& p) {
  return p.fidelity.software_seconds / p.row.simulated_seconds;
}

namespace {

struct Width {
  RecordedRun functional;
  SolverOptions solver;
  std::uint64_t max_segments = 0;
  WidthFidelity fidelity;
};

// Every width's own solve, and its fidelity against one double-precision solve (fidelity.h).
// Without `measure`, the widths' own solves only (their error not measured).
std::map<int, Width> solve_widths(const Workload& w, BitExactVisibility visibility, const Scene& scene, const std::set<int>& bits,
                                  int steps, bool measure, DesignSearchResult& r, const Progress& progress) {
  const SolverOptions solver = solver_options(w, steps);
  std::vector<Arithmetic> arithmetics;
  for (int b : bits) arithmetics.push_back({choice_name(visibility), b});
  FidelityOptions options;
  options.progress = progress;
  FidelityResult measured;
  if (measure) {
    measured = measure_fidelity(scene, solver, arithmetics, options);
    r.reference_steps = measured.reference.steps;
  } else {
    std::vector<RecordedRun> runs = solve_arithmetics(scene, solver, arithmetics, options);
    for (std::size_t i = 0; i < runs.size(); ++i) measured.rows.push_back({arithmetics[i], std::move(runs[i]), {}, {}});
  }
  std::map<int, Width> out;
  for (ArithmeticFidelity& f : measured.rows) {
    Width& width = out[f.arithmetic.bits];
    width.functional = std::move(f.run);
    width.solver = solver;
    width.solver.fixed_steps = width.functional.result.steps;  // to convergence: replay what was solved
    for (int i = 0; i < width.functional.result.steps; ++i)
      width.max_segments =
          std::max<std::uint64_t>(width.max_segments, width.functional.recording.segments(static_cast<std::size_t>(i)));
    WidthFidelity& fid = width.fidelity;
    fid.bits = f.arithmetic.bits;
    fid.steps = width.functional.result.steps;
    if (!measure) continue;
    fid.relative_rmse = f.error.relative_rmse();
    fid.relative_max = f.error.relative_max();
    fid.decisions_compared = f.decisions.compared;
    fid.decisions_differ = f.decisions.differ();
  }
  return out;
}

void note_infeasible(DesignSearchResult& r, const std::vector<DesignCandidate>& candidates) {
  std::set<Validity> seen;
  for (const DesignCandidate& c : candidates) {
    if (c.check.validity == Validity::ok) {
      r.pruned += c.spare_banks ? 1 : 0;
      continue;
    }
    ++r.infeasible;
    if (seen.insert(c.check.validity).second)
      r.infeasible_reasons.push_back(to_string(c.check.validity) + ": " + c.design.config.label() + ": " + c.check.reason);
  }
}

}  // namespace

DesignSearchResult search_designs(const Workload& workload, BitExactVisibility visibility, const DesignSpace& space,
                                  const DesignConstraints& constraints, bool exhaustive, const Progress& progress) {
  const ConfigChecker checker({space.device, "xc2v6000"}, {space.host}, {}, "command line", space.resources,
                              space.ray_split);
  DesignSearchResult r;
  r.device = space.device;
  r.workload = workload;
  r.max_banks = constraints.max_banks ? constraints.max_banks : checker.device(space.device).bank_count;
  const std::vector<DesignCandidate> candidates = enumerate_designs(space, constraints, checker);
  r.designs = candidates.size();
  note_infeasible(r, candidates);
  progress("preparing the scene");
  const Scene scene = prepare_scene(workload.scene).scene;
  r.faces = scene.faces.size();
  r.patches = scene.patches.size();
  const int steps = steps_to_solve(workload, r.faces, r.patches);
  std::set<int> bits_solved = {15};  // the reference's
  for (const DesignCandidate& c : candidates)
    if (c.check.validity == Validity::ok) bits_solved.insert(c.design.config.bits);
  progress("solving at " + std::to_string(bits_solved.size()) + (bits_solved.size() == 1 ? " width" : " widths") +
           (space.measure_fidelity ? " and in double precision" : ""));
  std::map<int, Width> widths = solve_widths(workload, visibility, scene, bits_solved, steps, space.measure_fidelity, r, progress);
  r.steps = widths.at(15).solver.fixed_steps;
  std::vector<TimingCase> cases;
  std::vector<std::size_t> index(candidates.size(), ~std::size_t{0});
  for (const auto& [bits, w] : widths) {
    std::vector<DesignCandidate> at;
    std::vector<std::size_t> where;
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (candidates[i].design.config.bits == bits) at.push_back(candidates[i]), where.push_back(i);
    DesignCases dc = design_cases(at, scene, w.solver, w.functional.recording, w.max_segments, exhaustive);
    for (std::size_t j = 0; j < at.size(); ++j)
      if (dc.index[j] != ~std::size_t{0}) index[where[j]] = cases.size() + dc.index[j];
    for (TimingCase& t : dc.cases) cases.push_back(std::move(t));
  }
  const Width& w15 = widths.at(15);
  DesignCandidate reference{paper_two_lane_design(checker), {}, false};
  reference.check = checker.check(reference.design.config);
  DesignCases ref = design_cases({reference}, scene, w15.solver, w15.functional.recording, w15.max_segments, true);
  const std::size_t ref_case = cases.size();
  cases.push_back(ref.cases.at(0));
  // Software alone at every width: the host testing every segment of that width's own solve.
  std::map<int, std::size_t> software_case;
  for (const auto& [bits, w] : widths) {
    TimingCase software;
    software.label = "software-" + std::to_string(bits);
    software.scene = &scene;
    software.solver = w.solver;
    software.recording = &w.functional.recording;
    software.software = true;
    software.host = space.host;
    software.host_profile = checker.host(reference.design.config);
    software_case[bits] = cases.size();
    cases.push_back(std::move(software));
  }
  progress("simulating " + std::to_string(cases.size()) + " systems");
  const std::vector<TimingOutcome> outcomes = run_timing_study(cases);
  for (auto& [bits, w] : widths) {
    w.fidelity.software_seconds = outcomes[software_case.at(bits)].simulated_seconds;
    r.widths.push_back(w.fidelity);
  }
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (index[i] != ~std::size_t{0}) {
      const Width& w = widths.at(candidates[i].design.config.bits);
      r.points.push_back(design_point(candidates[i].design, outcomes[index[i]], w.fidelity.steps));
      r.points.back().profile = *candidates[i].check.options.device_profile;
      r.points.back().fidelity = w.fidelity;
    }
  r.reference = design_point(reference.design, outcomes[ref_case], r.steps);
  r.reference->profile = *reference.check.options.device_profile;
  r.reference->fidelity = w15.fidelity;
  r.software_seconds = w15.fidelity.software_seconds;
  apply_caps(r.points, constraints);
  mark_front(r.points);
  r.best = fastest(r.points);
  return r;
}

}  // namespace rc

namespace rc {

Roofline design_roofline(const DesignSearchResult& r, double paper_software_rate) {
  const board::DeviceProfile device = board::find_device_profile(r.device);
  Roofline roof;
  if (r.best) {
    const DesignPoint& b = r.points[*r.best];
    roof = device_roofs(device, static_cast<int>(b.design.config.lanes), b.row.clock_mhz, b.design.config.banks,
                        b.design.bank_clock_mhz);
    workload_roofs(roof, b.pci_bytes_per_test, b.row.host_compute_seconds + b.row.driver_cpu_seconds,
                   static_cast<double>(b.tests));
  } else {
    roof = device_roofs(device, 1, device.clock_mhz(1), device.bank_count, device.bank_clock_mhz);
  }
  const board::PaperEstimate rule = board::paper_rule_lanes_that_fit(device, paper_software_rate);
  roof.points.push_back({"paper", "paper's rule: " + std::to_string(rule.lanes) + " lanes at " +
                                      std::to_string(rule.clock_mhz).substr(0, 5) + " MHz",
                         rule.bytes_per_intersection, rule.intersections_per_s});
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const DesignPoint& p = r.points[i];
    if (!p.on_front && !(r.best && *r.best == i)) continue;
    roof.points.push_back({r.best && *r.best == i ? "best" : "design", describe(p.design), p.bank_bytes_per_test,
                           p.row.intersections_per_second_while_busy});
  }
  if (r.reference) {
    roof.points.push_back({"reference", "paper's two-lane design (simulated)", r.reference->bank_bytes_per_test,
                           r.reference->row.intersections_per_second_while_busy});
  }
  return roof;
}

}  // namespace rc
