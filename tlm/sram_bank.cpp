#include "tlm/sram_bank.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "tlm/address_map.h"
#include "tlm/no_data_extension.h"
#include "tlm/timing.h"

namespace rc::tlmx {

namespace {
constexpr const char* kSramBankMsgType = "rc/tlmx/SramBank";
}

SramBank::SramBank(const sc_core::sc_module_name& name, const SramBankConfig& config)
    : sc_core::sc_module(name), in("in"), m_config(config), m_memory(config.capacity_bytes, config.page_bytes) {
  if (m_config.capacity_bytes == 0 || m_config.word_bytes == 0 || m_config.cycles_per_word == 0)
    SC_REPORT_ERROR(kSramBankMsgType, "capacity_bytes, word_bytes and cycles_per_word must be positive");
  in.register_b_transport(this, &SramBank::b_transport);
  in.register_transport_dbg(this, &SramBank::transport_dbg);
  in.register_get_direct_mem_ptr(this, &SramBank::get_direct_mem_ptr);
}

sc_core::sc_time SramBank::access_time(tlm::tlm_command command, std::uint64_t address,
                                       std::uint64_t bytes) const {
  const std::uint64_t word = m_config.word_bytes;
  const std::uint64_t words = bytes == 0 ? 0 : (address + bytes - 1) / word - address / word + 1;
  const std::uint64_t latency =
      command == tlm::TLM_WRITE_COMMAND ? m_config.write_latency_cycles : m_config.read_latency_cycles;
  return cycles(latency + words * m_config.cycles_per_word, m_config.clock_period);
}

sc_core::sc_time SramBank::dmi_latency(tlm::tlm_command command) const {
  return access_time(command, 0, m_config.word_bytes);
}

bool SramBank::in_range(std::uint64_t address, std::uint64_t bytes) const {
  // Written so that address + bytes cannot overflow.
  return address <= m_config.capacity_bytes && bytes <= m_config.capacity_bytes - address;
}

void SramBank::check_range(std::uint64_t address, std::uint64_t bytes, const char* what) const {
  if (in_range(address, bytes)) return;
  std::ostringstream msg;
  msg << name() << ": " << what << " of 0x" << std::hex << bytes << " bytes at 0x" << address
      << " is outside the bank (capacity 0x" << m_config.capacity_bytes << ")";
  throw std::out_of_range(msg.str());
}

void SramBank::debug_read(std::uint64_t address, void* out, std::uint64_t bytes) const {
  check_range(address, bytes, "debug_read");
  m_memory.read(address, static_cast<std::uint8_t*>(out), bytes);
}

std::vector<std::uint8_t> SramBank::debug_bytes(std::uint64_t address, std::uint64_t bytes) const {
  check_range(address, bytes, "debug_bytes");
  std::vector<std::uint8_t> out(bytes);
  m_memory.read(address, out.data(), bytes);
  return out;
}

void SramBank::debug_write(std::uint64_t address, const void* data, std::uint64_t bytes) {
  check_range(address, bytes, "debug_write");
  m_memory.write(address, static_cast<const std::uint8_t*>(data), bytes);
}

namespace {
// IEEE 1666-2011 14.14: 0x00 disables a byte, 0xFF enables it, any other value is undefined; a
// byte-enable pointer needs a length. Only the elements the data uses are looked at.
bool byte_enables_valid(const tlm::tlm_generic_payload& trans) {
  const unsigned length = trans.get_byte_enable_length();
  if (length == 0) return false;
  const unsigned char* enables = trans.get_byte_enable_ptr();
  const unsigned used = std::min(length, trans.get_data_length());
  for (unsigned i = 0; i < used; ++i)
    if (enables[i] != TLM_BYTE_DISABLED && enables[i] != TLM_BYTE_ENABLED) return false;
  return true;
}
}  // namespace

// Malformed length first (a read or write of nothing has no address to check), then the address
// (the most useful diagnosis), then the features this simple target does not offer.
tlm::tlm_response_status SramBank::check(const tlm::tlm_generic_payload& trans) {
  if (trans.get_data_length() == 0) {
    ++m_report.rejected;
    return tlm::TLM_BURST_ERROR_RESPONSE;
  }
  if (!in_range(trans.get_address(), bytes_touched(trans))) {
    ++m_report.address_errors;
    std::ostringstream msg;
    msg << name() << ": address 0x" << std::hex << trans.get_address() << " + 0x" << bytes_touched(trans)
        << " bytes is outside the bank (capacity 0x" << m_config.capacity_bytes << ")";
    SC_REPORT_WARNING(kSramBankMsgType, msg.str().c_str());
    return tlm::TLM_ADDRESS_ERROR_RESPONSE;
  }
  if (trans.get_byte_enable_ptr() != nullptr && !byte_enables_valid(trans)) {
    ++m_report.rejected;
    return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
  }
  if (trans.get_streaming_width() < trans.get_data_length()) {
    ++m_report.rejected;
    return tlm::TLM_BURST_ERROR_RESPONSE;
  }
  return tlm::TLM_OK_RESPONSE;
}

void SramBank::copy(tlm::tlm_generic_payload& trans) {
  if (carries_no_data(trans)) return;
  if (trans.get_byte_enable_ptr() != nullptr) return copy_enabled(trans);
  if (trans.is_read())
    m_memory.read(trans.get_address(), trans.get_data_ptr(), trans.get_data_length());
  else
    m_memory.write(trans.get_address(), trans.get_data_ptr(), trans.get_data_length());
}

// Byte i of the data moves only when element i % byte_enable_length is enabled; the pattern
// repeats when it is shorter than the data (14.14). Page by page, so untouched pages read as zeros.
void SramBank::copy_enabled(tlm::tlm_generic_payload& trans) {
  const unsigned char* enables = trans.get_byte_enable_ptr();
  const unsigned pattern = trans.get_byte_enable_length();
  unsigned char* data = trans.get_data_ptr();
  const std::uint64_t first = trans.get_address(), n = trans.get_data_length();
  for (std::uint64_t i = 0; i < n;) {
    const std::uint64_t address = first + i;
    const std::uint64_t run = std::min(n - i, m_memory.page_last(address) - address + 1);
    const std::uint64_t offset = address - m_memory.page_start(address);
    if (trans.is_read()) {
      const std::uint8_t* page = m_memory.find_page(address);
      for (std::uint64_t j = 0; j < run; ++j)
        if (enables[(i + j) % pattern] == TLM_BYTE_ENABLED) data[i + j] = page != nullptr ? page[offset + j] : 0;
    } else {
      std::uint8_t* page = m_memory.page(address);
      for (std::uint64_t j = 0; j < run; ++j)
        if (enables[(i + j) % pattern] == TLM_BYTE_ENABLED) page[offset + j] = data[i + j];
    }
    i += run;
  }
}

void SramBank::count(const tlm::tlm_generic_payload& trans, const sc_core::sc_time& delay) {
  if (trans.is_read()) {
    ++m_report.reads;
    m_report.bytes_read += trans.get_data_length();
  } else {
    ++m_report.writes;
    m_report.bytes_written += trans.get_data_length();
  }
  m_report.busy += delay;
}

void SramBank::b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  if (trans.get_command() == tlm::TLM_IGNORE_COMMAND) {
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
    return;
  }
  const tlm::tlm_response_status status = check(trans);
  trans.set_response_status(status);
  if (status != tlm::TLM_OK_RESPONSE) return;
  copy(trans);
  const sc_core::sc_time taken = access_time(trans.get_command(), trans.get_address(), trans.get_data_length());
  count(trans, taken);
  delay += taken;
  trans.set_dmi_allowed(true);
}

// Debug access: same data, no time, no counters; clipped to the array as the TLM rules ask.
unsigned int SramBank::transport_dbg(tlm::tlm_generic_payload& trans) {
  const std::uint64_t address = trans.get_address();
  if (address >= m_config.capacity_bytes || trans.get_command() == tlm::TLM_IGNORE_COMMAND) return 0;
  const std::uint64_t bytes = std::min<std::uint64_t>(trans.get_data_length(), m_config.capacity_bytes - address);
  if (trans.is_read())
    m_memory.read(address, trans.get_data_ptr(), bytes);
  else
    m_memory.write(address, trans.get_data_ptr(), bytes);
  return static_cast<unsigned int>(bytes);
}

// One page (the only contiguous host memory there is), read and write, with the latency of one
// access; outside the bank, a refusal that says where it holds (header comment).
bool SramBank::get_direct_mem_ptr(tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi) {
  const std::uint64_t address = trans.get_address();
  if (address >= m_config.capacity_bytes) {
    dmi.set_dmi_ptr(nullptr);
    dmi.allow_none();
    dmi.set_start_address(m_config.capacity_bytes);
    dmi.set_end_address(std::numeric_limits<std::uint64_t>::max());
    ++m_report.dmi_refusals;
    return false;
  }
  dmi.set_dmi_ptr(m_memory.page(address));
  dmi.set_start_address(m_memory.page_start(address));
  dmi.set_end_address(m_memory.page_last(address));
  dmi.allow_read_write();
  dmi.set_read_latency(dmi_latency(tlm::TLM_READ_COMMAND));
  dmi.set_write_latency(dmi_latency(tlm::TLM_WRITE_COMMAND));
  ++m_report.dmi_grants;
  return true;
}

void SramBank::record_dmi_access(const DmiActivity& activity) {
  m_report.reads += activity.reads;
  m_report.writes += activity.writes;
  m_report.dmi_reads += activity.reads;
  m_report.dmi_writes += activity.writes;
  m_report.bytes_read += activity.bytes_read;
  m_report.bytes_written += activity.bytes_written;
  m_report.busy += activity.busy;
}

std::string SramBank::summary() const {
  const SramBankReport& r = m_report;
  std::ostringstream out;
  out << name() << ": reads " << r.reads << " (" << r.bytes_read << " B), writes " << r.writes << " ("
      << r.bytes_written << " B), busy " << r.busy << ", address errors " << r.address_errors << ", rejected "
      << r.rejected << ", DMI grants " << r.dmi_grants << ", refusals " << r.dmi_refusals << " (DMI reads "
      << r.dmi_reads << ", writes " << r.dmi_writes << "), pages " << m_memory.pages_allocated() << " of "
      << m_memory.page_bytes() << " B";
  return out.str();
}

void SramBank::end_of_simulation() {
  if (m_config.report_at_end) SC_REPORT_INFO(kSramBankMsgType, summary().c_str());
}

}  // namespace rc::tlmx
