// `rc2000sim paper` as a study: the paper's four implementations of every Table 2 scene, sec 4.1's
// bank variants on the largest scene, and the withheld columns again under every driver-model
// variant whose cross-validated error is within kVariantTolerance of the best (the spread), all
// replayed in one timing study; and sec 5.6 under the paper's rule and the model's, the model's best
// design per device found by a design search simulated in the same study (paper_design_search.h). The command
// (apps/paper_command.cpp) turns the result into paper.json, paper.csv, plots and paper.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "board/throughput_estimates.h"
#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/studies/calibration_variants.h"
#include "host_sw/studies/paper_design_search.h"
#include "host_sw/studies/paper_workload.h"
#include "host_sw/studies/timing_study.h"

namespace rc {

// One spread case: a withheld column of one scene under one variant. A mechanism case (`mechanism`)
// is the concurrent column under a CPU/FPGA split (host_sw/driver/cpu_split.h), the pipelined driver
// (BoardVisibilityOptions::chunk_rays) or both, which the paper's words allow beside sec 4.3's form
// factors; it widens the range, not the variants' spread.
struct SpreadCase {
  std::size_t scene = 0;
  int implementation = 0;
  std::string driver_model;
  bool mechanism = false;
  std::size_t outcome_index = 0;             // in the study's outcomes
  std::size_t main_index = ~std::size_t{0};  // or the main column's outcome it equals (not simulated twice)
  std::size_t index() const { return main_index != ~std::size_t{0} ? main_index : outcome_index; }
};

// The pipelined driver as a mechanism of the concurrent column (docs/calibration.md, "The concurrent
// column"), under sec 4.3's overlap of each in-spread variant, alone and with the balanced split on the
// second Athlon (pipelined_splits). Not with the split on the solver's processor: that processor would
// test its share after the first chunk's START instead of sending the later chunks, so the board idles
// and the pipeline is undone. Not under the dual_cpu overlap: simulated once, inside the range on every
// scene, so left out for the command's wall time (docs/calibration.md says when to look again). The
// chunk follows one stated rule, the same for every scene and fixed before any simulation of it: the
// scene's largest step in kPipelinedChunksPerStep chunks, rounded up. Nothing about the withheld
// columns enters it.
inline constexpr std::uint64_t kPipelinedChunksPerStep = 2;
inline constexpr const char* kPipelinedChunkRule =
    "chunk_rays = ceil(S / 2), S the most segments of any of the scene's steps: each step fills the two halves of "
    "the ray and result banks once, the fewest chunks that overlap anything, so the per-pass costs a chunk repeats "
    "(the calibrated driver sends the faces with every pass) are paid least; half a bank (the board's limit on a "
    "chunk) would hold every step of Table 2 whole, one chunk that overlaps nothing";
// Off (the pipelined driver alone) and balanced on 2 CPUs.
std::vector<CpuSplit> pipelined_splits();
// ceil(S / kPipelinedChunksPerStep), S the most segments of the scene's first row.steps recorded steps;
// throws std::invalid_argument when there are none.
std::uint64_t pipelined_chunk_rays(const PaperScene& scene);

// Sec 4.1's six- and seven-bank variants against five banks, on the largest scene: at 15 bits a
// word holds two coordinates, so five banks feed two full-rate lanes, and one or two more banks
// feed two more lanes at 1/3 or 2/3 rate.
struct BankVariant {
  unsigned banks, lanes;
};
inline constexpr BankVariant kBankVariants[] = {{5, 2}, {6, 4}, {7, 4}};

struct PaperPrediction {
  const std::vector<PaperScene>* scenes = nullptr;
  std::vector<TimingOutcome> outcomes;  // kPaperImplementations per scene, the bank variants, the spread
  std::vector<SpreadCase> spread;
  std::vector<board::PaperEstimate> paper_rule, model;  // sec 5.6, pairwise
  // Sec 5.6 per device from the model's search (paper_design_search.h), on the 280/4480 scene; empty
  // when the table has no such scene.
  std::vector<Sec56Search> searched;

  // The calibration's own uncertainty: quantiles of the left-out relative errors, (prediction -
  // measured) / measured, pooled over the in-spread variants (PredictionInterval).
  double left_out_error_low = 0, left_out_error_high = 0;
  std::size_t left_out_errors = 0;

  // (driver model, seconds) of every spread case of (scene, implementation): the variants', or the
  // extra mechanisms'.
  std::vector<std::pair<std::string, double>> spread_of(std::size_t scene, int impl, bool mechanisms = false) const;
  const TimingOutcome& at(std::size_t scene, int impl) const { return outcomes[scene * kPaperImplementations + impl]; }
  const TimingOutcome& bank_variant(std::size_t v) const { return outcomes[scenes->size() * kPaperImplementations + v]; }
};

// One cell of Table 2: a scene under one implementation, with what the paper measured (given
// columns) or the spread of the variants (withheld columns).
struct PaperTableRow {
  PaperRow scene;  // faces, patches, steps, the paper's given seconds
  PaperImplementation implementation = PaperImplementation::Software;
  double seconds = 0;
  bool calibration = false;  // software and single pipeline: the columns the model was fitted to
  double fpga_busy_seconds = 0, speedup_vs_software = 0, steps_per_second = 0;
  int convergence_steps_ours = 0;
  std::vector<std::pair<std::string, double>> spread;  // (driver model, seconds); empty for calibration cells
  double spread_min_seconds = 0, spread_max_seconds = 0;
  // The concurrent column under the CPU/FPGA split mechanisms (empty elsewhere), the range of every
  // variant and mechanism, and the prediction interval: that range widened by the calibration's
  // left-out error quantiles (a true time t with t (1 + e) = predicted).
  std::vector<std::pair<std::string, double>> mechanisms;
  double range_min_seconds = 0, range_max_seconds = 0;
  double interval_low_seconds = 0, interval_high_seconds = 0;

  double paper_seconds() const;      // calibration cells only
  double relative_residual() const;  // calibration cells only
};

// How a prediction interval is made (docs/calibration.md, "Prediction intervals"): the quantiles
// kIntervalQuantiles of the pooled left-out errors e of the in-spread variants bound the true time
// at predicted / (1 + e); the interval runs from the fastest variant or mechanism over (1 + e_high)
// to the slowest over (1 + e_low).
inline constexpr double kIntervalQuantiles[2] = {0.1, 0.9};
// The q-quantile of `values` (linear between order statistics; values need not be sorted).
double quantile(std::vector<double> values, double q);

// The interval of a cell whose variants and mechanisms predict `fastest`..`slowest` seconds, given the
// left-out error quantiles e_low <= e_high (each above -1): {fastest / (1 + e_high), slowest / (1 + e_low)}.
std::pair<double, double> prediction_interval(double fastest, double slowest, double error_low, double error_high);

struct BankVariantRow {
  BankVariant variant;
  double seconds = 0, fpga_busy_seconds = 0, fpga_speedup_over_five_banks = 0, run_speedup_over_five_banks = 0;
};

struct PaperSummary {
  double average_overall_speedup = 0;            // software / concurrent, over the scenes
  double largest_scene_overall_speedup = 0;
  double average_steps_per_second_concurrent = 0;
};

// The scene with the most work per step (patches x faces, then steps): the one the summary's
// "largest scene" and the sec 4.1 bank variants are about, wherever it is in the table.
std::size_t largest_scene_index(const std::vector<PaperScene>& scenes);

// Rows in scene order, kPaperImplementations per scene.
std::vector<PaperTableRow> table_rows(const PaperPrediction& prediction);
std::vector<BankVariantRow> bank_variant_rows(const PaperPrediction& prediction);
PaperSummary summarize(const PaperPrediction& prediction);

// `host`: the profile of the main columns (by name, as `rc2000sim paper --host` gives it, and
// loaded); `variants`: the calibrated variants (load_calibrated_variants). Runs the timing study
// (once per process). `resources`: the source of the sec 5.6 design searches' lane fits (Table 2's
// two-lane design is measured: it fits under either).
PaperPrediction predict_paper(const std::vector<PaperScene>& scenes, const std::vector<PaperRow>& rows,
                              const std::string& host_name, const HostProfile& host,
                              const std::vector<CalibratedVariant>& variants,
                              pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit);

}  // namespace rc
