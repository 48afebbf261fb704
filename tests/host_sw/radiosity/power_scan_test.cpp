// scan_powers picks the next shooter and vouches for the energy guard without the guard's sum in
// index order; checked against that single loop on random powers (ties, zeros, NaNs, negative
// values, totals at the limit).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "host_sw/radiosity/radiosity.h"

namespace rc {
namespace {

struct SingleLoop {
  std::size_t first_maximum = 0;
  double total = 0;
};

// The definition: one pass in index order, as the solver's scan was written.
SingleLoop single_loop(const std::vector<double>& power) {
  SingleLoop r;
  double best = power[0];
  r.total = power[0];
  for (std::size_t i = 1; i < power.size(); ++i) {
    r.total += power[i];
    if (power[i] > best) best = power[i], r.first_maximum = i;
  }
  return r;
}

TEST(PowerScan, FindsTheFirstMaximumAndNeverVouchesForASumAboveTheLimit) {
  std::mt19937_64 rng(2026);
  const auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
  std::size_t vouched = 0, near_limit = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::size_t n = 1 + rng() % 300;
    std::vector<double> power(n);
    const int kind = trial % 6;
    for (double& p : power) {
      switch (kind) {
        case 0: p = uniform(); break;                              // distinct
        case 1: p = static_cast<double>(rng() % 4); break;         // many ties
        case 2: p = rng() % 3 ? 0.0 : uniform() * 1e300; break;    // zeros, huge values
        case 3: p = uniform() - 0.25; break;                       // some negative
        case 4: p = rng() % 50 ? uniform() : std::nan(""); break;  // a NaN here and there
        default: p = std::ldexp(1.0 + uniform(), static_cast<int>(rng() % 60) - 30); break;
      }
    }
    if (trial % 97 == 0) power[0] = std::nan("");
    const SingleLoop expected = single_loop(power);
    // Limits around the index-order total: just below, at, and just above it.
    for (const double scale : {1.0 - 1e-12, 1.0, 1.0 + 1e-15, 1.0 + 1e-9, 2.0}) {
      const double limit = expected.total * scale;
      const PowerScan scan = scan_powers(power.data(), n, limit);
      ASSERT_EQ(scan.first_maximum, expected.first_maximum) << "trial " << trial << ", n " << n;
      if (scan.within_limit) {
        ++vouched;
        ASSERT_TRUE(std::isfinite(expected.total) && expected.total <= limit) << "trial " << trial;
      }
      near_limit += scale < 1.0;
    }
  }
  EXPECT_GT(vouched, 20000u) << "the fast answer should hold for most totals well below the limit";
  EXPECT_GT(near_limit, 0u);
}

TEST(PowerScan, ASingleValue) {
  const double one[] = {3.5};
  EXPECT_EQ(scan_powers(one, 1, 3.5 * 2).first_maximum, 0u);
  EXPECT_TRUE(scan_powers(one, 1, 3.5 * 2).within_limit);
  EXPECT_FALSE(scan_powers(one, 1, 3.0).within_limit);
}

}  // namespace
}  // namespace rc
