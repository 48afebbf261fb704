#include "board/word_format.h"

namespace rc::board {

void face_record_words(const pipeline::FaceRecord& f, std::uint64_t w[9]) {
  const std::int64_t v[9] = {f.v0.x, f.v0.y, f.v0.z, f.edge1.x, f.edge1.y, f.edge1.z, f.edge2.x, f.edge2.y, f.edge2.z};
  for (int i = 0; i < 9; ++i) w[i] = static_cast<std::uint64_t>(v[i]);  // two's complement, cut to the word by store_word
}

pipeline::FaceRecord face_record_from_words(const std::uint64_t w[9], unsigned word_bits) {
  auto s = [&](int i) { return signed_word(w[i], word_bits); };
  return {{s(0), s(1), s(2)}, {s(3), s(4), s(5)}, {s(6), s(7), s(8)}};
}

void float_face_record_words(const pipeline::FloatFaceRecord& f, const pipeline::FloatFormat& format,
                             std::uint64_t w[9]) {
  const double v[9] = {f.v0.x, f.v0.y, f.v0.z, f.edge1.x, f.edge1.y, f.edge1.z, f.edge2.x, f.edge2.y, f.edge2.z};
  for (int i = 0; i < 9; ++i) w[i] = float_code(v[i], format);
}

pipeline::FloatFaceRecord float_face_record_from_words(const std::uint64_t w[9], const pipeline::FloatFormat& format) {
  const std::uint64_t mask = (std::uint64_t(1) << format.bits_per_value()) - 1;
  auto v = [&](int i) { return float_from_code(w[i] & mask, format); };
  return {{v(0), v(1), v(2)}, {v(3), v(4), v(5)}, {v(6), v(7), v(8)}};
}

void pack_rays(const BankLayout& layout, const RaySplit& split, const std::int64_t* x, const std::int64_t* y,
               const std::int64_t* z, std::vector<std::vector<std::uint8_t>>& images) {
  const unsigned word_bytes = layout.word_bits / 8;
  blank_ray_images(layout, split, images);
  const std::int64_t* axis[3] = {x, y, z};
  for (std::size_t g = 0; g < layout.groups.size(); ++g) {
    const RayGroup& group = layout.groups[g];
    for (std::uint64_t p = 0; p < split.packets[g]; ++p) {
      for (unsigned a = 0; a < 3; ++a) {
        std::uint64_t word = 0;
        for (unsigned slot = 0; slot < group.lanes; ++slot) {
          const std::uint64_t r = p * group.lanes + slot;
          if (r >= split.rays[g]) break;
          word |= static_cast<std::uint64_t>(axis[a][split.first_ray[g] + r]) << (slot * layout.field_bits);
        }
        const WordAddress at = ray_word(group, p, a);
        store_word(images[at.bank].data(), at.word, word_bytes, word);
      }
    }
  }
}

void blank_ray_images(const BankLayout& layout, const RaySplit& split, std::vector<std::vector<std::uint8_t>>& images) {
  for (auto& image : images) image.clear();
  size_ray_images(layout, split, images);  // grown from empty: every byte zero
}

void size_ray_images(const BankLayout& layout, const RaySplit& split, std::vector<std::vector<std::uint8_t>>& images) {
  const unsigned word_bytes = layout.word_bits / 8;
  images.resize(layout.banks_available);  // a bank outside the groups keeps no words (pack_rays: empty)
  for (std::size_t g = 0; g < layout.groups.size(); ++g) {
    const RayGroup& group = layout.groups[g];
    for (unsigned j = 0; j < group.k(); ++j) images[group.banks[j]].resize(group_bank_words(group, j, split.packets[g]) * word_bytes);
  }
}

void unpack_results(const BankLayout& layout, const RaySplit& split, const std::uint8_t* result_words,
                    std::uint8_t* blocked) {
  const unsigned word_bytes = layout.word_bits / 8;
  for (std::size_t g = 0; g < layout.groups.size(); ++g) {
    const RayGroup& group = layout.groups[g];
    for (std::uint64_t r = 0; r < split.rays[g]; ++r) {
      const std::uint64_t word = load_word(result_words, split.result_base[g] + r / group.lanes, word_bytes);
      blocked[split.first_ray[g] + r] = static_cast<std::uint8_t>((word >> (r % group.lanes)) & 1);
    }
  }
}

}  // namespace rc::board
