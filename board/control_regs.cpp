#include "board/control_regs.h"

#include <cstring>

#include "tlm/address_map.h"

namespace rc::board {

ControlRegs::ControlRegs(const sc_core::sc_module_name& name, sc_core::sc_time access_time,
                         std::uint32_t config_value)
    : sc_core::sc_module(name), in("in"), m_access_time(access_time) {
  m_regs[reg::kId / 4] = reg::kIdValue;
  m_regs[reg::kConfig / 4] = config_value;
  m_regs[reg::kSourceFace / 4] = reg::kNoFace;
  m_regs[reg::kSourceFaces / 4] = 1;
  in.register_b_transport(this, &ControlRegs::b_transport);
  in.register_transport_dbg(this, &ControlRegs::transport_dbg);
  in.register_get_direct_mem_ptr(this, &ControlRegs::get_direct_mem_ptr);
  SC_HAS_PROCESS(ControlRegs);
  SC_METHOD(acknowledge_now);
  sensitive << m_acknowledge_event;
  dont_initialize();
}

void ControlRegs::acknowledge_now() {
  if (m_acknowledge) m_acknowledge();
}

std::uint32_t ControlRegs::take_start() {
  const StartCommand& oldest = m_starts[m_start_head];
  const std::uint32_t bits = oldest.bits;
  m_pass = oldest.regs;
  m_start_head = (m_start_head + 1) % kStartQueue;
  --m_start_count;
  return bits;
}

void ControlRegs::set_busy(bool busy) {
  std::uint32_t& status = m_regs[reg::kStatus / 4];
  status = busy ? (status | reg::kBusy) : (status & ~reg::kBusy);
}

void ControlRegs::finish_pass(std::uint64_t cycles, std::uint32_t error) {
  std::uint32_t& status = m_regs[reg::kStatus / 4];
  status = (status & ~reg::kBusy) | reg::kDone | (error != reg::kOk ? reg::kError : 0);
  m_regs[reg::kErrorCode / 4] = error;
  m_regs[reg::kPassCyclesLo / 4] = static_cast<std::uint32_t>(cycles);
  m_regs[reg::kPassCyclesHi / 4] = static_cast<std::uint32_t>(cycles >> 32);
  ++m_regs[reg::kPasses / 4];
}

void ControlRegs::write(std::uint64_t offset, std::uint32_t value, const sc_core::sc_time& effective) {
  switch (offset) {
    case reg::kId: case reg::kConfig: case reg::kPassCyclesLo: case reg::kPassCyclesHi:
    case reg::kPasses: case reg::kErrorCode:
      return;  // read-only
    case reg::kControl:
      if (value & reg::kStart) {
        if (m_start_count >= kStartQueue) {
          m_regs[reg::kStatus / 4] |= reg::kError;
          m_regs[reg::kErrorCode / 4] = reg::kStartWhileBusy;
          return;
        }
        m_starts[(m_start_head + m_start_count) % kStartQueue] = {effective, value, m_regs};
        ++m_start_count;
        m_start_event.notify(effective - sc_core::sc_time_stamp());
      }
      return;
    case reg::kStatus: {
      std::uint32_t& status = m_regs[reg::kStatus / 4];
      const std::uint32_t clear = value & (reg::kDone | reg::kError);
      status &= ~clear;
      if ((clear & reg::kDone) && m_acknowledge) {
        // At the access: now for a synced host, later for one running ahead of simulated time.
        if (effective > sc_core::sc_time_stamp()) {
          m_acknowledge_event.notify(effective - sc_core::sc_time_stamp());
        } else {
          m_acknowledge();
        }
      }
      return;
    }
    default:
      m_regs[offset / 4] = value;
  }
}

// The response a transaction gets, in the order of the header's table.
tlm::tlm_response_status ControlRegs::check(const tlm::tlm_generic_payload& trans) {
  const std::uint64_t address = trans.get_address();
  const unsigned length = trans.get_data_length();
  if (trans.get_command() == tlm::TLM_IGNORE_COMMAND) return tlm::TLM_OK_RESPONSE;
  if (length == 0) return tlm::TLM_BURST_ERROR_RESPONSE;  // nothing to address: the length first
  const std::uint64_t touched = tlmx::bytes_touched(trans);  // a streaming burst repeats its first addresses
  if (address % 4 != 0 || address > reg::kBarSize || touched > reg::kBarSize - address)
    return tlm::TLM_ADDRESS_ERROR_RESPONSE;
  if (trans.get_byte_enable_ptr() != nullptr) return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
  if (length % 4 != 0 || trans.get_streaming_width() < length) return tlm::TLM_BURST_ERROR_RESPONSE;
  return tlm::TLM_OK_RESPONSE;
}

// Aligned accesses of whole registers, one or several (a burst writes consecutive registers in
// address order).
void ControlRegs::b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  trans.set_response_status(check(trans));
  if (!trans.is_response_ok() || trans.get_command() == tlm::TLM_IGNORE_COMMAND) return;
  ++m_accesses;
  delay += m_access_time;
  const sc_core::sc_time effective = sc_core::sc_time_stamp() + delay;
  const std::uint64_t address = trans.get_address();
  unsigned char* data = trans.get_data_ptr();
  for (unsigned i = 0; i < trans.get_data_length(); i += 4) {
    const std::uint64_t offset = address + i;
    std::uint32_t v = 0;
    if (trans.is_write()) {
      std::memcpy(&v, data + i, 4);
      if (offset < reg::kSize) write(offset, v, effective);
    } else {
      v = offset < reg::kSize ? m_regs[offset / 4] : 0;
      std::memcpy(data + i, &v, 4);
    }
  }
}

unsigned int ControlRegs::transport_dbg(tlm::tlm_generic_payload& trans) {
  const std::uint64_t address = trans.get_address();
  if (address % 4 != 0 || !trans.is_read()) return 0;
  unsigned done = 0;
  for (; done + 4 <= trans.get_data_length() && address + done < reg::kSize; done += 4) {
    const std::uint32_t v = m_regs[(address + done) / 4];
    std::memcpy(trans.get_data_ptr() + done, &v, 4);
  }
  return done;
}

// Every access must reach b_transport: registers have side effects.
bool ControlRegs::get_direct_mem_ptr(tlm::tlm_generic_payload&, tlm::tlm_dmi& dmi) {
  dmi.set_dmi_ptr(nullptr);
  dmi.allow_none();
  dmi.set_start_address(0);
  dmi.set_end_address(~sc_dt::uint64{0});
  return false;
}

}  // namespace rc::board
