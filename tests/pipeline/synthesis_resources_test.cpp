// The synthesis source of resources (pipeline/synthesis_resources.h): its fit and leave-one-out
// errors against an independent solve, its interpolation between synthesised widths, its errors,
// and the resource model and the device fit under it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/resource_model.h"
#include "pipeline/synthesis_resources.h"
#include "profiles/synthesis_table.h"

namespace rc::pipeline {
namespace {

std::string config(const char* name) { return std::string(RC_SOURCE_DIR) + "/configs/" + name; }

const ResourceModel& paper() {
  static const ResourceModel m = ResourceModel::load(config("pipeline_resources.json"));
  return m;
}
const profiles::SynthesisTable& table() {
  static const profiles::SynthesisTable t = profiles::read_synthesis_table(config("synthesis_resources.json"));
  return t;
}
const ResourceModel& synthesis() {
  static const ResourceModel m = paper().with_synthesis(table(), "synthesis_resources.json");
  return m;
}

// A table whose slices follow slices = 0.5 LUTs + 0.25 FFs exactly at the published points.
profiles::SynthesisTable exact_table() {
  profiles::SynthesisTable t;
  t.synthesizer = "test";
  t.command = "none";
  t.source = "made up";
  profiles::SynthesisFamily f;
  f.family = "xc2v";
  f.part_prefix = "XC2V";
  // Published: without block multipliers 1951, 5471, 10615, 16889; with 1128, 1976 (paper). Choose FFs,
  // then LUTs = 2 (slices - 0.25 FFs).
  const auto row = [](int bits, double slices, int ffs, int blocks) {
    return profiles::SynthesisPoint{bits, static_cast<int>(std::lround(2 * (slices - 0.25 * ffs))), 0, ffs, blocks};
  };
  f.array = {row(7, 1951, 4000, 0), row(15, 5471, 8000, 0), row(23, 10615, 12000, 0), row(31, 16889, 16000, 0)};
  f.block = {row(7, 1128, 4000, 27), row(15, 1976, 8000, 27), row(23, 3000, 12000, 102)};
  t.families = {f};
  return t;
}

TEST(SynthesisResources, RecoversAnExactRuleWithZeroLeaveOneOutError) {
  const SynthesisResources s = SynthesisResources::build(exact_table(), paper().published_slices(), "XC2V6000", "exact");
  EXPECT_NEAR(s.fit().per_lut, 0.5, 1e-9);
  EXPECT_NEAR(s.fit().per_flip_flop, 0.25, 1e-9);
  ASSERT_EQ(s.fit().leave_one_out.size(), 6u);
  for (const LeaveOneOutError& e : s.fit().leave_one_out) EXPECT_NEAR(e.relative_error, 0, 1e-9) << e.point.frac_bits;
  EXPECT_NEAR(s.fit().max_abs_leave_one_out, 0, 1e-9);
}

// The real table: the fit and each leave-one-out prediction against an independent solve (a 2x2
// system by Cramer's rule over the normal equations, written out here), on the paper's own points.
TEST(SynthesisResources, FitAndLeaveOneOutMatchAnIndependentSolve) {
  struct P { int bits; bool block; double slices; double luts, ffs; };
  std::vector<P> points;
  for (const PublishedSlices& p : paper().published_slices()) {
    const profiles::SynthesisFamily& f = table().families.front();
    ASSERT_EQ(f.family, "xc2v");
    const auto& rows = p.block_multipliers ? f.block : f.array;
    bool found = false;
    for (const profiles::SynthesisPoint& r : rows) {
      if (r.frac_bits == p.frac_bits) {
        points.push_back({p.frac_bits, p.block_multipliers, p.slices, double(r.luts + r.srls), double(r.flip_flops)});
        found = true;
      }
    }
    ASSERT_TRUE(found) << p.frac_bits;
  }
  const auto solve = [](const std::vector<P>& use, double& a, double& b) {
    double sll = 0, slf = 0, sff = 0, sls = 0, sfs = 0;
    for (const P& p : use) {
      sll += p.luts * p.luts, slf += p.luts * p.ffs, sff += p.ffs * p.ffs, sls += p.luts * p.slices, sfs += p.ffs * p.slices;
    }
    const double d = sll * sff - slf * slf;
    a = (sls * sff - slf * sfs) / d;
    b = (sll * sfs - slf * sls) / d;
  };
  const SynthesisSliceFit& fit = synthesis().synthesis()->fit();
  double a = 0, b = 0;
  solve(points, a, b);
  EXPECT_NEAR(fit.per_lut, a, 1e-12 * std::fabs(a) + 1e-15);
  EXPECT_NEAR(fit.per_flip_flop, b, 1e-12 * std::fabs(b) + 1e-15);
  ASSERT_EQ(fit.leave_one_out.size(), points.size());
  double worst = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<P> rest = points;
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
    solve(rest, a, b);
    const double predicted = a * points[i].luts + b * points[i].ffs;
    EXPECT_NEAR(fit.leave_one_out[i].predicted, predicted, 1e-6) << points[i].bits;
    EXPECT_NEAR(fit.leave_one_out[i].relative_error, (predicted - points[i].slices) / points[i].slices, 1e-12);
    worst = std::max(worst, std::fabs((predicted - points[i].slices) / points[i].slices));
  }
  EXPECT_DOUBLE_EQ(fit.max_abs_leave_one_out, worst);
  // Both coefficients are physical: a slice holds two LUTs and two flip-flops, so each is in (0, 0.5].
  EXPECT_GT(fit.per_lut, 0);
  EXPECT_LE(fit.per_lut, 0.5);
  EXPECT_GT(fit.per_flip_flop, 0);
  EXPECT_LE(fit.per_flip_flop, 0.5);
}

TEST(SynthesisResources, InterpolatesBetweenSynthesisedWidthsAndFlagsIt) {
  const SynthesisResources s = SynthesisResources::build(exact_table(), paper().published_slices(), "XC2V6000", "exact");
  const SynthesisCounts at15 = s.counts("XC2V6000", 15, false), at23 = s.counts("xc2v6000", 23, false);
  EXPECT_FALSE(at15.interpolated || at15.extrapolated);
  const SynthesisCounts at19 = s.counts("XC2V6000", 19, false);
  EXPECT_TRUE(at19.interpolated);
  EXPECT_FALSE(at19.extrapolated);
  EXPECT_EQ(at19.flip_flops, (at15.flip_flops + at23.flip_flops) / 2);
  EXPECT_EQ(at19.luts, static_cast<int>(std::lround((at15.luts + at23.luts) / 2.0)));
  // Block multipliers between widths with different counts: the wider neighbour's (the larger).
  EXPECT_EQ(s.counts("XC2V6000", 19, true).block_multipliers, 102);
  // Beyond the synthesised widths (block rows end at 23): extrapolated from the two nearest.
  const SynthesisCounts at31 = s.counts("XC2V6000", 31, true);
  EXPECT_TRUE(at31.extrapolated);
  EXPECT_EQ(at31.flip_flops, 16000);
}

TEST(SynthesisResources, RefusesPartsAndTablesItCannotAnswer) {
  const SynthesisResources s = SynthesisResources::build(exact_table(), paper().published_slices(), "XC2V6000", "exact.json");
  try {
    (void)s.counts("XC5VLX330", 15, true);
    FAIL() << "no family for the part";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("XC5VLX330"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("XC2V"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("exact.json"), std::string::npos) << e.what();
  }
  profiles::SynthesisTable missing = exact_table();
  missing.families.front().block.erase(missing.families.front().block.begin() + 1);  // 15 bits with block mults
  try {
    (void)SynthesisResources::build(missing, paper().published_slices(), "XC2V6000", "missing.json");
    FAIL() << "a published point without a synthesis";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("15 bits with block multipliers"), std::string::npos) << e.what();
  }
}

// Under the synthesis source: the synthesizer's block count and the fitted slices for the device's
// family, the paper's clock, and the same answer for every family Yosys maps alike.
TEST(SynthesisResources, ModelTakesSlicesAndBlocksFromTheSynthesizerAndTheClockFromThePaper) {
  const SynthesisSliceFit& fit = synthesis().synthesis()->fit();
  for (const char* part : {"", "XC2V6000", "XC4VSX55", "XC3S5000"}) {
    for (bool block : {false, true}) {
      for (int bits : {7, 15, 23, 31}) {
        const PipelineResources p = synthesis().pipeline(bits, block, part);
        const SynthesisCounts c = synthesis().synthesis()->counts(*part ? part : "XC2V6000", bits, block);
        EXPECT_EQ(p.source, ResourceSource::synthesis);
        EXPECT_EQ(p.slices, std::lround(fit.per_lut * (c.luts + c.srls) + fit.per_flip_flop * c.flip_flops)) << part << bits;
        EXPECT_EQ(p.block_multipliers, c.block_multipliers);
        EXPECT_DOUBLE_EQ(p.clock_mhz, paper().pipeline(bits, block).clock_mhz) << part << bits;
        EXPECT_TRUE(p.interpolated);
      }
    }
  }
  EXPECT_EQ(synthesis().pipeline(15, true, "XC4VSX55").synthesis_family, "xc4v");
  // The paper source is unchanged by the synthesis table's existence.
  EXPECT_EQ(paper().pipeline(15, true).slices, 1976);
  EXPECT_EQ(paper().pipeline(15, true).source, ResourceSource::paper_fit);
}

}  // namespace
}  // namespace rc::pipeline
