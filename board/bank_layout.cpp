#include "board/bank_layout.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "pipeline/fixed_format.h"

namespace rc::board {

unsigned BankLayout::banks_used() const {
  unsigned n = 2 + (mask_bank ? 1 : 0);
  for (const RayGroup& g : groups) n += g.k();
  return n;
}

std::string BankLayout::role(unsigned bank) const {
  static const char* kAxis[] = {"X", "Y", "Z"};
  if (bank == face_bank) return mask_in_face_bank() ? "faces + own-face table" : "faces";
  if (bank == result_bank) return "results";
  if (mask_bank && bank == *mask_bank) return "own-face table";
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const RayGroup& group = groups[g];
    for (unsigned j = 0; j < group.k(); ++j) {
      if (group.banks[j] != bank) continue;
      std::string r = "rays g" + std::to_string(g) + " ";
      if (group.k() == 3) return r + kAxis[j];
      return r + (group.k() == 1 ? "XYZ" : "XYZ interleaved " + std::to_string(j));
    }
  }
  return "spare";
}

double BankLayout::nominal_rays_per_cycle() const {
  double r = 0;
  for (const RayGroup& g : groups) r += g.lanes * g.k() / 3.0;
  return r;
}

const std::vector<std::string>& result_store_names() {
  static const std::vector<std::string> names = {"bank", "on_chip"};
  return names;
}

std::string bank_capacity_problem(std::uint64_t capacity_bytes, unsigned word_bits) {
  const std::uint64_t word_bytes = word_bits / 8;
  const std::string words = " words of " + std::to_string(word_bytes) + " bytes";
  if (capacity_bytes % word_bytes != 0) return "is not a whole number of " + std::to_string(word_bytes) + "-byte words";
  if (capacity_bytes < kMinBankWords * word_bytes) {
    return "is smaller than one face record and its own-face table entry (" + std::to_string(kMinBankWords * word_bytes) +
           " bytes: " + std::to_string(kMinBankWords) + words + "; a pass needs both in the face bank when no spare bank "
           "holds the table)";
  }
  if (capacity_bytes / word_bytes > kMaxBankWords) {
    return "is larger than the wrapper can address (" + std::to_string(kMaxBankWords * word_bytes) + " bytes: " +
           std::to_string(kMaxBankWords) + words + ", 2^32 - 1 face records and their own-face table entries, the "
           "most the 32-bit FACE_COUNT register reaches)";
  }
  return "";
}

const std::vector<std::string>& ray_split_names() {
  static const std::vector<std::string> names = {"nominal", "limit"};
  return names;
}

const char* to_string(RaySplitRule rule) { return ray_split_names()[static_cast<std::size_t>(rule)].c_str(); }

RaySplitRule parse_ray_split(const std::string& text) {
  if (text == "nominal") return RaySplitRule::nominal;
  if (text == "limit") return RaySplitRule::limit;
  throw std::invalid_argument("ray split '" + text + "' is not one of nominal, limit");
}

const char* to_string(ResultStore store) { return result_store_names()[static_cast<std::size_t>(store)].c_str(); }

namespace {

std::string lanes_text(unsigned lanes) { return std::to_string(lanes) + (lanes == 1 ? " lane" : " lanes"); }

// Largest ray count the layout accepts in one pass (monotone search on split_rays().fits), at most
// what RAY_COUNT holds.
std::uint64_t max_rays(const BankLayout& layout) {
  std::uint64_t lo = 0, hi = 1;
  while (lo < kMaxRegisterCount && split_rays(layout, hi).fits) {
    lo = hi;
    hi *= 2;
  }
  while (hi - lo > 1) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    (split_rays(layout, mid).fits ? lo : hi) = mid;
  }
  return std::min(lo, kMaxRegisterCount);
}

// Largest R such that every batch of at most R rays fits the block RAM. A split gives every group but
// the last one it fills a whole number of packets (split_rays: each takes lanes * packets), so the
// store holds a batch's rays plus at most (lanes - 1) unused slots of one packet: every r <= bits -
// pad fits, and the few counts above are tried one by one (the first that does not fit ends it,
// so no smaller batch is ever refused).
std::uint64_t max_rays_on_chip(const BankLayout& layout) {
  unsigned pad = 0;
  for (const RayGroup& g : layout.groups) pad = std::max(pad, g.lanes - 1);
  const std::uint64_t bits = layout.result_store_bits;
  std::uint64_t r = bits > pad ? bits - pad : 0;
  while (r < bits && result_store_bits(layout, split_rays(layout, r + 1)) <= bits) ++r;
  return r;
}

// The layout for coordinates of `value_bits` bits; `what` names them in errors ("15 fractional
// bits", "float:5,10 (16-bit values)").
BankLayout make_layout(LaneCount lanes, unsigned banks, unsigned value_bits, const std::string& what,
                       unsigned word_bits, std::uint64_t bank_capacity_bytes) {
  if (word_bits != 32 && word_bits != 64) throw std::invalid_argument("bank words must be 32 or 64 bits wide");
  const std::string capacity_problem = bank_capacity_problem(bank_capacity_bytes, word_bits);
  if (!capacity_problem.empty())
    throw std::invalid_argument("a bank capacity of " + std::to_string(bank_capacity_bytes) + " bytes " + capacity_problem);
  if (banks < kMinBanks) {
    throw std::invalid_argument("the wrapper needs at least 5 banks (faces, X, Y, Z, results; paper sec 4.1); the board has " +
                                std::to_string(banks));
  }
  if (banks > kMaxBanks) {
    throw std::invalid_argument(std::to_string(banks) + " banks: the wrapper's CONFIG register counts banks in 8 bits (at most " +
                                std::to_string(kMaxBanks) + ")");
  }
  BankLayout L;
  L.lanes = lanes;
  L.banks_available = banks;
  L.value_bits = value_bits;
  L.word_bits = word_bits;
  L.coords_per_word = word_bits / value_bits;
  L.field_bits = word_bits / L.coords_per_word;
  L.bank_words = bank_capacity_bytes / (word_bits / 8);

  const unsigned c = L.coords_per_word;
  const unsigned groups = (lanes + c - 1) / c;
  const unsigned full_need = 2 + 3 * groups;
  const unsigned last_k = full_need <= banks ? 3 : banks + 3 > full_need ? banks + 3 - full_need : 0;
  if (last_k == 0) {
    throw std::invalid_argument(
        lanes_text(lanes) + " at " + what + " (" + std::to_string(c) +
        " coordinate(s) per " + std::to_string(word_bits) + "-bit word) need " + std::to_string(full_need) +
        " banks at full rate (3 per group of " + std::to_string(c) + " lanes + faces + results), or at least " +
        std::to_string(full_need - 2) + " with the last group in one bank at 1/3 rate (sec 4.1); the board has " +
        std::to_string(banks));
  }
  unsigned next_bank = 1, lane = 0;
  for (unsigned g = 0; g < groups; ++g) {
    RayGroup group;
    const unsigned k = g + 1 == groups ? last_k : 3;
    for (unsigned j = 0; j < k; ++j) group.banks.push_back(next_bank++);
    group.first_lane = lane;
    group.lanes = std::min(c, lanes - lane);
    lane += group.lanes;
    group.max_packets = L.bank_words * k / 3;  // the first bank of the group holds ceil(3P / k) words
    L.groups.push_back(group);
  }
  L.face_bank = 0;
  L.result_bank = next_bank++;
  if (next_bank < banks) L.mask_bank = next_bank++;
  for (; next_bank < banks; ++next_bank) L.spare_banks.push_back(next_bank);
  L.max_faces_per_set = std::min(L.bank_words / (L.face_words() + (L.mask_in_face_bank() ? 1 : 0)), kMaxRegisterCount);
  L.max_rays_per_batch = max_rays(L);
  return L;
}

}  // namespace

BankLayout make_bank_layout(LaneCount lanes, unsigned banks, pipeline::FracBits bits, unsigned word_bits,
                            std::uint64_t bank_capacity_bytes) {
  BankLayout L = make_layout(lanes, banks, static_cast<unsigned>(bits), std::to_string(bits) + " fractional bits",
                             word_bits, bank_capacity_bytes);
  L.bits = bits;
  return L;
}

BankLayout make_bank_layout(LaneCount lanes, unsigned banks, pipeline::FloatFormat format, unsigned word_bits,
                            std::uint64_t bank_capacity_bytes) {
  const auto value_bits = static_cast<unsigned>(format.bits_per_value());
  const std::string what = format.to_string() + " (" + std::to_string(value_bits) + "-bit values)";
  if (value_bits > word_bits) {
    throw std::invalid_argument(what + " do not fit a " + std::to_string(word_bits) +
                                "-bit bank word: a coordinate or face-record value is one field of a word");
  }
  if (value_bits > 32) {
    throw std::invalid_argument(what + " do not fit the 32-bit start-point registers (START_X/Y/Z) of the " +
                                std::to_string(word_bits) + "-bit-word board");
  }
  BankLayout L = make_layout(lanes, banks, value_bits, what, word_bits, bank_capacity_bytes);
  L.float_format = format;
  return L;
}

BankLayout place_results(BankLayout layout, ResultStore store, std::uint64_t store_bits) {
  if (store == ResultStore::on_chip && store_bits == 0)
    throw std::invalid_argument("results on chip need block RAM, and the design has none left for them");
  layout.results = ResultStore::bank;  // the banks' own limit first (split_rays ignores the store)
  layout.result_store_bits = 0;
  layout.max_rays_per_batch = max_rays(layout);
  if (store == ResultStore::on_chip) {
    layout.result_store_bits = store_bits;
    layout.max_rays_per_batch = std::min(layout.max_rays_per_batch, max_rays_on_chip(layout));
    layout.results = ResultStore::on_chip;
  }
  return layout;
}

std::uint64_t result_store_bits(const BankLayout& layout, const RaySplit& split) {
  std::uint64_t bits = 0;
  for (std::size_t g = 0; g < layout.groups.size(); ++g) bits += split.packets[g] * layout.groups[g].lanes;
  return bits;
}

BankLayout place_split(BankLayout layout, RaySplitRule rule, std::uint64_t bank_period, std::uint64_t device_period) {
  if (bank_period == 0 || device_period == 0) throw std::invalid_argument("the ray split needs nonzero clock periods");
  layout.ray_split = rule;
  layout.split_bank_period = bank_period;
  layout.split_device_period = device_period;
  const ResultStore store = layout.results;
  const std::uint64_t store_bits = layout.result_store_bits;
  return place_results(std::move(layout), store, store_bits);
}

RaySplit split_rays(const BankLayout& layout, std::uint64_t rays) {
  const std::size_t G = layout.groups.size();
  const bool limit = layout.ray_split == RaySplitRule::limit;
  // Bank words one bank moves in n device cycles: to_device(w) <= n exactly when w <= this.
  auto bank_words_in = [&](std::uint64_t n) {
    const unsigned __int128 w = static_cast<unsigned __int128>(n) * layout.split_device_period / layout.split_bank_period;
    return static_cast<std::uint64_t>(std::min<unsigned __int128>(w, std::uint64_t{1} << 62));
  };
  // Packets group g can take in n cycles, within its capacity: at its nominal rate, or (limit) within
  // its lanes' and its ray banks' terms of the pass-timing formula (ceil(3P / k) <= min(n, W)).
  auto packets_in = [&](std::size_t g, std::uint64_t n) {
    const RayGroup& group = layout.groups[g];
    const std::uint64_t m = limit ? std::min(n, bank_words_in(n)) : n;
    return std::min(m * group.k() / 3, group.max_packets);
  };
  // Fills the groups in order, each up to its packets in n cycles and (limit, results in the bank)
  // the result bank's words left: a group's packet costs result_accesses() of them (a pass that does
  // not clear, pass_timing.h). Groups come in order of rays per result access (s / a: every full group
  // has c lanes, only the last may have fewer), so filling in order is filling the most rays per
  // access first. Returns the rays placed (at most `want`) and, if asked, the split's ray counts.
  const bool result_term = limit && layout.results == ResultStore::bank;
  auto fill = [&](std::uint64_t n, std::uint64_t want, std::vector<std::uint64_t>* out) {
    std::uint64_t left = want, budget = result_term ? bank_words_in(n) : ~std::uint64_t{0};
    for (std::size_t g = 0; g < G; ++g) {
      const RayGroup& group = layout.groups[g];
      std::uint64_t P = packets_in(g, n);
      if (result_term) P = std::min(P, budget / group.result_accesses());
      const std::uint64_t take = std::min<std::uint64_t>(group.lanes * P, left);
      if (result_term) budget -= group.result_accesses() * ((take + group.lanes - 1) / group.lanes);
      if (out) (*out)[g] = take;
      left -= take;
    }
    return want - left;
  };
  RaySplit s;
  s.rays.assign(G, 0);
  s.first_ray.assign(G, 0);
  s.packets.assign(G, 0);
  s.result_base.assign(G, 0);
  // Smallest n covering all rays. Nominal: 3 * rays cycles always would if capacity allowed. Limit:
  // every term is at most 3 * rays bank words (a packet's three words, two result accesses), which
  // ceil(3 * rays * Pb / Pd) device cycles move.
  std::uint64_t hi = 3 * rays;
  if (limit) {
    const unsigned __int128 n = (static_cast<unsigned __int128>(3 * rays) * layout.split_bank_period +
                                 layout.split_device_period - 1) / layout.split_device_period;
    hi = std::max<std::uint64_t>(hi, static_cast<std::uint64_t>(n));
  }
  std::uint64_t lo = 0;
  if (fill(hi, rays, nullptr) < rays) {
    s.fits = false;
    lo = hi;
  }
  while (lo < hi) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    if (fill(mid, rays, nullptr) >= rays)
      hi = mid;
    else
      lo = mid + 1;
  }
  fill(hi, rays, &s.rays);
  std::uint64_t left = rays, first = 0, words = 0;
  for (std::size_t g = 0; g < G; ++g) {
    const std::uint64_t take = s.rays[g];
    s.first_ray[g] = first;
    s.packets[g] = (take + layout.groups[g].lanes - 1) / layout.groups[g].lanes;
    s.result_base[g] = words;
    words += s.packets[g];
    first += take;
    left -= take;
  }
  s.result_words = words;
  if (left != 0 || words > layout.bank_words) s.fits = false;
  if (layout.results == ResultStore::on_chip && result_store_bits(layout, s) > layout.result_store_bits) s.fits = false;
  return s;
}

}  // namespace rc::board
