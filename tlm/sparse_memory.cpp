#include "tlm/sparse_memory.h"

#include <algorithm>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

namespace rc::tlmx {

SparseMemory::SparseMemory(std::uint64_t capacity, std::uint64_t page_bytes)
    : m_capacity(capacity), m_page_mask(page_bytes - 1), m_page_shift(0) {
  if (page_bytes == 0 || (page_bytes & (page_bytes - 1)) != 0)
    throw std::invalid_argument("SparseMemory: page_bytes = " + std::to_string(page_bytes) +
                                " is not a power of two");
  while ((std::uint64_t{1} << m_page_shift) != page_bytes) ++m_page_shift;
}

std::uint64_t SparseMemory::page_last(std::uint64_t address) const {
  const std::uint64_t start = page_start(address);
  return start + std::min(m_page_mask, m_capacity - 1 - start);  // no overflow: start < capacity
}

std::uint8_t* SparseMemory::page(std::uint64_t address) {
  Page& p = m_pages[page_number(address)];
  if (!p) {
    const std::uint64_t bytes = page_last(address) - page_start(address) + 1;
    // calloc: a page of 128 KiB or more comes from the kernel's zero pages without being cleared.
    p.reset(static_cast<std::uint8_t*>(std::calloc(bytes, 1)));
    if (!p) {
      m_pages.erase(page_number(address));
      throw std::bad_alloc();
    }
  }
  return p.get();
}

const std::uint8_t* SparseMemory::find_page(std::uint64_t address) const {
  const auto it = m_pages.find(page_number(address));
  return it == m_pages.end() ? nullptr : it->second.get();
}

std::uint64_t SparseMemory::in_page(std::uint64_t address, std::uint64_t bytes) const {
  const std::uint64_t after = page_last(address) - address;  // bytes of the page after the first
  return bytes - 1 <= after ? bytes : after + 1;
}

void SparseMemory::read(std::uint64_t address, std::uint8_t* out, std::uint64_t bytes) const {
  while (bytes > 0) {
    const std::uint64_t piece = in_page(address, bytes);
    if (const std::uint8_t* p = find_page(address))
      std::memcpy(out, p + (address - page_start(address)), piece);
    else
      std::memset(out, 0, piece);
    out += piece, address += piece, bytes -= piece;
  }
}

void SparseMemory::write(std::uint64_t address, const std::uint8_t* in, std::uint64_t bytes) {
  while (bytes > 0) {
    const std::uint64_t piece = in_page(address, bytes);
    std::memcpy(page(address) + (address - page_start(address)), in, piece);
    in += piece, address += piece, bytes -= piece;
  }
}

}  // namespace rc::tlmx
