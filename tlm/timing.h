// Cycle arithmetic shared by the TLM parts. Every model states its latencies in cycles of its own
// clock and converts to sc_time only here, with integer arithmetic on the kernel's time value, so
// that "n cycles at period p" is exactly n * p and tests can assert times with operator==.
#pragma once

#include <cstdint>

#include <systemc>

namespace rc::tlmx {

// ceil(a / b) for b > 0, in integers (no floating-point rounding).
constexpr std::uint64_t ceil_div(std::uint64_t a, std::uint64_t b) { return (a + b - 1) / b; }

// Exactly n clock periods. Integer multiply on the kernel's time value: 1,000,000 cycles of a
// 30303 ps clock is 30303000000 ps, not a double that happens to round there.
inline sc_core::sc_time cycles(std::uint64_t n, const sc_core::sc_time& period) {
  return sc_core::sc_time::from_value(period.value() * n);
}

// Clock period for a frequency in Hz, rounded to the kernel's time resolution (1 ps by default:
// 33 MHz -> 30303 ps). Configuration files may state frequencies; the models keep periods.
inline sc_core::sc_time period_from_hz(double hz) { return sc_core::sc_time(1.0 / hz, sc_core::SC_SEC); }

// ceil(n / efficiency) for efficiency in (0, 1]. A quotient within a relative 1e-9 of an integer is
// taken as that integer, so that 1024 / 0.8 is 1280 cycles and not 1281 because 0.8 is not exact in
// binary.
std::uint64_t ceil_over_efficiency(std::uint64_t n, double efficiency);

}  // namespace rc::tlmx
