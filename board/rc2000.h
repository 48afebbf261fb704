// The RC2000 board as one module: the PCI bus the host plugs into, the bridge's DMA channel, the
// board's local bus, N SRAM banks, the FPGA's control/status registers and wrapper (fast or
// cycle-level model), and the interrupt line to the host.
//
//   host initiators ──> pci.in        PciBus: BAR0 (registers) -> regs, BAR1 (banks) -> local
//   dma (bridge DMA) ──> pci.in
//   pci.out[0] ──> regs.in            control/status registers (register_map.h)
//   pci.out[1] ──> local.in[0]        Router, bridge latency; bank b at b * bank_stride
//   wrapper.out ──> local.in[1]       the FPGA reaches the banks through DMI on the same local bus,
//                                     page by page (wrapper_base.h); invalidations come back the same way
//   local.out[b] ──> bank[b].in
//   wrapper ──> irq                   raised at DONE, lowered when the host clears DONE
//
// The host reaches the banks only through PCI (BAR1); the wrapper only through the local bus.
// Inner hops: each of the hops above that the board binds itself (pci.out to regs and to local,
// wrapper.out to local, local.out to each bank) takes an interposer (tlm/hop_interposer.h: a
// monitor, a protocol checker) when InnerHops names one; the hop then runs through it.
// Construction throws std::invalid_argument for a layout the board cannot hold (bank_layout.h).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <systemc>

#include "board/bank_layout.h"
#include "board/board_interface.h"
#include "board/board_params.h"
#include "board/control_regs.h"
#include "board/wrapper_base.h"
#include "tlm/dma_engine.h"
#include "tlm/hop_interposer.h"
#include "tlm/irq_line.h"
#include "tlm/pci_bus.h"
#include "tlm/router.h"
#include "tlm/sram_bank.h"

namespace rc::board {

// Interposers for the board's inner hops (nullptr: the hop is bound directly). Each must outlive
// the simulation and be given for one hop only; banks: none, or one per bank.
struct InnerHops {
  tlmx::HopInterposer* pci_to_regs = nullptr;
  tlmx::HopInterposer* pci_to_local = nullptr;
  tlmx::HopInterposer* wrapper_to_local = nullptr;
  std::vector<tlmx::HopInterposer*> local_to_bank;
};

class Rc2000 : public sc_core::sc_module {
  // Declared first: the parts below are built from them.
  BoardParams m_params;
  BankLayout m_layout;
  std::uint64_t m_stride;

 public:
  static constexpr std::uint64_t kBar0 = 0xF000'0000;        // registers, reg::kBarSize bytes
  static constexpr std::uint64_t kBar1 = 0x1'0000'0000;      // banks (64-bit BAR)

  // bank_page_bytes: the banks' storage page (tlm/sram_bank.h), the unit in which their memory is
  // allocated and granted to the wrapper through DMI; it changes neither timing nor results (tests
  // make it smaller than a word to put every word across two pages).
  // Throws std::invalid_argument for InnerHops it cannot place (a wrong bank count, one interposer
  // named twice).
  Rc2000(const sc_core::sc_module_name& name, const BoardParams& params,
         std::uint64_t bank_page_bytes = tlmx::SramBankConfig{}.page_bytes, const InnerHops& hops = {});
  // With the layout of these parameters already made (and so checked) by the caller: it is not
  // made twice; its results are placed as `params` say (place_results). Throws std::logic_error if
  // it is not the layout of `params`.
  Rc2000(const sc_core::sc_module_name& name, const BoardParams& params, BankLayout layout,
         std::uint64_t bank_page_bytes = tlmx::SramBankConfig{}.page_bytes, const InnerHops& hops = {});

  const BoardParams& params() const { return m_params; }
  const BankLayout& layout() const { return m_layout; }
  std::uint64_t bank_stride() const { return m_stride; }
  std::uint64_t bank_pci_address(unsigned bank) const { return kBar1 + bank * m_stride; }
  // The board as a driver sees it through PCI (board_interface.h).
  BoardInterface interface() const {
    return {kBar0, kBar1, m_stride, m_params.bank_capacity_bytes, m_layout, m_params.model};
  }

  tlmx::PciBus pci;
  tlmx::DmaEngine dma;
  tlmx::Router local;
  ControlRegs regs;
  tlmx::IrqLine irq;
  tlmx::SramBank& bank(unsigned b) { return *m_banks[b]; }
  const tlmx::SramBank& bank(unsigned b) const { return *m_banks[b]; }
  WrapperBase& wrapper() { return *m_wrapper; }
  const WrapperBase& wrapper() const { return *m_wrapper; }

  // Control signals for VCD traces (sc_trace them before sc_start).
  sc_core::sc_signal<bool, sc_core::SC_MANY_WRITERS> start_signal, busy_signal, done_signal, irq_signal;

 private:
  std::vector<std::unique_ptr<tlmx::SramBank>> m_banks;
  std::unique_ptr<WrapperBase> m_wrapper;
};

}  // namespace rc::board
