#include "pipeline/synthesis_resources.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pipeline/part_family.h"

namespace rc::pipeline {

namespace {

struct Pair {
  PublishedSlices point;
  double luts = 0, flip_flops = 0;  // the synthesizer's, LUTs including SRLs
};

// Least squares slices = a * luts + b * flip_flops (two unknowns, normal equations).
bool solve(const std::vector<Pair>& pairs, double& a, double& b) {
  double xx = 0, xy = 0, yy = 0, xs = 0, ys = 0;
  for (const Pair& p : pairs) {
    xx += p.luts * p.luts;
    xy += p.luts * p.flip_flops;
    yy += p.flip_flops * p.flip_flops;
    xs += p.luts * p.point.slices;
    ys += p.flip_flops * p.point.slices;
  }
  const double det = xx * yy - xy * xy;
  if (!(std::fabs(det) > 1e-9 * xx * yy)) return false;
  a = (xs * yy - ys * xy) / det;
  b = (ys * xx - xs * xy) / det;
  return true;
}

const profiles::SynthesisPoint* at_width(const std::vector<profiles::SynthesisPoint>& rows, int bits) {
  for (const profiles::SynthesisPoint& p : rows)
    if (p.frac_bits == bits) return &p;
  return nullptr;
}

}  // namespace

const profiles::SynthesisFamily& SynthesisResources::family_of(const std::string& part) const {
  for (const profiles::SynthesisFamily& f : families_)
    if (part_in_family(part, f.part_prefix)) return f;
  std::string names;
  for (const profiles::SynthesisFamily& f : families_) names += (names.empty() ? "" : ", ") + f.part_prefix;
  throw std::invalid_argument("synthesis resources " + origin_ + ": no synthesis for the part " + part +
                              " (the file has families " + names + ")");
}

SynthesisResources SynthesisResources::build(const profiles::SynthesisTable& table,
                                             const std::vector<PublishedSlices>& published, const std::string& paper_part,
                                             const std::string& origin) {
  SynthesisResources s;
  s.families_ = table.families;
  s.synthesizer_ = table.synthesizer;
  s.origin_ = origin;
  const profiles::SynthesisFamily* paper_family = nullptr;
  for (const profiles::SynthesisFamily& f : s.families_)
    if (part_in_family(paper_part, f.part_prefix)) paper_family = &f;
  if (!paper_family) throw std::runtime_error("synthesis resources " + origin + ": no family for the paper's part " + paper_part);

  std::vector<Pair> pairs;
  for (const PublishedSlices& p : published) {
    const auto& rows = p.block_multipliers ? paper_family->block : paper_family->array;
    const profiles::SynthesisPoint* r = at_width(rows, p.frac_bits);
    if (!r) {
      throw std::runtime_error("synthesis resources " + origin + ": " + paper_family->family + " has no synthesis at " +
                               std::to_string(p.frac_bits) + " bits " + (p.block_multipliers ? "with" : "without") +
                               " block multipliers, a point the paper published (needed for the fit)");
    }
    pairs.push_back({p, static_cast<double>(r->luts + r->srls), static_cast<double>(r->flip_flops)});
  }
  if (pairs.size() < 3) throw std::runtime_error("synthesis resources " + origin + ": fewer than three published points to fit");
  if (!solve(pairs, s.fit_.per_lut, s.fit_.per_flip_flop)) {
    throw std::runtime_error("synthesis resources " + origin + ": the published points do not determine the fit");
  }
  for (const Pair& p : pairs) {
    const double e = (s.fit_.per_lut * p.luts + s.fit_.per_flip_flop * p.flip_flops - p.point.slices) / p.point.slices;
    s.fit_.max_abs_fit_error = std::max(s.fit_.max_abs_fit_error, std::fabs(e));
  }
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    std::vector<Pair> rest = pairs;
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
    double a = 0, b = 0;
    LeaveOneOutError l;
    l.point = pairs[i].point;
    if (solve(rest, a, b)) {
      l.predicted = a * pairs[i].luts + b * pairs[i].flip_flops;
      l.relative_error = (l.predicted - l.point.slices) / l.point.slices;
    } else {
      l.predicted = std::nan("");  // the other points do not determine the rule
      l.relative_error = std::nan("");
    }
    s.fit_.max_abs_leave_one_out = std::max(s.fit_.max_abs_leave_one_out, std::fabs(l.relative_error));
    s.fit_.leave_one_out.push_back(l);
  }
  return s;
}

SynthesisCounts SynthesisResources::counts(const std::string& part, FracBits bits, bool use_block_multipliers) const {
  const profiles::SynthesisFamily& f = family_of(part);
  const std::vector<profiles::SynthesisPoint>& rows = use_block_multipliers ? f.block : f.array;
  if (rows.empty()) {
    throw std::invalid_argument("synthesis resources " + origin_ + ": " + f.family + " has no synthesis " +
                                (use_block_multipliers ? "with" : "without") + " block multipliers");
  }
  SynthesisCounts c;
  c.frac_bits = bits;
  c.block_multipliers_used = use_block_multipliers;
  c.family = f.family;
  if (const profiles::SynthesisPoint* r = at_width(rows, bits)) {
    c.luts = r->luts;
    c.srls = r->srls;
    c.flip_flops = r->flip_flops;
    c.block_multipliers = r->block_multipliers;
    return c;
  }
  if (rows.size() == 1) {
    throw std::invalid_argument("synthesis resources " + origin_ + ": " + f.family + " was synthesised at one width only (" +
                                std::to_string(rows.front().frac_bits) + " bits); " + std::to_string(static_cast<int>(bits)) +
                                " bits needs two to interpolate");
  }
  // The two nearest rows around (or, beyond the ends, next to) the width.
  std::size_t hi = 1;
  while (hi + 1 < rows.size() && rows[hi].frac_bits < bits) ++hi;
  const profiles::SynthesisPoint &a = rows[hi - 1], &b = rows[hi];
  const double t = static_cast<double>(bits - a.frac_bits) / (b.frac_bits - a.frac_bits);
  const auto lerp = [t](int x, int y) { return static_cast<int>(std::lround(x + t * (y - x))); };
  c.luts = std::max(0, lerp(a.luts, b.luts));
  c.srls = std::max(0, lerp(a.srls, b.srls));
  c.flip_flops = std::max(0, lerp(a.flip_flops, b.flip_flops));
  c.block_multipliers = bits < a.frac_bits ? a.block_multipliers : b.block_multipliers;
  c.extrapolated = bits < rows.front().frac_bits || bits > rows.back().frac_bits;
  c.interpolated = !c.extrapolated;
  return c;
}

int SynthesisResources::slices(const SynthesisCounts& c) const {
  return static_cast<int>(std::lround(fit_.per_lut * (c.luts + c.srls) + fit_.per_flip_flop * c.flip_flops));
}

}  // namespace rc::pipeline
