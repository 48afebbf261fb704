#include "profiles/variants_file.h"

#include <stdexcept>

#include "profiles/profile_json.h"

namespace rc::profiles {

std::vector<VariantRecord> read_variants_file(const std::string& path) {
  const nlohmann::ordered_json j = read_json_file(path, io::kProfileLimitBytes, "a variants file");
  std::vector<VariantRecord> out;
  try {
    if (j.at("schema") != "rc2000sim.host-variants/1") {
      throw std::invalid_argument(path + ": schema is not rc2000sim.host-variants/1 (rerun `rc2000sim calibrate`)");
    }
    for (const auto& v : j.at("variants")) {
      VariantRecord r;
      r.driver_model = v.at("driver_model").get<std::string>();
      r.profile = document_of(v.at("profile"));
      r.cv_error = v.at("cv_mean_absolute_relative_error").get<double>();
      r.fit_rms = v.at("fit_rms_relative_residual").get<double>();
      r.chosen = v.at("chosen").get<bool>();
      r.in_spread = v.at("in_spread").get<bool>();
      for (const auto& o : v.at("profile").at("calibration").at("observations"))
        r.left_out_errors.push_back(o.at("left_out_relative_error").get<double>());
      out.push_back(std::move(r));
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
  return out;
}

}  // namespace rc::profiles
