#include "host_sw/studies/calibration_variants.h"

#include <cmath>
#include <stdexcept>

#include "board/profile_reader.h"

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

nlohmann::ordered_json variants_document(const std::vector<VariantCalibration>& variants, const std::string& base_name) {
  const std::size_t best = best_by_cross_validation(variants);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const VariantCalibration& v = variants[i];
    list.push_back({{"driver_model", v.used.driver_model.name()},
                    {"chosen", i == best},
                    {"in_spread", within_tolerance(v, variants[best])},
                    {"fit_rms_relative_residual", v.fit.rms_relative_residual},
                    {"cv_mean_absolute_relative_error", v.cv.mean_absolute},
                    {"cv_rms_relative_error", v.cv.rms},
                    {"cv_worst_relative_error", v.cv.worst},
                    {"profile", calibrated_profile(v.used, v.fit, v.observations, base_name + "-calibrated", &v.cv)}});
  }
  return {{"schema", "rc2000sim.host-variants/1"},
          {"description", "Every driver-model variant of " + base_name +
                              ".json calibrated on Table 2's software and single-pipeline columns, with its "
                              "leave-one-out cross-validated error. Written by `rc2000sim calibrate`; read by "
                              "`rc2000sim paper` for the prediction spread (docs/calibration.md, Variants)."},
          {"choice", "least cross-validated mean absolute relative error"},
          {"spread_tolerance", kVariantTolerance},
          {"variants", list}};
}

std::vector<CalibratedVariant> load_calibrated_variants(const std::string& path) {
  const nlohmann::ordered_json j = board::read_json_file(path, io::kProfileLimitBytes, "a variants file");
  std::vector<CalibratedVariant> out;
  try {
    if (j.at("schema") != "rc2000sim.host-variants/1") {
      throw std::invalid_argument(path + ": schema is not rc2000sim.host-variants/1 (rerun `rc2000sim calibrate`)");
    }
    for (const auto& v : j.at("variants")) {
      CalibratedVariant c;
      c.profile = host_profile_from_json(v.at("profile"), path + " (variant " + v.at("driver_model").get<std::string>() + ")");
      c.cv_error = v.at("cv_mean_absolute_relative_error").get<double>();
      c.fit_rms = v.at("fit_rms_relative_residual").get<double>();
      c.chosen = v.at("chosen").get<bool>();
      c.in_spread = v.at("in_spread").get<bool>();
      for (const auto& o : v.at("profile").at("calibration").at("observations")) {
        c.left_out_errors.push_back(o.at("left_out_relative_error").get<double>());
      }
      out.push_back(std::move(c));
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(path + ": " + e.what());
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

std::string default_variants_path() { return board::default_config_dir() + "/calibration/athlon-mp-2600-variants.json"; }

}  // namespace rc
