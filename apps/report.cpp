#include "apps/report.h"

#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/studies/paper_workload.h"

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace rc {

nlohmann::ordered_json scene_json(const Scene& scene, const std::string& source,
                                  const std::vector<std::string>& warnings) {
  nlohmann::ordered_json j;
  j["name"] = scene.name;
  j["source"] = source;
  j["surfaces"] = scene.surface_names.size();
  j["faces"] = scene.faces.size();
  j["patches"] = scene.patches.size();
  j["normalisation"] = {{"offset", {scene.normalisation.offset.x, scene.normalisation.offset.y,
                                    scene.normalisation.offset.z}},
                        {"scale", scene.normalisation.scale}};
  j["warnings"] = warnings;
  return j;
}

nlohmann::ordered_json solver_json(const SolverResult& r) {
  nlohmann::ordered_json j;
  j["steps"] = r.steps;
  j["converged"] = r.converged;
  if (r.exhausted) j["exhausted"] = true;  // stopped early: nothing normal left to shoot (docs/radiosity.md, Guards)
  j["convergence_reached"] = r.convergence_reached;
  j["max_initial_power"] = r.max_initial_power;
  j["max_unshot_power"] = r.max_unshot_power;
  j["energy"] = {{"emitted", r.energy.emitted},
                 {"absorbed", r.energy.absorbed},
                 {"escaping", r.energy.escaping},
                 {"unshot", r.energy.unshot}};
  j["segments"] = r.segments;
  j["blocked_segments"] = r.blocked_segments;
  j["receivers_skipped"] = r.receivers_skipped;
  const FormFactorSums& f = r.form_factor_sums;
  j["form_factor_sums"] = {{"normalised", f.normalised},
                           {"steps_above_one", f.steps_above_one},
                           {"largest", f.largest},
                           {"largest_step", f.largest_step},
                           {"largest_shooter", f.largest_shooter}};
  j["emission_exponent"] = r.emission_exponent;
  return j;
}

// Text that is not UTF-8 (a name or path from another tool) leaves as U+FFFD rather than as
// nlohmann's type_error.316 after the work (docs/outputs.md); names read by the scene readers are
// already escaped as \xNN (io/text_encoding.h).
std::string pretty_json(const nlohmann::ordered_json& json) {
  return json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

std::string patches_csv(const Scene& scene, const std::vector<Spectrum>& radiosity) {
  std::ostringstream out;
  out << "patch,face,centre_x,centre_y,centre_z,area";
  const char* band_names[] = {"r", "g", "b"};
  for (std::size_t b = 0; b < kBands; ++b) {
    out << ",radiosity_" << (kBands == 3 ? band_names[b] : std::to_string(b).c_str());
  }
  out << "\n" << std::setprecision(17);
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const Patch& p = scene.patches[i];
    out << i << ',' << p.face << ',' << p.centre.x << ',' << p.centre.y << ',' << p.centre.z << ',' << p.area;
    for (std::size_t b = 0; b < kBands; ++b) out << ',' << radiosity[i][b];
    out << "\n";
  }
  return out.str();
}

nlohmann::ordered_json estimate_json(const board::PaperEstimate& e) {
  return {{"estimate", e.estimate},
          {"rule", board::to_string(e.rule)},
          {"device", e.device},
          {"lanes", e.lanes},
          {"clock_mhz", e.clock_mhz},
          {"clock_assumption", e.clock_assumption},
          {"intersections_per_s", e.intersections_per_s},
          {"bytes_per_intersection", e.bytes_per_intersection},
          {"bytes_per_cycle", e.bytes_per_cycle},
          {"gb_per_s", e.gb_per_s},
          {"software_rate", e.software_rate},
          {"speedup_vs_software", e.speedup_vs_software},
          {"note", e.note}};
}

LanesThatFit lanes_that_fit(const std::string& device, const std::string& host, int bits) {
  return lanes_that_fit(board::find_device_profile(device), find_host_profile(host), bits);
}

namespace {

// The estimates, or why the profile cannot give them (LanesThatFit::missing).
template <class Estimate>
LanesThatFit estimated_or_why(const board::DeviceProfile& profile, Estimate estimate) {
  try {
    return estimate();
  } catch (const std::invalid_argument& e) {
    LanesThatFit none;
    none.paper_rule.device = none.model.device = profile.name;
    none.missing = std::string("not estimated: ") + e.what() +
                   " (the estimate tries every lane count up to what fits; the run itself needs only its own)";
    return none;
  }
}

}  // namespace

LanesThatFit lanes_that_fit(const board::DeviceProfile& profile, const HostProfile& host_profile, int bits,
                            pipeline::ResourceSource resources) {
  return estimated_or_why(profile, [&] {
    return LanesThatFit{
        board::paper_rule_lanes_that_fit(profile, measured_peak_software_rate(default_paper_table())),
        board::model_lanes_that_fit(profile, 1.0 / host_profile.work[static_cast<int>(HostWork::IntersectionTest)].to_seconds(),
                                    bits, resources),
        ""};
  });
}

LanesThatFit lanes_that_fit(const board::DeviceProfile& profile, const HostProfile& host_profile,
                            pipeline::FloatFormat format) {
  return estimated_or_why(profile, [&] {
    return LanesThatFit{
        board::paper_rule_lanes_that_fit(profile, measured_peak_software_rate(default_paper_table())),
        board::float_lanes_that_fit(profile, 1.0 / host_profile.work[static_cast<int>(HostWork::IntersectionTest)].to_seconds(),
                                    format),
        ""};
  });
}

nlohmann::ordered_json lanes_that_fit_json(const LanesThatFit& e) {
  if (!e.missing.empty()) return {{"not_estimated", e.missing}};
  return {{"paper_rule", estimate_json(e.paper_rule)},
          {"model", estimate_json(e.model)},
          {"why_different", board::why_estimates_differ(e.paper_rule, e.model)}};
}

std::string lanes_that_fit_line(const LanesThatFit& e) {
  if (!e.missing.empty()) return e.model.device + ": " + e.missing;
  char line[320];
  std::snprintf(line, sizeof line,
                "%s: paper's rule (15-bit Table 1 pipeline at %g MHz) %d lanes, %.4g int/s (%.1fx software); "
                "model %d lanes at %g MHz (the profile's design clock%s), %.4g int/s (%.1fx)",
                e.model.device.c_str(), e.paper_rule.clock_mhz, e.paper_rule.lanes, e.paper_rule.intersections_per_s,
                e.paper_rule.speedup_vs_software, e.model.lanes, e.model.clock_mhz,
                e.model.resources == pipeline::ResourceSource::synthesis ? "; synthesis resources" : "",
                e.model.intersections_per_s,
                e.model.speedup_vs_software);
  return line;
}

}  // namespace rc
