// Sec 5.6 from the model's search in `paper`: the pass-timing formula shortlists designs and only the
// shortlist is simulated. On the board as profiled the shortlist's best must be the best of every
// feasible design simulated, on every device; and the estimate it gives is that design's simulated
// figures in sec 5.6's units.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "host_sw/studies/paper_design_search.h"

namespace rc::test {
namespace {

PaperScene small_scene() {
  PaperScene p;
  p.scene = prepare_scene(SceneOptions{"", 70, 0, 1, 0}).scene;
  p.row.faces = static_cast<int>(p.scene.faces.size());
  p.row.patches = static_cast<int>(p.scene.patches.size());
  p.row.steps = 15;
  p.solver.cull_receivers = false;
  p.solver.form_factor = FormFactorKind::PointToPoint;
  p.solver.fixed_steps = p.row.steps;
  p.functional = record_functional_run(p.scene, p.solver, "fast", 15);
  return p;
}

TEST(PaperDesignSearch, ShortlistFindsTheBestOfEveryDesignOnTheProfiledBoard) {
  const std::string host = "athlon-mp-2600-calibrated";
  const PaperScene scene = small_scene();
  std::vector<Sec56Search> searches = plan_sec56_searches(host, scene.scene.patches.size(), scene.scene.faces.size());
  ASSERT_EQ(searches.size(), 2 * std::size(kSec56Devices));
  std::vector<TimingCase> cases;
  add_sec56_cases(searches, scene, cases);
  // Every feasible design of the profile-banks space, for the exhaustive answer.
  const ConfigChecker checker(std::vector<std::string>(std::begin(kSec56Devices), std::end(kSec56Devices)), host);
  std::uint64_t most = 0;
  for (int i = 0; i < scene.row.steps; ++i) most = std::max<std::uint64_t>(most, scene.functional.recording.segments(i));
  struct Whole {
    std::vector<DesignCandidate> candidates;
    DesignCases cases;
    std::size_t first = 0;
  };
  std::vector<Whole> whole;
  for (const char* device : kSec56Devices) {
    DesignSpace space;
    space.device = device;
    space.host = host;
    space.multipliers = {Multipliers::block};
    DesignConstraints c;
    c.min_bits = 15;
    Whole w;
    w.candidates = enumerate_designs(space, c, checker);
    w.cases = design_cases(w.candidates, scene.scene, scene.solver, scene.functional.recording, most, false);
    w.first = cases.size();
    for (const TimingCase& t : w.cases.cases) cases.push_back(t);
    whole.push_back(std::move(w));
  }
  const std::vector<TimingOutcome> outcomes = run_timing_study(cases);
  collect_sec56(searches, outcomes, scene.row.steps);
  for (std::size_t d = 0; d < whole.size(); ++d) {
    std::vector<DesignPoint> every;
    for (std::size_t i = 0; i < whole[d].candidates.size(); ++i)
      if (whole[d].cases.index[i] != ~std::size_t{0})
        every.push_back(design_point(whole[d].candidates[i].design, outcomes[whole[d].first + whole[d].cases.index[i]], 15));
    const std::optional<std::size_t> best = fastest(every);
    ASSERT_TRUE(best.has_value()) << kSec56Devices[d];
    const Sec56Search& s = searches[2 * d];
    ASSERT_EQ(s.assumption, "profile banks");
    ASSERT_TRUE(s.best.has_value());
    EXPECT_EQ(s.points[*s.best].design.config.label(), every[*best].design.config.label()) << kSec56Devices[d];
    EXPECT_EQ(s.points[*s.best].row.simulated_seconds, every[*best].row.simulated_seconds);
    // The estimate is the simulated design in sec 5.6's units.
    const board::PaperEstimate e = s.estimate(2e7);
    const DesignPoint& p = s.points[*s.best];
    EXPECT_EQ(e.lanes, static_cast<int>(p.design.config.lanes));
    EXPECT_DOUBLE_EQ(e.intersections_per_s, p.row.intersections_per_second_while_busy);
    EXPECT_DOUBLE_EQ(e.gb_per_s, e.intersections_per_s * p.bank_bytes_per_test / 1e9);
    EXPECT_NE(e.note.find("bound: "), std::string::npos);
    EXPECT_NE(e.clock_assumption.find("banks at"), std::string::npos);
    // The full-rate board has at least the profiled board's banks.
    const Sec56Search& full = searches[2 * d + 1];
    ASSERT_TRUE(full.best.has_value());
    EXPECT_GE(full.max_banks, s.max_banks);
  }
}

}  // namespace
}  // namespace rc::test
