#include "tlm/irq_line.h"

#include <sstream>

namespace rc::tlmx {

namespace {
constexpr const char* kIrqLineMsgType = "rc/tlmx/IrqLine";
}

IrqLine::IrqLine(const sc_core::sc_module_name& name, const IrqLineConfig& config)
    : sc_core::sc_module(name), m_config(config) {
  SC_HAS_PROCESS(IrqLine);
  SC_METHOD(deliver);
  sensitive << m_in_flight;
  dont_initialize();
}

void IrqLine::raise(const sc_core::sc_time& offset) {
  if (m_device_level) return;
  m_device_level = true;
  ++m_report.raises;
  m_in_flight.notify(offset + m_config.latency);
}

void IrqLine::lower() {
  if (!m_device_level) return;
  m_device_level = false;
  m_host_level = false;
  m_in_flight.cancel();
  ++m_report.lowers;
}

void IrqLine::deliver() {
  m_host_level = true;
  ++m_report.delivered;
  m_host_raised.notify();  // immediate: waiting threads run in this same time step
}

void IrqLine::wait_raised() {
  if (m_host_level) return;
  ++m_report.host_waits;
  while (!m_host_level) sc_core::wait(m_host_raised);
}

void IrqLine::wait_raised_ahead(const sc_core::sc_time& ahead) {
  if (ahead == sc_core::SC_ZERO_TIME || m_host_level || m_device_level) {  // a synced host's way
    sc_core::wait(ahead);  // zero: one delta cycle, as a quantum keeper's sync takes
    return wait_raised();
  }
  const sc_core::sc_time at = sc_core::sc_time_stamp() + ahead;
  while (!m_host_level) sc_core::wait(m_host_raised);  // nothing is on its way: no rise before the device's
  if (sc_core::sc_time_stamp() > at) {  // low all the way to the host's time: a synced host blocked there
    ++m_report.host_waits;
    return;
  }
  if (sc_core::sc_time_stamp() < at) sc_core::wait(at - sc_core::sc_time_stamp());
  wait_raised();  // at the host's time, as a synced host looks (the device may have lowered it meanwhile)
}

std::string IrqLine::summary() const {
  std::ostringstream out;
  out << name() << ": raises " << m_report.raises << ", lowers " << m_report.lowers << ", delivered "
      << m_report.delivered << ", host waits " << m_report.host_waits;
  return out.str();
}

void IrqLine::end_of_simulation() {
  if (m_config.report_at_end) SC_REPORT_INFO(kIrqLineMsgType, summary().c_str());
}

}  // namespace rc::tlmx
