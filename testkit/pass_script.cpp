#include "testkit/pass_script.h"

#include <gtest/gtest.h>

#include "board/register_map.h"

namespace rc::testkit {

std::vector<std::uint8_t> expected_blocked(const PassData& d, int bits) {
  std::vector<std::uint8_t> blocked(d.ends.size(), 0);
  for (std::size_t r = 0; r < d.ends.size(); ++r)
    for (std::size_t f = 0; f < d.faces.size(); ++f)
      if (static_cast<int>(f) != d.source_face && static_cast<int>(f) != d.end_faces[r])
        blocked[r] |= pipeline::segment_hits(d.faces[f], d.start, d.ends[r], bits);
  return blocked;
}

board::RaySplit load_pass(board::Rc2000& b, const PassData& d) {
  const board::BankLayout& L = b.layout();
  const unsigned wb = L.word_bits / 8;
  auto put = [&](unsigned bank, std::uint64_t word, std::uint64_t value) {
    std::uint8_t bytes[8];
    board::store_word(bytes, 0, wb, value);
    b.bank(bank).debug_write(word * wb, bytes, wb);
  };
  std::uint64_t words[9];
  for (std::size_t f = 0; f < d.faces.size(); ++f) {
    board::face_record_words(d.faces[f], words);
    for (unsigned i = 0; i < 9; ++i) put(L.face_bank, f * 9 + i, words[i]);
  }
  const unsigned mask_bank = L.mask_bank ? *L.mask_bank : L.face_bank;
  const std::uint64_t mask_first = L.mask_bank ? 0 : d.faces.size() * 9;
  for (std::size_t f = 0; f < d.faces.size(); ++f) {
    std::uint64_t n = 0;
    for (int e : d.end_faces) n += e == static_cast<int>(f);
    put(mask_bank, mask_first + f, n);
  }
  std::vector<std::int64_t> x, y, z;
  for (const auto& e : d.ends) x.push_back(e.x), y.push_back(e.y), z.push_back(e.z);
  const board::RaySplit split = board::split_rays(L, d.ends.size());
  std::vector<std::vector<std::uint8_t>> images;
  board::pack_rays(L, split, x.data(), y.data(), z.data(), images);
  for (unsigned bank = 0; bank < images.size(); ++bank)
    if (!images[bank].empty()) b.bank(bank).debug_write(0, images[bank].data(), images[bank].size());
  return split;
}

std::vector<std::uint8_t> run_pass(ScriptedHost& host, const PassData& d, bool clear) {
  namespace reg = board::reg;
  board::Rc2000& b = host.board();
  const board::RaySplit split = load_pass(b, d);
  std::uint32_t before = 0;
  for (int e : d.end_faces) before += e < 0 ? 1 : 0;  // rays "ending" before face 0
  host.write(reg::kRayCount, {static_cast<std::uint32_t>(d.ends.size()), static_cast<std::uint32_t>(d.faces.size()), 0,
                              d.source_face < 0 ? reg::kNoFace : static_cast<std::uint32_t>(d.source_face),
                              static_cast<std::uint32_t>(d.start.x), static_cast<std::uint32_t>(d.start.y),
                              static_cast<std::uint32_t>(d.start.z), before});
  host.write(reg::kControl, {reg::kStart | (clear ? reg::kClear : 0u)});
  b.irq.wait_raised();
  EXPECT_EQ(host.read(reg::kStatus) & (reg::kDone | reg::kError), reg::kDone);
  host.write(reg::kStatus, {reg::kDone});
  std::vector<std::uint8_t> blocked(d.ends.size(), 0);
  const std::vector<std::uint8_t> words =
      b.bank(b.layout().result_bank).debug_bytes(0, split.result_words * (b.layout().word_bits / 8));
  board::unpack_results(b.layout(), split, words.data(), blocked.data());
  return blocked;
}

}  // namespace rc::testkit
