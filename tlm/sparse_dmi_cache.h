// An initiator's cache of the DMI regions a target has granted, for targets that grant DMI piece by
// piece: a sparse memory (SramBank) can only hand out host memory that is contiguous, so it grants
// one page of its storage per get_direct_mem_ptr call, and an initiator streaming through a bank
// collects the pages it touches here.
//
// - read / write of n bytes at an address: straight through the region of the last read (write) when
//   it holds all n bytes (the hot path: one range check and a memcpy); otherwise the region is looked
//   up among those cached (binary search) or, on a miss, requested through `request` (the
//   initiator's socket, so the request goes through the interconnect and comes back in the
//   initiator's addresses), and bytes that straddle regions (a word across two pages) are split
//   between them. read_pointer / write_pointer give the host address itself when one region holds
//   all the bytes, for callers that want to load a word in place.
// - invalidate(start, end) drops exactly the cached regions that overlap [start, end] (inclusive, as
//   tlm_bw_direct_mem_if::invalidate_direct_mem_ptr gives it); the next access to them asks again.
// - A refused request, or a grant that does not hold the address or lacks the access asked for, is
//   an SC_REPORT_ERROR naming the owner and the address: the initiator has no other path to the data.
//
// The cache keeps every region granted and not invalidated: as many as the target has pages touched
// by this initiator, which the target's storage already pays for many times over.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <tlm>

namespace rc::tlmx {

// A granted region in the initiator's addresses, [start, end] inclusive.
struct DmiRegion {
  std::uint64_t start = 1, end = 0;  // empty until set
  std::uint8_t* data = nullptr;      // the byte at `start`
  bool readable = false, writable = false;

  // All of [address, address + bytes) inside the region (bytes >= 1; overflow-safe).
  bool holds(std::uint64_t address, std::uint64_t bytes) const {
    return address >= start && address <= end && bytes - 1 <= end - address;
  }
  bool overlaps(std::uint64_t first, std::uint64_t last) const { return start <= last && first <= end; }
};

struct SparseDmiCacheReport {
  std::uint64_t requests = 0;       // get_direct_mem_ptr calls made (misses)
  std::uint64_t invalidations = 0;  // invalidate() calls
  std::uint64_t dropped = 0;        // regions dropped by them
};

class SparseDmiCache {
 public:
  // Fills `dmi` for the payload's address and command; true when granted (get_direct_mem_ptr).
  using Request = std::function<bool(tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi)>;

  SparseDmiCache(std::string owner, Request request) : m_owner(std::move(owner)), m_request(std::move(request)) {}

  // The `bytes` bytes at `address` in host memory, when one region holds them all (looked up or
  // requested as needed); nullptr when they straddle two regions (then use read / write).
  const std::uint8_t* read_pointer(std::uint64_t address, std::uint64_t bytes) {
    if (m_last_read.holds(address, bytes)) return m_last_read.data + (address - m_last_read.start);
    return pointer_slow(address, bytes, tlm::TLM_READ_COMMAND);
  }
  std::uint8_t* write_pointer(std::uint64_t address, std::uint64_t bytes) {
    if (m_last_write.holds(address, bytes)) return m_last_write.data + (address - m_last_write.start);
    return pointer_slow(address, bytes, tlm::TLM_WRITE_COMMAND);
  }

  // Any bytes, across regions if need be.
  void read(std::uint64_t address, void* out, std::uint64_t bytes) {
    if (const std::uint8_t* p = read_pointer(address, bytes)) {
      std::memcpy(out, p, bytes);
      return;
    }
    read_pieces(address, static_cast<std::uint8_t*>(out), bytes);
  }
  void write(std::uint64_t address, const void* in, std::uint64_t bytes) {
    if (std::uint8_t* p = write_pointer(address, bytes)) {
      std::memcpy(p, in, bytes);
      return;
    }
    write_pieces(address, static_cast<const std::uint8_t*>(in), bytes);
  }

  // Drops every cached region overlapping [start, end].
  void invalidate(std::uint64_t start, std::uint64_t end);

  const std::vector<DmiRegion>& regions() const { return m_regions; }  // sorted by start, disjoint
  const SparseDmiCacheReport& report() const { return m_report; }

 private:
  std::uint8_t* pointer_slow(std::uint64_t address, std::uint64_t bytes, tlm::tlm_command command);
  void read_pieces(std::uint64_t address, std::uint8_t* out, std::uint64_t bytes);
  void write_pieces(std::uint64_t address, const std::uint8_t* in, std::uint64_t bytes);
  // The region holding `address` with the access `command` needs, from the cache or requested.
  const DmiRegion& region(std::uint64_t address, tlm::tlm_command command);
  const DmiRegion& acquire(std::uint64_t address, tlm::tlm_command command);

  std::string m_owner;
  Request m_request;
  std::vector<DmiRegion> m_regions;
  // Copies of the regions of the last read and the last write: the hot path touches nothing else.
  DmiRegion m_last_read, m_last_write;
  SparseDmiCacheReport m_report;
};

}  // namespace rc::tlmx
