#include "testkit/tlm/scripted_initiator.h"

#include <utility>

namespace rc::testkit {

ScriptedInitiator::ScriptedInitiator(const sc_core::sc_module_name& name, std::function<void(ScriptedInitiator&)> body)
    : sc_core::sc_module(name), out("out"), script(std::move(body)) {
  SC_HAS_PROCESS(ScriptedInitiator);
  SC_THREAD(run);
}

tlm::tlm_response_status ScriptedInitiator::access(tlm::tlm_command command, std::uint64_t address, void* data,
                                                   unsigned int length, sc_core::sc_time& delay,
                                                   unsigned char* byte_enable, unsigned int byte_enable_length) {
  tlm::tlm_generic_payload trans;
  trans.set_command(command);
  trans.set_address(address);
  trans.set_data_ptr(static_cast<unsigned char*>(data));
  trans.set_data_length(length);
  trans.set_streaming_width(length);
  trans.set_byte_enable_ptr(byte_enable);
  trans.set_byte_enable_length(byte_enable_length);
  trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  out->b_transport(trans, delay);
  last_address_seen = trans.get_address();
  return trans.get_response_status();
}

void ScriptedInitiator::run() {
  if (script) script(*this);
  finished = true;
}

}  // namespace rc::testkit
