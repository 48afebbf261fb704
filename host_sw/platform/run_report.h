// What one run of a SystemC system reports, as typed data: the code passes a RunReport around and
// reads its fields; JSON exists only at the output edge, host_sw/outputs/run_report_json.h (to_json:
// the rc2000sim.board/1 and rc2000sim.software/1 documents of docs/outputs.md; encode/decode: the
// internal format of the same fields the timing study's worker processes send to their parent).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "host_sw/energy/energy_model.h"
#include "host_sw/driver/host_cpu_model.h"

namespace rc {

struct WorkTally {
  std::uint64_t count = 0;
  double seconds = 0;
};

// The host thread's timeline: host_compute + driver_cpu + pci_transfer + waiting (+ second_cpu_wait
// with the dual-processor overlap) = simulated_seconds; fpga_busy runs beside it. With several cards
// the drivers run on their own threads (BoardDetail::cards): the host thread's driver_cpu and
// pci_transfer are 0, waiting is its wait for the cards, fpga_busy the sum over the cards.
struct RunTime {
  double host_compute = 0, driver_cpu = 0, pci_transfer = 0, waiting = 0;
  double fpga_busy = 0, overlap = 0;
  bool second_cpu = false;  // DriverModel::Overlap::DualCpu in a concurrent run
  double second_cpu_compute = 0, second_cpu_wait = 0;
};

struct DesignReport {
  int block_multiplier_lanes = 0, slice_multiplier_lanes = 0;
  int slices = 0, slices_available = 0, block_multipliers = 0, block_multipliers_available = 0;
  double pipeline_clock_mhz = 0;
  bool resources_modelled = false;
  std::string resources = "paper";  // where slices and block multipliers came from: "paper" or "synthesis"
};

struct DeviceReport {
  std::string profile;
  unsigned lanes = 0;
  int bits = 0;
  double clock_hz = 0;
  unsigned banks = 0;
  std::uint64_t bank_capacity_bytes = 0;
  unsigned bank_word_bits = 0;
  double bank_clock_hz = 0;
  unsigned pci_width_bits = 0;
  double pci_clock_hz = 0;
  unsigned pipeline_latency_cycles = 0;
  std::string wrapper_model;  // "fast" or "cycle"
  std::string lanes_impl = "cpp";  // the lanes' implementation: "cpp" (the C++ pipeline) or "rtl" (Verilated)
  DesignReport design;
};

struct RayGroupReport {
  std::vector<unsigned> banks;
  unsigned lanes = 0, first_lane = 0;
  double rate_per_lane = 0;
};

struct LayoutReport {
  unsigned coordinates_per_word = 0, field_bits = 0, face_bank = 0, result_bank = 0;
  std::string own_face_table;  // "bank N" or "face bank"
  std::vector<RayGroupReport> ray_groups;
  std::vector<unsigned> spare_banks;
  double nominal_rays_per_cycle = 0;
  std::string ray_split;  // how a pass's rays were divided over the groups: "limit" or "nominal" (bank_layout.h)
};

struct BatchingReport {
  std::uint64_t passes = 0, ray_batches = 0, max_batches_per_step = 0, face_sets = 0, face_set_uploads = 0;
};

struct PciReport {
  std::uint64_t bytes_to_board = 0, bytes_to_host = 0, dma_transfers = 0, pio_transfers = 0;
  std::uint64_t register_accesses = 0, bus_transactions = 0;
  double bus_busy_seconds = 0;
};

struct BankUseReport {
  unsigned bank = 0;
  std::string role;
  std::uint64_t reads = 0, writes = 0, bytes_read = 0, bytes_written = 0;
  double busy_seconds = 0, bytes_per_second = 0, bytes_per_second_while_fpga_busy = 0;
};

struct LaneReport {
  unsigned lane = 0;
  double rate = 0;
  std::uint64_t rays = 0;
  double utilisation = 0;
};

// What bounded the stream of some passes (board/pass_timing.h), and their FPGA time.
struct StreamLimitReport {
  std::string limit;
  std::uint64_t passes = 0;
  double fpga_busy_seconds = 0;
};

struct IntersectionReport {
  std::uint64_t tests = 0;
  double per_second = 0, per_second_while_fpga_busy = 0;  // the latter: board runs
};

// One card of several (docs/board.md, "Several cards").
struct CardReport {
  unsigned card = 0;
  std::uint64_t faces = 0, passes = 0, tests = 0;  // faces it holds; its passes and ray-face tests
  double fpga_busy_seconds = 0;
  std::uint64_t bytes_to_board = 0, bytes_to_host = 0;
  double pci_bus_busy_seconds = 0, pci_bus_wait_seconds = 0;  // its transfers' bus occupancy, arbitration waits
  // Its driver thread's timeline: driver_cpu + pci_transfer + waiting + idle = simulated_seconds.
  double driver_cpu_seconds = 0, pci_transfer_seconds = 0, waiting_seconds = 0, idle_seconds = 0;
};

// One PCI bus (segment) and the cards on it.
struct BusReport {
  std::vector<unsigned> cards;
  double busy_seconds = 0, utilisation = 0;  // occupancy, and its share of simulated_seconds
};

struct CardsReport {
  unsigned count = 1;  // 1: the section is not in the document
  std::string split, bus;  // "rays" | "faces", "shared" | "separate"
  std::vector<BusReport> buses;
  std::vector<CardReport> per_card;
};

// Board runs only. With several cards: the sums over the cards (banks and lanes index by index;
// device, layout and capacity are every card's), and the cards one by one in `cards`.
struct BoardDetail {
  DeviceReport device;
  LayoutReport layout;
  std::uint64_t max_rays_per_batch = 0, max_faces_per_set = 0;  // capacity
  BatchingReport batching;
  PciReport pci;
  std::vector<BankUseReport> banks;
  std::vector<LaneReport> lanes;
  std::vector<StreamLimitReport> stream_limits;
  std::string driver_model;  // DriverModel::name()
  std::array<WorkTally, kDriverWorkKinds> driver{};
  CardsReport cards;
};

struct RunReport {
  bool board_run = false;
  double simulated_seconds = 0;
  RunTime time;
  IntersectionReport intersections;
  std::string host_profile;
  std::array<WorkTally, kHostWorkKinds> work{};
  BoardDetail board;  // board_run only
  bool has_wall = false;
  double wall_seconds = 0, wall_seconds_per_step = 0;
  // Energy beside time (docs/energy.md): the estimate, or why there is none (a profile without an
  // energy table). Exactly one of the two is set.
  std::optional<energy::EnergyReport> energy;
  std::string energy_missing;
};

// What the run counted, as the energy model takes it; `steps` from the solver's result.
energy::Activity activity_of(const RunReport& report, std::uint64_t steps);
// Sets report.energy (or report.energy_missing, when a table is missing) from `tables`.
void attach_energy(RunReport& report, const energy::EnergyTables& tables, std::uint64_t steps);

}  // namespace rc
