// A user's own platform built from the installed parts rather than the whole board: one PCI bus
// (tlm/pci_bus.h) with one SRAM bank (tlm/sram_bank.h) behind a BAR window, and this file's own TLM
// initiator. It writes a pattern, reads it back, makes a two-burst write and touches an unmapped
// address, checking the data and every completion time, exactly, against the times worked out by
// hand below from the two headers' formulas. Exits 1 on any mismatch.
//
// 64-bit PCI at 15 ns (66 MHz), setup 8 cycles, 4 KiB bursts; bank of 32-bit words at 10 ns,
// latency 2. The bus is held for max(bus time, bank time) (pci_bus.h, "occupancy"):
//   256 B write:  bus (8 + 32) * 15 = 600 ns,  bank (2 + 64) * 10 = 660 ns   -> 660 ns, done at 660 ns
//   256 B read:   the same                                                  -> 660 ns, done at 1320 ns
//   8 KiB write:  bus 2 * (8 + 512) * 15 = 15600 ns, bank (2 + 2048) * 10 = 20500 ns -> done at 21820 ns
//   unmapped:     master abort, 6 * 15 = 90 ns, TLM_ADDRESS_ERROR_RESPONSE   -> done at 21910 ns
#include <cstdint>
#include <cstdio>
#include <vector>

#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>

#include "tlm/pci_bus.h"
#include "tlm/sram_bank.h"

namespace {

using sc_core::sc_time;
using sc_core::SC_NS;

constexpr std::uint64_t kBar = 0x8000'0000;

int g_failures = 0;
template <class T>
void check(const char* what, const T& got, const T& want) {
  if (got == want) return;
  ++g_failures;
  std::fprintf(stderr, "MISMATCH %s\n", what);
}

class Initiator : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<Initiator> out{"out"};
  std::vector<sc_time> done;  // simulated time after each access
  std::vector<tlm::tlm_response_status> status;
  std::vector<std::uint8_t> pattern, back;

  explicit Initiator(const sc_core::sc_module_name& name) : sc_core::sc_module(name) {
    SC_HAS_PROCESS(Initiator);
    SC_THREAD(run);
  }

 private:
  void access(tlm::tlm_command command, std::uint64_t address, std::uint8_t* data, unsigned bytes) {
    tlm::tlm_generic_payload t;
    t.set_command(command);
    t.set_address(address);
    t.set_data_ptr(data);
    t.set_data_length(bytes);
    t.set_streaming_width(bytes);
    t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_time delay = sc_core::SC_ZERO_TIME;
    out->b_transport(t, delay);
    sc_core::wait(delay);
    done.push_back(sc_core::sc_time_stamp());
    status.push_back(t.get_response_status());
  }
  void run() {
    pattern.resize(256);
    for (std::size_t i = 0; i < pattern.size(); ++i) pattern[i] = static_cast<std::uint8_t>(i * 37 + 11);
    back.assign(pattern.size(), 0);
    access(tlm::TLM_WRITE_COMMAND, kBar + 0x100, pattern.data(), 256);
    access(tlm::TLM_READ_COMMAND, kBar + 0x100, back.data(), 256);
    std::vector<std::uint8_t> big(8192, 0x5A);
    access(tlm::TLM_WRITE_COMMAND, kBar + 0x1000, big.data(), 8192);
    std::uint8_t word[4] = {};
    access(tlm::TLM_WRITE_COMMAND, 0x1000, word, 4);  // below the window: nobody answers
  }
};

}  // namespace

int sc_main(int, char**) {
  rc::tlmx::PciBusConfig bus_config;
  bus_config.width_bits = 64;
  bus_config.clock_period = sc_time(15, SC_NS);
  bus_config.setup_cycles = 8;
  bus_config.max_burst_bytes = 4096;
  bus_config.report_at_end = false;
  rc::tlmx::SramBankConfig bank_config;
  bank_config.capacity_bytes = 1u << 20;
  bank_config.report_at_end = false;

  rc::tlmx::PciBus bus("pci", bus_config);
  rc::tlmx::SramBank bank("bank", bank_config);
  Initiator host("host");
  host.out.bind(bus.in);
  bus.out.bind(bank.in);
  bus.map(kBar, bank.capacity(), 0, "bank");
  sc_core::sc_start();

  check("completion times", host.done,
        std::vector<sc_time>{sc_time(660, SC_NS), sc_time(1320, SC_NS), sc_time(21820, SC_NS), sc_time(21910, SC_NS)});
  check("responses", host.status,
        std::vector<tlm::tlm_response_status>{tlm::TLM_OK_RESPONSE, tlm::TLM_OK_RESPONSE, tlm::TLM_OK_RESPONSE,
                                              tlm::TLM_ADDRESS_ERROR_RESPONSE});
  check("data read back", host.back, host.pattern);
  check("bank holds the pattern", bank.debug_bytes(0x100, 256), host.pattern);
  check("bank holds the 8 KiB block", bank.debug_bytes(0x1000, 8192), std::vector<std::uint8_t>(8192, 0x5A));
  // The hand times agree with the two headers' formulas as the library computes them.
  check("bus formula, 8 KiB", bus.transfer_time(8192), sc_time(15600, SC_NS));
  check("bank formula, 8 KiB", bank.access_time(tlm::TLM_WRITE_COMMAND, 0x1000, 8192), sc_time(20500, SC_NS));
  const rc::tlmx::PciBusReport r = bus.report();
  check("bytes written through the bus", r.total.bytes_written, std::uint64_t{256 + 8192});
  check("bytes read through the bus", r.total.bytes_read, std::uint64_t{256});
  check("master aborts", r.total.address_errors, std::uint64_t{1});
  std::printf("bank and bus: 256 B write and read back at %s, 8 KiB at %s, unmapped at %s\n",
              host.done[1].to_string().c_str(), host.done[2].to_string().c_str(), host.done[3].to_string().c_str());
  return g_failures == 0 ? 0 : 1;
}
