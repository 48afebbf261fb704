// Sec 5.6 from the model's own design search (`rc2000sim paper`, docs/board.md "Sec 5.6"): for each
// device (XC2V6000, Virtex-4 SX55, Spartan-3 5000) and each of two stated board assumptions, the fastest
// design on the paper's 280-face, 4,480-patch workload, simulated in the paper command's own timing
// study, and its figures in sec 5.6's units.
//
// Board assumptions (bank count and clock; the device's profile gives the clock, 100 MHz for all three):
//   "profile banks"   the board as profiled: 6 banks (the RC2000's memory system)
//   "full-rate banks" as many banks as the most lanes that fit need at full rate (3 per group of
//                     lanes + faces + results, plus one for the own-face table), at most 64
// The space: 15 bits (sec 5.6's pipeline), every lane count that fits, 5 .. the assumption's banks,
// results in the bank or on chip, block multipliers while they last, one card, the concurrent driver.
// To keep `paper` fast the pass-timing formula (board/pass_timing.h: one pass of the workload's rays
// against its faces) ranks the designs and only the kSec56Simulated fastest by the formula (ties:
// fewer banks) are simulated; the best of those by simulated time is reported, every figure
// simulated. `rc2000sim design` simulates the whole space (docs/design.md); a test checks that it
// finds the same best design on the profile-banks assumption.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "board/throughput_estimates.h"
#include "host_sw/studies/design_search.h"
#include "host_sw/studies/paper_workload.h"

namespace rc {

inline constexpr const char* kSec56Devices[] = {"xc2v6000", "virtex4-sx55", "spartan3-5000"};
inline constexpr std::size_t kSec56Simulated = 4;

struct Sec56Search {
  std::string device;
  std::string assumption;  // "profile banks" or "full-rate banks"
  unsigned max_banks = 0;
  double bank_clock_mhz = 0;
  std::size_t designs = 0, feasible = 0;
  std::vector<DesignCandidate> simulated;  // the formula's fastest, in its order
  std::vector<double> formula_rate;        // tests per second by the pass-timing formula, per simulated design
  std::vector<std::size_t> case_index;     // in the timing study
  std::vector<DesignPoint> points;         // simulated, same order
  std::optional<std::size_t> best;         // in points

  // "6 banks at 100 MHz (the board as profiled)".
  std::string board_text() const;
  // The best design as a sec 5.6 estimate (rule model): its lanes and clock, its simulated
  // intersections per second while the FPGA is busy, the bank bytes it moved per intersection.
  board::PaperEstimate estimate(double software_rate) const;
};

// The searches of every device and assumption, planned (designs checked and ranked by the formula).
// `rays`, `faces`: one step's segments and the scene's faces, for the formula.
// `resources`: where the lanes' slices and block multipliers come from (which lane counts fit).
std::vector<Sec56Search> plan_sec56_searches(const std::string& host, std::uint64_t rays, std::uint64_t faces,
                                             pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit);
// Appends the simulated designs' timing cases on `scene` (its recording, the paper's steps).
void add_sec56_cases(std::vector<Sec56Search>& searches, const PaperScene& scene, std::vector<TimingCase>& cases);
// Reads the outcomes back and picks each search's best by simulated time.
void collect_sec56(std::vector<Sec56Search>& searches, const std::vector<TimingOutcome>& outcomes, int steps);

// The paper's 280-face, 4,480-patch scene among `scenes`, or none.
std::optional<std::size_t> sec56_scene(const std::vector<PaperScene>& scenes);

// The pass-timing formula's rate of a design: `rays` against `faces` in one pass, tests per second.
double formula_tests_per_second(const DesignCandidate& design, std::uint64_t rays, std::uint64_t faces);

}  // namespace rc
