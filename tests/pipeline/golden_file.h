// Reader for tests/pipeline/golden/pipeline_golden.txt (format: see generate_golden.py).
#pragma once

#include <array>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/fixed_mt.h"

namespace rc::pipeline::golden {

struct QuantLine {
  int bits;
  std::string x_text;
  std::int64_t q;
};

struct FaceLine {
  int bits;
  std::array<std::string, 9> vertex_text;
  FaceRecord record;
};

struct CaseLine {
  std::string kind;
  int bits;
  FixedVec3 start, end;
  FaceRecord face;
  FixedVec3 direction;
  std::array<std::int64_t, kMultiplierCount> multipliers;
  std::array<std::int64_t, kAddSubCount> add_subs;
  std::int64_t sign, abs_det;
  bool hit;
  __int128 exact_det, exact_u, exact_v, exact_t;
  bool exact_hit;
  int line_number;
};

struct File {
  std::vector<QuantLine> quantisations;
  std::vector<FaceLine> faces;
  std::vector<CaseLine> cases;
};

inline __int128 parse_wide(const std::string& s) {
  std::size_t i = 0;
  const bool negative = !s.empty() && s[0] == '-';
  if (negative) ++i;
  if (i == s.size()) throw std::runtime_error("bad integer '" + s + "'");
  __int128 v = 0;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') throw std::runtime_error("bad integer '" + s + "'");
    v = v * 10 + (s[i] - '0');
  }
  return negative ? -v : v;
}

inline std::string path() { return std::string(RC_SOURCE_DIR) + "/tests/pipeline/golden/pipeline_golden.txt"; }

inline File load() {
  std::ifstream in(path());
  if (!in) throw std::runtime_error("cannot open " + path());
  File f;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    const auto next = [&] {
      std::string tok;
      if (!(s >> tok)) throw std::runtime_error("short line " + std::to_string(number));
      return tok;
    };
    const auto int64 = [&] { return static_cast<std::int64_t>(parse_wide(next())); };
    const auto vec = [&] {
      const std::int64_t x = int64(), y = int64();
      return FixedVec3{x, y, int64()};
    };
    if (tag == "Q") {
      QuantLine q;
      q.bits = std::stoi(next());
      q.x_text = next();
      q.q = int64();
      f.quantisations.push_back(q);
    } else if (tag == "F") {
      FaceLine l;
      l.bits = std::stoi(next());
      for (std::string& t : l.vertex_text) t = next();
      l.record.v0 = vec();
      l.record.edge1 = vec();
      l.record.edge2 = vec();
      f.faces.push_back(l);
    } else if (tag == "C") {
      CaseLine c;
      c.line_number = number;
      c.kind = next();
      c.bits = std::stoi(next());
      c.start = vec();
      c.end = vec();
      c.face.v0 = vec();
      c.face.edge1 = vec();
      c.face.edge2 = vec();
      c.direction = vec();
      for (auto& m : c.multipliers) m = int64();
      for (auto& a : c.add_subs) a = int64();
      c.sign = int64();
      c.abs_det = int64();
      c.hit = int64() != 0;
      c.exact_det = parse_wide(next());
      c.exact_u = parse_wide(next());
      c.exact_v = parse_wide(next());
      c.exact_t = parse_wide(next());
      c.exact_hit = int64() != 0;
      std::string extra;
      if (s >> extra) throw std::runtime_error("long line " + std::to_string(number));
      f.cases.push_back(c);
    } else {
      throw std::runtime_error("unknown tag on line " + std::to_string(number));
    }
  }
  return f;
}

}  // namespace rc::pipeline::golden
