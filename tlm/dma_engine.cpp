#include "tlm/dma_engine.h"

#include <algorithm>
#include <sstream>

#include <tlm_utils/tlm_quantumkeeper.h>

namespace rc::tlmx {

namespace {
constexpr const char* kDmaEngineMsgType = "rc/tlmx/DmaEngine";
}

DmaEngine::DmaEngine(const sc_core::sc_module_name& name, const DmaConfig& config)
    : sc_core::sc_module(name), out("out"), m_config(config) {
  if (m_config.burst_bytes == 0 || m_config.burst_bytes > UINT32_MAX)
    SC_REPORT_ERROR(kDmaEngineMsgType, "burst_bytes must be in [1, 2^32)");  // a payload length is 32-bit
  SC_HAS_PROCESS(DmaEngine);
  SC_THREAD(worker);
}

DmaResult DmaEngine::transfer(DmaDirection direction, void* host, std::uint64_t device_address,
                              std::uint64_t bytes) {
  return transfer(DmaRequest{direction, host, device_address, bytes});
}

// One bus transaction of the request, starting `done` bytes in, issued at local time offset `local`.
tlm::tlm_response_status DmaEngine::burst(tlm::tlm_generic_payload& trans, const DmaRequest& request,
                                          std::uint64_t done, sc_core::sc_time& local) {
  const auto length = static_cast<unsigned int>(std::min(m_config.burst_bytes, request.bytes - done));
  trans.set_command(request.direction == DmaDirection::to_device ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND);
  trans.set_address(request.device_address + done);
  trans.set_data_ptr(static_cast<unsigned char*>(request.host) + done);
  trans.set_data_length(length);
  trans.set_streaming_width(length);
  trans.set_byte_enable_ptr(nullptr);
  trans.set_dmi_allowed(false);
  trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  out->b_transport(trans, local);
  ++m_report.bursts;
  return trans.get_response_status();
}

template <class Sync>
DmaResult DmaEngine::run_bursts(tlm::tlm_generic_payload& trans, const DmaRequest& request, sc_core::sc_time& local,
                                Sync&& sync) {
  if (request.host == nullptr && request.bytes != 0) SC_REPORT_ERROR(kDmaEngineMsgType, "transfer without a host buffer");
  if (request.no_data) trans.set_extension(&m_no_data);
  DmaResult result;
  result.start = sc_core::sc_time_stamp() + local;
  result.status = tlm::TLM_OK_RESPONSE;
  while (result.bytes_done < request.bytes) {  // zero bytes: no burst, done at once
    result.status = burst(trans, request, result.bytes_done, local);
    if (result.status != tlm::TLM_OK_RESPONSE) break;
    result.bytes_done += trans.get_data_length();
    sync(local);
  }
  if (request.no_data) trans.clear_extension(&m_no_data);  // the payload must not free it
  return result;
}

DmaResult DmaEngine::transfer(const DmaRequest& request) {
  tlm_utils::tlm_quantumkeeper keeper;  // per call: transfer() may run in several threads at once
  keeper.reset();
  sc_core::sc_time local = sc_core::SC_ZERO_TIME;
  tlm::tlm_generic_payload trans;  // per call too: the keeper's syncs let other threads in
  DmaResult result = run_bursts(trans, request, local, [&](sc_core::sc_time& t) {
    keeper.set(t);
    if (keeper.need_sync()) keeper.sync();
    t = keeper.get_local_time();
  });
  keeper.set(local);
  keeper.sync();
  result.end = sc_core::sc_time_stamp();
  count(request, result);
  return result;
}

DmaResult DmaEngine::transfer(const DmaRequest& request, sc_core::sc_time& local) {
  // Nothing waits until it returns, so one payload serves every decoupled call (constructing one
  // allocates its extension array).
  DmaResult result = run_bursts(m_decoupled_trans, request, local, [](sc_core::sc_time&) {});
  result.end = sc_core::sc_time_stamp() + local;
  count(request, result);
  return result;
}

void DmaEngine::start(const DmaRequest& request) {
  m_queue.push_back(request);
  m_kick.notify(sc_core::SC_ZERO_TIME);
}

void DmaEngine::worker() {
  for (;;) {
    while (m_queue.empty()) wait(m_kick);
    m_worker_busy = true;
    const DmaRequest request = m_queue.front();
    m_queue.pop_front();
    m_last = transfer(request);
    m_worker_busy = false;
    m_done.notify(sc_core::SC_ZERO_TIME);
  }
}

void DmaEngine::count(const DmaRequest& request, const DmaResult& result) {
  ++m_report.transfers;
  m_report.busy += result.duration();
  if (!result.ok()) ++m_report.errors;
  if (request.direction == DmaDirection::to_device)
    m_report.bytes_to_device += result.bytes_done;
  else
    m_report.bytes_to_host += result.bytes_done;
}

std::string DmaEngine::summary() const {
  const DmaReport& r = m_report;
  std::ostringstream text;
  text << name() << ": " << r.transfers << " transfers in " << r.bursts << " bursts, " << r.bytes_to_device
      << " B to device, " << r.bytes_to_host << " B to host, busy " << r.busy << ", errors " << r.errors;
  return text.str();
}

void DmaEngine::end_of_simulation() {
  if (m_config.report_at_end) SC_REPORT_INFO(kDmaEngineMsgType, summary().c_str());
}

}  // namespace rc::tlmx
