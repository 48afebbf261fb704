#include "host_sw/driver/cpu_split.h"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "io/parse_number.h"

namespace rc {

std::string CpuSplit::name() const {
  if (mode == Mode::off) return "off";
  std::string text;
  if (mode == Mode::balanced) {
    text = "balanced";
  } else {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", share);
    text = buffer;
  }
  return text + " on " + std::to_string(cores) + (cores == 1 ? " cpu" : " cpus");
}

bool CpuSplit::operator==(const CpuSplit& other) const {
  return mode == other.mode && share == other.share && cores == other.cores;
}

CpuSplit parse_cpu_split(const std::string& share, unsigned cores) {
  if (cores != 1 && cores != 2) {
    throw std::invalid_argument("--cpu-cores: expected 1 or 2 (the dual-processor host's Athlons), got " +
                                std::to_string(cores));
  }
  CpuSplit split;
  split.cores = cores;
  if (share == "balanced") {
    split.mode = CpuSplit::Mode::balanced;
    return split;
  }
  const std::optional<double> parsed = io::parse_finite(share);
  const double value = parsed.value_or(-1);
  if (!parsed || !(value >= 0 && value <= 1)) {
    throw std::invalid_argument("--cpu-share: expected a fraction 0..1 or 'balanced', got '" + share + "'");
  }
  split.mode = CpuSplit::Mode::fixed;
  split.share = value;
  return split;
}

std::size_t fixed_cpu_segments(std::size_t segments, double share) {
  const double k = std::floor(share * static_cast<double>(segments) + 0.5);
  return std::min(segments, static_cast<std::size_t>(k));
}

std::size_t balanced_cpu_segments(std::size_t segments, double cpu, double board) {
  if (board <= 0 || segments == 0) return 0;
  return fixed_cpu_segments(segments, board / (board + cpu));
}

}  // namespace rc
