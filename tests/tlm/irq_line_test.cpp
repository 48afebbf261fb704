// IrqLine: the host wakes exactly `latency` after the device raises; lower() cancels a raise in flight.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

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

// wait_raised_ahead(ahead) against its definition, wait(ahead) then wait_raised(), on twin lines
// driven by the same device script: the same wake time and the same host wait count in every case
// (rise after the host's time, before it, before it and withdrawn, zero ahead, a raise on its way,
// a line already high, zero latency), and the wake times computed by hand.
TEST(IrqLine, WaitAheadIsSyncThenWait) {
  struct Step {
    sc_time at;  // from time 0
    bool raise;  // else lower
  };
  struct Case {
    sc_time latency, host_start, ahead;
    std::vector<Step> device;
    sc_time expected_wake;
    std::uint64_t expected_waits;
  };
  const sc_time ns(1, SC_NS);
  const std::vector<Case> cases = {
      {100 * ns, sc_core::SC_ZERO_TIME, 200 * ns, {{500 * ns, true}}, 600 * ns, 1},             // rises after
      {100 * ns, sc_core::SC_ZERO_TIME, 1000 * ns, {{300 * ns, true}}, 1000 * ns, 0},           // rises before
      {100 * ns, sc_core::SC_ZERO_TIME, 1000 * ns, {{300 * ns, true}, {500 * ns, false}, {1200 * ns, true}}, 1300 * ns, 1},
      {100 * ns, sc_core::SC_ZERO_TIME, sc_core::SC_ZERO_TIME, {{50 * ns, true}}, 150 * ns, 1},  // nothing ahead
      {100 * ns, 10 * ns, 50 * ns, {{5 * ns, true}}, 105 * ns, 1},                               // on its way
      {sc_core::SC_ZERO_TIME, 10 * ns, 30 * ns, {{5 * ns, true}}, 40 * ns, 0},                   // already high
      {sc_core::SC_ZERO_TIME, sc_core::SC_ZERO_TIME, 100 * ns, {{300 * ns, true}}, 300 * ns, 1},  // zero latency
  };
  std::vector<std::unique_ptr<IrqLine>> lines;
  std::vector<std::unique_ptr<Thread>> threads;
  std::vector<sc_time> woke(2 * cases.size());
  for (std::size_t c = 0; c < cases.size(); ++c) {
    for (int ahead_way = 0; ahead_way < 2; ++ahead_way) {
      const std::string id = std::to_string(c) + (ahead_way ? "_ahead" : "_synced");
      lines.push_back(std::make_unique<IrqLine>(("irq" + id).c_str(), IrqLineConfig{cases[c].latency, false}));
      IrqLine& irq = *lines.back();
      const Case& k = cases[c];
      sc_time& wake = woke[2 * c + ahead_way];
      threads.push_back(std::make_unique<Thread>(("device" + id).c_str(), [&irq, &k] {
        for (const Step& step : k.device) {
          wait(step.at - sc_core::sc_time_stamp());
          step.raise ? irq.raise() : irq.lower();
        }
      }));
      threads.push_back(std::make_unique<Thread>(("host" + id).c_str(), [&irq, &k, &wake, ahead_way] {
        wait(k.host_start);
        if (ahead_way) {
          irq.wait_raised_ahead(k.ahead);
        } else {
          wait(k.ahead);
          irq.wait_raised();
        }
        wake = sc_core::sc_time_stamp();
      }));
    }
  }
  sc_core::sc_start();

  for (std::size_t c = 0; c < cases.size(); ++c) {
    SCOPED_TRACE("case " + std::to_string(c));
    EXPECT_EQ(woke[2 * c], cases[c].expected_wake);
    EXPECT_EQ(woke[2 * c + 1], cases[c].expected_wake);
    EXPECT_EQ(lines[2 * c]->report().host_waits, cases[c].expected_waits);
    EXPECT_EQ(lines[2 * c + 1]->report().host_waits, cases[c].expected_waits);
  }
}

}  // namespace
}  // namespace rc::tlmx::test
