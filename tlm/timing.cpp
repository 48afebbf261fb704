#include "tlm/timing.h"

#include <algorithm>
#include <cmath>

namespace rc::tlmx {

std::uint64_t ceil_over_efficiency(std::uint64_t n, double efficiency) {
  // Every bus at full efficiency takes this on each transaction: n / 1.0 is n exactly below 2^53.
  if (efficiency == 1.0 && n < (std::uint64_t{1} << 53)) return n;
  const double exact = static_cast<double>(n) / efficiency;
  const double nearest = std::round(exact);
  if (std::abs(exact - nearest) <= 1e-9 * std::max(1.0, exact)) return static_cast<std::uint64_t>(nearest);
  return static_cast<std::uint64_t>(std::ceil(exact));
}

}  // namespace rc::tlmx
