#include "board/wrapper_base.h"

#include <algorithm>

#include "board/word_format.h"

namespace rc::board {

WrapperBase::WrapperBase(const sc_core::sc_module_name& name, const BankLayout& layout, const WrapperTiming& timing,
                         ControlRegs& regs, tlmx::IrqLine& irq, std::vector<tlmx::DmiActivitySink*> bank_sinks,
                         std::vector<std::uint64_t> bank_addresses, WrapperSignals signals)
    : sc_core::sc_module(name),
      out("out"),
      m_layout(layout),
      m_timing(timing),
      m_regs(regs),
      m_irq(irq),
      m_word_bytes(layout.word_bits / 8),
      m_sinks(std::move(bank_sinks)),
      m_addresses(std::move(bank_addresses)),
      m_signals(signals) {
  m_stats.lane_rays.assign(layout.lanes, 0);
  m_window.assign(m_addresses.size(), 0);
  m_regs.on_acknowledge([this] { acknowledge(); });
  for (std::size_t b = 0; b < m_addresses.size(); ++b) {
    m_dmi.emplace_back(std::string(this->name()) + ": bank " + std::to_string(b),
                       [this](tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi) {
                         return out->get_direct_mem_ptr(trans, dmi);
                       });
  }
  out.register_invalidate_direct_mem_ptr(this, &WrapperBase::invalidate_direct_mem_ptr);
}

sc_core::sc_time WrapperBase::next_edge(const sc_core::sc_time& t) const {
  const std::uint64_t p = m_timing.device_period.value();
  return sc_core::sc_time::from_value((t.value() + p - 1) / p * p);
}

// Latched by read_inputs: the driver may write the next pass's registers while this one runs.
WrapperBase::OwnSurfaceTable WrapperBase::own_surface_table() {
  return {this, m_layout.mask_bank ? *m_layout.mask_bank : m_layout.face_bank, m_table_first};
}

// The windows put every word of the pass inside its bank: each ray bank's words of the split after
// RAY_BASE, the result words after RESULT_BASE, the table (one word per face) after TABLE_BASE.
std::uint32_t WrapperBase::window_error(const PassInputs& in) const {
  const std::uint64_t capacity = m_layout.bank_words;
  for (std::size_t g = 0; g < m_layout.groups.size(); ++g) {
    const RayGroup& group = m_layout.groups[g];
    for (unsigned j = 0; j < group.k(); ++j)
      if (in.ray_base + group_bank_words(group, j, in.split.packets[g]) > capacity) return reg::kWindowOverrun;
  }
  if (in.result_base + in.split.result_words > capacity) return reg::kWindowOverrun;
  if (m_table_first + in.faces > capacity) return reg::kWindowOverrun;
  return reg::kOk;
}

// The record's 9 words, in place when one DMI region holds them all.
void WrapperBase::face_words(std::uint64_t face_in_set, std::uint64_t words[9]) {
  const unsigned b = m_layout.face_bank;
  const std::uint64_t first = face_in_set * 9;
  if (const std::uint8_t* record = m_dmi[b].read_pointer(m_addresses[b] + first * m_word_bytes, 9 * m_word_bytes)) {
    for (unsigned i = 0; i < 9; ++i) words[i] = load_word(record, i, m_word_bytes);
  } else {
    for (unsigned i = 0; i < 9; ++i) words[i] = bank_word(b, first + i);
  }
}

pipeline::FaceRecord WrapperBase::face_record(std::uint64_t face_in_set) {
  std::uint64_t words[9];
  face_words(face_in_set, words);
  return face_record_from_words(words, m_layout.word_bits);
}

pipeline::FloatFaceRecord WrapperBase::float_face_record(std::uint64_t face_in_set) {
  std::uint64_t words[9];
  face_words(face_in_set, words);
  return float_face_record_from_words(words, *m_layout.float_format);
}

void WrapperBase::read_inputs(PassInputs& in) {
  in.error = reg::kOk;
  in.clear = (m_regs.take_start() & reg::kClear) != 0;
  in.rays = m_regs.pass_value(reg::kRayCount);
  in.faces = m_regs.pass_value(reg::kFaceCount);
  in.face_first = m_regs.pass_value(reg::kFaceFirst);
  in.source_face = m_regs.pass_value(reg::kSourceFace);
  in.source_faces = m_regs.pass_value(reg::kSourceFaces);
  in.mask_start = m_regs.pass_value(reg::kMaskStart);
  in.start = {m_regs.pass_value(reg::kStartX), m_regs.pass_value(reg::kStartY), m_regs.pass_value(reg::kStartZ)};
  in.ray_base = m_regs.pass_value(reg::kRayBase);
  in.result_base = m_regs.pass_value(reg::kResultBase);
  in.table_base = m_regs.pass_value(reg::kTableBase);
  in.t_guard = static_cast<int>(m_regs.pass_value(reg::kTGuard) & reg::kTGuardMask);
  in.split = m_split(in.rays);
  const std::uint64_t table_home = m_layout.mask_bank ? 0 : in.faces * m_layout.face_words();
  m_table_first = table_home + in.table_base;
  for (const RayGroup& group : m_layout.groups)
    for (unsigned b : group.banks) m_window[b] = in.ray_base;
  m_window[m_layout.result_bank] = in.result_base;
  if (!in.split.fits) {
    in.error = reg::kTooManyRays;
  } else if (in.faces > m_layout.max_faces_per_set) {
    in.error = reg::kTooManyFaces;
  } else if (window_error(in) != reg::kOk) {
    in.error = reg::kWindowOverrun;
  } else {
    OwnSurfaceRange masked(in.mask_start);
    const OwnSurfaceTable table = own_surface_table();
    // Every pass of every system reads its whole table: from one pointer when it can (the same
    // entries; a table that crosses DMI regions is walked word by word).
    if (const std::uint8_t* entries = in.faces ? table.in_place(in.faces) : nullptr) {
      masked.next = own_surface_end(entries, in.faces, m_word_bytes, in.mask_start);
    } else {
      for (std::uint64_t f = 0; f < in.faces; ++f) masked.advance(table.entry(f), f == 0);
    }
    if (masked.next > in.rays) in.error = reg::kMaskOverrun;
  }
  const std::int64_t limit = std::int64_t(1) << m_layout.value_bits;  // a code, or a float's bit pattern
  if (in.error == reg::kOk && (in.start.x >= limit || in.start.y >= limit || in.start.z >= limit))
    in.error = reg::kBadStartPoint;
  if (in.error != reg::kOk) {
    in.rays = in.faces = 0, in.split = m_split(0);
    std::fill(m_window.begin(), m_window.end(), 0);
  }
}

void WrapperBase::begin_pass() {
  if (!m_sideband.empty()) {
    m_oracle = m_sideband.front().oracle;
    m_timing_only = m_sideband.front().timing_only;
    m_sideband.pop_front();
  }
  m_regs.set_busy(true);
  write_signal(m_signals.start, true);
  write_signal(m_signals.busy, true);
}

void WrapperBase::complete_pass(const PassRecord& record) {
  m_regs.finish_pass(record.cycles, record.error);
  ++m_stats.passes;
  if (record.error != reg::kOk) ++m_stats.errors;
  m_stats.busy_cycles += record.cycles;
  m_stats.busy += record.end - record.start;
  m_stats.tests += record.rays * record.faces;
  for (std::size_t l = 0; l < record.lane_rays.size(); ++l) m_stats.lane_rays[l] += record.lane_rays[l];
  write_signal(m_signals.start, false);
  write_signal(m_signals.busy, false);
  write_signal(m_signals.done, true);
  write_signal(m_signals.irq, true);
  m_irq.raise();
  if (m_on_pass) m_on_pass(record);
}

std::vector<tlmx::DmiActivity> WrapperBase::bank_activity(const std::vector<BankTraffic>& traffic) const {
  std::vector<tlmx::DmiActivity> activity(traffic.size());
  for (std::size_t b = 0; b < traffic.size(); ++b) {
    const BankTraffic& t = traffic[b];
    tlmx::DmiActivity& a = activity[b];
    a.reads = t.reads;
    a.writes = t.writes;
    a.bytes_read = t.reads * m_word_bytes;
    a.bytes_written = t.writes * m_word_bytes;
    a.busy = sc_core::sc_time::from_value(m_timing.bank_period.value() * t.busy_bank_cycles);
  }
  return activity;
}

void WrapperBase::report_activity(const std::vector<tlmx::DmiActivity>& activity) {
  for (std::size_t b = 0; b < activity.size() && b < m_sinks.size(); ++b) {
    const tlmx::DmiActivity& a = activity[b];
    if (a.reads == 0 && a.writes == 0) continue;
    m_sinks[b]->record_dmi_access(a);
  }
}

// In local-bus addresses (the local bus translates the bank's range); every bank's cache drops what
// overlaps it, and only that.
void WrapperBase::invalidate_direct_mem_ptr(sc_dt::uint64 start, sc_dt::uint64 end) {
  for (tlmx::SparseDmiCache& cache : m_dmi) cache.invalidate(start, end);
}

void WrapperBase::acknowledge() {
  m_irq.lower();
  write_signal(m_signals.done, false);
  write_signal(m_signals.irq, false);
}

}  // namespace rc::board
