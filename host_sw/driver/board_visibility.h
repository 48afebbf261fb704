// The host driver of the RC2000 as a visibility backend: everything the solver asks goes host ->
// PCI -> banks -> lanes -> result bank -> PCI -> host.
//
// Per step (docs/board.md, "Pass protocol"): quantise the end points (pipeline::quantize_point; float
// lanes: round_point, then the values' bit patterns, board/word_format.h) in end-face order, pack
// them into the X/Y/Z bank words and DMA them to the ray banks; DMA the own-surface table; write the
// pass registers and START (with CLEAR on a batch's first face set); wait for the interrupt; clear
// DONE; DMA the result words back. Rays beyond a batch's capacity are split into batches and faces
// beyond a set's capacity into sets (paper sec 4.4); a batch's result words are ORed across its face
// sets on the board and read back once.
//
// Serial mode: submit() runs every pass and returns with the results. Concurrent mode (sec 4.3):
// submit() returns right after the first START, the solver computes form factors on the host (in
// simulated time, through HostCpuModel) while the board works, and collect() waits for the
// interrupt and runs any remaining passes.
//
// Call load_faces/submit/collect from the host SC_THREAD (they wait for the bus and the interrupt).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>

#include "board/board_interface.h"
#include "board/wrapper_base.h"
#include "tlm/dma_engine.h"
#include "tlm/irq_line.h"
#include "host_sw/driver/cpu_split.h"
#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/driver/timing_replay_target.h"
#include "host_sw/radiosity/visibility.h"
#include "pipeline/fixed_mt.h"
#include "pipeline/float_mt.h"
#include "tlm/no_data_extension.h"
#include "tlm/programmed_io_extension.h"

namespace rc {

class TraceWriter;

// Drivers of several cards take turns at the bus: with a turn, the driver syncs its local time and
// calls acquire() before every bus access (a DMA request, a register burst, a programmed I/O
// buffer) and release() right after the bus call returned, before anything can wait. The bus
// arbitrates in call order (tlm/pci_bus.h), so syncing first makes call order time order, and the
// turn orders accesses requested at the same time in a fixed way, whatever order the SystemC
// scheduler happens to run the drivers' threads in.
class BusTurn {
 public:
  virtual ~BusTurn() = default;
  virtual void acquire() = 0;
  virtual void release() = 0;
};

struct BoardVisibilityOptions {
  bool concurrent = false;     // paper sec 4.3
  bool allow_batching = true;  // false: a scene beyond one batch/set is an error
  // A host-side model whose answers are bit-identical to the lanes' (a recording being replayed,
  // or a culled fixed-point kernel at the same width). When set, the lanes copy its answer instead
  // of testing every ray against every face; timing, traffic and data movement are unchanged.
  VisibilityBackend* oracle = nullptr;
  // Several cards (host_sw/driver/multi_card_visibility.h): the trace tracks of this card ("card 1 host",
  // "card 1 dma", ...), and turns at the bus (BusTurn). Neither changes a time of one card alone.
  std::string trace_prefix;
  BusTurn* bus_turn = nullptr;
  // The CPU/FPGA split (host_sw/driver/cpu_split.h). Its answers come from `oracle` when set, else
  // from `cpu_kernel`: a host backend bit-identical to the lanes (fixed point at the board's width,
  // or the float lanes' format), which the platform provides.
  CpuSplit cpu_split;
  VisibilityBackend* cpu_kernel = nullptr;
  // The pipelined driver (board_visibility_pipelined.cpp; docs/board.md, "Pipelined passes"): a
  // step's board segments go in chunks of this many into alternating halves of the ray and result
  // banks and of the own-surface table, so packing and sending chunk k+1 and reading back chunk k-1
  // overlap the wrapper's pass over chunk k. 0: off (the unpipelined protocol).
  std::size_t chunk_rays = 0;
  // The lanes' guard band on t (pipeline/fixed_format.h; 0..kMaxTGuard LSBs, fixed-point lanes only):
  // written to T_GUARD before the first pass when it is not the reset value 0, so the paper's test
  // costs no register access. The oracle and cpu_kernel, when set, must answer with the same guard.
  int t_guard = 0;
};

// Passes whose stream was bounded by one term of the pass time (PassRecord::limit: "lanes",
// "bank N (role)"), and the FPGA time they took: what a faster board would have to relieve.
struct PassLimitTally {
  std::uint64_t passes = 0;
  sc_core::sc_time fpga_busy = sc_core::SC_ZERO_TIME;
};

struct BoardDriverStats {
  std::uint64_t passes = 0;
  std::uint64_t ray_batches = 0;        // over all steps
  std::uint64_t face_set_uploads = 0;   // face records uploaded (1 when the scene fits one set)
  std::uint64_t face_sets = 0;          // sets the scene needs
  std::uint64_t max_batches_per_step = 0;
  std::uint64_t dma_transfers = 0, register_accesses = 0;
  std::uint64_t pio_transfers = 0;      // buffers moved by programmed I/O (each many PCI transactions)
  std::uint64_t pio_bytes_written = 0, pio_bytes_read = 0;
  sc_core::sc_time pio = sc_core::SC_ZERO_TIME;  // host thread blocked in programmed I/O (part of pci)
  std::uint64_t bytes_to_board = 0, bytes_to_host = 0;
  std::uint64_t tests = 0;              // ray slots streamed: rays x faces per pass
  sc_core::sc_time pci = sc_core::SC_ZERO_TIME;      // host thread blocked in DMA and register accesses
  sc_core::sc_time waiting = sc_core::SC_ZERO_TIME;  // host thread waiting for the interrupt
  sc_core::sc_time fpga_busy = sc_core::SC_ZERO_TIME;  // sum of pass durations
  sc_core::sc_time overlap = sc_core::SC_ZERO_TIME;    // host compute during passes
  std::map<std::string, PassLimitTally> limits;        // by PassRecord::limit (ordered: deterministic reports)
  std::uint64_t cpu_segments = 0, cpu_tests = 0;       // the CPU/FPGA split's part (segments x faces)
};

// What the driver needs from the wrapper beside PCI, wired by the platform (host_sw/platform/board_run.h):
// before each START, which answer the lanes copy (null: they compute) and whether the pass moves
// data or only takes its time (timing replay).
struct WrapperSideband {
  std::function<void(const std::uint8_t* oracle_answer, bool timing_only)> before_start;
};

// The driver sees the board only through its ports: the host's PCI initiator socket, the board
// bridge's DMA channel, the interrupt line, and the board's self-description (BoardInterface).
struct BoardPorts {
  tlm::tlm_initiator_socket<>& pci;  // bound to the board's PCI bus
  tlmx::DmaEngine& dma;              // the board bridge's DMA channel (host memory <-> BAR1)
  tlmx::IrqLine& irq;                // the board's interrupt, as the host sees it
  board::BoardInterface board;       // BARs, bank layout, word formats, wrapper model
  WrapperSideband sideband;
};

class BoardVisibility : public VisibilityBackend, public TimingReplayTarget {
 public:
  BoardVisibility(BoardPorts ports, HostCpuModel& cpu, BoardVisibilityOptions options = {},
                  TraceWriter* trace = nullptr);

  // The platform calls this when the wrapper finishes a pass (the wrapper's on_pass hook).
  void pass_finished(const board::PassRecord& record);

  std::string name() const override { return "board"; }
  void load_triangles(const std::vector<Triangle>& faces) override;
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  std::uint64_t tests_performed() const override { return stats_.tests; }
  bool runs_on_host() const override { return false; }

  const BoardDriverStats& stats() const { return stats_; }

  // Timing replay (host_sw/platform/work_replay.h): exactly the passes, transfers, registers, interrupts
  // and driver work of submit()/collect() for a step of `segments` segments from `source_face`,
  // without the data: rays and results move as transfers of their real sizes that carry no bytes
  // (tlmx::NoDataExtension), the own-surface table and faces move for real, and the lanes do not compute.
  // Only the fast wrapper model supports it.
  void submit_timing_only(std::size_t segments, int source_face) override;
  void collect_timing_only() override;

 private:
  struct Pass {
    std::size_t batch = 0, set = 0;
    bool first_of_batch = false, last_of_batch = false;
  };

  // The CPU/FPGA split of a step of `segments`: how many the CPU tests, its charge (on the second
  // processor at once, or on this one after the first START), and the board part's costs measured
  // for the next balanced step.
  std::size_t cpu_segments_of(std::size_t segments) const;
  void begin_step(std::size_t segments);
  void charge_cpu_part();
  void answer_cpu_part(const SegmentBatch& batch);
  void board_part_done();
  bool second_cpu() const;  // this step forks the second processor
  void order_segments(const SegmentBatch& batch);
  pipeline::FixedVec3 end_point_code(const Vec3& p) const;  // codes (float lanes: bit patterns)
  void run_step();     // the step's passes (serial) or its first pass (concurrent)
  void finish_step();  // the remaining passes
  void ask_oracle(const SegmentBatch& batch);
  void plan_passes();
  void start_pass(const Pass& pass);
  void finish_pass(const Pass& pass);
  void upload_rays(std::size_t batch);
  void upload_faces(std::size_t set);
  void set_source(int source_face);
  // The own-surface table of rays [first, first + rays) against face set `set`, at `table_base` words
  // after its usual place (TABLE_BASE).
  void upload_mask(std::size_t first, std::size_t rays, std::size_t set, std::uint64_t table_base = 0);
  void fill_mask(std::size_t first, std::size_t rays, std::size_t set);  // mask_words_
  void read_results(std::size_t batch);

  // The pipelined driver (board_visibility_pipelined.cpp).
  bool pipelined() const { return options_.chunk_rays != 0; }
  void check_chunks() const;  // at load: the chunk's halves fit their banks, one face set
  void start_chunks();        // the step's first chunk (serial: every chunk)
  void finish_chunks();       // the remaining chunks, and the read-backs
  void send_chunk(std::size_t k);
  void await_chunk(std::size_t k);  // until PASSES counts chunk k done
  void read_chunk(std::size_t k);
  std::size_t chunk_first(std::size_t k) const { return k * options_.chunk_rays; }
  std::size_t chunk_size(std::size_t k) const { return std::min(rays_, chunk_first(k) + options_.chunk_rays) - chunk_first(k); }
  std::uint64_t half_words() const { return layout_.bank_words / 2; }

  // Bus access from the host thread; each syncs the host's local time first.
  void write_registers(std::uint64_t offset, std::initializer_list<std::uint32_t> values);
  std::uint32_t read_register(std::uint64_t offset);
  void register_access(tlm::tlm_command command, std::uint64_t offset, unsigned words);  // register_words_
  static void set_payload(tlm::tlm_generic_payload& trans, tlm::tlm_command command, std::uint64_t address, void* data,
                          std::uint64_t bytes);
  sc_core::sc_time decoupled_access(tlm::tlm_generic_payload& trans);
  // Moves a buffer between host and board the way the host profile's driver model says: a DMA
  // request (dma) or programmed I/O (pio). no_data: timed and counted like any transfer, bytes not
  // moved (timing replay of blank buffers).
  void transfer(tlmx::DmaDirection direction, void* host, std::uint64_t address, std::uint64_t bytes, const char* what,
                bool no_data = false);
  void dma(tlmx::DmaDirection direction, void* host, std::uint64_t address, std::uint64_t bytes, const char* what,
           bool no_data);
  void programmed_io(tlmx::DmaDirection direction, void* host, std::uint64_t address, std::uint64_t bytes,
                     const char* what, bool no_data);
  // The driver's CPU work for converting `rays` end points, storing `words` bank words of rays,
  // converting and storing `faces` face records, and loading `result_words` result words of `rays`
  // segments, in the profile's cost unit.
  void charge_end_points(std::size_t rays);
  void charge_ray_words(std::uint64_t words);
  void charge_faces(std::size_t faces);
  void charge_results(std::size_t rays, std::uint64_t result_words);
  bool per_word() const;
  bool dual_cpu() const;  // concurrent, with form factors on the second processor
  void host_event(const char* name, const sc_core::sc_time& from);
  bool tracing() const;
  std::string track(const char* name) const { return options_.trace_prefix + name; }
  void wait_for_interrupt();  // returns synced, at the later of the host's time and the interrupt's
  void acquire_bus();  // with a BusTurn: sync, then wait for the turn
  void release_bus();

  std::size_t batch_first(std::size_t b) const { return b * rays_per_batch_; }
  std::size_t batch_size(std::size_t b) const;
  std::size_t set_first(std::size_t s) const { return s * faces_per_set_; }
  std::size_t set_size(std::size_t s) const;

  BoardPorts ports_;
  tlm::tlm_initiator_socket<>& pci_;
  HostCpuModel& cpu_;
  BoardVisibilityOptions options_;
  TraceWriter* trace_;
  const board::BankLayout& layout_;
  unsigned word_bytes_;
  std::size_t rays_per_batch_, faces_per_set_;
  BoardDriverStats stats_;

  std::vector<pipeline::FaceRecord> faces_;  // as the face bank's words: codes (float lanes: bit patterns)
  long resident_set_ = -1;

  // The submitted batch, in end-face order: the board tests the first rays_, the CPU the cpu_rays_
  // after them (total_rays_ in all).
  std::size_t rays_ = 0;
  std::size_t total_rays_ = 0, cpu_rays_ = 0;
  sc_core::sc_time step_start_ = sc_core::SC_ZERO_TIME, fpga_before_ = sc_core::SC_ZERO_TIME;
  double board_seconds_per_segment_ = 0, pass_seconds_per_segment_ = 0;  // measured; 0 until then
  std::vector<std::size_t> order_;  // sorted position -> segment index of the batch
  bool identity_order_ = true;
  std::vector<int> end_faces_;
  std::vector<std::int64_t> x_, y_, z_;
  pipeline::FixedVec3 start_{0, 0, 0};
  std::uint32_t source_face_ = 0;           // SOURCE_FACE: the first face of the shooter's sheet
  std::uint32_t source_faces_ = 1;          // SOURCE_FACES: the faces of that sheet
  std::uint32_t source_faces_written_ = 1;  // what the register holds (1 at reset)
  std::uint32_t t_guard_written_ = 0;       // what T_GUARD holds (0 at reset)
  std::vector<std::uint8_t> blocked_;  // end-face order
  std::vector<std::uint8_t> oracle_answer_;  // end-face order, when options_.oracle is set
  bool timing_only_ = false;                 // the current step came from submit_timing_only
  std::vector<Pass> passes_;
  std::size_t next_pass_ = 0;
  std::size_t chunks_ = 0, next_chunk_ = 0;  // the pipelined step: its chunks, the next to send
  std::uint32_t passes_started_ = 0;         // STARTs written, as the PASSES register counts (mod 2^32)
  std::uint32_t passes_done_ = 0;            // PASSES as last read
  std::uint32_t chunk_base_ = 0;             // PASSES before the step's first chunk
  board::RaySplitMemo split_{layout_};  // of the current batch in the ray banks
  board::PassRecord last_record_;
  tlm::tlm_generic_payload register_trans_;
  tlm::tlm_generic_payload pio_trans_;  // programmed I/O: one payload, its extensions owned here
  tlmx::ProgrammedIoExtension pio_extension_;
  tlmx::NoDataExtension pio_no_data_;
  std::array<std::uint32_t, 8> register_words_{};  // the longest burst: RAY_COUNT..MASK_START
  std::vector<std::vector<std::uint8_t>> images_;
  static constexpr std::size_t kNoBlankImages = ~std::size_t{0};
  std::size_t blank_images_rays_ = kNoBlankImages;  // images_ are blank ones for a batch of this size
  // One buffer per kind of transfer, so that none is cleared again to another's size each pass.
  std::vector<std::uint8_t> face_words_, mask_words_, result_words_;
  // The rays and face set of the table in mask_words_ when a timing replay made it (upload_mask).
  struct MaskKey {
    std::size_t first = 0, rays = ~std::size_t{0}, set = 0;
    bool operator==(const MaskKey& o) const { return first == o.first && rays == o.rays && set == o.set; }
  };
  MaskKey mask_key_;
  PassLimitTally* last_limit_ = nullptr;  // stats_.limits[last_limit_name_], the last pass's
  std::string last_limit_name_;
};

}  // namespace rc
