// Bit-exactness of the floating-point pipeline against golden vectors from an independent Python
// model (exact rationals and its own rounding; tests/pipeline/golden/generate_float_golden.py):
// every rounding vector, the face record, the rounded end points, the direction, all 27
// multiplier and 18 add/sub outputs, sign, |det| and the decision, in every golden format.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/float_mt.h"

namespace rc::pipeline {
namespace {

// "0", "inf", "-inf", "nan" or "<integer>p<exponent>" (integer * 2^exponent, exact in double).
double parse_value(const std::string& s) {
  if (s == "0") return 0.0;
  if (s == "inf") return INFINITY;
  if (s == "-inf") return -INFINITY;
  if (s == "nan") return NAN;
  const std::size_t p = s.find('p');
  if (p == std::string::npos) throw std::runtime_error("bad value '" + s + "'");
  return std::ldexp(static_cast<double>(std::stoll(s.substr(0, p))), std::stoi(s.substr(p + 1)));
}

// Equal as values (the sign of a zero is not modelled: it changes no later value or decision),
// NaN equal to NaN.
bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }
bool same(const FloatVec3& a, const FloatVec3& b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }

struct RoundLine {
  FloatFormat format;
  std::string x_text;
  double expected;
};

struct CaseLine {
  std::string kind;
  FloatFormat format;
  Triangle triangle;
  Vec3 start, end;
  FloatFaceRecord face;
  FloatVec3 s, e, direction;
  std::array<double, kMultiplierCount> multipliers;
  std::array<double, kAddSubCount> add_subs;
  double sign, abs_det;
  bool hit;
  int line_number;
};

struct File {
  std::vector<RoundLine> roundings;
  std::vector<CaseLine> cases;
};

File load() {
  const std::string path = std::string(RC_SOURCE_DIR) + "/tests/pipeline/golden/float_golden.txt";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  File f;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    const auto next = [&] {
      std::string tok;
      if (!(s >> tok)) throw std::runtime_error("short line " + std::to_string(number));
      return tok;
    };
    const auto number_of = [&] { return std::strtod(next().c_str(), nullptr); };
    const auto vec3 = [&] { const double x = number_of(), y = number_of(); return Vec3{x, y, number_of()}; };
    const auto value = [&] { return parse_value(next()); };
    const auto fvec = [&] { const double x = value(), y = value(); return FloatVec3{x, y, value()}; };
    const std::string tag = next();
    if (tag == "R") {
      const int e = std::stoi(next()), m = std::stoi(next());
      std::string x = next();
      f.roundings.push_back({FloatFormat(e, m), x, value()});
    } else if (tag == "C") {
      const std::string kind = next();
      const int e = std::stoi(next()), m = std::stoi(next());
      CaseLine c{kind, FloatFormat(e, m), {}, {}, {}, {}, {}, {}, {}, {}, {}, 0, 0, false, number};
      c.triangle.v0 = vec3();
      c.triangle.v1 = vec3();
      c.triangle.v2 = vec3();
      c.start = vec3();
      c.end = vec3();
      c.face = {fvec(), fvec(), fvec()};
      c.s = fvec();
      c.e = fvec();
      c.direction = fvec();
      for (double& v : c.multipliers) v = value();
      for (double& v : c.add_subs) v = value();
      c.sign = std::stod(next());
      c.abs_det = value();
      c.hit = next() == "1";
      std::string extra;
      if (s >> extra) throw std::runtime_error("long line " + std::to_string(number));
      f.cases.push_back(c);
    } else {
      throw std::runtime_error("unknown tag on line " + std::to_string(number));
    }
  }
  return f;
}

const File& golden() {
  static const File file = load();
  return file;
}

std::string where(const CaseLine& c) {
  return "golden line " + std::to_string(c.line_number) + " (" + c.kind + ", " + c.format.to_string() + ")";
}

TEST(FloatGolden, CoversTheFormatsAndKinds) {
  std::set<std::string> formats, kinds;
  std::map<std::string, int> nonfinite;  // by format: the overflow vectors really overflow
  for (const CaseLine& c : golden().cases) {
    formats.insert(c.format.to_string());
    kinds.insert(c.kind);
    for (double v : c.add_subs) nonfinite[c.format.to_string()] += !std::isfinite(v);
  }
  EXPECT_EQ(formats, (std::set<std::string>{"float:8,23", "float:5,10", "float:6,9", "float:4,5"}));
  for (const char* k : {"random", "crossing", "edge", "vertex", "parallel", "near_parallel",
                        "det_near_zero", "degenerate", "end_on_triangle", "underflow", "overflow"}) {
    EXPECT_TRUE(kinds.count(k)) << k;
  }
  EXPECT_EQ(nonfinite["float:8,23"], 0);
  EXPECT_GT(nonfinite["float:5,10"], 0);
  EXPECT_GT(golden().cases.size(), 600u);
  EXPECT_GT(golden().roundings.size(), 150u);
}

TEST(FloatGolden, RoundingMatches) {
  for (const RoundLine& r : golden().roundings) {
    const double x = std::strtod(r.x_text.c_str(), nullptr);
    EXPECT_TRUE(same(round_to_format(x, r.format), r.expected))
        << r.x_text << " in " << r.format.to_string() << ": got " << round_to_format(x, r.format)
        << ", expected " << r.expected;
  }
}

TEST(FloatGolden, InputsRoundToTheGoldenFaceRecordAndEndPoints) {
  for (const CaseLine& c : golden().cases) {
    SCOPED_TRACE(where(c));
    const FloatFaceRecord face = make_float_face_record(c.triangle, c.format);
    EXPECT_TRUE(same(face.v0, c.face.v0) && same(face.edge1, c.face.edge1) && same(face.edge2, c.face.edge2));
    EXPECT_TRUE(same(round_point(c.start, c.format), c.s));
    EXPECT_TRUE(same(round_point(c.end, c.format), c.e));
  }
}

TEST(FloatGolden, TraceMatchesEveryBlock) {
  for (const CaseLine& c : golden().cases) {
    SCOPED_TRACE(where(c));
    const FloatTrace t = trace(c.face, c.s, c.e, c.format);
    EXPECT_TRUE(same(t.values.direction, c.direction));
    for (int m = 0; m < kMultiplierCount; ++m) {
      EXPECT_TRUE(same(t.multipliers[m], c.multipliers[m]))
          << name(static_cast<Multiplier>(m)) << ": " << t.multipliers[m] << " vs " << c.multipliers[m];
    }
    for (int a = 0; a < kAddSubCount; ++a) {
      EXPECT_TRUE(same(t.add_subs[a], c.add_subs[a]))
          << name(static_cast<AddSub>(a)) << ": " << t.add_subs[a] << " vs " << c.add_subs[a];
    }
    EXPECT_EQ(t.values.stage3.sign, c.sign);
    EXPECT_TRUE(same(t.values.stage3.abs_det, c.abs_det));
    EXPECT_EQ(t.hit(), c.hit);
  }
}

TEST(FloatGolden, NamedStageOutputsAreTheBlockOutputs) {
  for (const CaseLine& c : golden().cases) {
    SCOPED_TRACE(where(c));
    const auto add = [&](AddSub a) { return c.add_subs[static_cast<int>(a)]; };
    const auto mul = [&](Multiplier m) { return c.multipliers[static_cast<int>(m)]; };
    const PipelineValues<double> v = trace(c.face, c.s, c.e, c.format).values;
    EXPECT_TRUE(same(v.stage1.pvec, {add(AddSub::PvecX), add(AddSub::PvecY), add(AddSub::PvecZ)}));
    EXPECT_TRUE(same(v.stage1.tvec, {add(AddSub::TvecX), add(AddSub::TvecY), add(AddSub::TvecZ)}));
    EXPECT_TRUE(same(v.stage2.qvec, {add(AddSub::QvecX), add(AddSub::QvecY), add(AddSub::QvecZ)}));
    EXPECT_TRUE(same(v.stage2.det, add(AddSub::Det)));
    EXPECT_TRUE(same(v.stage3.u, add(AddSub::U)) && same(v.stage3.v, add(AddSub::V)) &&
                same(v.stage3.t, add(AddSub::T)));
    EXPECT_TRUE(same(v.stage3.u_signed, mul(Multiplier::SignU)) &&
                same(v.stage3.v_signed, mul(Multiplier::SignV)) &&
                same(v.stage3.t_signed, mul(Multiplier::SignT)));
    EXPECT_TRUE(same(v.stage3.uv_sum, add(AddSub::UPlusV)));
  }
}

TEST(FloatGolden, StageFunctionsAndKernelAgreeWithTheGolden) {
  for (const CaseLine& c : golden().cases) {
    SCOPED_TRACE(where(c));
    const FloatVec3 dir = segment_direction(c.s, c.e, c.format);
    const FloatStage1Result s1 = stage1(c.face, c.s, dir, c.format);
    const FloatStage2Result s2 = stage2(c.face, s1, c.format);
    const FloatStage3Result s3 = stage3(c.face, dir, s1, s2, c.format);
    EXPECT_TRUE(same(s2.det, c.add_subs[static_cast<int>(AddSub::Det)]));
    EXPECT_TRUE(same(s3.uv_sum, c.add_subs[static_cast<int>(AddSub::UPlusV)]));
    EXPECT_EQ(s3.hit, c.hit);
    EXPECT_EQ(segment_hits(c.face, c.s, c.e, c.format), c.hit);
    std::uint8_t blocked = 0;
    occlude_face(c.face, c.s, &c.e.x, &c.e.y, &c.e.z, 1, c.format, &blocked);
    EXPECT_EQ(blocked != 0, c.hit);
    const std::uint8_t skip = 1;
    blocked = 0;
    occlude_face(c.face, c.s, &c.e.x, &c.e.y, &c.e.z, 1, c.format, &blocked, &skip);
    EXPECT_EQ(blocked, 0);
  }
}

}  // namespace
}  // namespace rc::pipeline
