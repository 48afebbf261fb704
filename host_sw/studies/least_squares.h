// Non-negative linear least squares (Lawson and Hanson's active-set method), for fitting the host
// CPU cost model: every cost is a time per unit of work, so none may be negative.
#pragma once

#include <vector>

namespace rc {

struct LeastSquaresProblem {
  std::vector<std::vector<double>> rows;  // A: one row per observation, one column per parameter
  std::vector<double> targets;            // b
};

struct LeastSquaresSolution {
  std::vector<double> x;          // argmin |A x - b|, x >= 0
  std::vector<double> residuals;  // A x - b
  int iterations = 0;
};

// Throws std::invalid_argument for an empty or ragged problem.
LeastSquaresSolution solve_nonnegative_least_squares(const LeastSquaresProblem& problem);

}  // namespace rc
