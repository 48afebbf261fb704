#include "board/rc2000.h"

#include <stdexcept>
#include <string>

#include "board/cycle_wrapper.h"
#include "board/fast_wrapper.h"
#include "tlm/timing.h"

namespace rc::board {

namespace {

// Banks sit on a power-of-two stride of at least 16 MiB, so a bank's window never depends on the
// others' sizes.
std::uint64_t stride_for(std::uint64_t capacity) {
  std::uint64_t s = 16u << 20;
  while (s < capacity) s *= 2;
  return s;
}

std::uint32_t config_register(const BankLayout& l) {
  // Fractional bits, or for float lanes the value width 1+E+M (value_bits is the one or the other).
  return (l.lanes & 0xFF) | (static_cast<std::uint32_t>(l.value_bits) & 0xFF) << 8 |
         (static_cast<std::uint32_t>(l.groups.size()) & 0xFF) << 16 | (l.banks_available & 0xFF) << 24;
}

tlmx::SramBankConfig bank_config(const BoardParams& p, std::uint64_t page_bytes) {
  tlmx::SramBankConfig c;
  c.page_bytes = page_bytes;
  c.capacity_bytes = p.bank_capacity_bytes;
  c.word_bytes = p.word_bits / 8;
  c.clock_period = p.timing.bank_period;
  c.read_latency_cycles = p.timing.bank_read_latency;
  c.write_latency_cycles = p.bank_write_latency;
  c.cycles_per_word = 1;
  c.report_at_end = p.report_at_end;
  return c;
}

tlmx::PciBusConfig pci_config(const BoardParams& p) {
  tlmx::PciBusConfig c = p.pci;
  c.report_at_end = p.report_at_end;
  return c;
}

// Binds from -> to, through the interposer when there is one.
template <class From, class To>
void bind_hop(From& from, To& to, tlmx::HopInterposer* hop) {
  if (hop == nullptr) return from.bind(to);
  from.bind(hop->hop_in());
  hop->hop_out().bind(to);
}

void check_hops(const InnerHops& hops, unsigned banks) {
  if (!hops.local_to_bank.empty() && hops.local_to_bank.size() != banks) {
    throw std::invalid_argument("Rc2000: InnerHops.local_to_bank has " + std::to_string(hops.local_to_bank.size()) +
                                " interposers for " + std::to_string(banks) + " banks (give none or one per bank)");
  }
  std::vector<const tlmx::HopInterposer*> all{hops.pci_to_regs, hops.pci_to_local, hops.wrapper_to_local};
  all.insert(all.end(), hops.local_to_bank.begin(), hops.local_to_bank.end());
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (all[i] != nullptr && all[i] == all[j])
        throw std::invalid_argument("Rc2000: InnerHops names one interposer for two hops (each needs its own)");
}

}  // namespace

Rc2000::Rc2000(const sc_core::sc_module_name& name, const BoardParams& params, std::uint64_t bank_page_bytes,
               const InnerHops& hops)
    : Rc2000(name, params, make_bank_layout(params), bank_page_bytes, hops) {}

Rc2000::Rc2000(const sc_core::sc_module_name& name, const BoardParams& params, BankLayout layout,
               std::uint64_t bank_page_bytes, const InnerHops& hops)
    : sc_core::sc_module(name),
      m_params((check_hops(hops, params.banks), params)),  // before any part is built
      // A caller that made the layout from the banks alone (results in the bank) gets the results
      // placed as the parameters say (place_results is idempotent).
      m_layout(place_results(std::move(layout), params.results, params.result_store_bits)),
      m_stride(stride_for(params.bank_capacity_bytes)),
      pci("pci", pci_config(params)),
      dma("dma", tlmx::DmaConfig{params.pci.max_burst_bytes, params.report_at_end}),
      local("local", tlmx::RouterConfig{params.pci.clock_period, params.bridge_latency_cycles, params.report_at_end}),
      regs("regs", tlmx::cycles(params.register_access_cycles, params.timing.device_period), config_register(m_layout)),
      irq("irq", tlmx::IrqLineConfig{params.irq_latency, params.report_at_end}),
      start_signal("start"),
      busy_signal("busy"),
      done_signal("done"),
      irq_signal("irq_level") {
  if (m_layout.lanes != params.lanes || m_layout.banks_available != params.banks ||
      m_layout.float_format != params.float_format || (!params.float_format && m_layout.bits != params.bits) ||
      m_layout.word_bits != params.word_bits) {
    throw std::logic_error("Rc2000: the bank layout given is not the layout of the board's parameters");
  }
  dma.out.bind(pci.in);  // the bridge's DMA channel: pci.in[0]; host initiators bind after it
  bind_hop(pci.out, regs.in, hops.pci_to_regs);
  bind_hop(pci.out, local.in, hops.pci_to_local);
  pci.map(kBar0, reg::kBarSize, 0, "rc2000.regs");
  pci.map(kBar1, m_params.banks * m_stride, 1, "rc2000.banks");

  std::vector<tlmx::DmiActivitySink*> sinks;
  std::vector<std::uint64_t> addresses;
  for (unsigned b = 0; b < m_params.banks; ++b) {
    m_banks.push_back(std::make_unique<tlmx::SramBank>(("bank" + std::to_string(b)).c_str(), bank_config(m_params, bank_page_bytes)));
    bind_hop(local.out, m_banks.back()->in, hops.local_to_bank.empty() ? nullptr : hops.local_to_bank[b]);
    local.map(b * m_stride, m_params.bank_capacity_bytes, b, "bank" + std::to_string(b));
    sinks.push_back(m_banks.back().get());
    addresses.push_back(b * m_stride);
  }
  const WrapperSignals signals{&start_signal, &busy_signal, &done_signal, &irq_signal};
  if (m_params.model == WrapperModel::cycle)
    m_wrapper = std::make_unique<CycleWrapper>(
        "wrapper", m_layout, m_params.timing, regs, irq, sinks, addresses, signals,
        m_params.clocked_lanes ? m_params.clocked_lanes.make(m_layout.lanes.value(), m_params.bits) : nullptr);
  else
    m_wrapper = std::make_unique<FastWrapper>("wrapper", m_layout, m_params.timing, regs, irq, sinks, addresses, signals);
  bind_hop(m_wrapper->out, local.in, hops.wrapper_to_local);
}

}  // namespace rc::board
