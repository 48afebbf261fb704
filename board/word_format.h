// The wrapper's word formats, shared by the host driver (which packs) and the wrapper (which
// unpacks), so both sides agree by construction. Words are little-endian, 4 or 8 bytes.
//   coordinate word: c fields of field_bits bits, slot j at bit j * field_bits (bank_layout.h)
//   face record:     9 words, v0.xyz, edge1.xyz, edge2.xyz, two's complement (edges are signed 1.N)
//   own-surface table: one word per face of the set: bits 30..0 the rays of the pass that end on the
//                    face's sheet (scenes/sheets.h; a one-sided face is its own sheet), bit 31
//                    (reg::kSameSheet) set when the face continues the previous face's sheet
//   result word:     bit j = ray in slot j of the packet is blocked
// Float lanes (layout.float_format set; docs/board.md, "Float lanes"): every coordinate field, start
// register and face-record word holds the (1+E+M)-bit pattern of a format value, zero-extended:
// sign at bit E+M, biased exponent at bits M..E+M-1 (0: zero, all ones: infinity / NaN), fraction
// at bits 0..M-1 (float_code / float_from_code). Face records are v0, edge1, edge2 as for fixed point
// (make_float_face_record's values), one value per word.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "board/bank_layout.h"
#include "pipeline/fixed_format.h"
#include "pipeline/float_format.h"
#include "pipeline/float_mt.h"

namespace rc::board {

inline std::uint64_t load_word(const std::uint8_t* base, std::uint64_t index, unsigned word_bytes) {
  if (word_bytes == 4) {
    std::uint32_t w;
    std::memcpy(&w, base + index * 4, 4);
    return w;
  }
  std::uint64_t w;
  std::memcpy(&w, base + index * 8, 8);
  return w;
}

inline void store_word(std::uint8_t* base, std::uint64_t index, unsigned word_bytes, std::uint64_t value) {
  if (word_bytes == 4) {
    const auto w = static_cast<std::uint32_t>(value);
    std::memcpy(base + index * 4, &w, 4);
  } else {
    std::memcpy(base + index * 8, &value, 8);
  }
}

inline std::int64_t signed_word(std::uint64_t w, unsigned word_bits) {
  return word_bits == 32 ? static_cast<std::int64_t>(static_cast<std::int32_t>(static_cast<std::uint32_t>(w)))
                         : static_cast<std::int64_t>(w);
}

inline std::int64_t coordinate_field(std::uint64_t word, unsigned slot, unsigned field_bits) {
  const std::uint64_t mask = field_bits >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << field_bits) - 1;
  return static_cast<std::int64_t>((word >> (slot * field_bits)) & mask);
}

// The bit pattern of a value of the format (round_to_format's output: zero, a normal, infinity or
// NaN; the format has no subnormals), and back. float_from_code(float_code(v, f), f) == v, bit for bit
// (a NaN's payload is cut to M bits, kept non-zero).
inline std::uint64_t float_code(double v, const pipeline::FloatFormat& f) {
  const auto e_bits = static_cast<unsigned>(f.exponent_bits()), m_bits = static_cast<unsigned>(f.fraction_bits());
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  const std::uint64_t sign = b >> 63, exponent = (b >> 52) & 0x7ff, fraction = b & ((std::uint64_t(1) << 52) - 1);
  const std::uint64_t all_ones = (std::uint64_t(1) << e_bits) - 1;
  std::uint64_t e = 0, m = fraction >> (52 - m_bits);
  if (exponent == 0) {
    m = 0;  // zero (round_to_format flushes everything below the smallest normal)
  } else if (exponent == 0x7ff) {
    e = all_ones;
    if (fraction != 0 && m == 0) m = std::uint64_t(1) << (m_bits - 1);  // NaN stays NaN
  } else {
    e = exponent - 1023 + static_cast<std::uint64_t>(f.bias());
  }
  return sign << (e_bits + m_bits) | e << m_bits | m;
}

inline double float_from_code(std::uint64_t code, const pipeline::FloatFormat& f) {
  const auto e_bits = static_cast<unsigned>(f.exponent_bits()), m_bits = static_cast<unsigned>(f.fraction_bits());
  const std::uint64_t all_ones = (std::uint64_t(1) << e_bits) - 1;
  const std::uint64_t sign = (code >> (e_bits + m_bits)) & 1, e = (code >> m_bits) & all_ones;
  const std::uint64_t m = code & ((std::uint64_t(1) << m_bits) - 1);
  std::uint64_t b = sign << 63;
  if (e == all_ones) {
    b |= std::uint64_t(0x7ff) << 52 | m << (52 - m_bits);
  } else if (e != 0) {
    b |= (e + 1023 - static_cast<std::uint64_t>(f.bias())) << 52 | m << (52 - m_bits);
  }
  double v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

inline pipeline::FloatVec3 float_point_from_codes(std::int64_t x, std::int64_t y, std::int64_t z,
                                                  const pipeline::FloatFormat& f) {
  return {float_from_code(static_cast<std::uint64_t>(x), f), float_from_code(static_cast<std::uint64_t>(y), f),
          float_from_code(static_cast<std::uint64_t>(z), f)};
}

// The 9 words of a float face record, and back (words cut to the format's bits).
void float_face_record_words(const pipeline::FloatFaceRecord& face, const pipeline::FloatFormat& f,
                             std::uint64_t words[9]);
pipeline::FloatFaceRecord float_face_record_from_words(const std::uint64_t words[9], const pipeline::FloatFormat& f);

// The 9 words of a face record.
void face_record_words(const pipeline::FaceRecord& face, std::uint64_t words[9]);
pipeline::FaceRecord face_record_from_words(const std::uint64_t words[9], unsigned word_bits);

// Host side: packs end-point codes x[i], y[i], z[i] (rays in pass order) into one byte image per
// bank (images[bank], resized to the words that bank receives; banks without rays stay empty).
void pack_rays(const BankLayout& layout, const RaySplit& split, const std::int64_t* x, const std::int64_t* y,
               const std::int64_t* z, std::vector<std::vector<std::uint8_t>>& images);

// The images pack_rays would make, all words zero (pack_rays starts from them).
void blank_ray_images(const BankLayout& layout, const RaySplit& split, std::vector<std::vector<std::uint8_t>>& images);
// The images' sizes only, their bytes unspecified: what a transfer that carries no data
// (tlmx::NoDataExtension) moves. Clears nothing, so a buffer reused at another size costs no memset.
void size_ray_images(const BankLayout& layout, const RaySplit& split, std::vector<std::vector<std::uint8_t>>& images);

// Wrapper side: reads the coordinate words of a pass from the banks (load(bank, word) -> the word)
// back into x, y, z in pass order.
template <class LoadWord>
void unpack_rays(const BankLayout& layout, const RaySplit& split, LoadWord&& load, std::int64_t* x, std::int64_t* y,
                 std::int64_t* z) {
  std::int64_t* axis[3] = {x, y, z};
  for (std::size_t g = 0; g < layout.groups.size(); ++g) {
    const RayGroup& group = layout.groups[g];
    for (std::uint64_t p = 0; p < split.packets[g]; ++p) {
      for (unsigned a = 0; a < 3; ++a) {
        const WordAddress at = ray_word(group, p, a);
        const std::uint64_t word = load(at.bank, at.word);
        for (unsigned slot = 0; slot < group.lanes; ++slot) {
          const std::uint64_t r = p * group.lanes + slot;
          if (r >= split.rays[g]) break;
          axis[a][split.first_ray[g] + r] = coordinate_field(word, slot, layout.field_bits);
        }
      }
    }
  }
}

// Host side: blocked flags in pass order from the result words (result_base of the split onward).
void unpack_results(const BankLayout& layout, const RaySplit& split, const std::uint8_t* result_words,
                    std::uint8_t* blocked);

}  // namespace rc::board
