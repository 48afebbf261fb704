// The host CPU as a cost model: HostWork counts from the solver, and the driver's own CPU work,
// become simulated time on the host thread. Time accumulates in a tlm_quantumkeeper (local time,
// ahead of sc_time_stamp()); the driver syncs it before every bus or interrupt interaction, so the
// solver's work between submit() and collect() overlaps the board's pass in simulated time.
// Costs per unit come from a host profile (configs/hosts/*.json), each with its source.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <systemc>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "host_sw/driver/cpu_split.h"
#include "host_sw/radiosity/host_cost.h"
#include "profiles/profile_document.h"

namespace rc {

class TraceWriter;

// Driver work on the host CPU that the solver does not count (board runs only). Which kinds a
// driver charges depends on its cost unit (DriverModel): per segment and face record, or per
// coordinate converted and bank word stored or loaded (paper sec 4.1 vs 4.2 word formats).
enum class DriverWork : int {
  Call,               // one driver entry: a DMA request, a START, an interrupt wait
  SegmentPack,        // per_segment: quantise a segment's end point and pack it into bank words
  ResultUnpack,       // per_segment: take a segment's bit out of the result words
  FacePack,           // per_segment: convert and pack one face record (9 coordinates)
  CoordinateConvert,  // per_word: quantise one coordinate (3 per end point, 9 per face record)
  WordStore,          // per_word: assemble and store one bank word (ray or face words)
  WordLoad,           // per_word: load one result word and take its bits
  Count
};
constexpr int kDriverWorkKinds = static_cast<int>(DriverWork::Count);
std::string to_string(DriverWork work);

// How the paper's driver works where the paper does not say (docs/calibration.md, "Variants").
// Each choice is a structural alternative of the host model; `rc2000sim calibrate` fits every
// combination and picks the default by cross-validated error.
struct DriverModel {
  // What the driver's CPU time scales with: the segments and face records it handles, whatever
  // the word format, or the coordinates it converts and the bank words it stores and loads (one
  // coordinate per word with one lane, two with two lanes at 15 bits: sec 4.1, 4.2).
  enum class CostUnit { PerSegment, PerWord } cost_unit = CostUnit::PerSegment;
  // How words cross PCI: DMA bursts, or programmed I/O (every word its own PCI transaction; writes
  // posted, reads non-posted, each waiting `pio_read_round_trip` beyond its bus time).
  enum class Transfer { Dma, Pio } transfer = Transfer::Dma;
  // The face records: uploaded once for the run, or with every pass (sec 4.3's pseudocode calls
  // UploadData(rays, triangles) before every START).
  enum class FaceUpload { Once, EveryPass } face_upload = FaceUpload::Once;
  // What the concurrent driver overlaps with the board's pass (sec 4.3): the form factors on the
  // same processor between START and the wait (the pseudocode), or on the second processor of the
  // dual Athlon MP host (sec 5.4) from the moment the step's segments are handed to the driver.
  enum class Overlap { FormFactors, DualCpu } overlap = Overlap::FormFactors;
  sc_core::sc_time pio_read_round_trip = sc_core::SC_ZERO_TIME;
  // The CPU/FPGA split (host_sw/driver/cpu_split.h): optional driver_model.cpu_share (0..1),
  // cpu_balance ("fixed" or "balanced") and cpu_cores (1 or 2); absent or a fixed share of 0: off.
  // A study sweeps them as profile fields ("host.cpu_share"); `run --cpu-share` overrides them.
  CpuSplit cpu_split;
  // The pipelined driver (BoardVisibilityOptions::chunk_rays): optional driver_model.chunk_rays, rays
  // per chunk; absent or 0: off. Swept as "host.chunk_rays"; `run --chunk-rays` overrides it.
  std::uint64_t chunk_rays = 0;

  std::string name() const;  // e.g. "per_word/pio/every_pass/form_factors" (+ "/cpu 0.25 on 2 cpus" when split)
  bool operator==(const DriverModel& other) const;
};
const char* to_string(DriverModel::CostUnit unit);      // "per_segment", "per_word"
const char* to_string(DriverModel::Transfer transfer);  // "dma", "pio"
const char* to_string(DriverModel::FaceUpload upload);  // "once", "every_pass"
const char* to_string(DriverModel::Overlap overlap);    // "form_factors", "dual_cpu"

struct HostProfile {
  std::string name = "custom";
  std::string file;
  double clock_hz = 0;
  std::array<sc_core::sc_time, kHostWorkKinds> work{};      // per unit of HostWork
  std::array<sc_core::sc_time, kDriverWorkKinds> driver{};  // per unit of DriverWork
  sc_core::sc_time interrupt_latency = sc_core::SC_ZERO_TIME;  // device raises -> waiting thread runs
  DriverModel driver_model;
  // The file as loaded, sources included (a calibrated profile: as written; a variant: with its driver
  // model written in), for the energy table, a study's settings and the calibrated profile's writer.
  profiles::ProfileDocument document;
};

// The document with `model`'s four choices written into its driver_model section (each with `source`).
profiles::ProfileDocument with_driver_model(const profiles::ProfileDocument& profile, const DriverModel& model,
                                            const std::string& source);
// `base` (its costs and pio round trip) with `model`'s choices as its driver model, each sourced to the
// variant: the typed profile is set directly (the choices are valid by type), its document alongside.
HostProfile with_driver_model(const HostProfile& base, const DriverModel& model);
// Reads a profile from its document (checks it as load_host_profile does); `origin` names it in errors.
HostProfile host_profile_from_document(const profiles::ProfileDocument& document, const std::string& origin);

// Errors name the file and the field ("work_seconds.form_factor: missing").
HostProfile load_host_profile(const std::string& path);
HostProfile find_host_profile(const std::string& name_or_path);  // configs/hosts/NAME.json or a path

class HostCpuModel : public HostCostSink {
 public:
  explicit HostCpuModel(const HostProfile& profile);

  void charge(HostWork work, std::uint64_t count) override;
  void charge(DriverWork work, std::uint64_t count);
  void sync();                        // wait out the local time; from the host SC_THREAD only
  // The thread has waited in simulated time up to or past `host_time`, its time when the wait began
  // (tlmx::IrqLine::wait_raised_ahead): the local time is spent, and the quantum counts from
  // `host_time`, exactly as after a sync() there. Throws if the thread has not got that far.
  void caught_up(const sc_core::sc_time& host_time);
  // DriverModel::Overlap::DualCpu: from fork_second_cpu() until join_second_cpu(), form factors are
  // computed on the second processor, starting at the fork; the join moves this processor's time
  // to the later of the two. Outside a fork every charge is on this processor.
  // form_factors false: only charge_second_cpu() goes to the second processor (a CPU/FPGA split,
  // host_sw/driver/cpu_split.h, without the dual_cpu overlap).
  void fork_second_cpu(bool form_factors = true);
  void join_second_cpu();
  // Within a fork: `work` on the second processor, after what it already does.
  void charge_second_cpu(HostWork work, std::uint64_t count);
  // A host that talks to nothing (the software-only implementation) need not yield at every
  // quantum: its local time then only grows until sync() is called.
  void set_free_running(bool free_running) { free_running_ = free_running; }
  sc_core::sc_time now() const;       // sc_time_stamp() + local time
  sc_core::sc_time local() const { return keeper_.get_local_time(); }
  // A temporally decoupled bus access ran from local() to `local` (not earlier): the host's local
  // time moves there, syncing only if that passes the quantum. Bus time is not compute time.
  void set_local(const sc_core::sc_time& local);

  int step() const { return steps_done_ + 1; }  // the shooting step being worked on (from 1)
  // A processor that never charges HostWork::Step (a card's driver, host_sw/driver/multi_card_visibility.h)
  // follows the solver's step this way, for the trace's step range.
  void set_step(int step) { steps_done_ = step - 1; }
  // Its charges go to the trace's `track` ("host" unless said otherwise).
  void set_trace(TraceWriter* trace, std::string track = "host") {
    trace_ = trace;
    trace_track_ = std::move(track);
  }

  // Host compute intervals since the last clear, to measure overlap with a board pass.
  void clear_intervals() { intervals_.clear(); }
  sc_core::sc_time overlap(const sc_core::sc_time& from, const sc_core::sc_time& to) const;

  const HostProfile& profile() const { return profile_; }
  std::uint64_t count(HostWork w) const { return counts_[static_cast<int>(w)]; }
  std::uint64_t count(DriverWork w) const { return driver_counts_[static_cast<int>(w)]; }
  sc_core::sc_time time(HostWork w) const { return times_[static_cast<int>(w)]; }
  sc_core::sc_time time(DriverWork w) const { return driver_times_[static_cast<int>(w)]; }
  sc_core::sc_time compute_time() const;  // all HostWork, on either processor
  sc_core::sc_time second_cpu_compute() const { return second_cpu_compute_; }  // the part on the second
  sc_core::sc_time second_cpu_wait() const { return second_cpu_wait_; }  // this one waiting at joins
  sc_core::sc_time driver_time() const;   // all DriverWork

 private:
  void on_second_cpu(HostWork work, const sc_core::sc_time& cost);
  template <class Name>
  void advance(const sc_core::sc_time& cost, Name&& name, bool compute);

  // A quantum keeper whose reset can be dated: the state reset() at `when` would have left (the next
  // sync point at the global quantum's first multiple after `when`, as tlm_global_quantum computes it).
  class Keeper : public tlm_utils::tlm_quantumkeeper {
   public:
    void reset_as_at(const sc_core::sc_time& when) {
      const sc_core::sc_time quantum = tlm::tlm_global_quantum::instance().get();
      m_local_time = sc_core::SC_ZERO_TIME;
      m_next_sync_point = quantum == sc_core::SC_ZERO_TIME ? when : when + (quantum - when % quantum);
    }
    // need_sync() for a host whose time (sc_time_stamp() + local time) is known to be `host_time`.
    bool need_sync_at(const sc_core::sc_time& host_time) const { return host_time >= m_next_sync_point; }
  };

  HostProfile profile_;
  Keeper keeper_;
  std::array<std::uint64_t, kHostWorkKinds> counts_{};
  std::array<sc_core::sc_time, kHostWorkKinds> times_{};
  std::array<std::uint64_t, kDriverWorkKinds> driver_counts_{};
  std::array<sc_core::sc_time, kDriverWorkKinds> driver_times_{};
  int steps_done_ = 0;
  bool forked_ = false;
  bool second_cpu_form_factors_ = true;
  sc_core::sc_time second_cpu_end_ = sc_core::SC_ZERO_TIME;  // absolute time the second processor is busy until
  sc_core::sc_time second_cpu_compute_ = sc_core::SC_ZERO_TIME, second_cpu_wait_ = sc_core::SC_ZERO_TIME;
  bool free_running_ = false;
  TraceWriter* trace_ = nullptr;
  std::string trace_track_ = "host";
  std::vector<std::pair<sc_core::sc_time, sc_core::sc_time>> intervals_;
};

}  // namespace rc
