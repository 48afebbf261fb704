#include "board/board_params.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "board/design_fit.h"
#include "tlm/timing.h"

namespace rc::board {

BoardParams make_board_params(const DeviceProfile& p, const BoardChoices& c) {
  BoardParams b;
  b.device = p.name;
  b.lanes = c.lanes;
  b.banks = c.banks != 0 ? c.banks : p.bank_count;
  b.bits = c.bits;
  b.bank_capacity_bytes = c.bank_capacity_bytes != 0 ? c.bank_capacity_bytes : p.bank_capacity_bytes;
  b.word_bits = p.bank_word_bits;
  b.bank_write_latency = p.bank_write_latency_cycles;
  // The lanes must fit the device; the clock is the design's (wrapper-limited, or the pipeline's
  // own at this width if that is slower).
  b.float_format = c.float_format;
  if (c.float_format) {
    if (c.resources != pipeline::ResourceSource::paper_fit) {
      throw std::invalid_argument("resources from " + choice_name(c.resources) +
                                  " apply to fixed-point lanes only: the float lanes (" + c.float_format->to_string() +
                                  ") have no RTL to synthesise; their costs are counting-rule estimates");
    }
    b.fit = fit_float_design(p, pipeline::ResourceModel::load_default(), c.lanes, *c.float_format);  // an estimate
  } else {
    b.fit = fit_design(p, pipeline::ResourceModel::load_default(c.resources), static_cast<int>(c.lanes), c.bits);
  }
  if (!b.fit.fits) throw std::invalid_argument(b.fit.describe());
  b.timing.device_period = tlmx::period_from_hz(b.fit.clock_mhz * 1e6);
  b.timing.bank_period = tlmx::period_from_hz(p.bank_clock_mhz * 1e6);
  b.timing.bank_read_latency = p.bank_read_latency_cycles;
  b.timing.pass_start = p.pass_start_cycles;
  b.timing.face_setup = p.face_setup_cycles;
  b.timing.pass_finish = p.pass_finish_cycles;
  b.timing.pipeline_latency = p.pipeline_latency_cycles;
  b.register_access_cycles = p.register_access_cycles;
  b.pci.width_bits = p.pci_width_bits;
  b.pci.clock_period = tlmx::period_from_hz(p.pci_clock_mhz * 1e6);
  b.pci.burst_efficiency = p.pci_burst_efficiency;
  b.pci.setup_cycles = p.pci_setup_cycles;
  b.pci.max_burst_bytes = p.pci_max_burst_bytes;
  b.pci.master_abort_cycles = p.pci_master_abort_cycles;
  b.bridge_latency_cycles = p.bridge_latency_cycles;
  b.irq_latency = c.irq_latency;
  b.model = c.model;
  if (c.clocked_lanes) {
    if (c.float_format)
      throw std::invalid_argument("the " + c.clocked_lanes.name + " lanes are fixed-point: they do not apply to float lanes (" +
                                  c.float_format->to_string() + ")");
    if (c.model != WrapperModel::cycle)
      throw std::invalid_argument("the " + c.clocked_lanes.name + " lanes need the cycle-level wrapper model");
    b.clocked_lanes = c.clocked_lanes;
  }
  b.ray_split = c.ray_split;
  b.results = p.results;
  b.result_store_bits = b.fit.block_ram_bits_available - std::min(b.fit.block_ram_bits, b.fit.block_ram_bits_available);
  if (b.results == ResultStore::on_chip && b.result_store_bits == 0) {
    throw std::invalid_argument(p.file + ": wrapper.results is on_chip, but " + p.name + " has " +
                                std::to_string(b.fit.block_ram_bits_available) + " block RAM bits and the design uses " +
                                std::to_string(b.fit.block_ram_bits) + ": none left for the results");
  }
  return b;
}

BankLayout make_bank_layout(const BoardParams& p) {
  BankLayout layout = p.float_format
                          ? make_bank_layout(p.lanes, p.banks, *p.float_format, p.word_bits, p.bank_capacity_bytes)
                          : make_bank_layout(p.lanes, p.banks, p.bits, p.word_bits, p.bank_capacity_bytes);
  layout = place_results(std::move(layout), p.results, p.result_store_bits);
  return place_split(std::move(layout), p.ray_split, static_cast<std::uint64_t>(p.timing.bank_period.value()),
                     static_cast<std::uint64_t>(p.timing.device_period.value()));
}

}  // namespace rc::board
