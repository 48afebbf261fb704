// Byte storage of any capacity up to 2^64 - 1 bytes that costs memory only where it has been touched:
// fixed-size pages, allocated zeroed on first touch (a write, or page() for a DMI grant), found
// through a hash map keyed by page number, so the table too is O(pages touched), never O(capacity).
// Reading untouched memory gives zeros and allocates nothing. Pages never move and are never freed
// while the store lives, so a page pointer stays valid (what DMI needs).
//
// The last page is cut at the capacity: a 4 KiB store with 64 KiB pages allocates 4 KiB.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <unordered_map>

namespace rc::tlmx {

class SparseMemory {
 public:
  // page_bytes must be a power of two (std::invalid_argument otherwise). Any capacity, 0 included.
  SparseMemory(std::uint64_t capacity, std::uint64_t page_bytes);

  std::uint64_t capacity() const { return m_capacity; }
  std::uint64_t page_bytes() const { return m_page_mask + 1; }
  std::uint64_t pages_allocated() const { return m_pages.size(); }

  // The page holding `address` (< capacity): its first address and its last (cut at the capacity).
  std::uint64_t page_start(std::uint64_t address) const { return address & ~m_page_mask; }
  std::uint64_t page_last(std::uint64_t address) const;

  // The first byte of the page holding `address` (< capacity), allocated zeroed if untouched.
  std::uint8_t* page(std::uint64_t address);
  // The same, or nullptr when the page has never been touched; allocates nothing.
  const std::uint8_t* find_page(std::uint64_t address) const;

  // Copies of [address, address + bytes), which the caller has checked lies inside the capacity.
  // read gives zeros for untouched pages; write allocates the pages it touches.
  void read(std::uint64_t address, std::uint8_t* out, std::uint64_t bytes) const;
  void write(std::uint64_t address, const std::uint8_t* in, std::uint64_t bytes);

 private:
  struct FreeBytes {
    void operator()(std::uint8_t* p) const { std::free(p); }
  };
  using Page = std::unique_ptr<std::uint8_t, FreeBytes>;

  std::uint64_t page_number(std::uint64_t address) const { return address >> m_page_shift; }
  // Bytes of [address, address + bytes) that lie in address's page.
  std::uint64_t in_page(std::uint64_t address, std::uint64_t bytes) const;

  std::uint64_t m_capacity;
  std::uint64_t m_page_mask;
  unsigned m_page_shift;
  std::unordered_map<std::uint64_t, Page> m_pages;  // page number -> page
};

}  // namespace rc::tlmx
