// Address decoding shared by the interconnects (PciBus, Router): a set of non-overlapping windows,
// each mapping [base, base + size) to one output port. A target behind a window sees addresses
// relative to the window base, as a BAR-mapped PCI resource does.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <tlm>

namespace rc::tlmx {

struct AddressWindow {
  std::uint64_t base = 0;
  std::uint64_t size = 0;  // bytes, > 0
  unsigned port = 0;       // index of the output socket binding (binding order, from 0)
  std::string name;        // for messages and reports
};

struct Decoded {
  const AddressWindow* window = nullptr;  // into AddressMap::windows(); valid until the next add()
  std::uint64_t offset = 0;  // address - window->base
};

// A read or write of 0 bytes. The base protocol has none (IEEE 1666-2011 14.12: an initiator moves
// zero bytes with TLM_IGNORE_COMMAND), so every part answers it TLM_BURST_ERROR_RESPONSE, the
// status for a data length a target cannot act on (14.17), with no time and no effect; the
// interconnects do so before decoding, as the banks check the length before the address.
inline bool zero_length_transfer(const tlm::tlm_generic_payload& trans) {
  return trans.get_data_length() == 0 && trans.get_command() != tlm::TLM_IGNORE_COMMAND;
}

// The bytes a transaction's addresses span: [address, address + bytes_touched). A streaming burst
// (streaming width w below the data length, IEEE 1666-2011 14.15) repeats the addresses
// [address, address + w) and touches no other; otherwise it is the data length. Every part decodes by
// this (a FIFO register at the end of a window is reached by a long burst). A streaming width of 0
// is outside the payload rules (14.15); it is decoded as no streaming, and targets refuse it.
inline std::uint64_t bytes_touched(const tlm::tlm_generic_payload& trans) {
  const unsigned int width = trans.get_streaming_width();
  return width != 0 && width < trans.get_data_length() ? width : trans.get_data_length();
}

class AddressMap {
 public:
  // Adds a window; throws std::invalid_argument if it is empty, wraps past 2^64, or overlaps one
  // already mapped (an ambiguous decode is a configuration bug, never a run-time choice).
  void add(const AddressWindow& window);

  // The window holding all of [address, address + bytes), if any. An access that straddles a window
  // edge does not decode: it would otherwise reach two targets with one transaction.
  std::optional<Decoded> decode(std::uint64_t address, std::uint64_t bytes) const;

  // The unmapped range around an address that no window holds: [first, last], bounded by the
  // neighbouring windows (or by 0 and 2^64 - 1). Nothing if a window holds the address. An
  // interconnect refusing DMI there states this range, so the initiator need not ask again inside it.
  struct Gap {
    std::uint64_t first = 0;
    std::uint64_t last = 0;
  };
  std::optional<Gap> gap(std::uint64_t address) const;

  const std::vector<AddressWindow>& windows() const { return m_windows; }

 private:
  std::vector<AddressWindow> m_windows;
  // The window of the last decode, tried first. A cache only (any start finds the same window); an
  // AddressMap belongs to one interconnect of one simulation, never shared between threads.
  mutable std::size_t m_last = 0;
};

}  // namespace rc::tlmx
