#include "testkit/scripted_host.h"

#include <gtest/gtest.h>

#include <utility>

namespace rc::testkit {

ScriptedHost::ScriptedHost(const sc_core::sc_module_name& name, board::Rc2000& board,
                           std::function<void(ScriptedHost&)> body)
    : sc_core::sc_module(name), out("out"), script(std::move(body)), m_board(board) {
  out.bind(board.pci.in);
  SC_HAS_PROCESS(ScriptedHost);
  SC_THREAD(run);
}

bool ScriptedHost::transport(tlm::tlm_command command, std::uint64_t offset, std::uint32_t* values,
                             std::size_t count, sc_core::sc_time& delay) {
  tlm::tlm_generic_payload t;
  const auto n = static_cast<unsigned>(count * 4);
  t.set_command(command);
  t.set_address(board::Rc2000::kBar0 + offset);
  t.set_data_ptr(reinterpret_cast<unsigned char*>(values));
  t.set_data_length(n);
  t.set_streaming_width(n);
  t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  out->b_transport(t, delay);
  if (t.is_response_ok()) return true;
  ADD_FAILURE() << "register access at BAR0 + " << offset << ": " << t.get_response_string();
  return false;
}

void ScriptedHost::write(std::uint64_t offset, std::vector<std::uint32_t> values) {
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  transport(tlm::TLM_WRITE_COMMAND, offset, values.data(), values.size(), delay);
  sc_core::wait(delay);
}

std::uint32_t ScriptedHost::read(std::uint64_t offset) {
  std::uint32_t value = 0;
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  transport(tlm::TLM_READ_COMMAND, offset, &value, 1, delay);
  sc_core::wait(delay);
  return value;
}

sc_core::sc_time ScriptedHost::write_ahead(std::uint64_t offset, std::vector<std::uint32_t> values,
                                           sc_core::sc_time local) {
  transport(tlm::TLM_WRITE_COMMAND, offset, values.data(), values.size(), local);
  return local;
}

void ScriptedHost::dma(tlmx::DmaDirection direction, std::uint8_t* data, unsigned bank, std::uint64_t bytes) {
  if (bytes == 0) return;
  const tlmx::DmaResult r = m_board.dma.transfer(direction, data, m_board.bank_pci_address(bank), bytes);
  if (!r.ok()) ADD_FAILURE() << "DMA of " << bytes << " bytes with bank " << bank << " failed";
}

void ScriptedHost::run() {
  script(*this);
  finished = true;
}

void run_until_finished(const std::vector<const ScriptedHost*>& hosts, sc_core::sc_time step) {
  auto all = [&] {
    for (const ScriptedHost* h : hosts)
      if (!h->finished) return false;
    return true;
  };
  while (!all()) sc_core::sc_start(step);
  sc_core::sc_stop();
}

}  // namespace rc::testkit
