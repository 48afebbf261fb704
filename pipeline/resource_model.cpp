#include "pipeline/resource_model.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "pipeline/bit_bounds.h"
#include "pipeline/fixed_format.h"
#include "pipeline/hardware_blocks.h"

#ifndef RC_PIPELINE_RESOURCES_JSON
#define RC_PIPELINE_RESOURCES_JSON "configs/pipeline_resources.json"
#endif

namespace rc::pipeline {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& origin, const std::string& what) {
  throw std::runtime_error("pipeline resources " + origin + ": " + what);
}

const json& field(const json& j, const char* key, const std::string& origin) {
  if (!j.is_object() || !j.contains(key)) fail(origin, std::string("missing \"") + key + "\"");
  return j.at(key);
}

double number(const json& j, const char* key, const std::string& origin) {
  const json& v = field(j, key, origin);
  if (!v.is_number()) fail(origin, std::string("\"") + key + "\" is not a number");
  return v.get<double>();
}

int integer(const json& j, const char* key, const std::string& origin) {
  const json& v = field(j, key, origin);
  if (!v.is_number_integer()) fail(origin, std::string("\"") + key + "\" is not an integer");
  return v.get<int>();
}

// Every figure must say where it comes from.
void require_source(const json& j, const std::string& origin) {
  const json& s = field(j, "source", origin);
  if (!s.is_string() || s.get<std::string>().empty()) fail(origin, "empty \"source\"");
}

}  // namespace

ResourceModel ResourceModel::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open pipeline resources " + path);
  std::stringstream text;
  text << in.rdbuf();
  return from_json_text(text.str(), path);
}

std::string ResourceModel::default_path() { return RC_PIPELINE_RESOURCES_JSON; }

ResourceModel ResourceModel::load_default() { return load(default_path()); }

ResourceModel ResourceModel::from_json_text(const std::string& text, const std::string& origin) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    fail(origin, std::string("invalid JSON: ") + e.what());
  }
  ResourceModel m;

  const json& device = field(j, "device", origin);
  require_source(device, origin);
  m.device_ = {field(device, "name", origin).get<std::string>(), integer(device, "slices", origin),
               integer(device, "block_multipliers", origin)};
  const json& block = field(j, "block_multiplier", origin);
  require_source(block, origin);
  m.block_bits_ = integer(block, "operand_bits", origin);
  const json& limit = field(j, "block_multiplier_synthesis_limit", origin);
  require_source(limit, origin);
  m.block_synthesis_limit_ = integer(limit, "max_frac_bits", origin);

  const auto points = [&](const char* key, std::size_t at_least) {
    std::vector<Point> out;
    for (const json& p : field(j, key, origin)) {
      require_source(p, origin);
      const int bits = integer(p, "frac_bits", origin);
      if (!is_valid_frac_bits(bits)) fail(origin, std::string(key) + " has width " + std::to_string(bits));
      out.push_back({bits, number(p, "clock_mhz", origin), number(p, "slices", origin)});
    }
    std::sort(out.begin(), out.end(), [](const Point& a, const Point& b) { return a.frac_bits < b.frac_bits; });
    if (out.size() < at_least) fail(origin, std::string(key) + " needs at least " + std::to_string(at_least) + " points");
    return out;
  };
  m.soft_ = points("pipeline_without_block_multipliers", 3);
  m.hard_ = points("pipeline_with_block_multipliers", 2);
  m.soft_slices_ = fit(m.soft_, &Point::slices);
  m.soft_clock_ = fit(m.soft_, &Point::clock_mhz);
  // The block multiplier counts in the file are checked against the 18x18 splitting model.
  for (const json& p : field(j, "pipeline_with_block_multipliers", origin)) {
    const int bits = integer(p, "frac_bits", origin);
    if (integer(p, "block_multipliers", origin) != block_multipliers_needed(bits, m.block_bits_)) {
      fail(origin, "block multiplier count at " + std::to_string(bits) + " bits disagrees with the 18x18 model");
    }
  }

  // Designs: wrapper + L pipelines. With one and two lanes of the same pipeline,
  //   slices(L) = fixed + L * (pipeline + per_lane)
  // gives per_lane = slices(2) - slices(1) - pipeline and fixed = slices(1) - (pipeline + per_lane).
  const json* lane[2] = {nullptr, nullptr};
  for (const json& d : field(j, "designs", origin)) {
    require_source(d, origin);
    const int lanes = integer(d, "lanes", origin);
    if (lanes == 1 || lanes == 2) lane[lanes - 1] = &d;
  }
  if (!lane[0] || !lane[1]) fail(origin, "designs need a 1-lane and a 2-lane entry");
  const int bits = integer(*lane[0], "frac_bits", origin);
  const bool hard = field(*lane[0], "block_multipliers_used", origin).get<bool>();
  if (integer(*lane[1], "frac_bits", origin) != bits ||
      field(*lane[1], "block_multipliers_used", origin).get<bool>() != hard) {
    fail(origin, "the 1-lane and 2-lane designs use different pipelines");
  }
  m.design_bits_ = bits;
  m.design_block_multipliers_ = hard;
  const PipelineResources p = m.pipeline(bits, hard);
  const int s1 = integer(*lane[0], "slices", origin), s2 = integer(*lane[1], "slices", origin);
  m.wrapper_.per_lane_slices = s2 - s1 - p.slices;
  m.wrapper_.fixed_slices = s1 - (p.slices + m.wrapper_.per_lane_slices);
  m.wrapper_.block_multipliers = integer(*lane[0], "block_multipliers", origin) - p.block_multipliers;
  if (integer(*lane[1], "block_multipliers", origin) !=
      m.wrapper_.block_multipliers + 2 * p.block_multipliers) {
    fail(origin, "block multipliers of the 1-lane and 2-lane designs are inconsistent");
  }
  // The design clocks are far below the pipeline's own: they are the wrapper's clock.
  m.wrapper_clock_ = {number(*lane[0], "clock_mhz", origin), number(*lane[1], "clock_mhz", origin)};
  return m;
}

const ResourceModel::Point* ResourceModel::find(const std::vector<Point>& points, int bits) {
  for (const Point& p : points) {
    if (p.frac_bits == bits) return &p;
  }
  return nullptr;
}

// Linear through the two nearest points (extrapolating beyond the ends).
double ResourceModel::interpolate(const std::vector<Point>& points, int bits, double Point::*field) {
  std::size_t i = 1;
  while (i + 1 < points.size() && points[i].frac_bits < bits) ++i;
  const Point &a = points[i - 1], &b = points[i];
  const double f = static_cast<double>(bits - a.frac_bits) / (b.frac_bits - a.frac_bits);
  return a.*field + f * (b.*field - a.*field);
}

// Least squares y = a + b N + c N^2 (normal equations; three unknowns, so Cramer's rule).
ResourceModel::Quadratic ResourceModel::fit(const std::vector<Point>& points, double Point::*field) {
  double s[5] = {0, 0, 0, 0, 0}, t[3] = {0, 0, 0};
  for (const Point& p : points) {
    const double n = p.frac_bits;
    double nk = 1;
    for (int k = 0; k < 5; ++k, nk *= n) s[k] += nk;
    t[0] += p.*field;
    t[1] += n * p.*field;
    t[2] += n * n * p.*field;
  }
  const auto det3 = [](double a, double b, double c, double d, double e, double f, double g, double h, double i) {
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  };
  const double d = det3(s[0], s[1], s[2], s[1], s[2], s[3], s[2], s[3], s[4]);
  return {det3(t[0], s[1], s[2], t[1], s[2], s[3], t[2], s[3], s[4]) / d,
          det3(s[0], t[0], s[2], s[1], t[1], s[3], s[2], t[2], s[4]) / d,
          det3(s[0], s[1], t[0], s[1], s[2], t[1], s[2], s[3], t[2]) / d};
}

int ResourceModel::blocks_per_product(int a_bits, int b_bits, int block_bits) {
  const int piece = block_bits - 1;
  const auto pieces = [piece](int bits) { return std::max(1, (bits - 1 + piece - 1) / piece); };
  return pieces(a_bits) * pieces(b_bits);
}

int ResourceModel::block_multipliers_needed(FracBits bits, int block_bits) {
  int total = 0;
  for (int m = 0; m < kMultiplierCount; ++m) {
    const MultiplierOperands ops = operands_of(static_cast<Multiplier>(m));
    total += blocks_per_product(signed_bits(ops.a, bits), signed_bits(ops.b, bits), block_bits);
  }
  return total;
}

PipelineResources ResourceModel::pipeline(FracBits bits, bool use_block_multipliers) const {
  PipelineResources r;
  r.frac_bits = bits;
  r.block_multipliers_used = use_block_multipliers;
  if (!use_block_multipliers) {
    if (const Point* p = find(soft_, bits)) {
      r.slices = static_cast<int>(p->slices);
      r.clock_mhz = p->clock_mhz;
    } else {
      r.slices = static_cast<int>(std::lround(soft_slices_(bits)));
      r.clock_mhz = soft_clock_(bits);
      r.interpolated = true;
    }
    return r;
  }
  r.block_multipliers = block_multipliers_needed(bits, block_bits_);
  if (const Point* p = find(hard_, bits)) {
    r.slices = static_cast<int>(p->slices);
    r.clock_mhz = p->clock_mhz;
    return r;
  }
  r.interpolated = true;
  // What the block multipliers leave in slices (adders, comparators, pipeline registers) grows
  // linearly with the width.
  r.slices = static_cast<int>(std::lround(interpolate(hard_, bits, &Point::slices)));
  if (bits <= hard_.back().frac_bits) {
    r.clock_mhz = interpolate(hard_, bits, &Point::clock_mhz);
  } else {
    // Beyond the measured range: the soft-multiplier clock, slowed by the ratio the block
    // multipliers cost at the widest measured width (placement around fixed multiplier sites).
    const Point& last = hard_.back();
    r.clock_mhz = pipeline(bits, false).clock_mhz * last.clock_mhz / pipeline(last.frac_bits, false).clock_mhz;
  }
  r.extrapolated = bits > block_synthesis_limit_;
  return r;
}

double ResourceModel::wrapper_clock_mhz(int lanes) const {
  if (lanes < 1) throw std::invalid_argument("a design needs at least one lane, got " + std::to_string(lanes));
  // Beyond the measured lane counts the clock is held: the paper (sec 5.5) attributes the
  // near-equal clock to the pipelines being identical and independent.
  return wrapper_clock_[std::min<std::size_t>(static_cast<std::size_t>(lanes), wrapper_clock_.size()) - 1];
}

DesignResources ResourceModel::design(int bits, bool use_block_multipliers, int lanes) const {
  DesignResources d;
  d.lanes = lanes;
  d.pipeline = pipeline(bits, use_block_multipliers);
  d.slices = wrapper_.fixed_slices + lanes * (d.pipeline.slices + wrapper_.per_lane_slices);
  d.block_multipliers = wrapper_.block_multipliers + lanes * d.pipeline.block_multipliers;
  d.clock_mhz = std::min(d.pipeline.clock_mhz, wrapper_clock_mhz(lanes));
  // Only the paper's own designs (its pipeline, 1 or 2 lanes) are measured.
  d.interpolated = !(bits == design_bits_ && use_block_multipliers == design_block_multipliers_ &&
                     lanes <= static_cast<int>(wrapper_clock_.size()));
  return d;
}

}  // namespace rc::pipeline
