#include "tlm/timing.h"

#include <algorithm>
#include <cmath>

namespace rc::tlmx {

std::uint64_t ceil_over_efficiency(std::uint64_t n, double efficiency) {
  const double exact = static_cast<double>(n) / efficiency;
  const double nearest = std::round(exact);
  if (std::abs(exact - nearest) <= 1e-9 * std::max(1.0, exact)) return static_cast<std::uint64_t>(nearest);
  return static_cast<std::uint64_t>(std::ceil(exact));
}

}  // namespace rc::tlmx
