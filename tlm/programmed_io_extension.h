// Marks a transaction that stands for programmed I/O: the host CPU moving a buffer one word at a
// time with loads and stores to a mapped BAR window, each its own single-data-phase PCI
// transaction, instead of one DMA burst. A PciBus times such a payload as
//   accesses  = ceil(bytes / access_bytes)
//   occupancy = accesses * (burst_cycles(access_bytes) * P + (read ? read_round_trip : 0))
// (pci_bus.h): a write is posted (the host bridge takes it and the CPU goes on, so a long stream
// runs at the bus's rate), a read is not: the CPU waits for each word's round trip through the
// host bridge and the target's bridge. The payload carries the whole buffer so that the target
// is called once (one event per transfer, not per word). An ignorable extension: a bus that does
// not know it times the payload as one burst.
#pragma once

#include <cstdint>

#include <systemc>
#include <tlm>

namespace rc::tlmx {

struct ProgrammedIoExtension : tlm::tlm_extension<ProgrammedIoExtension> {
  unsigned access_bytes = 4;                                   // bytes per load or store
  sc_core::sc_time read_round_trip = sc_core::SC_ZERO_TIME;   // per read access, beyond its bus time

  tlm::tlm_extension_base* clone() const override { return new ProgrammedIoExtension(*this); }
  void copy_from(const tlm::tlm_extension_base& other) override {
    const auto& o = static_cast<const ProgrammedIoExtension&>(other);
    access_bytes = o.access_bytes;
    read_round_trip = o.read_round_trip;
  }
};

}  // namespace rc::tlmx
