// The timing test kit (rc2000tlm::testkit; README, "Use it as a library"): a scripted host that talks
// to an Rc2000 over its PCI window, and run_until_finished, so that a gtest test states a board's
// timing as exact sc_time values in a few lines:
//
//   TEST(MyBoard, IdRegisterReadTakesOneBusAccess) {
//     board::Rc2000 rc2000("rc2000", params);
//     sc_core::sc_time seen;
//     testkit::ScriptedHost host("host", rc2000, [&](testkit::ScriptedHost& h) {
//       h.read(board::reg::kId);
//       seen = sc_core::sc_time_stamp();
//     });
//     testkit::run_until_finished({&host});
//     EXPECT_EQ(seen, sc_core::sc_time(...));
//   }
//
// Link rc2000tlm::testkit: it brings the gtest main (testkit/main) that refuses to run more than one
// test per process, since SystemC elaborates once per process; register the tests with
// gtest_discover_tests (or rc2000tlm_add_timing_test) so that ctest runs each on its own.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>

#include "board/rc2000.h"
#include "tlm/dma_engine.h"

namespace rc::testkit {

// A host thread with a PCI master socket bound to a board; `script` runs once, from time 0.
class ScriptedHost : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<ScriptedHost> out;
  std::function<void(ScriptedHost&)> script;
  bool finished = false;

  ScriptedHost(const sc_core::sc_module_name& name, board::Rc2000& board, std::function<void(ScriptedHost&)> body);

  board::Rc2000& board() { return m_board; }

  // Register access through PCI BAR0; waits for the bus's completion time. A response other than
  // OK fails the running test (gtest ADD_FAILURE) and the access returns.
  void write(std::uint64_t offset, std::vector<std::uint32_t> values);
  std::uint32_t read(std::uint64_t offset);
  // Temporally decoupled write: issued at local offset `local`, returns the completion's offset
  // without waiting.
  sc_core::sc_time write_ahead(std::uint64_t offset, std::vector<std::uint32_t> values, sc_core::sc_time local);
  // Bank data over PCI BAR1 through the board's bridge DMA (timed, counted); a failed transfer
  // fails the running test.
  void dma(tlmx::DmaDirection direction, std::uint8_t* data, unsigned bank, std::uint64_t bytes);

 private:
  // The response and the completion offset of one BAR0 access issued at local offset `delay`.
  bool transport(tlm::tlm_command command, std::uint64_t offset, std::uint32_t* values, std::size_t count,
                 sc_core::sc_time& delay);
  void run();
  board::Rc2000& m_board;
};

// Runs the simulation until every host's script has finished, then stops it. Simulated time moves
// in steps of `step` (a script that never finishes keeps it running: a test's own time-out ends it).
void run_until_finished(const std::vector<const ScriptedHost*>& hosts,
                        sc_core::sc_time step = sc_core::sc_time(10, sc_core::SC_US));

// The hosts of test benches that hold one (`bench->host`), for run_until_finished.
template <class Bench>
std::vector<const ScriptedHost*> hosts_of(const std::vector<Bench*>& benches) {
  std::vector<const ScriptedHost*> hosts;
  for (const Bench* b : benches) hosts.push_back(b->host.get());
  return hosts;
}

}  // namespace rc::testkit
