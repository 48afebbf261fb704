#include "board/fast_wrapper.h"

#include "board/word_format.h"
#include "pipeline/fixed_mt.h"
#include "pipeline/float_mt.h"
#include "tlm/timing.h"

namespace rc::board {

std::vector<std::uint64_t> lane_rays_per_face(const BankLayout& layout, const RaySplit& split) {
  std::vector<std::uint64_t> lanes(layout.lanes, 0);
  for (std::size_t g = 0; g < layout.groups.size(); ++g) {
    const RayGroup& group = layout.groups[g];
    for (unsigned j = 0; j < group.lanes; ++j)
      lanes[group.first_lane + j] = split.rays[g] > j ? (split.rays[g] - j + group.lanes - 1) / group.lanes : 0;
  }
  return lanes;
}

FastWrapper::FastWrapper(const sc_core::sc_module_name& name, const BankLayout& layout, const WrapperTiming& timing,
                         ControlRegs& regs, tlmx::IrqLine& irq, std::vector<tlmx::DmiActivitySink*> bank_sinks,
                         std::vector<std::uint64_t> bank_addresses, WrapperSignals signals)
    : WrapperBase(name, layout, timing, regs, irq, std::move(bank_sinks), std::move(bank_addresses), signals) {
  SC_HAS_PROCESS(FastWrapper);
  SC_THREAD(run);
}

void FastWrapper::run() {
  for (;;) {
    if (!m_regs.start_pending()) sc_core::wait(m_regs.start_event());
    if (!m_regs.start_pending()) continue;
    if (m_regs.start_time() > sc_core::sc_time_stamp()) sc_core::wait(m_regs.start_time() - sc_core::sc_time_stamp());
    // Now, not the START's time: a START written during the last pass (register_map.h) starts at its end.
    const sc_core::sc_time start = next_edge(sc_core::sc_time_stamp());
    begin_pass();
    PassInputs& in = m_in;
    read_inputs(in);
    const TimedPass& timed = timed_pass(in);
    compute(in);
    PassRecord& record = m_record;
    record.start = start;
    record.cycles = timed.timing.total;
    record.end = start + tlmx::cycles(timed.timing.total, m_timing.device_period);
    record.rays = in.rays;
    record.faces = in.faces;
    record.error = in.error;
    record.limit = timed.timing.limit;
    record.lane_rays = timed.lane_rays;
    sc_core::wait(record.end - sc_core::sc_time_stamp());  // the pass: one timed wait
    if (!m_timing_only) write_results(in);
    report_activity(timed.activity);
    complete_pass(record);
  }
}

// A pass's timing depends only on its shape; a run's passes mostly share one, so the last few
// shapes are kept (their PassTiming and lane totals hold vectors and a string).
const FastWrapper::TimedPass& FastWrapper::timed_pass(const PassInputs& in) {
  for (const TimedPass& t : m_timed) {
    if (t.rays == in.rays && t.faces == in.faces && t.clear == in.clear) return t;
  }
  if (m_timed.size() >= kTimedPasses) m_timed.erase(m_timed.begin());
  TimedPass t;
  t.rays = in.rays;
  t.faces = in.faces;
  t.clear = in.clear;
  t.timing = pass_timing(m_layout, m_timing, in.split, in.faces, in.clear);
  t.lane_rays = lane_rays_per_face(m_layout, in.split);
  for (std::uint64_t& r : t.lane_rays) r *= in.faces;
  t.activity = bank_activity(t.timing.banks);
  m_timed.push_back(std::move(t));
  return m_timed.back();
}

// Face-outer, ray-inner over the end points read back from the X, Y, Z banks. The shooter's sheet
// is masked for every ray, and face f for the rays ending on its sheet: those form one contiguous
// range [lo, hi) because the host sends rays grouped by end face in face order (OwnSurfaceRange).
void FastWrapper::compute(const PassInputs& in) {
  const std::size_t R = in.rays;
  if (m_timing_only) return;
  if (m_oracle != nullptr) {  // the answer of a model proven bit-identical (set_oracle)
    m_blocked.assign(m_oracle, m_oracle + R);
    return;
  }
  m_x.resize(R);
  m_y.resize(R);
  m_z.resize(R);
  m_blocked.assign(R, 0);
  // In place when every ray bank's words of the pass lie in one DMI region, else word by word.
  m_ray_words.assign(m_layout.banks_available, nullptr);
  bool in_place = true;
  for (std::size_t g = 0; g < m_layout.groups.size(); ++g) {
    const RayGroup& group = m_layout.groups[g];
    for (unsigned j = 0; j < group.k(); ++j) {
      const std::uint64_t words = group_bank_words(group, j, in.split.packets[g]);
      if (words == 0) continue;
      m_ray_words[group.banks[j]] = bank_words(group.banks[j], words);
      in_place = in_place && m_ray_words[group.banks[j]] != nullptr;
    }
  }
  if (in_place) {
    const std::uint8_t* const* words = m_ray_words.data();
    const unsigned word_bytes = m_word_bytes;
    unpack_rays(m_layout, in.split,
                [words, word_bytes](unsigned b, std::uint64_t word) { return load_word(words[b], word, word_bytes); },
                m_x.data(), m_y.data(), m_z.data());
  } else {
    unpack_rays(m_layout, in.split, [this](unsigned b, std::uint64_t word) { return bank_word(b, word); }, m_x.data(),
                m_y.data(), m_z.data());
  }
  if (m_layout.float_format) return compute_float(in);
  OwnSurfaceRange own(in.mask_start);
  const OwnSurfaceTable table = own_surface_table();
  for (std::uint64_t f = 0; f < in.faces; ++f) {
    own.advance(table.entry(f), f == 0);
    if (in.in_source_sheet(f)) continue;
    const std::uint64_t lo = own.lo, hi = own.hi;
    const pipeline::FaceRecord face = face_record(f);
    pipeline::occlude_face(face, in.start, m_x.data(), m_y.data(), m_z.data(), lo, m_layout.bits, m_blocked.data(),
                           nullptr, in.t_guard);
    pipeline::occlude_face(face, in.start, m_x.data() + hi, m_y.data() + hi, m_z.data() + hi, R - hi, m_layout.bits,
                           m_blocked.data() + hi, nullptr, in.t_guard);
  }
}

// Float lanes: the same streaming order and masks, the codes read back decoded to format values
// and tested with the float pipeline (pipeline/float_mt.h).
void FastWrapper::compute_float(const PassInputs& in) {
  const std::size_t R = in.rays;
  const pipeline::FloatFormat format = *m_layout.float_format;
  m_fx.resize(R);
  m_fy.resize(R);
  m_fz.resize(R);
  for (std::size_t r = 0; r < R; ++r) {
    m_fx[r] = float_from_code(static_cast<std::uint64_t>(m_x[r]), format);
    m_fy[r] = float_from_code(static_cast<std::uint64_t>(m_y[r]), format);
    m_fz[r] = float_from_code(static_cast<std::uint64_t>(m_z[r]), format);
  }
  const pipeline::FloatVec3 start = float_start(in);
  OwnSurfaceRange own(in.mask_start);
  const OwnSurfaceTable table = own_surface_table();
  for (std::uint64_t f = 0; f < in.faces; ++f) {
    own.advance(table.entry(f), f == 0);
    if (in.in_source_sheet(f)) continue;
    const std::uint64_t lo = own.lo, hi = own.hi;
    const pipeline::FloatFaceRecord face = float_face_record(f);
    pipeline::occlude_face(face, start, m_fx.data(), m_fy.data(), m_fz.data(), lo, format, m_blocked.data());
    pipeline::occlude_face(face, start, m_fx.data() + hi, m_fy.data() + hi, m_fz.data() + hi, R - hi, format,
                           m_blocked.data() + hi);
  }
}

// The result words as the per-face read-modify-writes leave them: the OR over faces, on top of the
// bank's old contents unless the pass clears. In place when one DMI region holds the pass's result
// words, else word by word.
void FastWrapper::write_results(const PassInputs& in) {
  if (in.faces == 0) return;
  const unsigned results = m_layout.result_bank;
  if (std::uint8_t* words = writable_bank_words(results, in.split.result_words)) {
    or_results(
        in, [&](std::uint64_t at) { return load_word(words, at, m_word_bytes); },
        [&](std::uint64_t at, std::uint64_t value) { store_word(words, at, m_word_bytes, value); });
  } else {
    or_results(
        in, [&](std::uint64_t at) { return bank_word(results, at); },
        [&](std::uint64_t at, std::uint64_t value) { set_bank_word(results, at, value); });
  }
}

template <class Load, class Store>
void FastWrapper::or_results(const PassInputs& in, Load&& load, Store&& store) {
  for (std::size_t g = 0; g < m_layout.groups.size(); ++g) {
    const RayGroup& group = m_layout.groups[g];
    for (std::uint64_t p = 0; p < in.split.packets[g]; ++p) {
      const std::uint64_t at = in.split.result_base[g] + p;
      std::uint64_t word = in.clear ? 0 : load(at);
      for (unsigned slot = 0; slot < group.lanes; ++slot) {
        const std::uint64_t r = p * group.lanes + slot;
        if (r < in.split.rays[g]) word |= std::uint64_t(m_blocked[in.split.first_ray[g] + r]) << slot;
      }
      store(at, word);
    }
  }
}

}  // namespace rc::board
