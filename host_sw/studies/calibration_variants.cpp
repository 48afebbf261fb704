#include "host_sw/studies/calibration_variants.h"

#include <cmath>
#include <stdexcept>

#include "profiles/variants_file.h"

namespace rc {

std::vector<DriverModel> serial_driver_variants(const DriverModel& base) {
  std::vector<DriverModel> out;
  for (auto unit : {DriverModel::CostUnit::PerSegment, DriverModel::CostUnit::PerWord}) {
    for (auto transfer : {DriverModel::Transfer::Dma, DriverModel::Transfer::Pio}) {
      for (auto faces : {DriverModel::FaceUpload::Once, DriverModel::FaceUpload::EveryPass}) {
        DriverModel m = base;
        m.cost_unit = unit;
        m.transfer = transfer;
        m.face_upload = faces;
        out.push_back(m);
      }
    }
  }
  return out;
}

std::vector<DriverModel> with_each_overlap(const DriverModel& model) {
  DriverModel same_cpu = model, dual = model;
  same_cpu.overlap = DriverModel::Overlap::FormFactors;
  dual.overlap = DriverModel::Overlap::DualCpu;
  return {same_cpu, dual};
}

VariantCalibration calibrate_variant(const HostProfile& used, std::vector<CalibrationObservation> observations) {
  VariantCalibration v;
  v.used = used;
  v.fit = fit_calibration(observations);
  v.cv = cross_validate(observations);
  v.observations = std::move(observations);
  return v;
}

std::size_t best_by_cross_validation(const std::vector<VariantCalibration>& variants) {
  if (variants.empty()) throw std::invalid_argument("no variants to choose from");
  std::size_t best = 0;
  for (std::size_t i = 1; i < variants.size(); ++i) {
    if (variants[i].cv.mean_absolute < variants[best].cv.mean_absolute) best = i;
  }
  return best;
}

bool within_tolerance(const VariantCalibration& variant, const VariantCalibration& best) {
  return variant.cv.mean_absolute <= (1 + kVariantTolerance) * best.cv.mean_absolute;
}

std::vector<CalibratedVariant> load_calibrated_variants(const std::string& path) {
  std::vector<CalibratedVariant> out;
  for (const profiles::VariantRecord& v : profiles::read_variants_file(path)) {
    CalibratedVariant c;
    c.profile = host_profile_from_document(v.profile, path + " (variant " + v.driver_model + ")");
    c.cv_error = v.cv_error;
    c.fit_rms = v.fit_rms;
    c.chosen = v.chosen;
    c.in_spread = v.in_spread;
    c.left_out_errors = v.left_out_errors;
    out.push_back(std::move(c));
  }
  if (out.empty()) throw std::invalid_argument(path + ": no variants");
  // The file is written by `calibrate`; an edited or mixed-up copy must still say one coherent thing.
  std::size_t chosen = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::string where = path + ": variants[" + std::to_string(i) + "]";
    if (!(std::isfinite(out[i].cv_error) && out[i].cv_error >= 0 && std::isfinite(out[i].fit_rms) && out[i].fit_rms >= 0)) {
      throw std::invalid_argument(where + ": cross-validated and fitted errors must be finite and at least 0");
    }
    for (double e : out[i].left_out_errors) {
      if (!(std::isfinite(e) && e > -1)) throw std::invalid_argument(where + ": a left_out_relative_error must be finite and above -1");
    }
    if (out[i].in_spread && out[i].left_out_errors.size() < 2) {
      throw std::invalid_argument(where + ": profile.calibration.observations needs at least two left-out errors");
    }
    if (out[i].chosen && !out[i].in_spread) throw std::invalid_argument(where + ": the chosen variant must be in the spread");
    chosen += out[i].chosen ? 1 : 0;
  }
  if (chosen != 1) {
    throw std::invalid_argument(path + ": " + std::to_string(chosen) +
                                " variants are marked \"chosen\"; exactly one must be (rerun `rc2000sim calibrate`)");
  }
  return out;
}

std::string default_variants_path() { return profiles::default_config_dir() + "/calibration/athlon-mp-2600-variants.json"; }

}  // namespace rc
