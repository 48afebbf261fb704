#include "pipeline/resource_model.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "io/config_dir.h"
#include "pipeline/bit_bounds.h"
#include "pipeline/fixed_format.h"
#include "pipeline/hardware_blocks.h"
#include "profiles/resource_table.h"

#include "pipeline/part_family.h"

namespace rc::pipeline {

namespace {

[[noreturn]] void fail(const std::string& origin, const std::string& what) {
  throw std::runtime_error("pipeline resources " + origin + ": " + what);
}

}  // namespace

ResourceModel ResourceModel::load(const std::string& path) { return from_table(profiles::read_resource_table(path), path); }

ResourceModel ResourceModel::from_text(const std::string& text, const std::string& origin) {
  return from_table(profiles::parse_resource_table(text, origin), origin);
}

std::string ResourceModel::default_path() { return io::config_dir() + "/pipeline_resources.json"; }

std::string ResourceModel::default_synthesis_path() { return io::config_dir() + "/synthesis_resources.json"; }

// Read once per process, path and source: nothing writes the files while a command runs, and the
// design fit, the sec 5.6 estimates and the energy estimate each ask for it
// (tests/scripts/profile_reads_test.sh).
ResourceModel ResourceModel::load_default(ResourceSource source) {
  static std::mutex guard;
  static std::map<std::pair<std::string, ResourceSource>, ResourceModel> loaded;
  const std::string path = default_path();
  const std::lock_guard<std::mutex> lock(guard);
  auto it = loaded.find({path, source});
  if (it == loaded.end()) {
    ResourceModel m = load(path);
    if (source == ResourceSource::synthesis) {
      const std::string synthesis = default_synthesis_path();
      m = m.with_synthesis(profiles::read_synthesis_table(synthesis), synthesis);
    }
    it = loaded.emplace(std::make_pair(path, source), std::move(m)).first;
  }
  return it->second;
}

std::vector<PublishedSlices> ResourceModel::published_slices() const {
  std::vector<PublishedSlices> out;
  for (const Point& p : soft_) out.push_back({p.frac_bits, false, p.slices});
  for (const Point& p : hard_) out.push_back({p.frac_bits, true, p.slices});
  return out;
}

ResourceModel ResourceModel::with_synthesis(const profiles::SynthesisTable& table, const std::string& origin) const {
  ResourceModel m = *this;
  m.source_ = ResourceSource::synthesis;
  m.synthesis_ = std::make_shared<const SynthesisResources>(
      SynthesisResources::build(table, published_slices(), device_.name, origin));
  return m;
}

ResourceModel ResourceModel::from_table(const profiles::ResourceTable& t, const std::string& origin) {
  ResourceModel m;
  m.device_ = {t.device_name, t.device_slices, t.device_block_multipliers};
  m.block_bits_ = t.block_operand_bits;
  m.block_synthesis_limit_ = t.synthesis_limit_bits;

  const auto points = [&](const std::vector<profiles::ResourcePoint>& rows, const char* key, std::size_t at_least) {
    std::vector<Point> out;
    for (const profiles::ResourcePoint& p : rows) {
      if (!is_valid_frac_bits(p.frac_bits)) fail(origin, std::string(key) + " has width " + std::to_string(p.frac_bits));
      out.push_back({p.frac_bits, p.clock_mhz, p.slices});
    }
    std::sort(out.begin(), out.end(), [](const Point& a, const Point& b) { return a.frac_bits < b.frac_bits; });
    if (out.size() < at_least) fail(origin, std::string(key) + " needs at least " + std::to_string(at_least) + " points");
    return out;
  };
  m.soft_ = points(t.soft, "pipeline_without_block_multipliers", 3);
  m.hard_ = points(t.hard, "pipeline_with_block_multipliers", 2);
  m.soft_slices_ = fit(m.soft_, &Point::slices);
  m.soft_clock_ = fit(m.soft_, &Point::clock_mhz);
  // The block multiplier counts in the file are checked against the 18x18 splitting model.
  for (const profiles::ResourcePoint& p : t.hard) {
    if (p.block_multipliers != block_multipliers_needed(p.frac_bits, m.block_bits_)) {
      fail(origin, "block multiplier count at " + std::to_string(p.frac_bits) + " bits disagrees with the 18x18 model");
    }
  }

  // Designs: wrapper + L pipelines. With one and two lanes of the same pipeline,
  //   slices(L) = fixed + L * (pipeline + per_lane)
  // gives per_lane = slices(2) - slices(1) - pipeline and fixed = slices(1) - (pipeline + per_lane).
  const profiles::ResourceDesign* lane[2] = {nullptr, nullptr};
  for (const profiles::ResourceDesign& d : t.designs)
    if (d.lanes == 1 || d.lanes == 2) lane[d.lanes - 1] = &d;
  if (!lane[0] || !lane[1]) fail(origin, "designs need a 1-lane and a 2-lane entry");
  const int bits = lane[0]->frac_bits;
  const bool hard = lane[0]->block_multipliers_used;
  if (lane[1]->frac_bits != bits || lane[1]->block_multipliers_used != hard) {
    fail(origin, "the 1-lane and 2-lane designs use different pipelines");
  }
  m.design_bits_ = bits;
  m.design_block_multipliers_ = hard;
  const PipelineResources p = m.pipeline(bits, hard);
  const int s1 = lane[0]->slices, s2 = lane[1]->slices;
  m.wrapper_.per_lane_slices = s2 - s1 - p.slices;
  m.wrapper_.fixed_slices = s1 - (p.slices + m.wrapper_.per_lane_slices);
  m.wrapper_.block_multipliers = lane[0]->block_multipliers - p.block_multipliers;
  if (lane[1]->block_multipliers != m.wrapper_.block_multipliers + 2 * p.block_multipliers) {
    fail(origin, "block multipliers of the 1-lane and 2-lane designs are inconsistent");
  }
  // The design clocks are far below the pipeline's own: they are the wrapper's clock.
  m.wrapper_clock_ = {lane[0]->clock_mhz, lane[1]->clock_mhz};

  // Floating point: constants of the counting rules, each with its source (checked at the edge).
  m.float_multipliers_ = t.multipliers.value;
  m.float_sign_flips_ = t.sign_flips.value;
  m.float_add_subs_ = t.add_subs.value;
  m.float_comparators_ = t.comparators.value;
  m.guard_bits_ = t.guard_bits.value;
  m.luts_per_slice_ = t.luts_per_slice.value;
  m.flip_flops_per_slice_ = t.flip_flops_per_slice.value;
  if (m.luts_per_slice_ < 1 || m.flip_flops_per_slice_ < 1) fail(origin, "a slice needs at least one LUT and one flip-flop");
  if (m.float_comparators_ % 2 != 0) fail(origin, "float_pipeline.comparators: three against 0 and three against |det|");
  for (const profiles::FloatFamilyRow& f : t.families) {
    FloatFamily family{f.name, f.part_prefix, f.block_multiplier, f.operand_bits};
    if (family.operand_bits < 2) fail(origin, "family " + family.name + ": operand_bits below 2");
    m.families_.push_back(family);
  }
  if (m.families_.empty()) fail(origin, "float_pipeline.families is empty");
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

PipelineResources ResourceModel::pipeline(FracBits bits, bool use_block_multipliers, const std::string& part) const {
  PipelineResources r = paper_pipeline(bits, use_block_multipliers);
  if (source_ != ResourceSource::synthesis) return r;
  // Slices and block multipliers from the synthesizer; the clock stays the paper's (or its fit).
  const SynthesisCounts c = synthesis_->counts(part.empty() ? device_.name : part, bits, use_block_multipliers);
  r.source = ResourceSource::synthesis;
  r.synthesis_family = c.family;
  r.slices = synthesis_->slices(c);
  r.block_multipliers = c.block_multipliers;
  r.interpolated = true;  // a fitted rule on a synthesizer's counts, never a measured figure
  r.extrapolated = r.extrapolated || c.extrapolated;
  return r;
}

PipelineResources ResourceModel::paper_pipeline(FracBits bits, bool use_block_multipliers) const {
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
    r.clock_mhz = paper_pipeline(bits, false).clock_mhz * last.clock_mhz / paper_pipeline(last.frac_bits, false).clock_mhz;
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

// ---- Floating point ----------------------------------------------------------------------------
//
// ESTIMATES, by documented rules (docs/pipeline.md, "Resources, clock and lanes that fit"); p = M + 1
// significant bits, w = p + guard bits (guard, round, sticky), L(x) = ceil(log2 x). Counting
// conventions: one 4-input LUT per bit of an adder, subtractor, comparator or incrementer (the
// carry chain rides along in the slice), one LUT per bit per 2:1 multiplexer stage of a shifter,
// w/3 LUTs for a w-input OR (LUT4 tree), every LUT output registered (the operator is fully
// pipelined, as the Floating-Point Operator is at its maximum latency), and a slice holds
// luts_per_slice LUTs and flip_flops_per_slice flip-flops.

namespace {

int ceil_log2(int x) {
  int l = 0;
  while ((1 << l) < x) ++l;
  return l;
}

int ceil_div(int a, int b) { return (a + b - 1) / b; }

}  // namespace

int ResourceModel::slices_for(int luts, int flip_flops) const {
  return std::max(ceil_div(luts, luts_per_slice_), ceil_div(flip_flops, flip_flops_per_slice_));
}

const FloatFamily& ResourceModel::float_family_of_part(const std::string& part) const {
  for (const FloatFamily& f : families_) {
    if (part_in_family(part, f.part_prefix)) return f;
  }
  throw std::invalid_argument("no floating-point resource figures for the family of part \"" + part +
                              "\" (known: XC2V Virtex-II, XC4V Virtex-4, XC3S Spartan-3)");
}

const FloatFamily& ResourceModel::float_family(const std::string& name) const {
  for (const FloatFamily& f : families_) {
    if (f.name == name) return f;
  }
  throw std::invalid_argument("unknown FPGA family \"" + name + "\"");
}

int ResourceModel::float_multiplier_blocks(FloatFormat format, int block_bits) {
  const int pieces = ceil_div(format.precision(), block_bits - 1);
  return pieces * pieces;
}

// Add/subtract, the classic single-path architecture (swap, align, add, normalise, round):
//   exponent compare and difference 2(E+1), operand swap 2p, alignment shifter w L(w), sticky
//   OR ceil(w/3), significand add/sub w+1, leading-zero count w, normalisation shifter w L(w),
//   rounding incrementer p+1, exponent adjust E+2, special values (zero/inf/NaN in, flush and
//   overflow out) 2E.
FloatOperatorCost ResourceModel::float_adder(FloatFormat format) const {
  const int e = format.exponent_bits(), p = format.precision(), w = p + guard_bits_, l = ceil_log2(w);
  FloatOperatorCost c;
  c.luts = 2 * (e + 1) + 2 * p + 2 * w * l + ceil_div(w, 3) + (w + 1) + w + (p + 1) + (e + 2) + 2 * e;
  c.flip_flops = c.luts;
  c.slices = slices_for(c.luts, c.flip_flops);
  return c;
}

// Multiply: exponent add and bias subtract 2(E+2), normalisation (one-place shift) p, rounding
// incrementer p+1, sign XOR 1, special values 2E; the p x p significand product either on
// ceil(p/17)^2 blocks, whose partial products are summed by (blocks - 1) adders of 2p bits, or in
// slices at soft_multiplier_slices_per_bit_product() slices per bit of p^2.
FloatOperatorCost ResourceModel::float_multiplier(FloatFormat format, bool use_block_multipliers, int block_bits) const {
  const int e = format.exponent_bits(), p = format.precision();
  FloatOperatorCost c;
  c.luts = 2 * (e + 2) + p + (p + 1) + 1 + 2 * e;
  if (use_block_multipliers) {
    c.block_multipliers = float_multiplier_blocks(format, block_bits);
    c.luts += (c.block_multipliers - 1) * 2 * p;
    c.flip_flops = c.luts;
    c.slices = slices_for(c.luts, c.flip_flops);
  } else {
    c.flip_flops = c.luts;  // of the logic around the array; the array is counted in slices
    c.slices = slices_for(c.luts, c.flip_flops) +
               static_cast<int>(std::ceil(soft_multiplier_slices_per_bit_product() * p * p));
  }
  return c;
}

// Table 1 (15 bits, block multipliers) against sec 5.2 (15 bits, slice multipliers): the same
// lane but for its 27 multipliers, so the slices the slice multipliers cost over the blocks,
// divided by the partial-product bits sum(a_i * b_i) of the 27 products (widths from bit_bounds.h).
double ResourceModel::soft_multiplier_slices_per_bit_product() const {
  const Point& hard = hard_.back();
  const Point* soft = find(soft_, hard.frac_bits);
  const double extra = (soft ? soft->slices : soft_slices_(hard.frac_bits)) - hard.slices;
  double bit_products = 0;
  for (int m = 0; m < kMultiplierCount; ++m) {
    const MultiplierOperands ops = operands_of(static_cast<Multiplier>(m));
    bit_products += double(signed_bits(ops.a, hard.frac_bits)) * signed_bits(ops.b, hard.frac_bits);
  }
  return extra / bit_products;
}

// The fixed lane's arithmetic counted by the same rules: its 18 add/subs and the three direction
// subtractors at their register widths, |det| (negate and select, 2 LUTs per bit), the three
// comparisons with |det| (one LUT per bit of the wider operand) and the three with 0 (zero detect
// of a signed-dot-wide word, ceil(w/3)).
int ResourceModel::fixed_arithmetic_luts(FracBits bits) {
  int luts = 0;
  for (int a = 0; a < kAddSubCount; ++a) luts += signed_bits(result_of(static_cast<AddSub>(a)), bits);
  luts += 3 * signed_bits(Quantity::Difference, bits);
  luts += 2 * signed_bits(Quantity::AbsDet, bits);
  luts += 2 * signed_bits(Quantity::SignedDot, bits) + signed_bits(Quantity::UvSum, bits);
  luts += 3 * ceil_div(signed_bits(Quantity::SignedDot, bits), 3);
  return luts;
}

TGuardCost ResourceModel::t_guard_cost(FracBits bits) const {
  TGuardCost c;
  const int abs_det = signed_bits(Quantity::AbsDet, bits), t_signed = signed_bits(Quantity::SignedDot, bits);
  c.comparator_bits = std::max(abs_det, t_signed);
  c.luts = abs_det                                   // |det| - g
           + t_signed - ceil_div(t_signed, 3);       // g < t*s instead of 0 < t*s
  c.flip_flops = 10 * abs_det;                       // |det| - g at age 26 and its delay line to 35 (flip-flops,
                                                     // as rtl/mt_pipeline.v's mt_delay chains)
  c.slices = slices_for(c.luts, c.flip_flops);
  c.added_latency = 0;
  return c;
}

// What the paper's measured block-multiplier lanes (Table 1, 7 and 15 bits) hold beyond that
// counted arithmetic -- pipeline registers and delay lines over 37 stages, the blocks' interface,
// System Generator glue -- is linear in the width (two points); the float lane carries values of
// 1+E+M bits through the same data flow, so it gets this line at N = 1+E+M (the fixed lane's
// coordinates are N bits wide).
double ResourceModel::glue_slices(int word_bits) const {
  std::vector<Point> glue;
  for (const Point* p : {&hard_.front(), &hard_.back()}) {
    glue.push_back({p->frac_bits, p->clock_mhz,
                    p->slices - ceil_div(fixed_arithmetic_luts(p->frac_bits), luts_per_slice_)});
  }
  return interpolate(glue, word_bits, &Point::slices);
}

FloatPipelineResources ResourceModel::float_pipeline(FloatFormat format, const FloatFamily& family,
                                                     bool use_block_multipliers) const {
  FloatPipelineResources r;
  r.exponent_bits = format.exponent_bits();
  r.fraction_bits = format.fraction_bits();
  r.family = family.name;
  r.block_multiplier = family.block_multiplier;
  r.block_multipliers_used = use_block_multipliers;
  r.multiplier = float_multiplier(format, use_block_multipliers, family.operand_bits);
  r.adder = float_adder(format);
  r.multipliers = float_multipliers_;
  r.add_subs = float_add_subs_;
  r.sign_flips = float_sign_flips_;
  r.comparators = float_comparators_;
  r.operator_slices = r.multipliers * r.multiplier.slices + r.add_subs * r.adder.slices;
  // Sign flips: one LUT each. Half the comparators test x < |det| on sign and magnitude (E+M+1
  // LUTs), half test 0 < x (sign clear and exponent field nonzero: ceil(E/3)+1); AND of all six: 2.
  const int e = format.exponent_bits(), m = format.fraction_bits();
  const int decision_luts = r.sign_flips + (r.comparators / 2) * (e + m + 1) + (r.comparators / 2) * (ceil_div(e, 3) + 1) + 2;
  r.decision_slices = slices_for(decision_luts, decision_luts);
  r.glue_slices = static_cast<int>(std::lround(glue_slices(format.bits_per_value())));
  r.slices = r.operator_slices + r.decision_slices + r.glue_slices;
  r.block_multipliers = r.multipliers * r.multiplier.block_multipliers;
  // Clock: the paper's fixed lane at the width whose values carry as many significant bits as the
  // significand (N = p, within 7..31): the same carry chains (the significand adder is p+3+1 bits,
  // the fixed lane's add/subs N+1..N+5) and multipliers of the same block tiling.
  r.clock_frac_bits = std::clamp(format.precision(), kMinFracBits, kMaxFracBits);
  const PipelineResources fixed = paper_pipeline(r.clock_frac_bits, use_block_multipliers);  // the clock is the paper's under either source
  r.clock_mhz = fixed.clock_mhz;
  r.clock_interpolated = fixed.interpolated;
  r.clock_extrapolated = fixed.extrapolated;
  return r;
}

}  // namespace rc::pipeline
