// What the two wrapper models (fast: one event per pass; cycle-level: a clocked 37-stage pipeline)
// share: the bank layout, the registers, DMI to the banks (through the board's local bus), pass
// bookkeeping, the interrupt, statistics. The wrapper's bank traffic goes through DMI and is
// reported back to the banks (DmiActivitySink), so their counters include it.
//
// DMI: a bank grants one page of its sparse storage per request (tlm/sram_bank.h), so the wrapper
// keeps, per bank, a cache of the page regions granted so far (tlm/sparse_dmi_cache.h): a word is
// read or written through the region of the bank's last access when it holds the word, else the
// region is looked up or requested through `out` (the local bus translates it), and a word that
// straddles two regions is split between them. Invalidations arriving on `out` (translated by the
// local bus) drop exactly the cached regions they overlap; the next access asks again.
#pragma once

#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "board/bank_layout.h"
#include "board/control_regs.h"
#include "board/word_format.h"
#include "board/pass_timing.h"
#include "pipeline/fixed_format.h"
#include "tlm/dmi_activity.h"
#include "tlm/irq_line.h"
#include "tlm/sparse_dmi_cache.h"

namespace rc::board {

// Everything a pass reads from the registers, checked.
struct PassInputs {
  std::uint64_t rays = 0, faces = 0;
  std::uint32_t face_first = 0, source_face = reg::kNoFace, source_faces = 1, mask_start = 0;
  std::uint32_t ray_base = 0, result_base = 0, table_base = 0;  // the windows (register_map.h), in words
  int t_guard = 0;  // T_GUARD [7:0]: the lanes' guard band on t (fixed-point lanes)
  pipeline::FixedVec3 start{0, 0, 0};  // codes (float lanes: the values' bit patterns)
  bool clear = false;
  RaySplit split;
  std::uint32_t error = reg::kOk;

  // Face `face_in_set` of the pass lies on the shooter's sheet (SOURCE_FACE, SOURCE_FACES): masked
  // for every ray, since every segment starts on it.
  bool in_source_sheet(std::uint64_t face_in_set) const {
    const std::uint64_t face = std::uint64_t{face_first} + face_in_set;
    return face >= source_face && face < std::uint64_t{source_face} + source_faces;
  }
};

// Walks the own-surface table (word_format.h) face by face: before face f, advance(entry of f,
// f == 0) makes [lo, hi) the rays of the pass that end on f's sheet, the ones masked for f. Rays come
// grouped by end face in face order and a sheet's faces are contiguous, so a sheet's rays are one
// range: a face that continues its predecessor's sheet (reg::kSameSheet) keeps the range, any other
// face (and the pass's first) takes the next one. With one-sided faces this is the paper's own-face
// table: each entry is its face's count.
struct OwnSurfaceRange {
  std::uint64_t lo, hi, next;
  explicit OwnSurfaceRange(std::uint64_t mask_start) : lo(mask_start), hi(mask_start), next(mask_start) {}
  void advance(std::uint32_t entry, bool first_face) {
    if (!first_face && (entry & reg::kSameSheet) != 0) return;
    lo = next;
    hi = lo + (entry & reg::kSheetRays);
    next = hi;
  }
};

// The entries after the first: their counts where they start a sheet. One loop per word size, with
// no branch on the word size or the face inside it, so the compiler vectorises it (every pass of
// every system runs it over the whole set).
template <unsigned WordBytes>
inline std::uint64_t sheet_starts_sum(const std::uint8_t* entries, std::uint64_t count) {
  std::uint64_t sum = 0;
  for (std::uint64_t f = 1; f < count; ++f) {
    std::conditional_t<WordBytes == 4, std::uint32_t, std::uint64_t> word;
    std::memcpy(&word, entries + f * WordBytes, WordBytes);
    const auto entry = static_cast<std::uint32_t>(word);
    sum += (entry & reg::kSameSheet) == 0 ? entry : 0u;  // a sheet's start: the count is the entry
  }
  return sum;
}

// Where OwnSurfaceRange's walk over `count` table entries (in place, `word_bytes` each, as
// load_word reads them) leaves `next`: mask_start plus the ray counts of the first entry and of every
// entry that starts a sheet. The same sum in any order (integers), so it vectorises; read_inputs
// checks it against the pass's rays for every pass of every system (test
// OwnSurfaceTable.EndIsWhereTheWalkEnds).
inline std::uint64_t own_surface_end(const std::uint8_t* entries, std::uint64_t count, unsigned word_bytes,
                                     std::uint64_t mask_start) {
  if (count == 0) return mask_start;
  const auto first = static_cast<std::uint32_t>(load_word(entries, 0, word_bytes));
  const std::uint64_t rest =
      word_bytes == 4 ? sheet_starts_sum<4>(entries, count) : sheet_starts_sum<8>(entries, count);
  return mask_start + (first & reg::kSheetRays) + rest;
}

// One finished pass, for reports and traces.
struct PassRecord {
  sc_core::sc_time start, end;  // first device clock edge of the pass, DONE (interrupt raised)
  std::uint64_t rays = 0, faces = 0, cycles = 0;
  std::vector<std::uint64_t> lane_rays;  // rays each lane streamed, over all faces of the pass
  std::uint32_t error = reg::kOk;
  std::string limit;                     // what bounded the stream
};

struct WrapperStats {
  std::uint64_t passes = 0, errors = 0;
  std::uint64_t tests = 0;              // ray slots streamed: rays x faces, masked ones included
  std::uint64_t busy_cycles = 0;
  sc_core::sc_time busy = sc_core::SC_ZERO_TIME;
  std::vector<std::uint64_t> lane_rays; // per lane, summed over passes
};

struct WrapperSignals {  // optional, for VCD traces; written when they change
  sc_core::sc_signal<bool, sc_core::SC_MANY_WRITERS>* start = nullptr;
  sc_core::sc_signal<bool, sc_core::SC_MANY_WRITERS>* busy = nullptr;
  sc_core::sc_signal<bool, sc_core::SC_MANY_WRITERS>* done = nullptr;
  sc_core::sc_signal<bool, sc_core::SC_MANY_WRITERS>* irq = nullptr;
};

class WrapperBase : public sc_core::sc_module {
 protected:
  const std::uint8_t* m_oracle = nullptr;
  bool m_timing_only = false;


 public:
  tlm_utils::simple_initiator_socket<WrapperBase> out;  // to the board's local bus (banks)

  WrapperBase(const sc_core::sc_module_name& name, const BankLayout& layout, const WrapperTiming& timing,
              ControlRegs& regs, tlmx::IrqLine& irq, std::vector<tlmx::DmiActivitySink*> bank_sinks,
              std::vector<std::uint64_t> bank_addresses, WrapperSignals signals);

  const BankLayout& layout() const { return m_layout; }
  const WrapperTiming& timing() const { return m_timing; }
  const WrapperStats& stats() const { return m_stats; }
  void on_pass(std::function<void(const PassRecord&)> callback) { m_on_pass = std::move(callback); }
  // The signals written from now on ({}: none). Each change is an update and a delta cycle that only
  // a VCD trace of them sees; a system nobody traces (a timing study's) drops them before sc_start.
  void set_signals(WrapperSignals signals) { m_signals = signals; }

  // The lanes' answer for the next pass, one flag per ray in bank order, computed elsewhere by a
  // model proven bit-identical to them (a recording, or a culled kernel). The pass then copies it
  // instead of computing every ray against every face; its timing, bank traffic and result words
  // are unchanged. nullptr: compute. Only the fast model supports it.
  // The pipelined driver sets the next pass's answer before this pass has begun in simulated time:
  // each setting is queued and a pass takes the oldest at its start (none queued: the current one).
  void set_oracle(const std::uint8_t* flags) { m_sideband.push_back({flags, m_timing_only, true}); }
  // Timing replay: the next passes neither compute nor write result words (their values are not
  // wanted); timing and the banks' traffic counters are unchanged. Only the fast model.
  void set_timing_only(bool timing_only) {
    if (!m_sideband.empty() && m_sideband.back().open) {
      m_sideband.back().timing_only = timing_only;
      m_sideband.back().open = false;
    } else {
      m_sideband.push_back({m_sideband.empty() ? m_oracle : m_sideband.back().oracle, timing_only, false});
    }
  }

  // First device clock edge at or after t (edges at multiples of the device period from time 0).
  sc_core::sc_time next_edge(const sc_core::sc_time& t) const;

  // The DMI regions cached for bank b, in local-bus addresses, and how many were requested / dropped.
  const tlmx::SparseDmiCache& dmi_cache(unsigned b) const { return m_dmi[b]; }

 protected:
  // Word `index` of bank b (word_bits wide, little-endian), through DMI: in place when one region
  // holds the word (always, for pages of at least a word), else pieced together across regions.
  // Ray and result banks are read and written through the pass's window (RAY_BASE, RESULT_BASE,
  // latched by read_inputs): word `index` of the pass is word window + index of the bank.
  std::uint64_t bank_word(unsigned b, std::uint64_t index) {
    const std::uint64_t address = m_addresses[b] + (m_window[b] + index) * m_word_bytes;
    if (const std::uint8_t* p = m_dmi[b].read_pointer(address, m_word_bytes)) return load_word(p, 0, m_word_bytes);
    std::uint8_t bytes[8];
    m_dmi[b].read(address, bytes, m_word_bytes);
    return load_word(bytes, 0, m_word_bytes);
  }
  // The first `words` words of bank b in place, when one DMI region holds them all (a pass's words
  // usually lie in one page), else nullptr: bulk loops then run at raw-pointer speed, and fall back
  // to bank_word / set_bank_word when they cross a region.
  const std::uint8_t* bank_words(unsigned b, std::uint64_t words) {
    return m_dmi[b].read_pointer(m_addresses[b] + m_window[b] * m_word_bytes, words * m_word_bytes);
  }
  std::uint8_t* writable_bank_words(unsigned b, std::uint64_t words) {
    return m_dmi[b].write_pointer(m_addresses[b] + m_window[b] * m_word_bytes, words * m_word_bytes);
  }
  void set_bank_word(unsigned b, std::uint64_t index, std::uint64_t value) {
    const std::uint64_t address = m_addresses[b] + (m_window[b] + index) * m_word_bytes;
    if (std::uint8_t* p = m_dmi[b].write_pointer(address, m_word_bytes)) return store_word(p, 0, m_word_bytes, value);
    std::uint8_t bytes[8];
    store_word(bytes, 0, m_word_bytes, value);
    m_dmi[b].write(address, bytes, m_word_bytes);
  }
  // Registers -> `in`, with error checks. Fills the caller's object so that a wrapper reading one
  // pass after another reuses its vectors; the ray split is kept for the last ray count.
  void read_inputs(PassInputs& in);
  // The own-surface table in its bank (word_format.h): entry(f) for face f of the set.
  struct OwnSurfaceTable {
    WrapperBase* wrapper;
    unsigned bank;
    std::uint64_t first;  // word index of face 0's entry
    std::uint32_t entry(std::uint64_t face_in_set) const {
      return static_cast<std::uint32_t>(wrapper->bank_word(bank, first + face_in_set));
    }
    // Entries 0 .. count-1 in place (entry f is load_word(pointer, f)) when one DMI region holds
    // them all, else nullptr (then entry() word by word).
    const std::uint8_t* in_place(std::uint64_t count) const {
      return wrapper->m_dmi[bank].read_pointer(
          wrapper->m_addresses[bank] + (wrapper->m_window[bank] + first) * wrapper->m_word_bytes, count * wrapper->m_word_bytes);
    }
  };
  OwnSurfaceTable own_surface_table();
  pipeline::FaceRecord face_record(std::uint64_t face_in_set);
  // Float lanes (layout.float_format set): the record's words decoded as format values.
  pipeline::FloatFaceRecord float_face_record(std::uint64_t face_in_set);
  // Float lanes: the start point's registers (bit patterns) as format values.
  pipeline::FloatVec3 float_start(const PassInputs& in) const {
    return float_point_from_codes(in.start.x, in.start.y, in.start.z, *m_layout.float_format);
  }
  void begin_pass();
  void complete_pass(const PassRecord& record);
  // A pass's bank traffic as each bank's sink takes it (DmiActivity), and the reporting of it: a
  // model that repeats a pass shape keeps the activity with the shape instead of converting each pass.
  std::vector<tlmx::DmiActivity> bank_activity(const std::vector<BankTraffic>& traffic) const;
  void report_activity(const std::vector<tlmx::DmiActivity>& activity);
  void report_traffic(const std::vector<BankTraffic>& traffic) { report_activity(bank_activity(traffic)); }

  BankLayout m_layout;
  WrapperTiming m_timing;
  ControlRegs& m_regs;
  tlmx::IrqLine& m_irq;
  unsigned m_word_bytes;

 private:
  void acknowledge();
  std::uint32_t window_error(const PassInputs& in) const;
  void face_words(std::uint64_t face_in_set, std::uint64_t words[9]);
  void invalidate_direct_mem_ptr(sc_dt::uint64 start, sc_dt::uint64 end);
  void write_signal(sc_core::sc_signal<bool, sc_core::SC_MANY_WRITERS>* s, bool v) {
    if (s != nullptr && s->read() != v) s->write(v);
  }

  struct Sideband {
    const std::uint8_t* oracle;
    bool timing_only;
    bool open;  // set_oracle without its set_timing_only yet
  };
  std::deque<Sideband> m_sideband;
  std::vector<tlmx::DmiActivitySink*> m_sinks;
  std::vector<std::uint64_t> m_addresses;
  std::vector<tlmx::SparseDmiCache> m_dmi;  // per bank
  std::vector<std::uint64_t> m_window;      // per bank: the pass's word offset (ray and result banks)
  std::uint64_t m_table_first = 0;          // word index of the pass's own-surface table entry of face 0
  WrapperSignals m_signals;
  WrapperStats m_stats;
  std::function<void(const PassRecord&)> m_on_pass;
  RaySplitMemo m_split{m_layout};
};

}  // namespace rc::board
