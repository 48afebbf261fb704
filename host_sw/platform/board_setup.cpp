#include "host_sw/platform/board_setup.h"

namespace rc {

BoardSetup make_board_setup(const BoardRunOptions& o) {
  const board::DeviceProfile device = o.device_profile ? *o.device_profile : board::find_device_profile(o.device);
  BoardSetup s;
  s.host = o.host_profile ? *o.host_profile : find_host_profile(o.host);
  board::BoardChoices c;
  c.lanes = o.lanes;
  c.banks = o.banks;
  c.bits = o.bits;
  c.float_format = o.float_format;
  c.bank_capacity_bytes = o.bank_capacity_bytes;
  c.model = o.model;
  c.clocked_lanes = o.clocked_lanes;
  c.resources = o.resources;
  c.irq_latency = s.host.interrupt_latency;
  c.ray_split = o.ray_split;
  s.board = board::make_board_params(device, c);
  s.board.report_at_end = o.print_summaries;
  // The layout, made once: a bad configuration fails here, before elaboration, and the board uses it.
  s.layout = board::make_bank_layout(s.board);  // results placed as the profile says (bank or on chip)
  s.driver.concurrent = o.concurrent;
  s.driver.allow_batching = o.allow_batching;
  s.driver.oracle = o.oracle;
  s.driver.cpu_split = o.cpu_split.on() ? o.cpu_split : s.host.driver_model.cpu_split;  // the option, else the profile's
  if (s.driver.cpu_split.on() && o.cards > 1) {
    throw std::invalid_argument("--cpu-share: a CPU/FPGA split drives one card (got " +
                                std::to_string(o.cards.value()) + " cards)");
  }
  s.driver.chunk_rays = o.chunk_rays != 0 ? o.chunk_rays : s.host.driver_model.chunk_rays;  // the option, else the profile's
  if (s.driver.chunk_rays != 0 && o.cards > 1) {
    throw std::invalid_argument("--chunk-rays: the pipelined driver drives one card (got " +
                                std::to_string(o.cards.value()) + " cards)");
  }
  if (o.trace) {
    s.trace_first_step = o.trace_first_step;
    s.trace_last_step = o.trace_last_step;
  }
  s.on_progress = o.on_progress;
  s.on_answers = o.on_answers;
  s.cards = o.cards;
  s.card_split = o.card_split;
  s.card_bus = o.card_bus;
  s.energy = energy::load_energy_tables(&device, s.host.document, s.host.file);
  return s;
}

}  // namespace rc
