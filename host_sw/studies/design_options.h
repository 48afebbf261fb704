// The options of a design search (`rc2000sim design` and rc2000tlm.design(), docs/design.md) in one
// home: their defaults (the search's own structs, design_search.h; its workload's, workload.h's
// default_design_workload(); the axes' text spelt from them), the checks of values as given, and the
// resolution of the axes' text into the DesignSpace.
// Both front ends fill a DesignOptions with what the user gave and call these, so both take the same
// defaults and refuse the same values with the same message, naming the option and the limit.
#pragma once

#include <string>

#include "host_sw/studies/design_search.h"
#include "host_sw/studies/workload.h"

namespace rc {

// `rc2000sim run --banks` takes 1..64: a design the search reports must be one run can reproduce.
inline constexpr unsigned kMaxRunBanks = 64;

// The axes' text as the command line spells them ("1-8", "bank,on_chip", "on"); the defaults are the
// DesignSpace's own, written out (by the constructor). The workload's options are typed as given;
// resolve_design_options sets the rest of it.
struct DesignOptions {
  Workload workload = default_design_workload();  // scene, --steps (fixed) and --form-factor typed as given
  BitExactVisibility visibility = BitExactVisibility::fast;  // not an option: fixed answers the same, slower
  DesignSpace space;
  DesignConstraints constraints;
  std::string lanes, banks, bank_clocks;  // empty: the space's rule (1 .. what fits, 5 .. max banks, the profile's)
  std::string results, bits, multipliers, cards, concurrent;
  // The fix axes (--offset-lsb, --neighbour-rings, --coordinate-bits as lists, 0 = off; design_fixes).
  std::string offset_lsb, neighbour_rings, coordinate_bits;
  std::string fidelity = "on";  // --fidelity on|off: space.measure_fidelity
  bool culled = false;  // cull receivers behind the shooter (workload.paper_faithful = !culled)
  bool exhaustive = false;
  DesignOptions();  // the defaults: default_design_workload(), DesignSpace{}, DesignConstraints{}, the axes' text of DesignSpace{}
};

// Checks of one value as given (only given values are checked: 0 and infinity are the structs'
// "not given"). Each throws std::invalid_argument "<option>: <why and the limit>", in the words the
// command line's checks use ("--steps: Value 0 not in range 1 to 10000000").
void check_design_steps(long long steps);                         // --steps: 1 .. SolverOptions::max_steps
StepsChoice design_steps(long long steps);                        // checked, then that fixed count
void check_design_max_banks(long long banks);                     // --max-banks: 5 .. 255 (kMaxRunBanks at resolve)
void check_design_min_bits(long long bits);                       // --min-bits: 7 .. 31
void check_design_cap(const std::string& option, double value);   // --max-energy, --max-power: finite, above 0
void check_design_axis(const std::string& option, const std::string& text);  // given empty: refused (empty means "not given")
// The scene options as `add_scene_options` checks them on the command line (--faces at least 1,
// --face-levels and --patch-levels 0..8, --patch-size finite above 0, --scene an existing file) and
// --form-factor one of form_factor_names().
void check_scene_option(const std::string& option, long long value);  // --faces, --face-levels, --patch-levels
void check_patch_size(double size);
void check_scene_file(const std::string& path);
void check_form_factor(const std::string& name);
FormFactorKind design_form_factor(const std::string& name);  // checked, then its kind

// The axes' text parsed into options.space, the workload's source and segments set (from --scene
// and --culled), and the combinations checked
// (--min-bits against --bits, --max-banks against kMaxRunBanks, an error bound against --fidelity off,
// --coordinate-bits below every width searched, in `run`'s words).
// Throws std::invalid_argument naming the option.
void resolve_design_options(DesignOptions& options);

}  // namespace rc
