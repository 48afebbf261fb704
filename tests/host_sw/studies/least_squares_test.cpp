#include <gtest/gtest.h>

#include "host_sw/studies/least_squares.h"

namespace rc {
namespace {

// A synthetic calibration: times made from known costs per unit of work; the fit recovers them.
TEST(LeastSquares, RecoversKnownNonNegativeCosts) {
  const std::vector<double> costs = {48e-9, 1.1e-6, 3e-4};  // per test, per receiver, per step
  LeastSquaresProblem p;
  const double work[][3] = {{1.85e9, 2.6e7, 5889}, {2.9e10, 2.6e7, 5889}, {1.1e8, 1.6e6, 1488},
                            {4.4e8, 1.6e6, 1488}, {7.5e6, 1.1e5, 385}, {1.9e9, 6.6e6, 1488}};
  for (const auto& w : work) {
    p.rows.push_back({w[0], w[1], w[2]});
    p.targets.push_back(w[0] * costs[0] + w[1] * costs[1] + w[2] * costs[2]);
  }
  const LeastSquaresSolution s = solve_nonnegative_least_squares(p);
  for (std::size_t j = 0; j < costs.size(); ++j) EXPECT_NEAR(s.x[j], costs[j], 1e-9 * costs[j] + 1e-15) << j;
  for (double r : s.residuals) EXPECT_NEAR(r, 0.0, 1e-9);
}

TEST(LeastSquares, ClampsCostsThatWouldGoNegative) {
  // y = 2 a - small noise; the best unconstrained fit gives b < 0, the constrained one b = 0.
  LeastSquaresProblem p;
  p.rows = {{1, 1}, {2, 1}, {3, 1}, {4, 1}};
  p.targets = {1.5, 3.5, 5.5, 7.5};  // slope 2, intercept -0.5
  const LeastSquaresSolution s = solve_nonnegative_least_squares(p);
  EXPECT_GE(s.x[1], 0.0);
  EXPECT_EQ(s.x[1], 0.0);
  EXPECT_NEAR(s.x[0], (1.5 + 7.0 + 16.5 + 30.0) / 30.0, 1e-12);  // least squares through the origin
}

TEST(LeastSquares, RejectsEmptyAndRaggedProblems) {
  EXPECT_THROW(solve_nonnegative_least_squares({}), std::invalid_argument);
  LeastSquaresProblem ragged;
  ragged.rows = {{1, 2}, {1}};
  ragged.targets = {1, 2};
  EXPECT_THROW(solve_nonnegative_least_squares(ragged), std::invalid_argument);
}

}  // namespace
}  // namespace rc
