// BoardVisibility's bus access (host_sw/driver/board_visibility.h): register reads and writes, DMA and
// programmed I/O through the PCI port, each temporally decoupled at the host CPU's local time.
#include <stdexcept>

#include "host_sw/driver/board_visibility.h"
#include "host_sw/driver/trace_writer.h"

namespace rc {

using sc_core::sc_time;

bool BoardVisibility::tracing() const { return trace_ != nullptr && trace_->wants(cpu_.step()); }

void BoardVisibility::host_event(const char* name, const sc_time& from) {
  if (tracing()) trace_->complete(track("host"), name, from, cpu_.now());
}

// As a synced host waits (sync, then the line), with the same times and counts, but a pass that
// ends after the host's time wakes the host thread once, not twice (IrqLine::wait_raised_ahead).
void BoardVisibility::wait_for_interrupt() {
  const sc_time host_time = cpu_.now();
  ports_.irq.wait_raised_ahead(cpu_.local());
  cpu_.caught_up(host_time);
}

void BoardVisibility::acquire_bus() {
  if (options_.bus_turn == nullptr) return;
  cpu_.sync();
  options_.bus_turn->acquire();
}

void BoardVisibility::release_bus() {
  if (options_.bus_turn != nullptr) options_.bus_turn->release();
}

// Register accesses are temporally decoupled like the DMAs: issued at the host's local time, which
// moves to their completion. The bus hands the registers the access time (ControlRegs), so START
// and the acknowledge take effect when a synced host's would.
void BoardVisibility::write_registers(std::uint64_t offset, std::initializer_list<std::uint32_t> values) {
  if (values.size() > register_words_.size()) throw std::logic_error("register burst longer than the register file");
  std::copy(values.begin(), values.end(), register_words_.begin());
  register_access(tlm::TLM_WRITE_COMMAND, offset, static_cast<unsigned>(values.size()));
}

std::uint32_t BoardVisibility::read_register(std::uint64_t offset) {
  register_access(tlm::TLM_READ_COMMAND, offset, 1);
  return register_words_[0];
}

// Payloads are reused (nothing waits between setting one up and its return, so no other access can
// interleave, and a payload's construction allocates its extension array).
void BoardVisibility::set_payload(tlm::tlm_generic_payload& trans, tlm::tlm_command command, std::uint64_t address,
                                  void* data, std::uint64_t bytes) {
  trans.set_command(command);
  trans.set_address(address);
  trans.set_data_ptr(static_cast<unsigned char*>(data));
  trans.set_data_length(static_cast<unsigned>(bytes));
  trans.set_streaming_width(static_cast<unsigned>(bytes));
  trans.set_byte_enable_ptr(nullptr);
  trans.set_dmi_allowed(false);
  trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
}

// Temporally decoupled: the access is issued at the host's local time, which moves to its
// completion; the time it took counts as PCI time. Returns that time.
sc_time BoardVisibility::decoupled_access(tlm::tlm_generic_payload& trans) {
  acquire_bus();
  const sc_time issued = cpu_.local();
  sc_time delay = issued;
  pci_->b_transport(trans, delay);
  release_bus();
  cpu_.set_local(delay);
  stats_.pci += delay - issued;
  return delay - issued;
}

void BoardVisibility::register_access(tlm::tlm_command command, std::uint64_t offset, unsigned words) {
  set_payload(register_trans_, command, ports_.board.register_base + offset, register_words_.data(), words * 4);
  decoupled_access(register_trans_);
  if (!register_trans_.is_response_ok()) {
    throw std::runtime_error(std::string("register ") + (command == tlm::TLM_WRITE_COMMAND ? "write" : "read") +
                             " failed: " + register_trans_.get_response_string());
  }
  ++stats_.register_accesses;
}

void BoardVisibility::transfer(tlmx::DmaDirection direction, void* host, std::uint64_t address, std::uint64_t bytes,
                               const char* what, bool no_data) {
  if (bytes == 0) return;
  if (cpu_.profile().driver_model.transfer == DriverModel::Transfer::Pio) {
    programmed_io(direction, host, address, bytes, what, no_data);
  } else {
    dma(direction, host, address, bytes, what, no_data);
  }
  (direction == tlmx::DmaDirection::to_device ? stats_.bytes_to_board : stats_.bytes_to_host) += bytes;
}

// The CPU itself moves the words through the BAR window, one PCI transaction each (the bus times
// the payload as that, tlm/programmed_io_extension.h); it is blocked meanwhile, and no driver entry
// is needed (the window is mapped into the driver's address space).
void BoardVisibility::programmed_io(tlmx::DmaDirection direction, void* host, std::uint64_t address,
                                    std::uint64_t bytes, const char* what, bool no_data) {
  tlm::tlm_generic_payload& trans = pio_trans_;
  const bool write = direction == tlmx::DmaDirection::to_device;
  set_payload(trans, write ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND, address, host, bytes);
  trans.set_extension(&pio_extension_);
  if (no_data) trans.set_extension(&pio_no_data_);
  const sc_time start = cpu_.now();
  const sc_time took = decoupled_access(trans);
  trans.clear_extension(&pio_extension_);
  if (no_data) trans.clear_extension(&pio_no_data_);
  if (!trans.is_response_ok()) {
    throw std::runtime_error(std::string("programmed I/O of ") + what + " failed: " + trans.get_response_string());
  }
  stats_.pio += took;
  ++stats_.pio_transfers;
  (write ? stats_.pio_bytes_written : stats_.pio_bytes_read) += bytes;
  if (tracing()) {
    trace_->complete(track("host"), std::string("pio ") + what, start, cpu_.now(), {{"bytes", bytes}});
  }
}

void BoardVisibility::dma(tlmx::DmaDirection direction, void* host, std::uint64_t address, std::uint64_t bytes,
                          const char* what, bool no_data) {
  cpu_.charge(DriverWork::Call, 1);
  acquire_bus();
  // Temporally decoupled: issued at the host's local time, which moves to the completion. The bus
  // reserves itself at each burst's request time, so the times are those of a synced transfer.
  sc_time local = cpu_.local();
  const tlmx::DmaResult r = ports_.dma.transfer({direction, host, address, bytes, no_data}, local);
  release_bus();
  cpu_.set_local(local);
  if (!r.ok()) throw std::runtime_error(std::string("DMA of ") + what + " failed");
  stats_.pci += r.duration();
  ++stats_.dma_transfers;
  if (tracing()) {
    trace_->complete(track("dma"), what, r.start, r.end, {{"bytes", bytes}});
    trace_->complete(track("host"), std::string("dma ") + what, r.start, r.end);
  }
}

}  // namespace rc
