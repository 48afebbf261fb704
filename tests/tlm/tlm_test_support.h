// Test scaffolding for the generic TLM parts: the test kit's scripted initiator, whose SC_THREAD
// runs a test's lambda, and one-call helpers to build payloads. Every test builds its own modules (SystemC
// elaborates once per process, and ctest runs each test in its own process).
#pragma once

#include <cstdint>
#include <functional>
#include <utility>

#include <systemc>
#include <tlm>

#include "testkit/tlm/scripted_initiator.h"

namespace rc::tlmx::test {

using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_PS;
using sc_core::SC_US;
using sc_core::SC_ZERO_TIME;

// The scripted initiator is the timing test kit's (testkit/tlm/scripted_initiator.h).
using testkit::ScriptedInitiator;

}  // namespace rc::tlmx::test
