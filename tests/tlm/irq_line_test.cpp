// IrqLine: the host wakes exactly `latency` after the device raises; lower() cancels a raise in flight.
#include <gtest/gtest.h>

#include "tests/tlm/tlm_test_support.h"
#include "tlm/irq_line.h"

namespace rc::tlmx::test {
namespace {

// Runs a plain SC_THREAD body (no socket needed).
class Thread : public sc_core::sc_module {
 public:
  Thread(const sc_core::sc_module_name& name, std::function<void()> body)
      : sc_core::sc_module(name), m_body(std::move(body)) {
    SC_HAS_PROCESS(Thread);
    SC_THREAD(run);
  }

 private:
  void run() { m_body(); }
  std::function<void()> m_body;
};

TEST(IrqLine, HostWakesExactlyLatencyAfterRaise) {
  IrqLine irq("irq", IrqLineConfig{sc_time(250, SC_NS), true});
  sc_time woke, woke_again;
  bool raised_after_lower = true;
  Thread device("device", [&] {
    wait(sc_time(1, SC_US));
    irq.raise();
    wait(sc_time(1, SC_US));  // the host has acknowledged in between; raise a second time
    irq.raise();
  });
  Thread host("host", [&] {
    irq.wait_raised();
    woke = sc_core::sc_time_stamp();
    irq.lower();  // acknowledge
    raised_after_lower = irq.raised();
    irq.wait_raised();
    woke_again = sc_core::sc_time_stamp();
  });
  sc_core::sc_start();

  EXPECT_EQ(woke, sc_time(1250, SC_NS));
  EXPECT_FALSE(raised_after_lower);
  EXPECT_EQ(woke_again, sc_time(2250, SC_NS));
  const IrqLineReport r = irq.report();
  EXPECT_EQ(r.raises, 2u);
  EXPECT_EQ(r.lowers, 1u);
  EXPECT_EQ(r.delivered, 2u);
  EXPECT_EQ(r.host_waits, 2u);
  EXPECT_TRUE(irq.raised());
  EXPECT_TRUE(irq.driven());
}

TEST(IrqLine, LowerCancelsRaiseInFlightAndOffsetsAreHonoured) {
  IrqLine irq("irq", IrqLineConfig{sc_time(100, SC_NS), true});
  sc_time woke;
  Thread device("device", [&] {
    irq.raise();  // would reach the host at 100 ns...
    wait(sc_time(50, SC_NS));
    irq.lower();  // ...but is withdrawn at 50 ns
    wait(sc_time(10, SC_NS));
    irq.raise(sc_time(20, SC_NS));  // a decoupled device 20 ns ahead: reaches the host at 60 + 20 + 100
  });
  Thread host("host", [&] {
    irq.wait_raised();
    woke = sc_core::sc_time_stamp();
  });
  sc_core::sc_start();

  EXPECT_EQ(woke, sc_time(180, SC_NS));
  EXPECT_EQ(irq.report().raises, 2u);
  EXPECT_EQ(irq.report().delivered, 1u);
}

TEST(IrqLine, ZeroLatencyWakesInTheSameTimeStep) {
  IrqLine irq("irq");
  sc_time woke = sc_time(1, sc_core::SC_SEC);
  bool returned_at_once = false;
  Thread device("device", [&] {
    wait(sc_time(42, SC_NS));
    irq.raise();
  });
  Thread host("host", [&] {
    irq.wait_raised();
    woke = sc_core::sc_time_stamp();
    irq.wait_raised();  // still raised: returns without blocking
    returned_at_once = sc_core::sc_time_stamp() == woke;
  });
  sc_core::sc_start();

  EXPECT_EQ(woke, sc_time(42, SC_NS));
  EXPECT_TRUE(returned_at_once);
  EXPECT_EQ(irq.report().host_waits, 1u);
}

}  // namespace
}  // namespace rc::tlmx::test
