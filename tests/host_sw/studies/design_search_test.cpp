// The design search: its choice of the fastest design and of the Pareto front (against hand-made
// points and invariances), its space (feasibility, constraints), and its one pruning, which must
// give the best design and the front that simulating the whole space gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "host_sw/radiosity/segment_fix_names.h"
#include "host_sw/studies/design_search.h"

namespace rc::test {
namespace {

DesignPoint point(unsigned lanes, unsigned banks, double seconds, double joules) {
  DesignPoint p;
  p.design.config.device = "xc2v6000";
  p.design.config.lanes = lanes;
  p.design.config.banks = banks;
  p.row.config = p.design.config;
  p.row.simulated_seconds = seconds;
  p.row.energy_joules = joules;
  p.meets_constraints = true;
  return p;
}

std::set<std::string> front_of(std::vector<DesignPoint> points) {
  mark_front(points);
  std::set<std::string> labels;
  for (const DesignPoint& p : points)
    if (p.on_front) labels.insert(std::to_string(p.design.config.lanes) + "/" + std::to_string(p.design.config.banks));
  return labels;
}

TEST(DesignSearch, FrontAndFastestOfHandMadePoints) {
  // (lanes/banks, seconds, joules), worked by hand: 2/6 is fastest; 1/5 is the frugal end; 4/8 is as
  // fast as 2/6 but uses more of everything; 3/6 is beaten by 2/6 in time and energy at the same banks;
  // 1/7 is beaten by 1/5 in banks at equal time and energy; 2/5 trades time for banks and energy.
  std::vector<DesignPoint> points = {point(2, 6, 10, 100), point(1, 5, 30, 80), point(4, 8, 10, 120),
                                     point(3, 6, 12, 110), point(1, 7, 30, 80), point(2, 5, 20, 90)};
  EXPECT_EQ(front_of(points), (std::set<std::string>{"2/6", "1/5", "2/5"}));
  EXPECT_EQ(*fastest(points), 0u);
  // A tie in time goes to fewer banks: 2/6 (6 banks) before 4/8 whichever comes first.
  std::swap(points[0], points[2]);
  EXPECT_EQ(points[*fastest(points)].design.config.lanes, 2u);
}

// Banks count the whole design's: two cards of 5 banks are 10 banks, more than one card of 6.
TEST(DesignSearch, BanksCountEveryCard) {
  std::vector<DesignPoint> points = {point(2, 5, 10, 100), point(2, 6, 10, 100)};
  points[0].design.config.cards = 2;
  EXPECT_EQ(*fastest(points), 1u);
  mark_front(points);
  EXPECT_FALSE(points[0].on_front);
  EXPECT_TRUE(points[1].on_front);
}

TEST(DesignSearch, FrontIgnoresOrderAndDominatedAdditions) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> t(1, 10), e(1, 10);
  std::uniform_int_distribution<unsigned> b(5, 9);
  std::vector<DesignPoint> points;
  for (unsigned i = 0; i < 40; ++i) points.push_back(point(i + 1, b(random), t(random), e(random)));
  const std::set<std::string> front = front_of(points);
  ASSERT_FALSE(front.empty());
  std::vector<DesignPoint> shuffled = points;
  std::shuffle(shuffled.begin(), shuffled.end(), random);
  EXPECT_EQ(front_of(shuffled), front);
  // A point worse than some front point in all three objectives changes nothing.
  std::vector<DesignPoint> more = points;
  mark_front(more);
  const DesignPoint anchor = *std::find_if(more.begin(), more.end(), [](const DesignPoint& p) { return p.on_front; });
  more.push_back(point(99, anchor.design.config.banks + 1, anchor.row.simulated_seconds + 1, anchor.row.energy_joules + 1));
  EXPECT_EQ(front_of(more), front);
  // Every point off the front is dominated by one on it (an independent check of the definition).
  mark_front(points);
  for (const DesignPoint& p : points) {
    if (p.on_front) continue;
    EXPECT_TRUE(std::any_of(points.begin(), points.end(), [&](const DesignPoint& q) {
      return q.on_front && q.row.simulated_seconds <= p.row.simulated_seconds && q.row.energy_joules <= p.row.energy_joules &&
             q.design.config.banks <= p.design.config.banks;
    }));
  }
}

TEST(DesignSearch, CapsRemoveDesignsFromBestAndFront) {
  std::vector<DesignPoint> points = {point(2, 6, 10, 100), point(1, 5, 30, 80)};
  points[0].row.average_watts = 10;
  points[1].row.average_watts = 2.7;
  DesignConstraints c;
  c.max_energy_joules = 90;
  apply_caps(points, c);
  EXPECT_FALSE(points[0].meets_constraints);
  EXPECT_EQ(*fastest(points), 1u);
  c = DesignConstraints{};
  c.max_watts = 2;
  apply_caps(points, c);
  EXPECT_FALSE(fastest(points).has_value());
  mark_front(points);
  EXPECT_FALSE(points[0].on_front || points[1].on_front);
}

DesignPoint with_error(DesignPoint p, double rmse, double max) {
  p.fidelity.relative_rmse = rmse;
  p.fidelity.relative_max = max;
  return p;
}

// Error is the front's fourth objective: a faster design with a worse picture does not push a slower,
// more faithful one off the front; an unmeasured error counts as the worst.
TEST(DesignSearch, ErrorIsAnObjectiveOfTheFront) {
  std::vector<DesignPoint> points = {with_error(point(2, 6, 10, 100), 0.5, 2), with_error(point(2, 6, 12, 100), 0.001, 0.1),
                                     with_error(point(2, 6, 13, 100), 0.001, 0.1), point(2, 6, 14, 100)};
  mark_front(points);
  EXPECT_TRUE(points[0].on_front);
  EXPECT_TRUE(points[1].on_front);   // slower, but its picture is better
  EXPECT_FALSE(points[2].on_front);  // slower than [1] at the same error
  EXPECT_FALSE(points[3].on_front);  // not measured: the worst error
  EXPECT_EQ(*fastest(points), 0u);
}

// --max-error (relative RMSE) and --max-error-max: the fastest design whose picture meets them; a
// design whose fidelity was not measured meets no error bound.
TEST(DesignSearch, ErrorBoundChoosesTheFastestFaithfulDesign) {
  std::vector<DesignPoint> points = {with_error(point(2, 6, 10, 100), 0.5, 2), with_error(point(2, 6, 12, 100), 0.009, 0.9),
                                     with_error(point(2, 6, 13, 100), 0.001, 0.1), point(1, 5, 5, 50)};
  DesignConstraints c;
  c.max_error = 0.01;
  apply_caps(points, c);
  EXPECT_FALSE(points[0].meets_constraints);
  EXPECT_FALSE(points[3].meets_constraints);  // not measured
  EXPECT_EQ(*fastest(points), 1u);
  c.max_error_max = 0.5;
  apply_caps(points, c);
  EXPECT_EQ(*fastest(points), 2u);
  mark_front(points);
  EXPECT_TRUE(points[2].on_front);
  EXPECT_FALSE(points[0].on_front || points[1].on_front || points[3].on_front);
  apply_caps(points, DesignConstraints{});
  EXPECT_EQ(*fastest(points), 3u);  // no bound: the unmeasured design competes on time
}

TEST(DesignSearch, SpaceKeepsToTheConstraintsAndNamesWhatCannotExist) {
  const ConfigChecker checker({"xc2v6000"}, "athlon-mp-2600-calibrated");
  DesignSpace space;
  space.lanes = {1, 2, 4, 40};
  space.bits = {7, 15};
  DesignConstraints c;
  c.max_banks = 8;
  c.min_bits = 15;
  const std::vector<DesignCandidate> all = enumerate_designs(space, c, checker);
  std::set<Validity> kinds;
  for (const DesignCandidate& d : all) {
    EXPECT_LE(d.design.config.banks, 8u);
    EXPECT_EQ(d.design.config.bits, 15);
    kinds.insert(d.check.validity);
    if (d.design.config.lanes == 40) {
      EXPECT_EQ(d.check.validity, Validity::does_not_fit) << d.check.reason;
    }
    // 4 lanes at 15 bits: two groups; 5 banks cannot feed them (two groups need at least 6).
    if (d.design.config.lanes == 4 && d.design.config.banks == 5) {
      EXPECT_EQ(d.check.validity, Validity::too_few_banks);
    }
    // 1 lane needs 5 banks, a sixth holds the own-face table: from 7 on the rest are spare.
    if (d.design.config.lanes == 1 && d.check.validity == Validity::ok) {
      EXPECT_EQ(d.spare_banks, d.design.config.banks >= 7) << d.design.config.label();
    }
  }
  EXPECT_EQ(kinds, (std::set<Validity>{Validity::ok, Validity::does_not_fit, Validity::too_few_banks}));
  // 4 lane counts x banks 5..8 x 2 result places x 2 multiplier kinds, at 15 bits only.
  EXPECT_EQ(all.size(), 4u * 4u * 2u * 2u);
}

// The fix axes (issue 37): their cross product at each width, no fix first, each design carrying its
// fix at its width; a coordinate width not below a width searched refused in run's words.
TEST(DesignSearch, FixAxesAreACrossProductAtEachWidth) {
  DesignSpace space;
  space.offset_lsb = {0, 2};
  space.neighbour_rings = {1, 0};
  space.coordinate_bits = {0, 11};
  const std::vector<SegmentFixOptions> fixes = design_fixes(space, 15);
  ASSERT_EQ(fixes.size(), 8u);
  EXPECT_FALSE(fixes[0].any());
  for (std::size_t i = 1; i < fixes.size(); ++i) {
    EXPECT_TRUE(fixes[i].any());
    EXPECT_EQ(fixes[i].bits, 15);
    for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(fixes[i] == fixes[j]);
  }
  const ConfigChecker checker({"xc2v6000"}, "athlon-mp-2600-calibrated");
  space.lanes = {2};
  space.banks = {6};
  space.results = {board::ResultStore::bank};
  space.multipliers = {Multipliers::block};
  space.bits = {15, 19};
  const std::vector<DesignCandidate> all = enumerate_designs(space, DesignConstraints{}, checker);
  ASSERT_EQ(all.size(), 16u);
  std::size_t described = 0;
  for (const DesignCandidate& d : all) {
    if (!d.design.fixes.any()) continue;
    EXPECT_EQ(d.design.fixes.bits, d.design.config.bits);
    const std::string text = describe(d.design);
    described += !describe(d.design.fixes).empty() && text.find(", " + describe(d.design.fixes)) != std::string::npos;
  }
  EXPECT_EQ(described, 14u);  // every fixed design names its fix (2 widths x 7 fixes)
  space.coordinate_bits = {0, 15};
  try {
    enumerate_designs(space, DesignConstraints{}, checker);
    FAIL() << "coordinate bits at the width accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--coordinate-bits: must be below --bits (15): the lanes compute at --bits on coordinates of fewer "
                           "bits, got 15");
  }
  space.coordinate_bits = {};
  EXPECT_THROW(design_fixes(space, 15), std::invalid_argument);
}

TEST(DesignSearch, PrunedSearchEqualsExhaustiveOnASmallSpace) {
  // The whole space simulated once; the search's pruning drops only spare-bank designs and must give
  // the same best design and the same front. Two devices' worth of choices, one small workload.
  Workload w = default_design_workload();
  w.scene = SceneOptions{"", 70, 0, 1, 0};
  w.steps = {StepsChoice::Kind::fixed, 12};
  const ConfigChecker checker({"virtex4-sx55"}, "athlon-mp-2600-calibrated");
  DesignSpace space;
  space.device = "virtex4-sx55";
  space.lanes = {1, 2, 3, 4};
  DesignConstraints c;
  c.max_banks = 10;
  const std::vector<DesignCandidate> candidates = enumerate_designs(space, c, checker);
  const Scene scene = prepare_scene(w.scene).scene;
  SolverOptions solver;
  solver.cull_receivers = false;
  solver.form_factor = FormFactorKind::PointToPoint;
  solver.fixed_steps = w.steps.steps;
  const RecordedRun run = record_functional_run(scene, solver, "fast", 15);
  std::uint64_t most = 0;
  for (int i = 0; i < run.result.steps; ++i) most = std::max<std::uint64_t>(most, run.recording.segments(static_cast<std::size_t>(i)));
  const DesignCases all = design_cases(candidates, scene, solver, run.recording, most, true);
  const DesignCases pruned = design_cases(candidates, scene, solver, run.recording, most, false);
  ASSERT_LT(pruned.cases.size(), all.cases.size());
  const std::vector<TimingOutcome> outcomes = run_timing_study(all.cases);
  std::vector<DesignPoint> every, searched;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (all.index[i] == ~std::size_t{0}) continue;
    every.push_back(design_point(candidates[i].design, outcomes[all.index[i]], w.steps.steps));
    if (pruned.index[i] != ~std::size_t{0}) searched.push_back(every.back());
  }
  for (auto* points : {&every, &searched}) {
    apply_caps(*points, c);
    mark_front(*points);
  }
  const auto key = [](const DesignPoint& p) { return p.design.config.label(); };
  ASSERT_TRUE(fastest(every) && fastest(searched));
  EXPECT_EQ(key(every[*fastest(every)]), key(searched[*fastest(searched)]));
  std::set<std::string> front_all, front_searched;
  for (const DesignPoint& p : every)
    if (p.on_front) front_all.insert(key(p));
  for (const DesignPoint& p : searched)
    if (p.on_front) front_searched.insert(key(p));
  EXPECT_EQ(front_all, front_searched);
  // The reason the pruning is exact: a spare bank changes no time, and costs energy.
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!candidates[i].spare_banks) continue;
    const DesignPoint& spare = *std::find_if(every.begin(), every.end(), [&](const DesignPoint& p) { return key(p) == candidates[i].design.config.label(); });
    SweepConfig fewer = candidates[i].design.config;
    fewer.banks -= 1;
    const DesignPoint& base = *std::find_if(every.begin(), every.end(), [&](const DesignPoint& p) { return key(p) == fewer.label(); });
    EXPECT_EQ(spare.row.simulated_seconds, base.row.simulated_seconds) << key(spare);
    EXPECT_GT(spare.row.energy_joules, base.row.energy_joules) << key(spare);
  }
}

// The whole search on a workload that is not the default (converge, culled, disc; the fixed backend):
// every design replays the steps a solve to convergence of that workload takes, solved here on its
// own with the other bit-exact backend, and the result records the workload given.
TEST(DesignSearch, SearchSolvesTheWorkloadGivenToConvergence) {
  Workload w = default_design_workload();
  w.scene = SceneOptions{"", 70, 0, 1, 0};  // Table 2's 70/280 (385 steps): the converge policy ignores it
  w.steps.kind = StepsChoice::Kind::converge;
  w.paper_faithful = false;
  w.form_factor = FormFactorKind::Disc;
  DesignSpace space;
  space.device = "virtex4-sx55";
  space.lanes = {1};
  space.banks = {6};
  space.results = {board::ResultStore::bank};
  space.multipliers = {Multipliers::block};
  std::vector<std::string> phases;
  const DesignSearchResult r = search_designs(w, BitExactVisibility::fixed, space, DesignConstraints{}, false,
                                              [&](const std::string& what) { phases.push_back(what); });
  SolverOptions solver;
  solver.cull_receivers = true;
  solver.form_factor = FormFactorKind::Disc;
  const RecordedRun solved = record_functional_run(prepare_scene(w.scene).scene, solver, "fast", 15);
  ASSERT_GT(solved.result.steps, 0);
  EXPECT_NE(solved.result.steps, 385);
  EXPECT_EQ(r.steps, solved.result.steps);
  EXPECT_EQ(r.faces, 70u);
  EXPECT_EQ(r.patches, 280u);
  EXPECT_EQ(r.workload.steps.kind, StepsChoice::Kind::converge);
  EXPECT_FALSE(r.workload.paper_faithful);
  EXPECT_EQ(r.workload.form_factor, FormFactorKind::Disc);
  // The board tests every segment sent against every face: the replay sent the culled solve's segments.
  std::uint64_t segments = 0;
  for (int i = 0; i < solved.result.steps; ++i) segments += solved.recording.segments(static_cast<std::size_t>(i));
  ASSERT_EQ(r.points.size(), 1u);
  EXPECT_EQ(r.points[0].tests, segments * r.faces);
  ASSERT_TRUE(r.reference.has_value());
  EXPECT_EQ(r.reference->tests, segments * r.faces);
  ASSERT_GE(phases.size(), 4u);
  EXPECT_EQ(phases.front(), "preparing the scene");
  EXPECT_EQ(phases[1], "solving at 1 width and in double precision");
  EXPECT_EQ(phases.back(), "simulating 3 systems");  // the design, the paper's, software at 15 bits
  EXPECT_EQ(phases[phases.size() - 2], "solved fixed:15 (1 of 1)");
  // The width's own solve and its fidelity against one double-precision solve of the same workload.
  ASSERT_EQ(r.widths.size(), 1u);
  EXPECT_EQ(r.widths[0].bits, 15);
  EXPECT_EQ(r.widths[0].steps, solved.result.steps);
  EXPECT_TRUE(r.widths[0].measured());
  EXPECT_GT(r.widths[0].software_seconds, 0);
  EXPECT_GT(r.reference_steps, 0);
  EXPECT_EQ(r.points[0].fidelity.relative_rmse, r.widths[0].relative_rmse);
  EXPECT_EQ(r.points[0].row.steps, solved.result.steps);
  EXPECT_EQ(r.software_seconds, r.widths[0].software_seconds);
}

}  // namespace
}  // namespace rc::test
