#include "host_sw/studies/design_json.h"

#include <cmath>
#include <cstdio>

#include "host_sw/studies/workload_json.h"
#include "io/parse_number.h"

namespace rc {

namespace {

using Json = nlohmann::ordered_json;

Json finite_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

std::string scene_arguments(const SceneOptions& s) {
  std::string a;
  if (!s.file.empty()) a += " --scene " + s.file;
  if (s.face_target > 0) a += " --faces " + std::to_string(s.face_target);
  if (s.face_levels > 0) a += " --face-levels " + std::to_string(s.face_levels);
  // Numbers of a printed command in their shortest round-trip text: `--patch-size 0.2`, the value given.
  if (s.patch_size > 0) a += " --patch-size " + io::shortest_text(s.patch_size);
  else a += " --patch-levels " + std::to_string(s.patch_levels);
  return a;
}

// The fix's three values, 0 for off (run's --offset-lsb, --neighbour-rings, --coordinate-bits).
void fix_fields(Json& j, const SegmentFixOptions& f) {
  j["offset_lsb"] = f.offset_lsb;
  j["neighbour_rings"] = f.neighbour_rings;
  j["coordinate_bits"] = f.coordinate_bits;
}

// One width's own solve (with its fix) and its error against double precision; null figures: not measured.
Json fidelity_json(const WidthFidelity& f) {
  Json j;
  j["bits"] = f.bits;
  fix_fields(j, f.fixes);
  j["steps"] = f.steps;
  j["software_seconds"] = finite_or_null(f.software_seconds);
  j["measured"] = f.measured();
  j["relative_rmse"] = finite_or_null(f.relative_rmse);
  j["relative_max_error"] = finite_or_null(f.relative_max);
  j["decisions_compared"] = f.decisions_compared;
  j["decisions_differ"] = f.decisions_differ;
  j["decisions_differ_share"] = finite_or_null(f.decisions_differ_share());
  return j;
}

Json point_json(const DesignPoint& p, const DesignSearchResult& r) {
  const SweepConfig& c = p.design.config;
  Json j;
  j["design"] = describe(p.design);
  j["device"] = c.device;
  j["lanes"] = c.lanes;
  j["banks"] = c.banks;
  j["bank_clock_mhz"] = p.design.bank_clock_mhz;
  j["results"] = board::to_string(p.design.results);
  j["bits"] = c.bits;
  fix_fields(j, p.design.fixes);
  j["multipliers"] = to_string(p.design.multipliers);
  j["cards"] = c.cards;
  j["concurrent"] = c.concurrent;
  j["clock_mhz"] = finite_or_null(p.row.clock_mhz);
  j["simulated_seconds"] = p.row.simulated_seconds;
  j["speedup_vs_reference"] = r.reference ? finite_or_null(r.reference->row.simulated_seconds / p.row.simulated_seconds) : Json(nullptr);
  // Over the software-only run of the design's own width's solve (fidelity.software_seconds).
  j["speedup_vs_software"] = finite_or_null(speedup_over_software(p));
  j["steps"] = p.row.steps;
  j["fidelity"] = fidelity_json(p.fidelity);
  j["energy_joules"] = finite_or_null(p.row.energy_joules);
  j["average_watts"] = finite_or_null(p.row.average_watts);
  j["tests"] = p.tests;
  j["tests_per_second"] = p.tests_per_second;
  j["tests_per_second_while_fpga_busy"] = finite_or_null(p.row.intersections_per_second_while_busy);
  j["bank_bytes_per_test"] = p.bank_bytes_per_test;
  j["pci_bytes_per_test"] = p.pci_bytes_per_test;
  j["bound"] = {{"run", p.bound.run}, {"fpga_stream", p.bound.fpga}, {"fpga_share", p.bound.fpga_share},
                {"fpga_next", p.bound.next}, {"text", p.bound.text()}};
  j["meets_constraints"] = p.meets_constraints;
  j["on_front"] = p.on_front;
  return j;
}

Json roofline_json(const Roofline& r) {
  Json j;
  j["device"] = r.device;
  j["lanes_tests_per_second"] = r.lanes_tests_per_second;
  j["lanes"] = r.lanes;
  j["clock_mhz"] = r.clock_mhz;
  j["sram_bytes_per_second"] = r.sram_bytes_per_second;
  j["banks"] = r.banks;
  j["bank_clock_mhz"] = r.bank_clock_mhz;
  j["pci_bytes_per_second"] = r.pci_bytes_per_second;
  j["pci_tests_per_second"] = r.pci_tests_per_second;
  j["host_tests_per_second"] = r.host_tests_per_second;
  return j;
}

}  // namespace

std::string run_command(const DesignDocument& doc, const DesignPoint& p, const std::string& profile_file) {
  const SweepConfig& c = p.design.config;
  const Workload& w = doc.result.workload;
  std::string cmd = "rc2000sim run --impl board --device " + doc.out_dir + "/" + profile_file + " --host " + doc.space.host +
                    " --lanes " + std::to_string(c.lanes) + " --banks " + std::to_string(c.banks) + " --bits " +
                    std::to_string(c.bits);
  if (c.cards > 1) cmd += " --cards " + std::to_string(c.cards);
  if (c.concurrent) cmd += " --concurrent";
  const SegmentFixOptions& f = p.design.fixes;
  if (f.offset_lsb != 0) cmd += " --offset-lsb " + std::to_string(f.offset_lsb);
  if (f.neighbour_rings != 0) cmd += " --neighbour-rings " + std::to_string(f.neighbour_rings);
  if (f.coordinate_bits != 0) cmd += " --coordinate-bits " + std::to_string(f.coordinate_bits);
  // The source of resources decides whether the lanes fit: the run must use the search's.
  if (doc.space.resources != pipeline::ResourceSource::paper_fit) cmd += " --resources " + choice_name(doc.space.resources);
  if (doc.space.ray_split != board::RaySplitRule::limit) cmd += std::string(" --ray-split ") + board::to_string(doc.space.ray_split);
  cmd += scene_arguments(w.scene) + " --steps " + std::to_string(p.row.steps) + " --form-factor " + to_string(w.form_factor);
  if (w.paper_faithful) cmd += " --paper-faithful";
  return cmd + " --out " + doc.out_dir + "/best-run";
}

Json design_json(const DesignDocument& doc) {
  const DesignSearchResult& r = doc.result;
  Json j;
  j["schema"] = "rc2000sim.design/1";
  j["device"] = r.device;
  // As report.json, sweep.json and paper.json record theirs (workload.h).
  j["workload"] = workload_json(r.workload, r.faces, r.patches, r.steps);
  j["constraints"] = {{"max_banks", r.max_banks},
                      {"min_bits", doc.constraints.min_bits},
                      {"max_energy_joules", finite_or_null(doc.constraints.max_energy_joules)},
                      {"max_watts", finite_or_null(doc.constraints.max_watts)},
                      {"max_error", finite_or_null(doc.constraints.max_error)},
                      {"max_error_max", finite_or_null(doc.constraints.max_error_max)}};
  j["resources"] = choice_name(doc.space.resources);  // where the lanes' slices and block multipliers came from
  j["ray_split"] = board::to_string(doc.space.ray_split);  // how each pass divided its rays (board/bank_layout.h)
  j["designs"] = r.designs;
  j["infeasible"] = r.infeasible;
  j["pruned_spare_banks"] = r.pruned;
  j["simulated"] = r.points.size();
  j["infeasible_examples"] = r.infeasible_reasons;
  j["software_seconds"] = r.software_seconds;
  // Every width solved: its steps, its software-only time and its error against one double-precision
  // solve of the workload (reference_steps long).
  j["reference_steps"] = r.reference_steps > 0 ? Json(r.reference_steps) : Json(nullptr);  // null: --fidelity off
  Json widths = Json::array();
  for (const WidthFidelity& f : r.widths) widths.push_back(fidelity_json(f));
  j["widths"] = widths;
  if (r.best) {
    j["best"] = point_json(r.points[*r.best], r);
    j["best"]["run_command"] = run_command(doc, r.points[*r.best], "best-device.json");
  } else {
    j["best"] = nullptr;
    j["no_best_because"] = why_no_design(r, doc.constraints);  // only when no design meets the constraints
  }
  if (r.reference) j["reference"] = point_json(*r.reference, r);
  Json front = Json::array();
  for (const DesignPoint& p : r.points)
    if (p.on_front) front.push_back(point_json(p, r));
  j["front"] = front;
  j["roofline"] = roofline_json(doc.roofline);
  Json points = Json::array();
  for (const DesignPoint& p : r.points) points.push_back(point_json(p, r));
  j["points"] = points;
  return j;
}

}  // namespace rc
