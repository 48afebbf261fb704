#include "pipeline/hardware_blocks.h"

namespace rc::pipeline {

namespace {

constexpr const char* kMultiplierNames[kMultiplierCount] = {
    "pvec.x:dir.y*edge2.z", "pvec.x:dir.z*edge2.y", "pvec.y:dir.z*edge2.x",
    "pvec.y:dir.x*edge2.z", "pvec.z:dir.x*edge2.y", "pvec.z:dir.y*edge2.x",
    "qvec.x:tvec.y*edge1.z", "qvec.x:tvec.z*edge1.y", "qvec.y:tvec.z*edge1.x",
    "qvec.y:tvec.x*edge1.z", "qvec.z:tvec.x*edge1.y", "qvec.z:tvec.y*edge1.x",
    "det:edge1.x*pvec.x", "det:edge1.y*pvec.y", "det:edge1.z*pvec.z",
    "u:tvec.x*pvec.x", "u:tvec.y*pvec.y", "u:tvec.z*pvec.z",
    "v:dir.x*qvec.x", "v:dir.y*qvec.y", "v:dir.z*qvec.z",
    "t:edge2.x*qvec.x", "t:edge2.y*qvec.y", "t:edge2.z*qvec.z",
    "u*sign", "v*sign", "t*sign",
};

constexpr const char* kAddSubNames[kAddSubCount] = {
    "tvec.x", "tvec.y", "tvec.z", "pvec.x", "pvec.y", "pvec.z",
    "qvec.x", "qvec.y", "qvec.z", "det.xy", "det",
    "u.xy", "u", "v.xy", "v", "t.xy", "t", "us+vs",
};

}  // namespace

const char* name(Multiplier m) { return kMultiplierNames[static_cast<int>(m)]; }
const char* name(AddSub a) { return kAddSubNames[static_cast<int>(a)]; }

int stage_of(Multiplier m) {
  if (m <= Multiplier::PvecZ_DirY_Edge2X) return 1;
  if (m <= Multiplier::DetZ) return 2;
  return 3;
}

int stage_of(AddSub a) {
  if (a <= AddSub::PvecZ) return 1;
  if (a <= AddSub::Det) return 2;
  return 3;
}

}  // namespace rc::pipeline
