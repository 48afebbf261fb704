#include "apps/sweep_summary.h"

#include <cmath>
#include <cstdio>

#include "apps/sweep_json.h"

namespace rc {

std::string name_list_text(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& s : items) text += (text.empty() ? "" : ",") + s;
  return text;
}

namespace {

// "2.05x one lane", or what is missing when the ratio could not be formed (NaN: the group has no
// one-lane row, the software time was not measured): a summary never prints "nanx".
std::string times_text(double ratio, const char* against, const char* missing) {
  if (!std::isfinite(ratio)) return missing;
  char text[64];
  std::snprintf(text, sizeof text, "%.2fx %s", ratio, against);
  return text;
}

std::string rate_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

std::string cell(const SweepRow& r) {
  char text[16];
  if (r.validity == Validity::does_not_fit) return "fit";
  if (r.validity == Validity::too_few_banks) return "banks";
  if (r.validity != Validity::ok) return "-";
  std::snprintf(text, sizeof text, "%.3f", r.simulated_seconds);
  return text;
}

bool same_block(const SweepConfig& a, const SweepConfig& b) {
  if (a.device != b.device || a.bits != b.bits || a.concurrent != b.concurrent || a.host != b.host ||
      a.cards != b.cards || a.card_split != b.card_split || a.card_bus != b.card_bus)
    return false;
  for (std::size_t i = 0; i < a.settings.size(); ++i)
    if (a.settings[i].value != b.settings[i].value) return false;
  return true;
}

std::string block_title(const SweepConfig& c, bool show_host) {
  std::string title = c.device + ", " + std::to_string(c.bits) + "-bit, " + (c.concurrent ? "concurrent" : "serial") +
                      " driver";
  if (show_host) title += ", host " + c.host;
  if (c.cards > 1) title += ", " + std::to_string(c.cards) + " cards (" + choice_name(c.card_split) + ", " + choice_name(c.card_bus) + " bus)";
  for (const ProfileSetting& s : c.settings) title += ", " + s.text();
  return title;
}

// One lanes x banks block of simulated seconds per device, width, driver, host and profile values
// (rows are enumerated in that order, lanes and banks last: each block is contiguous).
void print_blocks(const std::vector<SweepRow>& rows, const SweepAxes& axes) {
  const std::size_t block = axes.banks.size();
  for (std::size_t first = 0; first < rows.size();) {
    const SweepConfig& c = rows[first].config;
    std::printf("\n%s: simulated seconds (fit: lanes do not fit; banks: too few banks)\n",
                block_title(c, axes.hosts.size() > 1).c_str());
    std::printf("  lanes \\ banks");
    for (int b : axes.banks) std::printf(" %8d", b);
    std::printf("\n");
    const SweepRow* best = nullptr;
    const SweepRow* frugal = nullptr;  // the least energy, among rows that have it
    std::size_t end = first;
    while (end < rows.size() && same_block(rows[end].config, c)) ++end;
    std::vector<unsigned> unfit;  // lane counts whose whole line does not fit the device
    for (std::size_t r = first; r < end; r += block) {
      if (rows[r].validity == Validity::does_not_fit) {
        unfit.push_back(rows[r].config.lanes);
        continue;
      }
      std::printf("  %13u", rows[r].config.lanes);
      for (std::size_t j = 0; j < block; ++j) {
        const SweepRow& x = rows[r + j];
        std::printf(" %8s", cell(x).c_str());
        if (x.validity == Validity::ok && (!best || x.simulated_seconds < best->simulated_seconds)) best = &x;
        if (x.validity == Validity::ok && std::isfinite(x.energy_joules) &&
            (!frugal || x.energy_joules < frugal->energy_joules))
          frugal = &x;
      }
      std::printf("\n");
    }
    if (!unfit.empty()) std::printf("  lanes %s: do not fit the device\n", range_list_text(unfit).c_str());
    if (best) {
      std::printf("  fastest: %u lanes, %u banks: %.3f s, %s, %s; bottleneck %s\n", best->config.lanes,
                  best->config.banks, best->simulated_seconds,
                  times_text(best->speedup_vs_one_lane, "one lane", "no one-lane design in its group to compare").c_str(),
                  times_text(best->speedup_vs_software, "software", "no software time").c_str(),
                  best->bottleneck.c_str());
      if (!best->stream_bound.empty()) {
        std::printf("           FPGA stream bound by %s at %.3g tests/s%s\n", best->stream_bound.c_str(),
                    best->stream_bound_tests_per_second,
                    best->stream_next.empty() ? ""
                                              : ("; next: " + best->stream_next + " at " +
                                                 rate_text(best->stream_next_tests_per_second) + " tests/s")
                                                    .c_str());
      }
    }
    if (frugal) {
      std::printf("  most frugal: %u lanes, %u banks: %.4g J (%.4g J per step, %.4g W), %.3f s\n", frugal->config.lanes,
                  frugal->config.banks, frugal->energy_joules, frugal->energy_per_step_joules, frugal->average_watts,
                  frugal->simulated_seconds);
    } else if (best && !best->energy_missing.empty()) {
      std::printf("  energy: not estimated: %s\n", best->energy_missing.c_str());
    }
    first = end;
  }
}

}  // namespace

void print_sweep_scene(const Study& s, const SceneSweep& r, const std::vector<SweptFit>& fits) {
  std::printf("rc2000sim sweep: %s, %llu faces, %llu patches, %s, host %s\n", r.scene.name.c_str(),
              static_cast<unsigned long long>(r.scene.faces), static_cast<unsigned long long>(r.scene.patches),
              s.paper_faithful ? "paper-faithful (every segment)" : "receivers culled", name_list_text(s.axes.hosts).c_str());
  for (const auto& [bits, w] : r.widths) {
    const nlohmann::ordered_json software = software_at(r, bits);
    if (software.is_number()) {
      std::printf("  %d-bit: %d steps replayed; software alone %.3f s\n", bits, w.steps, software.get<double>());
    } else {
      std::printf("  %d-bit: %d steps replayed; software alone:", bits, w.steps);
      for (auto it = software.begin(); it != software.end(); ++it)
        std::printf(" %s %.3f s;", it.key().c_str(), it.value().get<double>());
      std::printf("\n");
    }
  }
  std::printf("  %zu configurations: %zu simulated, %zu cannot exist; rays split by %s (docs/board.md, Ray split)\n",
              r.rows.size(), r.valid, r.rows.size() - r.valid,
              s.ray_split == board::RaySplitRule::limit ? "the limiting resource" : "nominal lane rate (the paper's)");
  print_blocks(r.rows, s.axes);
  std::printf("\n  sec 5.6, lanes that fit at full rate (docs/calibration.md):\n");
  for (const SweptFit& f : fits) {
    std::string settings;  // the swept device fields' values this estimate used
    for (const ProfileSetting& p : f.settings) settings += (settings.empty() ? " [" : ", ") + p.text();
    if (!settings.empty()) settings += "]";
    const std::string line = f.cannot_exist.empty() ? lanes_that_fit_line(f.estimates) : f.device + ": cannot exist: " + f.cannot_exist;
    std::printf("    %d-bit%s %s\n", f.bits, settings.c_str(), line.c_str());
  }
}

}  // namespace rc
