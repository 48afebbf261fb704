#include <gtest/gtest.h>

#include "host_sw/studies/bench_study.h"

namespace rc {
namespace {

TEST(BenchStudy, EachDimensionVariesAloneAndFloatFormatsStandBesideTheWidths) {
  BenchSpec spec;
  spec.widths = {11, 15};  // 15 is the base's: left out
  spec.convergences = {0.995, 0.999};
  spec.patch_levels = {2};
  spec.formats = {pipeline::Arithmetic::parse("float:5,10"), pipeline::Arithmetic::parse("float:8,23")};
  const std::vector<BenchPoint> points = sweep_points(spec);
  std::vector<std::string> labels;
  for (const BenchPoint& p : points) labels.push_back(p.varied + " " + p.label());
  EXPECT_EQ(labels, (std::vector<std::string>{"base 15 bits", "bits 11 bits", "arith float:5,10", "arith float:8,23",
                                              "convergence 15 bits", "form_factor 15 bits", "form_factor 15 bits"}));
  EXPECT_EQ(points[2].bits, spec.base.bits);  // a float point keeps the base's other settings
  EXPECT_EQ(points[4].convergence, 0.999);
  // The base is analytic; the other kinds are one point each, in the names' order.
  EXPECT_EQ(points[0].form_factor, FormFactorKind::Analytic);
  EXPECT_EQ(points[5].form_factor, FormFactorKind::PointToPoint);
  EXPECT_EQ(points[6].form_factor, FormFactorKind::Disc);
}

}  // namespace
}  // namespace rc
