#include "host_sw/visibility/end_point_catalogue.h"

#include <cstring>

#include "pipeline/fixed_mt.h"

namespace rc {

namespace {

// A catalogue this much larger than the batch it serves is mostly stale points (a caller that
// changes its end points); it is started afresh rather than grown without bound.
constexpr std::size_t kStaleFactor = 4;
constexpr std::size_t kStaleSlack = 4096;

std::uint64_t mix(std::uint64_t h) {  // a 64-bit finaliser (splitmix64)
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

}  // namespace

void EndPointCatalogue::clear() {
  keys_.clear();
  quantised_.clear();
  coords_.clear();
  table_.clear();
  first_segment_.clear();
  added_ = true;  // whatever was built over the old points is stale
}

EndPointCatalogue::Key EndPointCatalogue::key_of(const Vec3& p) {
  Key k;
  std::memcpy(&k.x, &p.x, sizeof k.x);
  std::memcpy(&k.y, &p.y, sizeof k.y);
  std::memcpy(&k.z, &p.z, sizeof k.z);
  return k;
}

std::uint32_t EndPointCatalogue::find(const Key& key) const {
  if (table_.empty()) return kNone;
  const std::size_t mask = table_.size() - 1;
  for (std::size_t slot = mix(key.x ^ mix(key.y ^ mix(key.z))) & mask;; slot = (slot + 1) & mask) {
    const std::uint32_t id = table_[slot];
    if (id == kNone || keys_[id] == key) return id;
  }
}

// Quantises first, so that a point outside [0, 1)^3 throws before anything is stored.
std::uint32_t EndPointCatalogue::add(const Key& key, const Vec3& p, int bits) {
  const pipeline::FixedVec3 q = pipeline::quantize_point(p, bits);
  const std::uint32_t id = static_cast<std::uint32_t>(keys_.size());
  keys_.push_back(key);
  quantised_.push_back(q);
  coords_.insert(coords_.end(), {double(q.x), double(q.y), double(q.z)});
  if (2 * keys_.size() > table_.size()) grow_table();  // at most half full
  const std::size_t mask = table_.size() - 1;
  std::size_t slot = mix(key.x ^ mix(key.y ^ mix(key.z))) & mask;
  while (table_[slot] != kNone) slot = (slot + 1) & mask;
  table_[slot] = id;
  added_ = true;
  return id;
}

void EndPointCatalogue::grow_table() {
  std::size_t size = 64;
  while (size < 4 * keys_.size()) size *= 2;
  table_.assign(size, kNone);
  const std::size_t mask = table_.size() - 1;
  for (std::uint32_t id = 0; id + 1 < keys_.size(); ++id) {  // the newest is placed by add()
    const Key& key = keys_[id];
    std::size_t slot = mix(key.x ^ mix(key.y ^ mix(key.z))) & mask;
    while (table_[slot] != kNone) slot = (slot + 1) & mask;
    table_[slot] = id;
  }
}

bool EndPointCatalogue::assign(const SegmentBatch& batch, int bits) {
  const std::size_t n = batch.size();
  if (keys_.size() > kStaleFactor * n + kStaleSlack) clear();
  point_of_.resize(n);
  std::uint32_t guess = 0;
  for (std::size_t s = 0; s < n; ++s) {
    const Key key = key_of(batch.ends[s]);
    std::uint32_t id = guess < keys_.size() && keys_[guess] == key ? guess : find(key);
    if (id == kNone) id = add(key, batch.ends[s], bits);
    point_of_[s] = id;
    guess = id + 1;
  }
  // Link each point's segments, in batch order.
  first_segment_.assign(keys_.size(), kNone);
  next_segment_.resize(n);
  for (std::size_t s = n; s-- > 0;) {
    const std::uint32_t id = point_of_[s];
    next_segment_[s] = first_segment_[id];
    first_segment_[id] = static_cast<std::uint32_t>(s);
  }
  const bool added = added_;
  added_ = false;
  return added;
}

}  // namespace rc
