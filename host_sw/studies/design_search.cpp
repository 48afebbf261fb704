#include "host_sw/studies/design_search.h"

#include "host_sw/radiosity/segment_fix_names.h"

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

std::tuple<int, int, int> fix_key(const SegmentFixOptions& f) {
  return {f.offset_lsb, f.neighbour_rings, f.coordinate_bits};
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
  const std::string fixes = d.fixes.any() ? ", " + describe(d.fixes) : std::string();
  return c.device + ", " + std::to_string(c.lanes) + (c.lanes == 1 ? " lane, " : " lanes, ") + std::to_string(c.banks) +
         " banks at " + clock + " MHz, results " + (d.results == board::ResultStore::bank ? "in the bank" : "on chip") +
         ", " + std::to_string(c.bits) + "-bit, " + to_string(d.multipliers) + " multipliers, " + std::to_string(c.cards) +
         (c.cards == 1 ? " card, " : " cards, ") + (c.concurrent ? "concurrent" : "serial") + " driver" + fixes;
}

std::vector<SegmentFixOptions> design_fixes(const DesignSpace& space, int bits) {
  require(space.offset_lsb, "--offset-lsb");
  require(space.neighbour_rings, "--neighbour-rings");
  require(space.coordinate_bits, "--coordinate-bits");
  std::vector<SegmentFixOptions> out;
  for (int c : space.coordinate_bits) {
    const std::string problem = coordinate_bits_problem(bits, c);
    if (!problem.empty()) throw std::invalid_argument("--coordinate-bits: " + problem);
    for (int r : space.neighbour_rings)
      for (int k : space.offset_lsb) {
        SegmentFixOptions f;
        f.offset_lsb = k;
        f.neighbour_rings = r;
        f.coordinate_bits = c;
        if (f.any()) f.bits = bits;
        if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
      }
  }
  std::stable_partition(out.begin(), out.end(), [](const SegmentFixOptions& f) { return !f.any(); });
  return out;
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
    for (const SegmentFixOptions& fix : design_fixes(space, bits))
    for (bool concurrent : space.concurrent)
      for (int cards : space.cards)
        for (board::ResultStore results : space.results)
          for (double clock : clocks)
            for (Multipliers m : space.multipliers) {
              DesignConfig d;
              d.results = results;
              d.bank_clock_mhz = clock;
              d.multipliers = m;
              d.fixes = fix;
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
                           p.design.config.cards, error_or_worst(p), p.row.config.label(), fix_key(p.design.fixes));
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

std::vector<DesignCap> design_caps(const DesignConstraints& c) {
  std::vector<DesignCap> caps;
  auto add = [&](const char* option, const char* unit, double limit, double (*figure)(const DesignPoint&),
                 const char* unknown) {
    if (!std::isinf(limit)) caps.push_back({option, unit, limit, figure, unknown});
  };
  add("--max-energy", "J", c.max_energy_joules, [](const DesignPoint& p) { return p.row.energy_joules; },
      "no energy figure: the profile has no energy table");
  add("--max-power", "W", c.max_watts, [](const DesignPoint& p) { return p.row.average_watts; },
      "no power figure: the profile has no energy table");
  add("--max-error", "relative RMSE", c.max_error, [](const DesignPoint& p) { return p.fidelity.relative_rmse; },
      "error not measured");
  add("--max-error-max", "relative max error", c.max_error_max,
      [](const DesignPoint& p) { return p.fidelity.relative_max; }, "error not measured");
  return caps;
}

std::vector<std::string> why_no_design(const DesignSearchResult& r, const DesignConstraints& c) {
  std::vector<std::string> why;
  if (r.points.empty()) {
    why.push_back("no design was simulated: " + std::to_string(r.infeasible) + " of " + std::to_string(r.designs) +
                  " cannot exist" + (r.pruned ? ", " + std::to_string(r.pruned) + " pruned" : std::string()));
    return why;
  }
  bool each_met = true;
  for (const DesignCap& cap : design_caps(c)) {
    std::size_t met = 0, unknown = 0;
    double least = std::numeric_limits<double>::infinity();
    for (const DesignPoint& p : r.points) {
      const double v = cap.figure(p);
      if (std::isnan(v)) ++unknown;
      else least = std::min(least, v);
      met += v <= cap.limit ? 1 : 0;
    }
    each_met = each_met && met > 0;
    char limit[48], best[48];
    std::snprintf(limit, sizeof limit, "%g", cap.limit);
    std::snprintf(best, sizeof best, "%.4g", least);
    std::string line = std::string(cap.option) + " " + limit + " (" + cap.unit + "): met by " + std::to_string(met) + " of " +
                       std::to_string(r.points.size()) + " simulated designs";
    if (unknown > 0) line += "; " + std::to_string(unknown) + " with " + cap.unknown;
    if (met == 0 && std::isfinite(least)) line += "; the least is " + std::string(best);
    why.push_back(line);
  }
  if (each_met && !why.empty())
    why.push_back("each limit is met by some design but no design meets them all: the limits contradict each other "
                  "for this workload; relax one");
  return why;
}

void apply_caps(std::vector<DesignPoint>& points, const DesignConstraints& c) {
  const std::vector<DesignCap> caps = design_caps(c);
  for (DesignPoint& p : points) {
    p.meets_constraints = true;
    // Not measured or not known (NaN) fails a cap that is set, as NaN fails any comparison.
    for (const DesignCap& cap : caps) p.meets_constraints = p.meets_constraints && cap.figure(p) <= cap.limit;
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

// Whether the search leaves a candidate out unsimulated because a cheaper design dominates it: one
// rule for what is simulated (design_cases) and what the outputs count as pruned (note_infeasible).
static bool is_pruned(const DesignCandidate& c, bool exhaustive) {
  return c.check.validity == Validity::ok && c.spare_banks && !exhaustive;
}

DesignCases design_cases(const std::vector<DesignCandidate>& candidates, const Scene& scene, const SolverOptions& solver,
                         const VisibilityRecording& recording, std::uint64_t max_segments, bool exhaustive) {
  DesignCases out;
  for (const DesignCandidate& c : candidates) {
    if (c.check.validity != Validity::ok || is_pruned(c, exhaustive)) {
      out.index.push_back(~std::size_t{0});
      continue;
    }
    TimingCase t;
    t.label = c.design.config.label() + (c.design.fixes.any() ? " (" + describe(c.design.fixes) + ")" : "");
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
  // Every test, as `run` counts its visibility_tests: the board's and the host's own (the neighbour
  // rule's re-tests); the bytes per test are the board's, over the tests its lanes made.
  p.tests = r.intersections.tests + r.work[static_cast<int>(HostWork::IntersectionTest)].count;
  double bank_bytes = 0;
  for (const BankUseReport& b : r.board.banks) bank_bytes += static_cast<double>(b.bytes_read + b.bytes_written);
  const double tests = static_cast<double>(r.intersections.tests);
  p.bank_bytes_per_test = tests > 0 ? bank_bytes / tests : 0;
  p.pci_bytes_per_test = tests > 0 ? static_cast<double>(r.board.pci.bytes_to_board + r.board.pci.bytes_to_host) / tests : 0;
  p.tests_per_second = r.simulated_seconds > 0 ? static_cast<double>(p.tests) / r.simulated_seconds : 0;
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

// A width and the fix it is solved with: what one solve (and its designs' recording) is of.
using WidthKey = std::tuple<int, int, int, int>;  // bits, offset_lsb, neighbour_rings, coordinate_bits
WidthKey width_key(int bits, const SegmentFixOptions& f) { return {bits, f.offset_lsb, f.neighbour_rings, f.coordinate_bits}; }
WidthKey width_key(const DesignConfig& d) { return width_key(d.config.bits, d.fixes); }

// Every width's own solve (with its fix), and its fidelity against one double-precision solve
// (fidelity.h). Without `measure`, the widths' own solves only (their error not measured).
std::map<WidthKey, Width> solve_widths(const Workload& w, BitExactVisibility visibility, const Scene& scene,
                                       const std::map<WidthKey, SegmentFixOptions>& keys, int steps, bool measure,
                                       DesignSearchResult& r, const Progress& progress) {
  const SolverOptions solver = solver_options(w, steps);
  std::vector<Arithmetic> arithmetics;
  for (const auto& [key, fix] : keys) arithmetics.push_back({choice_name(visibility), std::get<0>(key), fix});
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
  std::map<WidthKey, Width> out;
  for (ArithmeticFidelity& f : measured.rows) {
    Width& width = out[width_key(f.arithmetic.bits, f.arithmetic.fixes)];
    width.functional = std::move(f.run);
    width.solver = solver;
    width.solver.fixed_steps = width.functional.result.steps;  // to convergence: replay what was solved
    for (int i = 0; i < width.functional.result.steps; ++i)
      width.max_segments =
          std::max<std::uint64_t>(width.max_segments, width.functional.recording.segments(static_cast<std::size_t>(i)));
    WidthFidelity& fid = width.fidelity;
    fid.bits = f.arithmetic.bits;
    fid.fixes = f.arithmetic.fixes;
    fid.steps = width.functional.result.steps;
    if (!measure) continue;
    fid.relative_rmse = f.error.relative_rmse();
    fid.relative_max = f.error.relative_max();
    fid.decisions_compared = f.decisions.compared;
    fid.decisions_differ = f.decisions.differ();
  }
  return out;
}

void note_infeasible(DesignSearchResult& r, const std::vector<DesignCandidate>& candidates, bool exhaustive) {
  std::set<Validity> seen;
  r.exhaustive = exhaustive;
  for (const DesignCandidate& c : candidates) {
    if (c.check.validity == Validity::ok) {
      r.pruned += is_pruned(c, exhaustive) ? 1 : 0;
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
  note_infeasible(r, candidates, exhaustive);
  progress("preparing the scene");
  const Scene scene = prepare_scene(workload.scene).scene;
  r.faces = scene.faces.size();
  r.patches = scene.patches.size();
  const int steps = steps_to_solve(workload, r.faces, r.patches);
  std::map<WidthKey, SegmentFixOptions> solved = {{width_key(15, {}), {}}};  // the reference's
  for (const DesignCandidate& c : candidates)
    if (c.check.validity == Validity::ok) solved[width_key(c.design)] = c.design.fixes;
  std::set<int> bits_solved;
  for (const auto& [key, fix] : solved) bits_solved.insert(std::get<0>(key));
  const bool any_fix = solved.size() > bits_solved.size();
  progress("solving at " + std::to_string(bits_solved.size()) + (bits_solved.size() == 1 ? " width" : " widths") +
           (any_fix ? " (" + std::to_string(solved.size()) + " with their fixes)" : std::string()) +
           (space.measure_fidelity ? " and in double precision" : ""));
  std::map<WidthKey, Width> widths = solve_widths(workload, visibility, scene, solved, steps, space.measure_fidelity, r, progress);
  const WidthKey key15 = width_key(15, {});
  r.steps = widths.at(key15).solver.fixed_steps;
  std::vector<TimingCase> cases;
  std::vector<std::size_t> index(candidates.size(), ~std::size_t{0});
  for (const auto& [key, w] : widths) {
    std::vector<DesignCandidate> at;
    std::vector<std::size_t> where;
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (width_key(candidates[i].design) == key) at.push_back(candidates[i]), where.push_back(i);
    DesignCases dc = design_cases(at, scene, w.solver, w.functional.recording, w.max_segments, exhaustive);
    for (std::size_t j = 0; j < at.size(); ++j)
      if (dc.index[j] != ~std::size_t{0}) index[where[j]] = cases.size() + dc.index[j];
    for (TimingCase& t : dc.cases) cases.push_back(std::move(t));
  }
  const Width& w15 = widths.at(key15);
  DesignCandidate reference{paper_two_lane_design(checker), {}, false};
  reference.check = checker.check(reference.design.config);
  DesignCases ref = design_cases({reference}, scene, w15.solver, w15.functional.recording, w15.max_segments, true);
  const std::size_t ref_case = cases.size();
  cases.push_back(ref.cases.at(0));
  // Software alone at every width: the host testing every segment of that width's own solve.
  std::map<WidthKey, std::size_t> software_case;
  for (const auto& [key, w] : widths) {
    TimingCase software;
    software.label = "software-" + std::to_string(std::get<0>(key)) +
                     (w.fidelity.fixes.any() ? " (" + describe(w.fidelity.fixes) + ")" : std::string());
    software.scene = &scene;
    software.solver = w.solver;
    software.recording = &w.functional.recording;
    software.software = true;
    software.host = space.host;
    software.host_profile = checker.host(reference.design.config);
    software_case[key] = cases.size();
    cases.push_back(std::move(software));
  }
  progress("simulating " + std::to_string(cases.size()) + " systems");
  const std::vector<TimingOutcome> outcomes = run_timing_study(cases);
  for (auto& [key, w] : widths) {
    w.fidelity.software_seconds = outcomes[software_case.at(key)].simulated_seconds;
    r.widths.push_back(w.fidelity);
  }
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (index[i] != ~std::size_t{0}) {
      const Width& w = widths.at(width_key(candidates[i].design));
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
