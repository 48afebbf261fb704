// Test scaffolding for the generic TLM parts: a scripted initiator whose SC_THREAD runs a test's
// lambda, and one-call helpers to build payloads. Every test builds its own modules (SystemC
// elaborates once per process, and ctest runs each test in its own process).
#pragma once

#include <cstdint>
#include <functional>
#include <utility>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

namespace rc::tlmx::test {

using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_PS;
using sc_core::SC_US;
using sc_core::SC_ZERO_TIME;

// Runs `script` in an SC_THREAD at time 0, with `out` to talk to whatever it is bound to.
class ScriptedInitiator : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<ScriptedInitiator> out;
  std::function<void(ScriptedInitiator&)> script;

  explicit ScriptedInitiator(const sc_core::sc_module_name& name,
                             std::function<void(ScriptedInitiator&)> body = {})
      : sc_core::sc_module(name), out("out"), script(std::move(body)) {
    SC_HAS_PROCESS(ScriptedInitiator);
    SC_THREAD(run);
  }

  // One b_transport; `delay` is the local time offset in and the annotated completion out.
  tlm::tlm_response_status access(tlm::tlm_command command, std::uint64_t address, void* data,
                                  unsigned int length, sc_time& delay, unsigned char* byte_enable = nullptr,
                                  unsigned int byte_enable_length = 0) {
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

  tlm::tlm_response_status write(std::uint64_t address, void* data, unsigned int length, sc_time& delay) {
    return access(tlm::TLM_WRITE_COMMAND, address, data, length, delay);
  }
  tlm::tlm_response_status read(std::uint64_t address, void* data, unsigned int length, sc_time& delay) {
    return access(tlm::TLM_READ_COMMAND, address, data, length, delay);
  }

  std::uint64_t last_address_seen = 0;  // the payload address after the call (interconnects restore it)
  bool finished = false;                // set when the script has run to the end

 private:
  void run() {
    if (script) script(*this);
    finished = true;
  }
};

}  // namespace rc::tlmx::test
