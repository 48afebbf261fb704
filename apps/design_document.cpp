#include "apps/design_document.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace rc {

namespace {

using Json = nlohmann::ordered_json;

Json number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

std::string fmt(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string scene_arguments(const SceneOptions& s) {
  std::string a;
  if (!s.file.empty()) a += " --scene " + s.file;
  if (s.face_target > 0) a += " --faces " + std::to_string(s.face_target);
  if (s.face_levels > 0) a += " --face-levels " + std::to_string(s.face_levels);
  if (s.patch_size > 0) a += " --patch-size " + fmt("%.17g", s.patch_size);
  else a += " --patch-levels " + std::to_string(s.patch_levels);
  return a;
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
  j["multipliers"] = to_string(p.design.multipliers);
  j["cards"] = c.cards;
  j["concurrent"] = c.concurrent;
  j["clock_mhz"] = number(p.row.clock_mhz);
  j["simulated_seconds"] = p.row.simulated_seconds;
  j["speedup_vs_reference"] = r.reference ? number(r.reference->row.simulated_seconds / p.row.simulated_seconds) : Json(nullptr);
  j["speedup_vs_software"] = number(r.software_seconds / p.row.simulated_seconds);
  j["energy_joules"] = number(p.row.energy_joules);
  j["average_watts"] = number(p.row.average_watts);
  j["tests"] = p.tests;
  j["tests_per_second"] = p.tests_per_second;
  j["tests_per_second_while_fpga_busy"] = number(p.row.intersections_per_second_while_busy);
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
  const DesignWorkload& w = doc.result.workload;
  std::string cmd = "rc2000sim run --impl board --device " + doc.out_dir + "/" + profile_file + " --host " + doc.space.host +
                    " --lanes " + std::to_string(c.lanes) + " --banks " + std::to_string(c.banks) + " --bits " +
                    std::to_string(c.bits);
  if (c.cards > 1) cmd += " --cards " + std::to_string(c.cards);
  if (c.concurrent) cmd += " --concurrent";
  cmd += scene_arguments(w.scene) + " --steps " + std::to_string(doc.result.steps) + " --form-factor " + w.form_factor;
  if (w.paper_faithful) cmd += " --paper-faithful";
  return cmd + " --out " + doc.out_dir + "/best-run";
}

Json design_json(const DesignDocument& doc) {
  const DesignSearchResult& r = doc.result;
  Json j;
  j["schema"] = "rc2000sim.design/1";
  j["device"] = r.device;
  j["workload"] = {{"scene", r.workload.scene.file.empty() ? "cornell-box" : r.workload.scene.file},
                   {"faces", r.faces},
                   {"patches", r.patches},
                   {"steps", r.steps},
                   {"paper_faithful", r.workload.paper_faithful},
                   {"form_factor", r.workload.form_factor}};
  j["constraints"] = {{"max_banks", r.max_banks},
                      {"min_bits", doc.constraints.min_bits},
                      {"max_energy_joules", number(doc.constraints.max_energy_joules)},
                      {"max_watts", number(doc.constraints.max_watts)}};
  j["designs"] = r.designs;
  j["infeasible"] = r.infeasible;
  j["pruned_spare_banks"] = r.pruned;
  j["simulated"] = r.points.size();
  j["infeasible_examples"] = r.infeasible_reasons;
  j["software_seconds"] = r.software_seconds;
  if (r.best) {
    j["best"] = point_json(r.points[*r.best], r);
    j["best"]["run_command"] = run_command(doc, r.points[*r.best], "best-device.json");
  } else {
    j["best"] = nullptr;
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

std::string design_csv(const DesignSearchResult& r) {
  std::ostringstream out;
  out << "device,lanes,banks,bank_clock_mhz,results,bits,multipliers,cards,concurrent,clock_mhz,simulated_seconds,"
         "energy_joules,average_watts,tests_per_second,tests_per_second_while_fpga_busy,bank_bytes_per_test,"
         "pci_bytes_per_test,bound,fpga_stream_limit,meets_constraints,on_front,best\n";
  out.precision(17);
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const DesignPoint& p = r.points[i];
    const SweepConfig& c = p.design.config;
    auto num = [](double v) { return std::isfinite(v) ? fmt("%.17g", v) : std::string(); };
    out << c.device << ',' << c.lanes << ',' << c.banks << ',' << num(p.design.bank_clock_mhz) << ','
        << board::to_string(p.design.results) << ',' << c.bits << ',' << to_string(p.design.multipliers) << ',' << c.cards
        << ',' << (c.concurrent ? "on" : "off") << ',' << num(p.row.clock_mhz) << ',' << num(p.row.simulated_seconds) << ','
        << num(p.row.energy_joules) << ',' << num(p.row.average_watts) << ',' << num(p.tests_per_second) << ','
        << num(p.row.intersections_per_second_while_busy) << ',' << num(p.bank_bytes_per_test) << ','
        << num(p.pci_bytes_per_test) << ',' << p.bound.run << ",\"" << p.bound.fpga << "\","
        << (p.meets_constraints ? 1 : 0) << ',' << (p.on_front ? 1 : 0) << ',' << (r.best && *r.best == i ? 1 : 0) << '\n';
  }
  return out.str();
}

namespace {

std::string point_line(const DesignPoint& p, const DesignSearchResult& r) {
  return describe(p.design) + ": " + fmt("%.3f s", p.row.simulated_seconds) + ", " + fmt("%.4g J", p.row.energy_joules) +
         ", " + fmt("%.3g W", p.row.average_watts) + ", " + fmt("%.4g tests/s", p.tests_per_second) + " (" +
         fmt("%.4g", p.row.intersections_per_second_while_busy) + " while the FPGA is busy), " +
         fmt("%.3g bank bytes/test", p.bank_bytes_per_test) +
         (r.reference ? ", " + fmt("%.2fx", r.reference->row.simulated_seconds / p.row.simulated_seconds) + " the paper's two-lane design"
                      : std::string()) +
         "; bound: " + p.bound.text();
}

}  // namespace

std::string design_markdown(const DesignDocument& doc) {
  const DesignSearchResult& r = doc.result;
  std::ostringstream md;
  md << "# Design search: " << r.device << "\n\n"
     << "Generated by `" << doc.command << "` (docs/design.md): every figure is simulated by the SystemC model.\n\n"
     << "Workload: " << r.faces << " faces, " << r.patches << " patches, " << r.steps << " steps, "
     << (r.workload.paper_faithful ? "every segment sent (paper-faithful)" : "receivers culled") << ", form factor "
     << r.workload.form_factor << ". Software alone: " << fmt("%.3f s", r.software_seconds) << ".\n\n"
     << "Space: " << r.designs << " designs within at most " << r.max_banks << " banks and at least "
     << doc.constraints.min_bits << " bits; " << r.infeasible << " cannot exist, " << r.pruned
     << " pruned (spare banks only: dominated), " << r.points.size() << " simulated.\n\n";
  if (r.best) md << "**Best:** " << point_line(r.points[*r.best], r) << ".\n\nRun it: `" << run_command(doc, r.points[*r.best], "best-device.json") << "`\n\n";
  else md << "**Best:** no design meets the constraints.\n\n";
  if (r.reference) md << "**The paper's two-lane design** (sec 5.5, concurrent driver): " << point_line(*r.reference, r) << ".\n\n";
  md << "## Pareto front (time, energy, banks)\n\n| design | seconds | joules | watts | banks | bound |\n|---|---|---|---|---|---|\n";
  for (const DesignPoint& p : r.points)
    if (p.on_front)
      md << "| " << describe(p.design) << " | " << fmt("%.3f", p.row.simulated_seconds) << " | " << fmt("%.4g", p.row.energy_joules)
         << " | " << fmt("%.3g", p.row.average_watts) << " | " << p.design.config.banks << " | " << p.bound.text() << " |\n";
  md << "\n![time against energy](design.png)\n\n## Roofline\n\n![roofline](roofline.png)\n\n"
     << "Roofs of the best design: lanes " << fmt("%.4g tests/s", doc.roofline.lanes_tests_per_second) << ", SRAM "
     << fmt("%.4g GB/s", doc.roofline.sram_bytes_per_second / 1e9) << ", PCI " << fmt("%.4g tests/s", doc.roofline.pci_tests_per_second)
     << ", host " << fmt("%.4g tests/s", doc.roofline.host_tests_per_second) << ".\n";
  if (!r.infeasible_reasons.empty()) {
    md << "\n## Designs that cannot exist (an example of each reason)\n\n";
    for (const std::string& why : r.infeasible_reasons) md << "- " << why << "\n";
  }
  return md.str();
}

void print_design(const DesignDocument& doc) {
  const DesignSearchResult& r = doc.result;
  std::printf("rc2000sim design: %s, %zu faces, %zu patches, %d steps (%s)\n", r.device.c_str(), r.faces, r.patches, r.steps,
              r.workload.paper_faithful ? "paper-faithful" : "culled");
  std::printf("  %zu designs within %u banks: %zu cannot exist, %zu pruned (spare banks), %zu simulated\n", r.designs,
              r.max_banks, r.infeasible, r.pruned, r.points.size());
  if (r.best) std::printf("  best: %s\n  run:  %s\n", point_line(r.points[*r.best], r).c_str(),
                          run_command(doc, r.points[*r.best], "best-device.json").c_str());
  else std::printf("  best: no design meets the constraints\n");
  if (r.reference) std::printf("  paper's two-lane design: %s\n", point_line(*r.reference, r).c_str());
  std::printf("  Pareto front (time, energy, banks):\n");
  for (const DesignPoint& p : r.points)
    if (p.on_front) std::printf("    %s\n", point_line(p, r).c_str());
}

}  // namespace rc
