#include "host_sw/studies/least_squares.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace rc {

namespace {

using Matrix = std::vector<std::vector<double>>;

// Unconstrained least squares on the columns in `passive` (normal equations with partial
// pivoting; the problems here have a handful of columns and are scaled first).
std::vector<double> solve_on(const Matrix& a, const std::vector<double>& b, const std::vector<bool>& passive) {
  const std::size_t n = passive.size();
  std::vector<std::size_t> cols;
  for (std::size_t j = 0; j < n; ++j) {
    if (passive[j]) cols.push_back(j);
  }
  const std::size_t k = cols.size();
  Matrix m(k, std::vector<double>(k + 1, 0.0));
  for (std::size_t r = 0; r < a.size(); ++r) {
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t j = 0; j < k; ++j) m[i][j] += a[r][cols[i]] * a[r][cols[j]];
      m[i][k] += a[r][cols[i]] * b[r];
    }
  }
  for (std::size_t c = 0; c < k; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < k; ++r) {
      if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
    }
    std::swap(m[c], m[pivot]);
    if (m[c][c] == 0) continue;  // a column that never varies: leave it at zero
    for (std::size_t r = 0; r < k; ++r) {
      if (r == c) continue;
      const double f = m[r][c] / m[c][c];
      for (std::size_t j = c; j <= k; ++j) m[r][j] -= f * m[c][j];
    }
  }
  std::vector<double> x(n, 0.0);
  for (std::size_t i = 0; i < k; ++i) x[cols[i]] = m[i][i] != 0 ? m[i][k] / m[i][i] : 0.0;
  return x;
}

std::vector<double> residuals_of(const Matrix& a, const std::vector<double>& b, const std::vector<double>& x) {
  std::vector<double> r(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    double s = -b[i];
    for (std::size_t j = 0; j < x.size(); ++j) s += a[i][j] * x[j];
    r[i] = s;
  }
  return r;
}

}  // namespace

LeastSquaresSolution solve_nonnegative_least_squares(const LeastSquaresProblem& p) {
  if (p.rows.empty() || p.rows.size() != p.targets.size()) throw std::invalid_argument("least squares: no observations");
  const std::size_t n = p.rows.front().size();
  for (const auto& row : p.rows) {
    if (row.size() != n || n == 0) throw std::invalid_argument("least squares: rows of different lengths");
  }
  // Scale columns to unit norm so that costs of very different magnitudes (ns per test, ms per
  // step) are treated alike; undo the scaling at the end.
  std::vector<double> scale(n, 1.0);
  for (std::size_t j = 0; j < n; ++j) {
    double norm = 0;
    for (const auto& row : p.rows) norm += row[j] * row[j];
    if (norm > 0) scale[j] = 1.0 / std::sqrt(norm);
  }
  Matrix a = p.rows;
  for (auto& row : a) {
    for (std::size_t j = 0; j < n; ++j) row[j] *= scale[j];
  }
  const std::vector<double>& b = p.targets;

  LeastSquaresSolution out;
  std::vector<double> x(n, 0.0);
  std::vector<bool> passive(n, false);
  const double tolerance = 1e-12;
  for (int outer = 0; outer < 30 * int(n); ++outer) {
    ++out.iterations;
    // Gradient w = A^T (b - A x): the column that would lower the error most joins the passive set.
    const std::vector<double> r = residuals_of(a, b, x);
    std::size_t best = n;
    double best_w = tolerance;
    for (std::size_t j = 0; j < n; ++j) {
      if (passive[j]) continue;
      double w = 0;
      for (std::size_t i = 0; i < a.size(); ++i) w -= a[i][j] * r[i];
      if (w > best_w) best_w = w, best = j;
    }
    if (best == n) break;
    passive[best] = true;
    for (;;) {
      const std::vector<double> z = solve_on(a, b, passive);
      bool feasible = true;
      for (std::size_t j = 0; j < n; ++j) feasible = feasible && (!passive[j] || z[j] > 0);
      if (feasible) {
        x = z;
        break;
      }
      // Step back towards x until the first passive variable hits zero, and drop it.
      double alpha = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < n; ++j) {
        if (passive[j] && z[j] <= 0) alpha = std::min(alpha, x[j] / (x[j] - z[j]));
      }
      for (std::size_t j = 0; j < n; ++j) {
        x[j] += alpha * (z[j] - x[j]);
        if (passive[j] && x[j] <= tolerance) passive[j] = false, x[j] = 0;
      }
    }
  }
  out.residuals = residuals_of(a, b, x);
  for (std::size_t j = 0; j < n; ++j) x[j] *= scale[j];
  out.x = x;
  return out;
}

}  // namespace rc
