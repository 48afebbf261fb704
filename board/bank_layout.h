// How the FPGA wrapper uses the board's memory banks (paper sec 4.1, 4.2, fig 5), generalised to any
// number of lanes (pipeline instances) and banks.
//
//   bank 0                     face records: 9 words per face (v0, edge1, edge2), then, when no
//                              spare bank is left, the own-face table (one word per face)
//   banks 1 .. 3G (or fewer)   end-point coordinates, in G ray groups (below)
//   next bank                  results, one word per packet of a group
//                              (with results on chip, the wrapper accumulates a pass's blocked bits in
//                              block RAM and writes each result word here once, at the end of the pass)
//   remaining banks            spare; the first one holds the own-face table
//
// A coordinate is a `bits`-bit unsigned 0.N code; a bank word of W bits holds c = floor(W / bits)
// of them, in fields of floor(W / c) bits (15 bits: two 16-bit halves of a 32-bit word, sec 4.2).
// Float lanes (docs/board.md, "Float lanes"): a coordinate is the (1+E+M)-bit pattern of a value of
// the format (sign | biased exponent | fraction, word_format.h), packed the same way with bits = 1+E+M
// (float:5,10: two 16-bit fields per 32-bit word; float:8,23: one per word).
// A ray group is a set of k banks (k = 3 normally; 1 or 2 in the 6- and 7-bank variants of sec 4.1)
// feeding up to c lanes. Its rays are stored as packets of c rays (one per lane, "slot"); packet p
// is three words, X, Y, Z, at stream positions 3p, 3p + 1, 3p + 2, and stream position i lives in
// the group's bank i mod k at word i div k. So k = 3 is fig 5 (one bank each for X, Y and Z, all
// read in one cycle), k = 1 keeps X, Y, Z interleaved in one bank (a packet every 3 cycles, the
// lane runs at 1/3 rate) and k = 2 gives 2/3 rate.
// Groups are filled with full-rate triples first; only the last group may be a 1- or 2-bank group.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "board/lane_count.h"
#include "pipeline/fixed_format.h"
#include "pipeline/float_format.h"

namespace rc::board {

// Where the wrapper accumulates a pass's blocked bits (docs/board.md, "Results on chip"):
//   bank     in the result bank, one read-modify-write (or write) per packet and face (paper sec 4.1, 4.2)
//   on_chip  in the FPGA's block RAM, one entry per packet; each result word is written to the result
//            bank once, at the end of the pass
enum class ResultStore { bank, on_chip };

// How split_rays divides a pass's rays over the ray groups (docs/board.md, "Ray split"):
//   nominal  by the groups' nominal lane rates (the paper's design: a group of k banks and s lanes
//            does s * floor(n * k / 3) rays in n cycles), whatever else limits the stream
//   limit    by what each group can do in n device cycles under the pass-timing formula's every
//            term (pass_timing.h): its lanes, its ray banks at the bank clock and the result bank's
//            accesses (results in the bank), so the split's stream is the fewest cycles any split of
//            contiguous ranges takes, and a layout with more banks is never slower
enum class RaySplitRule { nominal, limit };
const char* to_string(RaySplitRule rule);               // "nominal", "limit": the option's spelling
const std::vector<std::string>& ray_split_names();      // in enum order
RaySplitRule parse_ray_split(const std::string& text);  // throws std::invalid_argument naming the choices
const char* to_string(ResultStore store);  // "bank", "on_chip": the profile's spelling
const std::vector<std::string>& result_store_names();  // in enum order

struct RayGroup {
  std::vector<unsigned> banks;  // k = 1, 2 or 3 banks
  unsigned lanes = 0;           // slots used per packet (<= coordinates per word)
  unsigned first_lane = 0;      // global index of the lane in slot 0
  std::uint64_t max_packets = 0;  // what its banks can hold

  unsigned k() const { return static_cast<unsigned>(banks.size()); }
  // Accesses to the result bank per packet: a result word shared by two or more lanes is
  // read-modify-written (sec 4.2); a word of one lane is only written.
  unsigned result_accesses() const { return lanes >= 2 ? 2 : 1; }
};

struct BankLayout {
  // The lane count's fourth and last hand-off, still a LaneCount (docs/architecture.md, "The lane
  // count"): --lanes -> BoardRunOptions -> BoardChoices -> BoardParams -> here, read by the wrapper.
  LaneCount lanes = 1;
  unsigned banks_available = 0;
  pipeline::FracBits bits = 15;  // set by make_bank_layout (fixed point; unused by float lanes)
  std::optional<pipeline::FloatFormat> float_format;  // set: float lanes in this format (docs/board.md)
  unsigned value_bits = 15;      // bits of one coordinate: `bits`, or 1+E+M for float lanes
  unsigned word_bits = 32;
  unsigned coords_per_word = 0;  // c
  unsigned field_bits = 0;       // width of one coordinate field in a word
  std::uint64_t bank_words = 0;  // words per bank
  unsigned face_bank = 0;
  unsigned result_bank = 0;
  std::optional<unsigned> mask_bank;  // spare bank holding the own-face table; none: in the face bank
  std::vector<unsigned> spare_banks;  // unused by the wrapper (the mask bank excluded)
  std::vector<RayGroup> groups;
  std::uint64_t max_faces_per_set = 0;
  std::uint64_t max_rays_per_batch = 0;  // the smaller of what the banks and (on chip) the block RAM hold
  ResultStore results = ResultStore::bank;
  std::uint64_t result_store_bits = 0;   // on chip: block RAM bits the design leaves for the results
  // How split_rays divides a pass's rays, and (limit) the clocks it reads: bank and device periods in
  // any one unit (make_bank_layout(BoardParams) sets them from the design's WrapperTiming).
  RaySplitRule ray_split = RaySplitRule::nominal;
  std::uint64_t split_bank_period = 1, split_device_period = 1;

  unsigned banks_used() const;
  unsigned face_words() const { return 9; }
  bool mask_in_face_bank() const { return !mask_bank.has_value(); }
  std::string role(unsigned bank) const;  // "faces", "rays g0 X", "results", "own-face table", "spare"
  // Rays per device cycle at full bank bandwidth: sum over groups of lanes * k / 3.
  double nominal_rays_per_cycle() const;
};

// ---- the limits a bank's capacity must respect (docs/board.md, "Profiles") --------------------------
// Every layout's banks share one capacity, so the bound is the most any bank of any layout needs.

// The fewest words a bank must hold for one pass of one ray against one face, in any layout: the
// face bank's face record (9 words) and, when no spare bank is left for it, that face's own-face
// table entry (1 word). A one-bank ray group's packet (3 words) and the pass's result word are fewer.
inline constexpr std::uint64_t kMinBankWords = 10;
// The wrapper finds every word it reads from counts in its 32-bit registers (RAY_COUNT, FACE_COUNT,
// MASK_START; register_map.h). The bank those counts reach furthest into is the face bank: FACE_COUNT
// face records of 9 words and their own-face table entries, 10 x (2^32 - 1) words. A larger bank
// could never be used, so a capacity beyond it is an error rather than memory spent for nothing.
inline constexpr std::uint64_t kMaxRegisterCount = 0xFFFFFFFFu;
inline constexpr std::uint64_t kMaxBankWords = kMinBankWords * kMaxRegisterCount;
// The banks' count is the CONFIG register's field [31:24]: at most 255.
inline constexpr unsigned kMaxBanks = 255;
// The wrapper needs faces, X, Y, Z and results (paper sec 4.1).
inline constexpr unsigned kMinBanks = 5;

// What is wrong with a bank of `capacity_bytes` made of `word_bits`-bit words, as the rest of a
// sentence that starts with the capacity ("is smaller than one face record ..."), or "" when it is
// a valid bank: a whole number of words, at least kMinBankWords and at most kMaxBankWords.
std::string bank_capacity_problem(std::uint64_t capacity_bytes, unsigned word_bits);

// Throws std::invalid_argument for zero lanes, a width outside 7..31, a word narrower than a
// coordinate, a bank capacity bank_capacity_problem() refuses, more than kMaxBanks banks, or more
// banks needed than available (naming lanes, banks needed and available). The batch and set limits
// never exceed kMaxRegisterCount (RAY_COUNT and FACE_COUNT are 32-bit registers).
// Results in the bank unless placed on chip (below, or board_params.h's make_bank_layout(BoardParams)).
BankLayout make_bank_layout(LaneCount lanes, unsigned banks, pipeline::FracBits bits, unsigned word_bits,
                            std::uint64_t bank_capacity_bytes);
// The same for float lanes: coordinates and face-record values are (1+E+M)-bit patterns. Also
// throws std::invalid_argument when a value is wider than the bank word or than the 32-bit
// start-point registers (naming the format and the word).
BankLayout make_bank_layout(LaneCount lanes, unsigned banks, pipeline::FloatFormat format, unsigned word_bits,
                            std::uint64_t bank_capacity_bytes);
// The layout with its results kept `store` (on chip: in `store_bits` bits of block RAM), its batch
// limit recomputed. Idempotent. Throws std::invalid_argument for results on chip with no bits.
BankLayout place_results(BankLayout layout, ResultStore store, std::uint64_t store_bits);

// The rays of one pass divided over the groups: contiguous ranges in ray order, each group filled
// up to what it can do in the smallest number of cycles n that covers all rays, by layout.ray_split:
//   nominal  at the groups' nominal rates (a group of k banks and s lanes does s * floor(n * k / 3)
//            rays in n cycles)
//   limit    s * min(floor(m * k / 3), capacity) rays with m = min(n, W), W = floor(n * Pd / Pb) the
//            bank words one bank moves in n device cycles; with results in the bank, the groups' result
//            accesses (a per packet, 2 when lanes share a word) together at most W
// The host packs, and the wrapper unpacks, with this same function.
struct RaySplit {
  std::vector<std::uint64_t> rays;         // per group
  std::vector<std::uint64_t> first_ray;    // global index of the group's first ray
  std::vector<std::uint64_t> packets;      // ceil(rays / lanes)
  std::vector<std::uint64_t> result_base;  // first result word of the group
  std::uint64_t result_words = 0;
  bool fits = true;                        // within every bank's capacity (and, on chip, the block RAM)
};
RaySplit split_rays(const BankLayout& layout, std::uint64_t rays);
// The layout with its rays split by `rule` at these clocks (periods in one unit), its batch limit
// recomputed (the split decides which batches fit). Throws std::invalid_argument for a zero period.
BankLayout place_split(BankLayout layout, RaySplitRule rule, std::uint64_t bank_period, std::uint64_t device_period);
// Block RAM bits a split's results take on chip: one entry per packet, as wide as its group's lanes.
std::uint64_t result_store_bits(const BankLayout& layout, const RaySplit& split);

// split_rays for one layout, remembered for the last two ray counts: a run's passes mostly share one
// (a pipelined step's chunks two: the full one and the last), and a split holds four vectors. The host
// (packing) and the wrapper (reading) each keep one. A reference it returned stays valid through the
// next call (that call replaces the other entry, if any).
class RaySplitMemo {
 public:
  explicit RaySplitMemo(const BankLayout& layout) : m_layout(&layout) {}
  const RaySplit& operator()(std::uint64_t rays) {
    if (rays == m_rays[m_last]) return m_split[m_last];
    m_last ^= 1;
    if (rays != m_rays[m_last]) {
      m_split[m_last] = split_rays(*m_layout, rays);
      m_rays[m_last] = rays;
    }
    return m_split[m_last];
  }

 private:
  const BankLayout* m_layout;
  std::uint64_t m_rays[2] = {~std::uint64_t{0}, ~std::uint64_t{0}};
  RaySplit m_split[2];
  unsigned m_last = 0;
};

struct WordAddress {
  unsigned bank;
  std::uint64_t word;
};
// Where coordinate word `axis` (0 X, 1 Y, 2 Z) of packet p of a group lives.
inline WordAddress ray_word(const RayGroup& g, std::uint64_t packet, unsigned axis) {
  const std::uint64_t i = 3 * packet + axis;
  return {g.banks[i % g.k()], i / g.k()};
}
// Words the j-th bank of a group holds for `packets` packets.
inline std::uint64_t group_bank_words(const RayGroup& g, unsigned j, std::uint64_t packets) {
  const std::uint64_t n = 3 * packets;
  return n > j ? (n - j + g.k() - 1) / g.k() : 0;
}

}  // namespace rc::board
