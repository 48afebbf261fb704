// Creates a software visibility backend by name; the board backend is built by the board runner.
#pragma once

#include <memory>
#include <string>

#include "host_sw/radiosity/visibility.h"
#include "io/choice.h"

namespace rc {

// The software backends by name (ChoiceNames below): double-precision float, and the two that give
// the pipeline's answers bit for bit. Adding a backend: its name here, its case in
// make_software_visibility (the compiler asks for it), its tests.
enum class SoftwareVisibility { float_double, fixed, fast };
// The bit-exact ones, the pipeline's answers (what a recording or a study asks): fixed and fast.
enum class BitExactVisibility { fixed, fast };

}  // namespace rc

template <>
struct rc::ChoiceNames<rc::SoftwareVisibility> {
  static constexpr std::string_view what = "visibility backend";
  static constexpr std::array<std::string_view, 3> names = {"float", "fixed", "fast"};
};
template <>
struct rc::ChoiceNames<rc::BitExactVisibility> {
  static constexpr std::string_view what = "bit-exact visibility backend";
  static constexpr std::array<std::string_view, 2> names = {"fixed", "fast"};
};

namespace rc {

// "float" (double precision), "fixed" (the bit-exact pipeline arithmetic at `bits` fractional bits,
// every segment against every face, on the CPU), "fast" (the same answers bit for bit, testing only
// the faces that could hit, on every core; docs/fast-visibility.md) or "float:E,M" (the
// floating-point pipeline's bit-exact arithmetic in that format, every segment against every face,
// on the CPU; `bits` is ignored; pipeline/float_format.h): a SoftwareVisibility's name or a float
// format's. Throws std::invalid_argument with the accepted names otherwise, or with the format error for a malformed or unsupported "float:E,M".
// `threads` (fast only): 0 = every core. `t_guard` (fixed and fast only): the guard band on the
// pipeline's t test in LSBs (pipeline/fixed_format.h); a non-zero one with a float backend, or one
// outside 0..kMaxTGuard, throws std::invalid_argument.
std::unique_ptr<VisibilityBackend> make_software_visibility(const std::string& name, int bits, int threads = 0,
                                                            int t_guard = 0);
std::unique_ptr<VisibilityBackend> make_software_visibility(SoftwareVisibility kind, int bits, int threads = 0,
                                                            int t_guard = 0);

// The same backend for answers whose tests nobody pays for (a recording for timing replay, the
// board's oracle): it skips segments the solver does not need and reuses a repeated shooter's
// answer (NeededOnlyVisibility, ShooterMemoVisibility). The solver's results are bit-identical;
// tests_performed() counts only the tests really run.
std::unique_ptr<VisibilityBackend> make_functional_answer(const std::string& name, int bits, int threads = 0,
                                                          int t_guard = 0);

}  // namespace rc
