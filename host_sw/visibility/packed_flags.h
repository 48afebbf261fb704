// Blocked flags (one byte per segment) packed eight to a byte and back, eight at a time: the
// shooter memo and the recordings keep a step's answers as bits. Flag 8k + j is bit j of byte k.
#pragma once

#include <cstdint>
#include <cstring>

namespace rc {

// Bit j set where flags[j] is not zero, for flags[0..7].
inline std::uint8_t pack_flags8(const std::uint8_t* flags) {
  std::uint64_t x;
  std::memcpy(&x, flags, sizeof x);
  // Bit 7 of each byte set where the byte is not zero (the low seven bits plus 0x7f carry into
  // bit 7 unless they are all zero; no carry leaves a byte), then one 0/1 per byte.
  constexpr std::uint64_t low7 = 0x7f7f7f7f7f7f7f7full;
  x = ((((x & low7) + low7) | x) >> 7) & 0x0101010101010101ull;
  // Byte j (0 or 1) times 2^(7 - k) at byte k lands on bit 56 + j when j + k = 7; every product
  // falls on its own bit, so nothing carries.
  return static_cast<std::uint8_t>((x * 0x0102040810204080ull) >> 56);
}

// flags[j] = bit j of `bits` (0 or 1), for flags[0..7].
inline void unpack_flags8(std::uint8_t bits, std::uint8_t* flags) {
  // The byte in every byte, byte j keeping bit j (0 or 2^j); adding 0x7f sets bit 7 exactly where
  // that bit was set, without a carry out of the byte.
  std::uint64_t x = (bits * 0x0101010101010101ull) & 0x8040201008040201ull;
  x = ((x + 0x7f7f7f7f7f7f7f7full) >> 7) & 0x0101010101010101ull;
  std::memcpy(flags, &x, sizeof x);
}

// The set bits of a byte (without the POPCNT instruction, which the baseline x86-64 lacks).
inline unsigned count_flags8(std::uint8_t bits) {
  unsigned v = bits;
  v = v - ((v >> 1) & 0x55u);
  v = (v & 0x33u) + ((v >> 2) & 0x33u);
  return (v + (v >> 4)) & 0x0fu;
}

}  // namespace rc
