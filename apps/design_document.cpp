#include "apps/design_document.h"

#include "host_sw/radiosity/segment_fix_names.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace rc {

namespace {

std::string fmt(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

}  // namespace

std::string design_csv(const DesignSearchResult& r) {
  std::ostringstream out;
  out << "device,lanes,banks,bank_clock_mhz,results,bits,multipliers,cards,concurrent,clock_mhz,simulated_seconds,"
         "energy_joules,average_watts,tests_per_second,tests_per_second_while_fpga_busy,bank_bytes_per_test,"
         "pci_bytes_per_test,bound,fpga_stream_limit,meets_constraints,on_front,best,steps,software_seconds,"
         "speedup_vs_software,speedup_vs_reference,relative_rmse,relative_max_error,decisions_differ_share,offset_lsb,"
         "neighbour_rings,coordinate_bits\n";
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
        << (p.meets_constraints ? 1 : 0) << ',' << (p.on_front ? 1 : 0) << ',' << (r.best && *r.best == i ? 1 : 0) << ','
        << p.row.steps << ',' << num(p.fidelity.software_seconds) << ',' << num(speedup_over_software(p)) << ','
        << (r.reference ? num(r.reference->row.simulated_seconds / p.row.simulated_seconds) : std::string()) << ','
        << num(p.fidelity.relative_rmse) << ',' << num(p.fidelity.relative_max) << ','
        << num(p.fidelity.decisions_differ_share()) << ',' << p.design.fixes.offset_lsb << ','
        << p.design.fixes.neighbour_rings << ',' << p.design.fixes.coordinate_bits << '\n';
  }
  return out.str();
}

namespace {

// The picture's error against double precision, or that it was not measured.
std::string fidelity_text(const WidthFidelity& f) {
  if (!f.measured()) return "fidelity not measured";
  return "error " + fmt("%.3g", f.relative_rmse) + " relative RMSE, " + fmt("%.3g", f.relative_max) + " max, " +
         fmt("%.3g%%", 100.0 * f.decisions_differ_share()) + " of decisions differ";
}

std::string point_line(const DesignPoint& p, const DesignSearchResult& r) {
  const double software = speedup_over_software(p);
  return describe(p.design) + ": " + fmt("%.3f s", p.row.simulated_seconds) + " (" + std::to_string(p.row.steps) +
         " steps; " + (std::isfinite(software) ? fmt("%.2fx", software) + " software at its width" : "no software time") +
         (r.reference ? ", " + fmt("%.2fx", r.reference->row.simulated_seconds / p.row.simulated_seconds) + " the paper's two-lane design"
                      : std::string()) +
         "), " + fidelity_text(p.fidelity) + ", " + fmt("%.4g J", p.row.energy_joules) +
         ", " + fmt("%.3g W", p.row.average_watts) + ", " + fmt("%.4g tests/s", p.tests_per_second) + " (" +
         fmt("%.4g", p.row.intersections_per_second_while_busy) + " while the FPGA is busy), " +
         fmt("%.3g bank bytes/test", p.bank_bytes_per_test) + "; bound: " + p.bound.text();
}

std::string width_table(const DesignSearchResult& r) {
  std::ostringstream md;
  if (r.reference_steps > 0)
    md << "Each width's own solve against one double-precision solve of the workload (" << r.reference_steps
       << " steps; `rc2000sim accuracy`'s definitions):";
  else
    md << "Each width's own solve (its error not measured: `--fidelity off`):";
  md << "\n\n| bits | steps | software alone, s | relative RMSE | relative max | decisions that differ |\n"
        "|---:|---:|---:|---:|---:|---:|\n";
  for (const WidthFidelity& f : r.widths) {
    md << "| " << f.bits << (f.fixes.any() ? ", " + describe(f.fixes) : std::string()) << " | " << f.steps << " | " << fmt("%.3f", f.software_seconds) << " | ";
    if (f.measured())
      md << fmt("%.3g", f.relative_rmse) << " | " << fmt("%.3g", f.relative_max) << " | " << fmt("%.3g%%", 100.0 * f.decisions_differ_share());
    else
      md << "not measured | not measured | not measured";
    md << " |\n";
  }
  md << "\n";
  return md.str();
}

}  // namespace

std::string design_markdown(const DesignDocument& doc) {
  const DesignSearchResult& r = doc.result;
  std::ostringstream md;
  md << "# Design search: " << r.device << "\n\n"
     << "Generated by `" << doc.command << "` (docs/design.md): every figure is simulated by the SystemC model.\n\n"
     << "Workload: " << r.faces << " faces, " << r.patches << " patches, " << r.steps << " steps, "
     << (r.workload.paper_faithful ? "every segment sent (paper-faithful)" : "receivers culled") << ", form factor "
     << to_string(r.workload.form_factor) << ". Software alone: " << fmt("%.3f s", r.software_seconds) << " (15 bits).\n\n"
     << width_table(r)
     << "Space: " << r.designs << " designs within at most " << r.max_banks << " banks and at least "
     << doc.constraints.min_bits << " bits; " << r.infeasible << " cannot exist, "
     << (r.exhaustive ? std::string("none pruned (--exhaustive)")
                      : std::to_string(r.pruned) + " pruned (spare banks only: dominated)")
     << ", " << r.points.size() << " simulated.\n\n";
  if (r.best) md << "**Best:** " << point_line(r.points[*r.best], r) << ".\n\nRun it: `" << run_command(doc, r.points[*r.best], "best-device.json") << "`\n\n";
  else {
    md << "**Best:** no design meets the constraints.\n\n";
    for (const std::string& why : why_no_design(r, doc.constraints)) md << "- " << why << "\n";
    md << "\n";
  }
  if (r.reference) md << "**The paper's two-lane design** (sec 5.5, concurrent driver): " << point_line(*r.reference, r) << ".\n\n";
  md << "## Pareto front (time, energy, banks, error)\n\n| design | seconds | joules | watts | banks | relative RMSE | bound |\n"
        "|---|---|---|---|---|---|---|\n";
  for (const DesignPoint& p : r.points)
    if (p.on_front)
      md << "| " << describe(p.design) << " | " << fmt("%.3f", p.row.simulated_seconds) << " | " << fmt("%.4g", p.row.energy_joules)
         << " | " << fmt("%.3g", p.row.average_watts) << " | " << p.design.config.banks << " | "
         << (p.fidelity.measured() ? fmt("%.3g", p.fidelity.relative_rmse) : std::string("not measured")) << " | " << p.bound.text() << " |\n";
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
  std::printf("  %zu designs within %u banks: %zu cannot exist, %s, %zu simulated\n", r.designs, r.max_banks, r.infeasible,
              r.exhaustive ? "none pruned (--exhaustive)" : (std::to_string(r.pruned) + " pruned (spare banks)").c_str(),
              r.points.size());
  std::printf("  rays split by %s (docs/board.md, Ray split)\n",
              doc.space.ray_split == board::RaySplitRule::limit ? "the limiting resource" : "nominal lane rate (the paper's)");
  if (r.reference_steps > 0)
    std::printf("  widths against one double-precision solve (%d steps):\n", r.reference_steps);
  else
    std::printf("  widths (their error not measured: --fidelity off):\n");
  for (const WidthFidelity& f : r.widths)
    std::printf("    %2d bits%s: %d steps, software %.3f s, %s\n", f.bits,
                f.fixes.any() ? (", " + describe(f.fixes)).c_str() : "", f.steps, f.software_seconds, fidelity_text(f).c_str());
  if (std::isfinite(doc.constraints.max_error) || std::isfinite(doc.constraints.max_error_max))
    std::printf("  error bound: relative RMSE %s, relative max %s\n",
                std::isfinite(doc.constraints.max_error) ? fmt("<= %g", doc.constraints.max_error).c_str() : "any",
                std::isfinite(doc.constraints.max_error_max) ? fmt("<= %g", doc.constraints.max_error_max).c_str() : "any");
  if (r.best) std::printf("  best: %s\n  run:  %s\n", point_line(r.points[*r.best], r).c_str(),
                          run_command(doc, r.points[*r.best], "best-device.json").c_str());
  else {
    std::printf("  best: no design meets the constraints\n");
    for (const std::string& why : why_no_design(r, doc.constraints)) std::printf("        %s\n", why.c_str());
  }
  if (r.reference) std::printf("  paper's two-lane design: %s\n", point_line(*r.reference, r).c_str());
  std::printf("  Pareto front (time, energy, banks, error):\n");
  for (const DesignPoint& p : r.points)
    if (p.on_front) std::printf("    %s\n", point_line(p, r).c_str());
}

}  // namespace rc
