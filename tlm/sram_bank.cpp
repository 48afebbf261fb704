#include "tlm/sram_bank.h"

#include <algorithm>
#include <cstring>
#include <new>
#include <sstream>

#include "tlm/no_data_extension.h"
#include "tlm/timing.h"

namespace rc::tlmx {

namespace {
constexpr const char* kMsgType = "rc/tlmx/SramBank";
}

SramBank::SramBank(const sc_core::sc_module_name& name, const SramBankConfig& config)
    : sc_core::sc_module(name), in("in"), m_config(config) {
  if (m_config.capacity_bytes == 0 || m_config.word_bytes == 0 || m_config.cycles_per_word == 0)
    SC_REPORT_ERROR(kMsgType, "capacity_bytes, word_bytes and cycles_per_word must be positive");
  // Allocated up front (an always-valid array keeps DMI simple) but zeroed lazily (sram_bank.h).
  m_data.reset(static_cast<std::uint8_t*>(std::calloc(m_config.capacity_bytes, 1)));
  if (!m_data && m_config.capacity_bytes != 0) throw std::bad_alloc();
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

bool SramBank::in_range(std::uint64_t address, std::uint64_t bytes) const {
  // Written so that address + bytes cannot overflow.
  return address <= m_config.capacity_bytes && bytes <= m_config.capacity_bytes - address;
}

// Address first (the most useful diagnosis), then the features this simple target does not offer.
tlm::tlm_response_status SramBank::check(const tlm::tlm_generic_payload& trans) {
  if (!in_range(trans.get_address(), trans.get_data_length())) {
    ++m_report.address_errors;
    std::ostringstream msg;
    msg << name() << ": address 0x" << std::hex << trans.get_address() << " + 0x" << trans.get_data_length()
        << " bytes is outside the bank (capacity 0x" << m_config.capacity_bytes << ")";
    SC_REPORT_WARNING(kMsgType, msg.str().c_str());
    return tlm::TLM_ADDRESS_ERROR_RESPONSE;
  }
  if (trans.get_byte_enable_ptr() != nullptr) {
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
  std::uint8_t* cell = m_data.get() + trans.get_address();
  if (trans.is_read())
    std::memcpy(trans.get_data_ptr(), cell, trans.get_data_length());
  else
    std::memcpy(cell, trans.get_data_ptr(), trans.get_data_length());
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
    std::memcpy(trans.get_data_ptr(), m_data.get() + address, bytes);
  else
    std::memcpy(m_data.get() + address, trans.get_data_ptr(), bytes);
  return static_cast<unsigned int>(bytes);
}

// The whole array, read and write. The latencies are per byte of a stream, i.e. the burst rate
// C * P / W, because DMI users stream; the first-word latency is theirs to add once per stream.
bool SramBank::get_direct_mem_ptr(tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi) {
  if (trans.get_address() >= m_config.capacity_bytes) return false;
  dmi.set_dmi_ptr(m_data.get());
  dmi.set_start_address(0);
  dmi.set_end_address(m_config.capacity_bytes - 1);
  dmi.allow_read_write();
  const sc_core::sc_time per_byte = sc_core::sc_time::from_value(
      m_config.clock_period.value() * m_config.cycles_per_word / m_config.word_bytes);
  dmi.set_read_latency(per_byte);
  dmi.set_write_latency(per_byte);
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
      << r.rejected << ", DMI grants " << r.dmi_grants << " (DMI reads " << r.dmi_reads << ", writes "
      << r.dmi_writes << ")";
  return out.str();
}

void SramBank::end_of_simulation() {
  if (m_config.report_at_end) SC_REPORT_INFO(kMsgType, summary().c_str());
}

}  // namespace rc::tlmx
