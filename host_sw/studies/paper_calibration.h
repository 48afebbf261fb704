// Calibrating the host model on the paper's Table 2, every driver-model variant at once: the
// software run of each scene (the driver does not touch it) and every variant's single-pipeline run
// of each scene are simulated in one timing study; each variant is fitted to its cells (two per table row) and
// cross-validated (calibration_variants.h), and the one with the least cross-validated error is
// chosen (docs/calibration.md).
#pragma once

#include <cstddef>
#include <vector>

#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/studies/calibration_variants.h"
#include "host_sw/studies/paper_workload.h"

namespace rc {

struct PaperCalibration {
  std::vector<VariantCalibration> variants;  // serial_driver_variants(base.driver_model), in that order
  std::size_t chosen = 0;                    // best_by_cross_validation(variants)
  std::size_t simulated_runs = 0;
};

// `scenes` solved by prepare_paper_scenes from `rows`. Runs the timing study (once per process).
PaperCalibration calibrate_on_paper(const std::vector<PaperScene>& scenes, const HostProfile& base);

}  // namespace rc
