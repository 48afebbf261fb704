#include "host_sw/studies/paper_design_search.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "board/design_fit.h"
#include "host_sw/platform/board_run.h"

namespace rc {

namespace {

std::string format(const char* pattern, double a, double b = 0) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

Sec56Search plan_one(const ConfigChecker& checker, const std::string& device, const std::string& host, bool full_rate,
                     std::uint64_t rays, std::uint64_t faces) {
  const board::DeviceProfile& profile = checker.device(device);
  Sec56Search s;
  s.device = device;
  s.assumption = full_rate ? "full-rate banks" : "profile banks";
  s.bank_clock_mhz = profile.bank_clock_mhz;
  const int most = board::max_lanes(profile, checker.resources(), 15);
  s.max_banks = full_rate ? std::min(board::banks_for_full_rate(profile, std::max(most, 1), 15) + 1, 64u) : profile.bank_count;
  DesignSpace space;
  space.device = device;
  space.host = host;
  space.multipliers = {Multipliers::block};
  DesignConstraints constraints;
  constraints.max_banks = s.max_banks;
  constraints.min_bits = 15;
  std::vector<DesignCandidate> all = enumerate_designs(space, constraints, checker);
  s.designs = all.size();
  std::vector<std::pair<double, std::size_t>> ranked;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].check.validity != Validity::ok || all[i].spare_banks) continue;
    ++s.feasible;
    ranked.emplace_back(formula_tests_per_second(all[i], rays, faces), i);
  }
  // Fastest by the formula first; among equals, fewer banks, then fewer lanes (enumeration order).
  std::stable_sort(ranked.begin(), ranked.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first > b.first;
    return all[a.second].design.config.banks < all[b.second].design.config.banks;
  });
  for (std::size_t k = 0; k < ranked.size() && k < kSec56Simulated; ++k) {
    s.simulated.push_back(all[ranked[k].second]);
    s.formula_rate.push_back(ranked[k].first);
  }
  return s;
}

}  // namespace

double formula_tests_per_second(const DesignCandidate& d, std::uint64_t rays, std::uint64_t faces) {
  const BoardSetup setup = make_board_setup(d.check.options);
  const board::RaySplit split = board::split_rays(setup.layout, rays);
  const board::PassTiming t = board::pass_timing(setup.layout, setup.board.timing, split, faces, true);
  const double seconds = static_cast<double>(t.total) * setup.board.timing.device_period.to_seconds();
  return static_cast<double>(rays) * static_cast<double>(faces) / seconds;
}

std::string Sec56Search::board_text() const {
  return std::to_string(max_banks) + " banks at " + format("%g", bank_clock_mhz) + " MHz (" +
         (assumption == "profile banks" ? "the board as profiled" : "as many as the most lanes need at full rate") + ")";
}

board::PaperEstimate Sec56Search::estimate(double software_rate) const {
  board::PaperEstimate e;
  e.estimate = "best design from the search, " + assumption;
  e.rule = board::EstimateRule::Model;
  e.device = device;
  e.software_rate = software_rate;
  if (!best) {
    e.note = "no design of the space could be simulated";
    return e;
  }
  const DesignPoint& p = points[*best];
  e.lanes = static_cast<int>(p.design.config.lanes);
  e.clock_mhz = p.row.clock_mhz;
  e.intersections_per_s = p.row.intersections_per_second_while_busy;
  e.bytes_per_intersection = p.bank_bytes_per_test;
  e.bytes_per_cycle = e.intersections_per_s / (e.clock_mhz * 1e6) * e.bytes_per_intersection;
  e.gb_per_s = e.intersections_per_s * e.bytes_per_intersection / 1e9;
  e.speedup_vs_software = e.intersections_per_s / software_rate;
  e.note = describe(p.design) + format("; paper's workload %.2f s", p.row.simulated_seconds) + "; bound: " + p.bound.text();
  e.clock_assumption = format("the profile's design clock for %g lanes, %g MHz; ", e.lanes, e.clock_mhz) + board_text();
  return e;
}

std::vector<Sec56Search> plan_sec56_searches(const std::string& host, std::uint64_t rays, std::uint64_t faces,
                                             pipeline::ResourceSource resources) {
  const ConfigChecker checker(std::vector<std::string>(std::begin(kSec56Devices), std::end(kSec56Devices)), {host}, {},
                              "command line", resources);
  std::vector<Sec56Search> out;
  for (const char* device : kSec56Devices)
    for (bool full_rate : {false, true}) out.push_back(plan_one(checker, device, host, full_rate, rays, faces));
  return out;
}

void add_sec56_cases(std::vector<Sec56Search>& searches, const PaperScene& scene, std::vector<TimingCase>& cases) {
  std::uint64_t most = 0;
  for (int i = 0; i < scene.row.steps; ++i)
    most = std::max<std::uint64_t>(most, scene.functional.recording.segments(static_cast<std::size_t>(i)));
  for (Sec56Search& s : searches) {
    DesignCases dc = design_cases(s.simulated, scene.scene, scene.solver, scene.functional.recording, most, false);
    s.case_index.clear();
    for (std::size_t i : dc.index) s.case_index.push_back(i == ~std::size_t{0} ? i : cases.size() + i);
    for (TimingCase& t : dc.cases) cases.push_back(std::move(t));
  }
}

void collect_sec56(std::vector<Sec56Search>& searches, const std::vector<TimingOutcome>& outcomes, int steps) {
  for (Sec56Search& s : searches) {
    s.points.clear();
    for (std::size_t i = 0; i < s.simulated.size(); ++i) {
      if (s.case_index[i] == ~std::size_t{0}) continue;
      s.points.push_back(design_point(s.simulated[i].design, outcomes.at(s.case_index[i]), steps));
      s.points.back().profile = *s.simulated[i].check.options.device_profile;
    }
    s.best = fastest(s.points);
  }
}

std::optional<std::size_t> sec56_scene(const std::vector<PaperScene>& scenes) {
  for (std::size_t i = 0; i < scenes.size(); ++i)
    if (scenes[i].row.faces == 280 && scenes[i].row.patches == 4480) return i;
  return std::nullopt;
}

}  // namespace rc
