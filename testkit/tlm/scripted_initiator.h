// The timing test kit's generic initiator (rc2000tlm::testkit_tlm, also in rc2000tlm::testkit): a
// module whose SC_THREAD runs a test's script from time 0 with a TLM-2.0 initiator socket, for tests
// of the tlm/ parts (a bank, the PCI bus, a router) without the board. Each access is one
// b_transport with the caller's local time offset in and the annotated completion out; the script
// decides when to wait. Pair it with testkit/main (one SystemC test per process).
#pragma once

#include <cstdint>
#include <functional>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

namespace rc::testkit {

class ScriptedInitiator : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<ScriptedInitiator> out;
  std::function<void(ScriptedInitiator&)> script;

  explicit ScriptedInitiator(const sc_core::sc_module_name& name, std::function<void(ScriptedInitiator&)> body = {});

  // One b_transport; `delay` is the local time offset in and the annotated completion out.
  tlm::tlm_response_status access(tlm::tlm_command command, std::uint64_t address, void* data, unsigned int length,
                                  sc_core::sc_time& delay, unsigned char* byte_enable = nullptr,
                                  unsigned int byte_enable_length = 0);
  tlm::tlm_response_status write(std::uint64_t address, void* data, unsigned int length, sc_core::sc_time& delay) {
    return access(tlm::TLM_WRITE_COMMAND, address, data, length, delay);
  }
  tlm::tlm_response_status read(std::uint64_t address, void* data, unsigned int length, sc_core::sc_time& delay) {
    return access(tlm::TLM_READ_COMMAND, address, data, length, delay);
  }

  std::uint64_t last_address_seen = 0;  // the payload address after the call (interconnects restore it)
  bool finished = false;                // set when the script has run to the end

 private:
  void run();
};

}  // namespace rc::testkit
