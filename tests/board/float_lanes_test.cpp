// Float lanes (docs/board.md, "Float lanes"): coordinates and face records are (1+E+M)-bit patterns
// of values of a pipeline::FloatFormat, packed like fixed-point codes, and the lanes run the float
// pipeline (pipeline/float_mt.h). Checked: the encoding round-trips every kind of value; the layout
// follows the value width and refuses a value wider than the word; a pass's cycles from the formula
// equal the cycle-level model's and the fast model's, to the cycle (float:5,10 and float:8,23, 1 and
// 2 lanes, hand-worked values for some); the blocked bits equal float_mt's segment_hits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "board/board_params.h"
#include "board/device_profile.h"
#include "board/word_format.h"
#include "pipeline/float_mt.h"
#include "tlm/timing.h"
#include "tests/board/board_test_support.h"

namespace rc::board::test {
namespace {

using pipeline::FloatFaceRecord;
using pipeline::FloatFormat;
using pipeline::FloatVec3;

std::int64_t code(double v, FloatFormat f) { return static_cast<std::int64_t>(float_code(v, f)); }
pipeline::FixedVec3 codes(const FloatVec3& v, FloatFormat f) { return {code(v.x, f), code(v.y, f), code(v.z, f)}; }

// A pass in format values, and the same pass as the banks hold it (PassData of bit patterns, which
// load_pass / run_pass move like fixed-point codes).
struct FloatPass {
  std::vector<FloatFaceRecord> faces;
  FloatVec3 start{0, 0, 0};
  std::vector<FloatVec3> ends;
  PassData data;
};

// Faces across the middle of [-0.5, 0.5]^3 (face 0 at z = 0: zero exponents; negative coordinates:
// sign bits, bit 31 of a float:8,23 word), a start below and end points above them.
FloatPass crossing_float_pass(std::uint64_t rays, FloatFormat format, unsigned faces, unsigned seed, int source = -1) {
  FloatPass p;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.48, 0.48);
  for (unsigned f = 0; f < faces; ++f) {
    const double z = 0.05 * f, s = 0.9 / (f + 1);
    p.faces.push_back(pipeline::make_float_face_record({{-0.45, -0.45, z}, {-0.45 + s, -0.4, z}, {-0.4, -0.45 + s, z}},
                                                       format));
  }
  p.start = pipeline::round_point({-0.2, -0.2, -0.4}, format);
  for (std::uint64_t r = 0; r < rays; ++r) {
    p.ends.push_back(pipeline::round_point({u(rng), u(rng), 0.45}, format));
    p.data.end_faces.push_back(faces > 1 ? static_cast<int>(r * faces / (rays + 1)) : -1);
  }
  for (const FloatFaceRecord& f : p.faces) {
    p.data.faces.push_back({codes(f.v0, format), codes(f.edge1, format), codes(f.edge2, format)});
  }
  p.data.start = codes(p.start, format);
  for (const FloatVec3& e : p.ends) p.data.ends.push_back(codes(e, format));
  p.data.source_face = source;
  return p;
}

// float_mt's answer, with the own-face rule.
std::vector<std::uint8_t> float_expected(const FloatPass& p, FloatFormat format) {
  std::vector<std::uint8_t> blocked(p.ends.size(), 0);
  for (std::size_t r = 0; r < p.ends.size(); ++r)
    for (std::size_t f = 0; f < p.faces.size(); ++f)
      if (static_cast<int>(f) != p.data.source_face && static_cast<int>(f) != p.data.end_faces[r])
        blocked[r] |= pipeline::segment_hits(p.faces[f], p.start, p.ends[r], format);
  return blocked;
}

BoardParams float_params(unsigned lanes, FloatFormat format, WrapperModel model) {
  BoardParams p = round_params(lanes, 15, 6, model);
  p.float_format = format;
  return p;
}

// One board running passes one after another from a scripted host.
struct Bench {
  std::unique_ptr<Rc2000> board;
  std::unique_ptr<ScriptedHost> host;
  std::vector<PassRecord> passes;
  std::vector<std::vector<std::uint8_t>> blocked;

  Bench(const std::string& name, const BoardParams& params, const std::vector<FloatPass>& steps) {
    board = std::make_unique<Rc2000>(name.c_str(), params);
    board->wrapper().on_pass([this](const PassRecord& r) { passes.push_back(r); });
    host = std::make_unique<ScriptedHost>((name + "_host").c_str(), *board, [this, steps](ScriptedHost& h) {
      for (const FloatPass& s : steps) blocked.push_back(run_pass(h, s.data, true));
    });
  }
  std::uint64_t formula(const FloatPass& s) const {
    const BankLayout& L = board->layout();
    return pass_timing(L, board->params().timing, split_rays(L, s.ends.size()), s.faces.size(), true).total;
  }
};

TEST(FloatLanes, BitPatternsRoundTrip) {
  const FloatFormat half(5, 10), single(8, 23);
  EXPECT_EQ(float_code(1.0, half), 0x3C00u);
  EXPECT_EQ(float_code(-2.0, half), 0xC000u);
  EXPECT_EQ(float_code(0.0, half), 0x0000u);
  EXPECT_EQ(float_code(-0.0, half), 0x8000u);
  EXPECT_EQ(float_code(65504.0, half), 0x7BFFu);  // largest finite
  EXPECT_EQ(float_code(std::ldexp(1.0, -14), half), 0x0400u);  // smallest normal
  EXPECT_EQ(float_code(std::numeric_limits<double>::infinity(), half), 0x7C00u);
  EXPECT_EQ(float_code(1.0, single), 0x3F800000u);
  EXPECT_EQ(float_code(-0.1f, single), 0xBDCCCCCDu);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  for (const FloatFormat f : {half, single, FloatFormat(2, 1), FloatFormat(10, 24), FloatFormat(6, 9)}) {
    for (int i = 0; i < 1000; ++i) {
      const double v = pipeline::round_to_format(u(rng), f);
      const std::uint64_t c = float_code(v, f);
      EXPECT_LT(c, std::uint64_t(1) << f.bits_per_value());
      const double back = float_from_code(c, f);
      EXPECT_EQ(std::memcmp(&back, &v, sizeof v), 0) << f.to_string() << " " << v;
    }
    for (const double v : {0.0, -0.0, f.min_normal(), -f.max_finite(), std::numeric_limits<double>::infinity()})
      EXPECT_EQ(std::signbit(float_from_code(float_code(v, f), f)), std::signbit(v));
    EXPECT_TRUE(std::isnan(float_from_code(float_code(std::nan(""), f), f)));
  }
}

TEST(FloatLanes, LayoutFollowsTheValueWidth) {
  const BankLayout half = make_bank_layout(2, 6, FloatFormat(5, 10), 32, 1u << 20);
  EXPECT_EQ(half.value_bits, 16u);
  EXPECT_EQ(half.coords_per_word, 2u);
  EXPECT_EQ(half.field_bits, 16u);
  EXPECT_EQ(half.groups.size(), 1u);
  const BankLayout single = make_bank_layout(2, 6, FloatFormat(8, 23), 32, 1u << 20);
  EXPECT_EQ(single.coords_per_word, 1u);
  EXPECT_EQ(single.field_bits, 32u);
  ASSERT_EQ(single.groups.size(), 2u);
  EXPECT_EQ(single.groups[1].k(), 1u);  // the second lane's X, Y, Z in one bank at 1/3 rate
  const BankLayout six = make_bank_layout(3, 8, FloatFormat(6, 9), 64, 1u << 20);
  EXPECT_EQ(six.coords_per_word, 4u);  // 16-bit values, four per 64-bit word
  for (const auto& [format, word, parts] :
       std::vector<std::tuple<FloatFormat, unsigned, std::vector<std::string>>>{
           {FloatFormat(10, 24), 32, {"float:10,24", "35-bit", "32-bit bank word"}},
           {FloatFormat(10, 24), 64, {"float:10,24", "35-bit", "32-bit start-point registers", "64-bit-word"}}}) {
    try {
      (void)make_bank_layout(1, 6, format, word, 1u << 20);
      ADD_FAILURE() << "no error for " << format.to_string();
    } catch (const std::invalid_argument& e) {
      for (const std::string& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
    }
  }
  BoardParams p = float_params(2, FloatFormat(5, 10), WrapperModel::fast);
  EXPECT_EQ(make_bank_layout(p).float_format, FloatFormat(5, 10));
  p.float_format.reset();
  EXPECT_FALSE(make_bank_layout(p).float_format.has_value());
}

// The device clock of float lanes is fit_float_design's estimate; the pipeline latency the profile's.
TEST(FloatLanes, BoardParamsTakeTheFloatDesignsClock) {
  const DeviceProfile device = find_device_profile("xc2v6000");
  BoardChoices c;
  c.lanes = 2;
  c.float_format = FloatFormat(5, 10);
  const BoardParams p = make_board_params(device, c);
  const FloatDesignFit fit = fit_float_design(device, pipeline::ResourceModel::load_default(), 2, FloatFormat(5, 10));
  EXPECT_TRUE(fit.fits);
  EXPECT_EQ(p.fit.clock_mhz, fit.clock_mhz);
  EXPECT_EQ(p.fit.bits, 16);
  EXPECT_TRUE(p.fit.modelled);
  EXPECT_EQ(p.timing.device_period, tlmx::period_from_hz(fit.clock_mhz * 1e6));
  EXPECT_EQ(p.timing.pipeline_latency, device.pipeline_latency_cycles);
  EXPECT_EQ(p.float_format, FloatFormat(5, 10));
}

// Formula = cycle-level model = fast model, every pass, to the cycle; blocked bits = float_mt's.
TEST(FloatLanes, FormulaCycleModelAndFastModelAgree) {
  struct Config {
    const char* name;
    unsigned lanes;
    FloatFormat format;
  };
  const std::vector<Config> configs = {{"h1", 1, FloatFormat(5, 10)},
                                       {"h2", 2, FloatFormat(5, 10)},
                                       {"s1", 1, FloatFormat(8, 23)},
                                       {"s2", 2, FloatFormat(8, 23)}};
  std::vector<std::vector<FloatPass>> steps;
  std::vector<std::unique_ptr<Bench>> fast, cycle;
  for (const Config& c : configs) {
    steps.push_back({crossing_float_pass(37, c.format, 1, 37), crossing_float_pass(100, c.format, 5, 700, 2),
                     crossing_float_pass(1, c.format, 1, 1)});
    fast.push_back(std::make_unique<Bench>(std::string("fast_") + c.name, float_params(c.lanes, c.format, WrapperModel::fast),
                                           steps.back()));
    cycle.push_back(std::make_unique<Bench>(std::string("cycle_") + c.name,
                                            float_params(c.lanes, c.format, WrapperModel::cycle), steps.back()));
  }
  std::vector<const ScriptedHost*> hosts;
  for (std::size_t i = 0; i < configs.size(); ++i) hosts.insert(hosts.end(), {fast[i]->host.get(), cycle[i]->host.get()});
  run_until_finished(hosts);

  for (std::size_t i = 0; i < configs.size(); ++i) {
    const Bench& f = *fast[i];
    const Bench& c = *cycle[i];
    const char* n = configs[i].name;
    ASSERT_EQ(f.passes.size(), steps[i].size()) << n;
    ASSERT_EQ(c.passes.size(), steps[i].size()) << n;
    for (std::size_t s = 0; s < steps[i].size(); ++s) {
      const std::uint64_t total = f.formula(steps[i][s]);
      EXPECT_EQ(f.passes[s].error, reg::kOk) << n << " step " << s;
      EXPECT_EQ(c.passes[s].error, reg::kOk) << n << " step " << s;
      EXPECT_EQ(f.passes[s].cycles, total) << n << " step " << s;
      EXPECT_EQ(c.passes[s].cycles, total) << n << " step " << s;
      EXPECT_EQ(f.passes[s].end - f.passes[s].start, c.passes[s].end - c.passes[s].start) << n << " step " << s;
      EXPECT_EQ(f.passes[s].limit, c.passes[s].limit) << n << " step " << s;
      EXPECT_EQ(f.passes[s].lane_rays, c.passes[s].lane_rays) << n << " step " << s;
      const std::vector<std::uint8_t> want = float_expected(steps[i][s], configs[i].format);
      EXPECT_EQ(f.blocked[s], want) << n << " step " << s;
      EXPECT_EQ(c.blocked[s], want) << n << " step " << s;
    }
    // The crossing passes block some rays and not others.
    std::uint64_t blocked = 0;
    for (const std::uint8_t b : f.blocked[1]) blocked += b;
    EXPECT_GT(blocked, 0u) << n;
    EXPECT_LT(blocked, 100u) << n;
  }

  // Worked by hand (device 20 ns, banks 10 ns: fetch = ceil((2 + 9) / 2) = 6), 37 rays, 1 face, CLEAR:
  //   float:5,10, 1 lane: 2 + 1 + 6 + 37 (stream: a packet a cycle) + 37 + 1 = 84
  EXPECT_EQ(fast[0]->passes[0].cycles, 84u);
  //   float:5,10, 2 lanes (two 16-bit fields a word): 19 packets: 2 + 7 + 19 + 37 + 1 = 66
  EXPECT_EQ(fast[1]->passes[0].cycles, 66u);
  //   float:8,23, 2 lanes (one value a word, 6 banks): lane 1's group in one bank at 1/3 rate; 28 rays
  //   to lane 0 and 9 to lane 1 (28 + floor(28 / 3) = 37): stream max(28, 27, ...) = 28:
  //   2 + 7 + 28 + 37 + 1 = 75
  EXPECT_EQ(fast[3]->passes[0].cycles, 75u);
  EXPECT_EQ(fast[3]->passes[0].lane_rays, (std::vector<std::uint64_t>{28, 9}));
}

}  // namespace
}  // namespace rc::board::test
