#include "host_sw/studies/paper_prediction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <cstdint>
#include <tuple>
#include <utility>

namespace rc {

namespace {

// The CPU/FPGA splits the paper's words allow for its concurrent column ("concurrent execution of
// hardware and software elements", sec 1 and 4; the dual-processor host, sec 5.4): software tests
// balanced against the board on the solver's processor or on the second Athlon.
std::vector<CpuSplit> split_mechanisms() { return {parse_cpu_split("balanced", 1), parse_cpu_split("balanced", 2)}; }

// The concurrent column under `model` (a split, a pipelined driver or both) as a mechanism case.
void add_mechanism(std::size_t scene_index, const PaperScene& scene, const HostProfile& variant, const DriverModel& model,
                   const std::string& host_name, std::vector<SpreadCase>& out, std::vector<TimingCase>& cases) {
  TimingCase c = paper_timing_case(scene, PaperImplementation::Concurrent, host_name);
  c.label += " " + model.name();
  c.board.host_profile = with_driver_model(variant, model);
  out.push_back({scene_index, static_cast<int>(PaperImplementation::Concurrent), model.name(), true, cases.size()});
  cases.push_back(c);
}

// A spread case that is the main column's own case (the default profile itself) is not simulated
// twice: its outcome is the main one (main_index).
std::vector<SpreadCase> spread_cases(const std::vector<PaperScene>& scenes, const std::vector<CalibratedVariant>& variants,
                                     const HostProfile& host, std::vector<TimingCase>& cases) {
  std::vector<SpreadCase> out;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const std::uint64_t chunk = pipelined_chunk_rays(scenes[i]);
    for (const CalibratedVariant& v : variants) {
      if (!v.in_spread) continue;
      for (const DriverModel& m : with_each_overlap(v.profile.driver_model)) {
        const HostProfile profile = with_driver_model(v.profile, m);
        for (PaperImplementation impl : {PaperImplementation::TwoPipes, PaperImplementation::Concurrent}) {
          if (impl == PaperImplementation::TwoPipes && m.overlap != DriverModel::Overlap::FormFactors) continue;
          SpreadCase spread{i, static_cast<int>(impl), m.name()};
          if (profile.document == host.document) {
            spread.main_index = i * kPaperImplementations + static_cast<std::size_t>(impl);
          } else {
            TimingCase c = paper_timing_case(scenes[i], impl, host.name);
            c.label += " " + m.name();
            c.board.host_profile = profile;
            spread.outcome_index = cases.size();
            cases.push_back(c);
          }
          out.push_back(spread);
        }
        // The concurrent column only: each split under each overlap; the pipelined driver alone and with the
        // split on 2 CPUs under sec 4.3's overlap (pipelined_splits).
        for (const CpuSplit& split : split_mechanisms()) {
          DriverModel with_split = m;
          with_split.cpu_split = split;
          add_mechanism(i, scenes[i], v.profile, with_split, host.name, out, cases);
        }
        if (m.overlap != DriverModel::Overlap::FormFactors) continue;
        for (const CpuSplit& split : pipelined_splits()) {
          DriverModel pipelined = m;
          pipelined.cpu_split = split;
          pipelined.chunk_rays = chunk;
          add_mechanism(i, scenes[i], v.profile, pipelined, host.name, out, cases);
        }
      }
    }
  }
  return out;
}

TimingCase bank_variant_case(const PaperScene& s, const BankVariant& v, const std::string& host) {
  TimingCase c = paper_timing_case(s, PaperImplementation::TwoPipes, host);
  c.label = s.row.label() + " " + std::to_string(v.banks) + " banks " + std::to_string(v.lanes) + " lanes";
  c.board.banks = v.banks;
  c.board.lanes = v.lanes;
  return c;
}

}  // namespace

std::vector<CpuSplit> pipelined_splits() { return {CpuSplit{}, parse_cpu_split("balanced", 2)}; }

std::uint64_t pipelined_chunk_rays(const PaperScene& scene) {
  const VisibilityRecording& recording = scene.functional.recording;
  const std::size_t steps = std::min<std::size_t>(recording.steps(), static_cast<std::size_t>(scene.row.steps));
  std::uint64_t largest = 0;
  for (std::size_t step = 0; step < steps; ++step) largest = std::max<std::uint64_t>(largest, recording.segments(step));
  if (largest == 0) throw std::invalid_argument("pipelined_chunk_rays: scene " + scene.row.label() + " has no segments to chunk");
  return (largest + kPipelinedChunksPerStep - 1) / kPipelinedChunksPerStep;
}

std::vector<std::pair<std::string, double>> PaperPrediction::spread_of(std::size_t scene, int impl, bool mechanisms) const {
  std::vector<std::pair<std::string, double>> out;
  for (const SpreadCase& s : spread) {
    if (s.scene == scene && s.implementation == impl && s.mechanism == mechanisms)
      out.emplace_back(s.driver_model, outcomes[s.index()].simulated_seconds);
  }
  return out;
}

std::pair<double, double> prediction_interval(double fastest, double slowest, double error_low, double error_high) {
  if (!(error_low > -1 && error_low <= error_high && fastest <= slowest)) {
    throw std::invalid_argument("prediction_interval: needs -1 < error_low <= error_high and fastest <= slowest");
  }
  return {fastest / (1 + error_high), slowest / (1 + error_low)};
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) throw std::invalid_argument("a quantile of no values");
  std::sort(values.begin(), values.end());
  const double at = q * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (at - static_cast<double>(below)) * (values[above] - values[below]);
}

double PaperTableRow::paper_seconds() const {
  return implementation == PaperImplementation::Software ? scene.software_seconds : scene.one_pipe_seconds;
}

double PaperTableRow::relative_residual() const { return (seconds - paper_seconds()) / paper_seconds(); }

std::vector<PaperTableRow> table_rows(const PaperPrediction& r) {
  std::vector<PaperTableRow> rows;
  for (std::size_t i = 0; i < r.scenes->size(); ++i) {
    const PaperScene& s = (*r.scenes)[i];
    for (int impl = 0; impl < kPaperImplementations; ++impl) {
      const TimingOutcome& o = r.at(i, impl);
      PaperTableRow row;
      row.scene = s.row;
      row.implementation = PaperImplementation(impl);
      row.seconds = o.simulated_seconds;
      row.calibration = impl < 2;
      row.fpga_busy_seconds = o.report.time.fpga_busy;  // 0 for a software run
      row.speedup_vs_software = r.at(i, 0).simulated_seconds / o.simulated_seconds;
      row.steps_per_second = s.row.steps / o.simulated_seconds;
      row.convergence_steps_ours = s.convergence_steps;
      row.spread = r.spread_of(i, impl);
      if (!row.spread.empty()) {
        row.spread_min_seconds = row.spread_max_seconds = row.spread[0].second;
        for (const auto& [model, seconds] : row.spread) {
          row.spread_min_seconds = std::min(row.spread_min_seconds, seconds);
          row.spread_max_seconds = std::max(row.spread_max_seconds, seconds);
        }
        row.mechanisms = r.spread_of(i, impl, true);
        row.range_min_seconds = row.spread_min_seconds;
        row.range_max_seconds = row.spread_max_seconds;
        for (const auto& [model, seconds] : row.mechanisms) {
          row.range_min_seconds = std::min(row.range_min_seconds, seconds);
          row.range_max_seconds = std::max(row.range_max_seconds, seconds);
        }
        std::tie(row.interval_low_seconds, row.interval_high_seconds) =
            prediction_interval(row.range_min_seconds, row.range_max_seconds, r.left_out_error_low, r.left_out_error_high);
      }
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

std::vector<BankVariantRow> bank_variant_rows(const PaperPrediction& r) {
  std::vector<BankVariantRow> rows;
  const TimingOutcome& base = r.bank_variant(0);
  for (std::size_t v = 0; v < std::size(kBankVariants); ++v) {
    const TimingOutcome& o = r.bank_variant(v);
    rows.push_back({kBankVariants[v], o.simulated_seconds, o.report.time.fpga_busy,
                    base.report.time.fpga_busy / o.report.time.fpga_busy,
                    base.simulated_seconds / o.simulated_seconds});
  }
  return rows;
}

std::size_t largest_scene_index(const std::vector<PaperScene>& scenes) {
  // The most work (segments x faces per step, then steps), not the last row: a table in another order
  // or a subset of the rows would otherwise report its last scene as the largest.
  const auto work = [](const PaperRow& row) { return std::make_pair(std::uint64_t(row.patches) * row.faces, row.steps); };
  std::size_t largest = 0;
  for (std::size_t i = 1; i < scenes.size(); ++i) {
    if (work(scenes[i].row) > work(scenes[largest].row)) largest = i;
  }
  return largest;
}

PaperSummary summarize(const PaperPrediction& r) {
  double speedup_sum = 0, steps_per_s = 0;
  const std::size_t n = r.scenes->size();
  for (std::size_t i = 0; i < n; ++i) {
    speedup_sum += r.at(i, 0).simulated_seconds / r.at(i, 3).simulated_seconds;
    steps_per_s += (*r.scenes)[i].row.steps / r.at(i, 3).simulated_seconds;
  }
  const std::size_t largest = largest_scene_index(*r.scenes);
  return {speedup_sum / n, r.at(largest, 0).simulated_seconds / r.at(largest, 3).simulated_seconds, steps_per_s / n};
}

PaperPrediction predict_paper(const std::vector<PaperScene>& scenes, const std::vector<PaperRow>& rows,
                              const std::string& host_name, const HostProfile& host,
                              const std::vector<CalibratedVariant>& variants, pipeline::ResourceSource resources) {
  std::vector<TimingCase> cases;
  for (const PaperScene& s : scenes) {
    for (int impl = 0; impl < kPaperImplementations; ++impl) {
      cases.push_back(paper_timing_case(s, PaperImplementation(impl), host_name));
    }
  }
  for (const BankVariant& v : kBankVariants) cases.push_back(bank_variant_case(scenes[largest_scene_index(scenes)], v, host_name));
  PaperPrediction r;
  r.scenes = &scenes;
  r.spread = spread_cases(scenes, variants, host, cases);
  const std::optional<std::size_t> workload = sec56_scene(scenes);
  if (workload) {
    const PaperScene& s = scenes[*workload];
    r.searched = plan_sec56_searches(host_name, s.scene.patches.size(), s.scene.faces.size(), resources);
    add_sec56_cases(r.searched, s, cases);
  }
  std::vector<double> errors;
  for (const CalibratedVariant& v : variants)
    if (v.in_spread) errors.insert(errors.end(), v.left_out_errors.begin(), v.left_out_errors.end());
  r.left_out_errors = errors.size();
  r.left_out_error_low = quantile(errors, kIntervalQuantiles[0]);
  r.left_out_error_high = quantile(errors, kIntervalQuantiles[1]);
  r.outcomes = run_timing_study(cases);
  if (workload) collect_sec56(r.searched, r.outcomes, scenes[*workload].row.steps);
  r.paper_rule = board::paper_rule_estimates(measured_peak_software_rate(rows));
  r.model = board::model_estimates(1.0 / host.work[static_cast<int>(HostWork::IntersectionTest)].to_seconds(), 15,
                                   resources);
  return r;
}

}  // namespace rc
