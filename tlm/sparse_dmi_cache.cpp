#include "tlm/sparse_dmi_cache.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include <systemc>

namespace rc::tlmx {

namespace {
constexpr const char* kSparseDmiCacheMsgType = "rc/tlmx/SparseDmiCache";

bool allows(const DmiRegion& r, tlm::tlm_command command) {
  return command == tlm::TLM_WRITE_COMMAND ? r.writable : r.readable;
}

// How many of `bytes` bytes from `address` (inside r) r holds; r.end - address + 1 would wrap for a
// region that ends at 2^64 - 1.
std::uint64_t bytes_held(const DmiRegion& r, std::uint64_t address, std::uint64_t bytes) {
  const std::uint64_t after = r.end - address;  // bytes held after the first
  return bytes - 1 <= after ? bytes : after + 1;
}
}  // namespace

std::uint8_t* SparseDmiCache::pointer_slow(std::uint64_t address, std::uint64_t bytes, tlm::tlm_command command) {
  if (bytes == 0) return nullptr;
  const DmiRegion& r = region(address, command);
  (command == tlm::TLM_WRITE_COMMAND ? m_last_write : m_last_read) = r;
  return r.holds(address, bytes) ? r.data + (address - r.start) : nullptr;
}

void SparseDmiCache::read_pieces(std::uint64_t address, std::uint8_t* out, std::uint64_t bytes) {
  while (bytes > 0) {
    const DmiRegion& r = region(address, tlm::TLM_READ_COMMAND);
    const std::uint64_t piece = bytes_held(r, address, bytes);
    std::memcpy(out, r.data + (address - r.start), piece);
    m_last_read = r;
    out += piece, address += piece, bytes -= piece;
  }
}

void SparseDmiCache::write_pieces(std::uint64_t address, const std::uint8_t* in, std::uint64_t bytes) {
  while (bytes > 0) {
    const DmiRegion& r = region(address, tlm::TLM_WRITE_COMMAND);
    const std::uint64_t piece = bytes_held(r, address, bytes);
    std::memcpy(r.data + (address - r.start), in, piece);
    m_last_write = r;
    in += piece, address += piece, bytes -= piece;
  }
}

const DmiRegion& SparseDmiCache::region(std::uint64_t address, tlm::tlm_command command) {
  // The last region starting at or before the address is the only one that can hold it.
  auto after = std::upper_bound(m_regions.begin(), m_regions.end(), address,
                                [](std::uint64_t a, const DmiRegion& r) { return a < r.start; });
  if (after != m_regions.begin()) {
    const DmiRegion& r = *(after - 1);
    if (r.holds(address, 1) && allows(r, command)) return r;
  }
  return acquire(address, command);
}

const DmiRegion& SparseDmiCache::acquire(std::uint64_t address, tlm::tlm_command command) {
  tlm::tlm_generic_payload trans;
  trans.set_address(address);
  trans.set_command(command);
  tlm::tlm_dmi dmi;  // initialised as the LRM asks: no access, [0, max], zero latencies
  ++m_report.requests;
  const bool granted = m_request(trans, dmi);
  DmiRegion r;
  r.start = dmi.get_start_address();
  r.end = dmi.get_end_address();
  r.data = dmi.get_dmi_ptr();
  r.readable = dmi.is_read_allowed();
  r.writable = dmi.is_write_allowed();
  if (!granted || r.data == nullptr || !r.holds(address, 1) || !allows(r, command)) {
    std::ostringstream msg;
    msg << m_owner << ": no DMI " << (command == tlm::TLM_WRITE_COMMAND ? "write" : "read") << " access at 0x"
        << std::hex << address << (granted ? " (the grant does not cover it)" : " (refused)");
    SC_REPORT_ERROR(kSparseDmiCacheMsgType, msg.str().c_str());
    throw std::runtime_error(msg.str());  // in case errors were set not to throw: never use the region
  }
  // A new grant replaces whatever it overlaps (a target may grant a larger region after an invalidation).
  m_regions.erase(std::remove_if(m_regions.begin(), m_regions.end(),
                                 [&](const DmiRegion& old) { return old.overlaps(r.start, r.end); }),
                  m_regions.end());
  auto at = std::upper_bound(m_regions.begin(), m_regions.end(), r.start,
                             [](std::uint64_t a, const DmiRegion& x) { return a < x.start; });
  return *m_regions.insert(at, r);
}

void SparseDmiCache::invalidate(std::uint64_t start, std::uint64_t end) {
  ++m_report.invalidations;
  const std::size_t before = m_regions.size();
  m_regions.erase(std::remove_if(m_regions.begin(), m_regions.end(),
                                 [&](const DmiRegion& r) { return r.overlaps(start, end); }),
                  m_regions.end());
  m_report.dropped += before - m_regions.size();
  if (m_last_read.overlaps(start, end)) m_last_read = DmiRegion{};
  if (m_last_write.overlaps(start, end)) m_last_write = DmiRegion{};
}

}  // namespace rc::tlmx
