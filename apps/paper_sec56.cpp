#include "apps/paper_sec56.h"

#include <cmath>
#include <cstdio>

#include "board/device_profile.h"

namespace rc {

namespace {

using nlohmann::ordered_json;

std::string format(const char* pattern, double a, double b = 0) {
  char text[200];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

ordered_json finite_or_null(double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(); }

// The paper's rule again at the clock the device's design was measured at, when that differs from
// Table 1's: the profile's clock for the most lanes it lists (sec 5.5's two lanes on the XC2V6000).
void at_design_clock(const board::DeviceProfile& device, const board::PaperEstimate& rule, std::vector<Sec56DeviceRow>& rows) {
  if (device.clock_mhz_by_lanes.empty()) return;
  const auto& [lanes, mhz] = *device.clock_mhz_by_lanes.rbegin();
  if (std::fabs(mhz - rule.clock_mhz) < 1e-9) return;
  Sec56DeviceRow row;
  row.estimate = rule;
  row.estimate.estimate = "lanes that fit, at the design clock";
  row.estimate.clock_mhz = mhz;
  row.estimate.intersections_per_s = rule.lanes * mhz * 1e6;
  row.estimate.gb_per_s = row.estimate.intersections_per_s * rule.bytes_per_intersection / 1e9;
  row.estimate.speedup_vs_software = row.estimate.intersections_per_s / rule.software_rate;
  row.estimate.clock_assumption =
      format("the device's measured design clock, %g MHz (%g lanes with the wrapper, sec 5.4-5.5)", mhz, lanes);
  rows.push_back(row);
}

}  // namespace

std::vector<Sec56DeviceRow> sec56_device_rows(const PaperPrediction& r, double paper_rate, double model_rate) {
  std::vector<Sec56DeviceRow> rows;
  for (const char* name : kSec56Devices) {
    const board::DeviceProfile device = board::find_device_profile(name);
    Sec56DeviceRow rule;
    rule.estimate = board::paper_rule_lanes_that_fit(device, paper_rate);
    rows.push_back(rule);
    at_design_clock(device, rule.estimate, rows);
    for (const Sec56Search& s : r.searched) {
      if (s.device != name) continue;
      Sec56DeviceRow m;
      m.estimate = s.estimate(model_rate);
      m.board = s.board_text();
      m.designs = s.designs;
      m.feasible = s.feasible;
      m.simulated = s.points.size();
      if (s.best) {
        const DesignPoint& p = s.points[*s.best];
        m.bound = p.bound.text();
        m.run_seconds = p.row.simulated_seconds;
        m.nanojoules_per_test = p.tests > 0 ? p.row.energy_joules / static_cast<double>(p.tests) * 1e9 : NAN;
      }
      rows.push_back(m);
    }
  }
  return rows;
}

std::vector<Roofline> sec56_rooflines(const PaperPrediction& r, double paper_rate) {
  std::vector<Roofline> out;
  const std::optional<std::size_t> scene = sec56_scene(*r.scenes);
  for (const char* name : kSec56Devices) {
    const board::DeviceProfile device = board::find_device_profile(name);
    const board::PaperEstimate rule = board::paper_rule_lanes_that_fit(device, paper_rate);
    Roofline roof = device_roofs(device, 1, device.clock_mhz(1), device.bank_count, device.bank_clock_mhz);
    bool roofs_set = false;
    for (const Sec56Search& s : r.searched) {
      if (s.device != name || !s.best) continue;
      const DesignPoint& p = s.points[*s.best];
      if (s.assumption == "full-rate banks" || !roofs_set) {  // the roofs of the fuller board
        std::vector<RooflinePoint> keep = roof.points;
        roof = device_roofs(device, static_cast<int>(p.design.config.lanes), p.row.clock_mhz, p.design.config.banks,
                            p.design.bank_clock_mhz);
        workload_roofs(roof, p.pci_bytes_per_test, p.row.host_compute_seconds + p.row.driver_cpu_seconds,
                       static_cast<double>(p.tests));
        roof.points = keep;
        roofs_set = true;
      }
      roof.points.push_back({"best", "model's best, " + s.assumption + ": " + describe(p.design), p.bank_bytes_per_test,
                             p.row.intersections_per_second_while_busy});
    }
    roof.points.push_back({"paper", format("paper's rule: %g lanes at %g MHz", rule.lanes, rule.clock_mhz),
                           rule.bytes_per_intersection, rule.intersections_per_s});
    if (scene) {
      const RunReport& two = r.at(*scene, static_cast<int>(PaperImplementation::Concurrent)).report;
      double bytes = 0;
      for (const BankUseReport& b : two.board.banks) bytes += static_cast<double>(b.bytes_read + b.bytes_written);
      const double tests = static_cast<double>(two.intersections.tests);
      if (tests > 0)
        roof.points.push_back({"reference", "paper's two-lane design (simulated)", bytes / tests,
                               two.intersections.per_second_while_fpga_busy});
    }
    out.push_back(std::move(roof));
  }
  return out;
}

ordered_json sec56_devices_json(const std::vector<Sec56DeviceRow>& rows) {
  ordered_json list = ordered_json::array();
  for (const Sec56DeviceRow& row : rows) {
    const board::PaperEstimate& e = row.estimate;
    ordered_json j = {{"device", e.device},
                      {"estimate", e.estimate},
                      {"rule", board::to_string(e.rule)},
                      {"lanes", e.lanes},
                      {"clock_mhz", e.clock_mhz},
                      {"clock_assumption", e.clock_assumption},
                      {"intersections_per_s", finite_or_null(e.intersections_per_s)},
                      {"bytes_per_intersection", finite_or_null(e.bytes_per_intersection)},
                      {"bytes_per_cycle", finite_or_null(e.bytes_per_cycle)},
                      {"gb_per_s", finite_or_null(e.gb_per_s)},
                      {"speedup_vs_software", finite_or_null(e.speedup_vs_software)},
                      {"note", e.note}};
    if (e.rule == board::EstimateRule::Model) {
      j["board_assumption"] = row.board;
      j["bound"] = row.bound;
      j["workload_seconds"] = finite_or_null(row.run_seconds);
      j["nanojoules_per_intersection"] = finite_or_null(row.nanojoules_per_test);
      j["designs"] = row.designs;
      j["feasible"] = row.feasible;
      j["simulated"] = row.simulated;
    }
    list.push_back(j);
  }
  return list;
}

void print_sec56_devices(const std::vector<Sec56DeviceRow>& rows) {
  std::printf("\nSec 5.6 per device: the paper's rule (its clock stated) and the model's best design from its own search\n"
              "(simulated on the 280-face, 4480-patch workload; intersections/s while the FPGA streams)\n");
  std::printf("  %-14s %-5s %5s %7s %11s %7s %7s %9s %9s %10s  %s\n", "device", "rule", "lanes", "MHz", "int/s", "B/int",
              "GB/s", "speedup", "run s", "sys nJ/int", "design, clock and board; bound");
  for (const Sec56DeviceRow& row : rows) {
    const board::PaperEstimate& e = row.estimate;
    const bool model = e.rule == board::EstimateRule::Model;
    std::printf("  %-14s %-5s %5d %7.1f %11.4g %7.3f %7.2f %8.2fx %9s %10s  %s\n", e.device.c_str(), board::to_string(e.rule),
                e.lanes, e.clock_mhz, e.intersections_per_s, e.bytes_per_intersection, e.gb_per_s, e.speedup_vs_software,
                model ? format("%.2f", row.run_seconds).c_str() : "", model ? format("%.1f", row.nanojoules_per_test).c_str() : "",
                model ? (e.note + "; clock: " + e.clock_assumption).c_str() : ("clock: " + e.clock_assumption).c_str());
  }
}

void sec56_devices_markdown(std::ostream& md, const std::vector<Sec56DeviceRow>& rows) {
  md << "| device | rule | lanes | MHz | int/s | bytes/int | GB/s | speedup | workload s | nJ/int, whole run (card + host) | clock and board | design; bound |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n";
  for (const Sec56DeviceRow& row : rows) {
    const board::PaperEstimate& e = row.estimate;
    const bool model = e.rule == board::EstimateRule::Model;
    md << "| " << e.device << " | " << board::to_string(e.rule) << " | " << e.lanes << " | " << format("%.1f", e.clock_mhz)
       << " | " << format("%.4g", e.intersections_per_s) << " | " << format("%.3f", e.bytes_per_intersection) << " | "
       << format("%.2f", e.gb_per_s) << " | " << format("%.2fx", e.speedup_vs_software) << " | "
       << (model ? format("%.2f", row.run_seconds) : "") << " | " << (model ? format("%.1f", row.nanojoules_per_test) : "")
       << " | " << e.clock_assumption << " | " << (model ? e.note : e.estimate + ": " + e.note) << " |\n";
  }
}

Sec56LanesBySource sec56_lanes_by_source() {
  Sec56LanesBySource out;
  for (const char* name : kSec56Devices) out.devices.push_back(board::lanes_by_source(board::find_device_profile(name), 15));
  const pipeline::ResourceModel synthesis = pipeline::ResourceModel::load_default(pipeline::ResourceSource::synthesis);
  out.fit = synthesis.synthesis()->fit();
  out.synthesizer = synthesis.synthesis()->synthesizer();
  return out;
}

namespace {

ordered_json fit_json(const board::DesignFit& f, int lanes) {
  return {{"lanes", lanes},
          {"block_multiplier_lanes", lanes > 0 ? f.hard_lanes : 0},
          {"slice_multiplier_lanes", lanes > 0 ? f.soft_lanes : 0},
          {"slices", lanes > 0 ? f.slices : 0},
          {"block_multipliers", lanes > 0 ? f.block_multipliers : 0},
          {"clock_mhz", lanes > 0 ? f.clock_mhz : 0}};
}

std::string lanes_text(const board::DesignFit& f, int lanes) {
  if (lanes == 0) return "none fits";
  char text[160];
  std::snprintf(text, sizeof text, "%d (%d block + %d slice), %d slices, %d blocks", lanes, f.hard_lanes, f.soft_lanes,
                f.slices, f.block_multipliers);
  return text;
}

std::string signed_percent(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.1f%%", 100.0 * x);
  return text;
}

}  // namespace

ordered_json lanes_by_source_json(const Sec56LanesBySource& lanes) {
  ordered_json devices = ordered_json::array();
  for (const board::LanesBySource& d : lanes.devices) {
    devices.push_back({{"device", d.device},
                       {"bits", d.bits},
                       {"paper", fit_json(d.paper, d.paper_lanes)},
                       {"synthesis", fit_json(d.synthesis, d.synthesis_lanes)}});
  }
  ordered_json loo = ordered_json::array();
  for (const pipeline::LeaveOneOutError& e : lanes.fit.leave_one_out) {
    loo.push_back({{"frac_bits", e.point.frac_bits},
                   {"block_multipliers", e.point.block_multipliers},
                   {"paper_slices", e.point.slices},
                   {"predicted_slices", finite_or_null(e.predicted)},
                   {"relative_error", finite_or_null(e.relative_error)}});
  }
  return {{"devices", devices},
          {"synthesis_rule",
           {{"synthesizer", lanes.synthesizer},
            {"slices_per_lut", lanes.fit.per_lut},
            {"slices_per_flip_flop", lanes.fit.per_flip_flop},
            {"max_abs_fit_error", lanes.fit.max_abs_fit_error},
            {"max_abs_leave_one_out_error", finite_or_null(lanes.fit.max_abs_leave_one_out)},
            {"leave_one_out", loo}}}};
}

void print_lanes_by_source(const Sec56LanesBySource& lanes) {
  std::printf("\nLanes that fit at 15 bits by source of resources (docs/pipeline.md, Two sources of resources; the wrapper "
              "counted, block-multiplier lanes first)\n");
  std::printf("  %-14s %-52s %s\n", "device", "paper fit", "synthesis");
  for (const board::LanesBySource& d : lanes.devices) {
    std::printf("  %-14s %-52s %s\n", d.device.c_str(), lanes_text(d.paper, d.paper_lanes).c_str(),
                lanes_text(d.synthesis, d.synthesis_lanes).c_str());
  }
  std::printf("  synthesis: %s counts, slices = %.4f x LUTs + %.4f x flip-flops fitted on the paper's %zu points; "
              "leave-one-out error on them up to %s (fit %s)\n",
              lanes.synthesizer.c_str(), lanes.fit.per_lut, lanes.fit.per_flip_flop, lanes.fit.leave_one_out.size(),
              format("%.1f%%", 100.0 * lanes.fit.max_abs_leave_one_out).c_str(),
              format("%.1f%%", 100.0 * lanes.fit.max_abs_fit_error).c_str());
}

void lanes_by_source_markdown(std::ostream& md, const Sec56LanesBySource& lanes) {
  md << "| device | paper fit: lanes | slices | blocks | synthesis: lanes | slices | blocks |\n"
        "|---|---:|---:|---:|---:|---:|---:|\n";
  for (const board::LanesBySource& d : lanes.devices) {
    md << "| " << d.device << " | " << d.paper_lanes << " (" << d.paper.hard_lanes << " block + " << d.paper.soft_lanes
       << " slice) | " << d.paper.slices << " | " << d.paper.block_multipliers << " | " << d.synthesis_lanes << " ("
       << d.synthesis.hard_lanes << " block + " << d.synthesis.soft_lanes << " slice) | " << d.synthesis.slices << " | "
       << d.synthesis.block_multipliers << " |\n";
  }
  md << "\nSynthesis: " << lanes.synthesizer << " counts of `rtl/mt_pipeline.v`; slices = "
     << format("%.4f", lanes.fit.per_lut) << " x LUTs + " << format("%.4f", lanes.fit.per_flip_flop)
     << " x flip-flops, fitted on the paper's published pipelines; leave-one-out error on each:";
  for (const pipeline::LeaveOneOutError& e : lanes.fit.leave_one_out) {
    md << " " << e.point.frac_bits << " bits " << (e.point.block_multipliers ? "with" : "without") << " block multipliers "
       << signed_percent(e.relative_error) << ";";
  }
  md << " largest " << format("%.1f%%", 100.0 * lanes.fit.max_abs_leave_one_out) << ".\n";
}

}  // namespace rc
