// Accounting for accesses made through a DMI pointer. DMI bypasses b_transport, so a target cannot
// see those accesses; an initiator that streams through DMI (the FPGA wrapper does, for every bank)
// reports what it did through this interface so that per-target activity counters stay complete.
#pragma once

#include <cstdint>

#include <systemc>

namespace rc::tlmx {

struct DmiActivity {
  std::uint64_t reads = 0;          // read accesses (one per word, burst or whatever unit the initiator uses)
  std::uint64_t writes = 0;         // write accesses
  std::uint64_t bytes_read = 0;
  std::uint64_t bytes_written = 0;
  sc_core::sc_time busy = sc_core::SC_ZERO_TIME;  // time the target was occupied by these accesses
};

// Implemented by targets that grant DMI and keep activity counters.
class DmiActivitySink {
 public:
  virtual void record_dmi_access(const DmiActivity& activity) = 0;

 protected:
  ~DmiActivitySink() = default;  // not owned through this interface
};

}  // namespace rc::tlmx
