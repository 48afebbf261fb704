#include "tlm/address_map.h"

#include <algorithm>
#include <stdexcept>

namespace rc::tlmx {

namespace {
// Last address of a window; windows are checked not to wrap, so this cannot overflow.
std::uint64_t last(const AddressWindow& w) { return w.base + (w.size - 1); }
}  // namespace

void AddressMap::add(const AddressWindow& window) {
  if (window.size == 0) throw std::invalid_argument("address window '" + window.name + "' is empty");
  if (window.base > UINT64_MAX - (window.size - 1))
    throw std::invalid_argument("address window '" + window.name + "' wraps past the end of the address space");
  for (const AddressWindow& other : m_windows) {
    if (window.base <= last(other) && other.base <= last(window))
      throw std::invalid_argument("address window '" + window.name + "' overlaps '" + other.name + "'");
  }
  m_windows.push_back(window);
}

// Windows do not overlap, so the one that holds the address is the answer wherever the search
// starts: the last hit is tried first (a bus's traffic mostly goes to one window after another).
std::optional<Decoded> AddressMap::decode(std::uint64_t address, std::uint64_t bytes) const {
  auto hit = [&](const AddressWindow& w) -> std::optional<Decoded> {
    const std::uint64_t offset = address - w.base;
    if (bytes > w.size - offset) return std::nullopt;  // straddles the end of the window
    return Decoded{&w, offset};
  };
  if (m_last < m_windows.size()) {
    const AddressWindow& w = m_windows[m_last];
    if (address >= w.base && address <= last(w)) return hit(w);
  }
  for (std::size_t i = 0; i < m_windows.size(); ++i) {
    const AddressWindow& w = m_windows[i];
    if (address < w.base || address > last(w)) continue;
    m_last = i;
    return hit(w);
  }
  return std::nullopt;
}

std::optional<AddressMap::Gap> AddressMap::gap(std::uint64_t address) const {
  Gap g{0, UINT64_MAX};
  for (const AddressWindow& w : m_windows) {
    if (w.base > address) {
      g.last = std::min(g.last, w.base - 1);
    } else if (last(w) < address) {
      g.first = std::max(g.first, last(w) + 1);
    } else {
      return std::nullopt;  // mapped
    }
  }
  return g;
}

}  // namespace rc::tlmx
