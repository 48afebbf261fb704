#include "board/cycle_wrapper.h"

#include "board/word_format.h"

namespace rc::board {

namespace {
constexpr const char* kMsgType = "rc/board/CycleWrapper";
}

CycleWrapper::CycleWrapper(const sc_core::sc_module_name& name, const BankLayout& layout,
                           const WrapperTiming& timing, ControlRegs& regs, tlmx::IrqLine& irq,
                           std::vector<tlmx::DmiActivitySink*> bank_sinks, std::vector<std::uint64_t> bank_addresses,
                           WrapperSignals signals, std::unique_ptr<ClockedLanes> lanes)
    : WrapperBase(name, layout, timing, regs, irq, std::move(bank_sinks), std::move(bank_addresses), signals),
      clock("clock", timing.device_period, 0.5, sc_core::SC_ZERO_TIME, true),
      m_plugged(std::move(lanes)) {
  if (timing.pipeline_latency < 4) SC_REPORT_ERROR(kMsgType, "the cycle-level pipeline needs a latency of at least 4");
  if (m_plugged) {
    if (layout.float_format) SC_REPORT_ERROR(kMsgType, "plugged-in lanes are fixed-point: not with float lanes");
    if (m_plugged->lanes() != layout.lanes.value()) SC_REPORT_ERROR(kMsgType, "plugged-in lanes: not as many as the layout's");
    m_staged.assign(layout.lanes.value(), ClockedLaneInput{});
  }
  SC_HAS_PROCESS(CycleWrapper);
  SC_METHOD(on_edge);
  sensitive << clock.posedge_event();
  dont_initialize();
}

std::uint64_t CycleWrapper::allowed(std::uint64_t t) const {
  return t * m_timing.device_period.value() / m_timing.bank_period.value();
}

// A START written during a pass (register_map.h) begins the next pass on the edge that ends this one,
// as the fast model's does.
void CycleWrapper::on_edge() {
  if (m_running && m_phase == Phase::Tail && m_cycle == m_done_cycle) finish();
  if (!m_running) {
    if (!m_regs.start_pending() || m_regs.start_time() > sc_core::sc_time_stamp()) return;
    begin();
  }
  if (m_plugged) clock_plugged_lanes();
  advance_pipeline();
  controller();
  ++m_cycle;
}

void CycleWrapper::clock_plugged_lanes() {
  m_plugged->clock_edge(m_staged);
  for (ClockedLaneInput& in : m_staged) in.valid = false;
}

void CycleWrapper::begin() {
  m_running = true;
  begin_pass();
  read_inputs(m_in);
  m_record = PassRecord{};
  m_record.start = sc_core::sc_time_stamp();
  m_record.lane_rays.assign(m_layout.lanes, 0);
  m_traffic.assign(m_layout.banks_available, BankTraffic{});
  m_cycle = 0;
  m_phase = Phase::Start;
  m_left = m_timing.pass_start;
  m_face = 0;
  m_own = OwnSurfaceRange(m_in.mask_start);
  m_pipe.clear();
  stream_cycles(m_layout, m_timing, m_in.split, false, &m_limit);
  if (m_layout.float_format) m_float_start = float_start(m_in);
  if (m_layout.results == ResultStore::on_chip) {
    m_store.assign(m_in.split.result_words, 0);
    m_word_group.assign(m_in.split.result_words, 0);
    for (unsigned g = 0; g < m_layout.groups.size(); ++g)
      for (std::uint64_t p = 0; p < m_in.split.packets[g]; ++p) m_word_group[m_in.split.result_base[g] + p] = g;
  }
}

// One cycle of the wrapper's state machine. Phases of zero length fall through without a cycle.
void CycleWrapper::controller() {
  for (;;) {
    switch (m_phase) {
      case Phase::Start:
        if (m_left == 0) {
          m_phase = Phase::NextFace;
          continue;
        }
        --m_left;
        return;
      case Phase::NextFace:
        if (m_face == m_in.faces) {
          if (m_layout.results == ResultStore::on_chip && m_in.faces > 0 && !m_store.empty()) {
            m_phase = Phase::Drain;  // from the cycle after the last packet's write into block RAM
            m_drain_first = m_cycle + m_timing.pipeline_latency;
            m_phase_cycle = 0;
            m_drain_word = m_drain_used = 0;
            return;
          }
          m_phase = Phase::Tail;
          m_done_cycle = m_cycle + m_timing.pipeline_latency + m_timing.pass_finish;
          return;
        }
        m_left = m_timing.face_setup;
        m_phase = Phase::Setup;
        continue;
      case Phase::Setup:
        if (m_left == 0) {
          m_phase = Phase::Fetch;
          m_phase_cycle = 0;
          continue;
        }
        --m_left;
        return;
      case Phase::Fetch: {
        ++m_phase_cycle;
        const std::uint64_t lr = m_timing.bank_read_latency;
        const std::uint64_t words = m_layout.face_words() + (m_layout.mask_in_face_bank() ? 1 : 0);
        const bool face_ready = allowed(m_phase_cycle) >= lr + words;
        const bool mask_ready = !m_layout.mask_bank || allowed(m_phase_cycle) >= lr + 1;
        if (!(face_ready && mask_ready)) return;
        if (m_layout.float_format)
          m_float_face = float_face_record(m_face);  // the words have arrived: latch them
        else
          m_face_record = face_record(m_face);
        m_own.advance(own_surface_table().entry(m_face), m_face == 0);
        m_traffic[m_layout.face_bank].reads += words;
        m_traffic[m_layout.face_bank].busy_bank_cycles += lr + words;
        if (m_layout.mask_bank) {
          m_traffic[*m_layout.mask_bank].reads += 1;
          m_traffic[*m_layout.mask_bank].busy_bank_cycles += lr + 1;
        }
        m_phase = Phase::Stream;
        m_phase_cycle = 0;
        m_issued.assign(m_layout.groups.size(), 0);
        m_result_used = 0;
        return;
      }
      case Phase::Stream: {
        auto all_issued = [&] {
          for (std::size_t g = 0; g < m_issued.size(); ++g)
            if (m_issued[g] < m_in.split.packets[g]) return false;
          return true;
        };
        auto next_face = [&] {
          ++m_face;
          m_phase = Phase::NextFace;
        };
        if (all_issued()) {
          next_face();
          continue;
        }
        ++m_phase_cycle;
        for (unsigned g = 0; g < m_layout.groups.size(); ++g) try_issue(g);
        if (all_issued()) next_face();
        return;
      }
      case Phase::Drain:
        if (m_cycle < m_drain_first) return;  // packets still in the pipeline
        if (drain()) {
          m_phase = Phase::Tail;
          m_done_cycle = m_cycle + 1 + m_timing.pass_finish;
        }
        return;
      case Phase::Tail:
        return;
    }
  }
}

// One cycle of the write-out: every next word whose accesses the phase's bank budget covers.
bool CycleWrapper::drain() {
  ++m_phase_cycle;
  const unsigned results = m_layout.result_bank;
  BankTraffic& traffic = m_traffic[m_layout.result_bank];
  while (m_drain_word < m_store.size()) {
    const RayGroup& group = m_layout.groups[m_word_group[m_drain_word]];
    const bool rmw = !m_in.clear && group.result_accesses() == 2;
    const unsigned accesses = rmw ? 2 : 1;
    if (m_drain_used + accesses > allowed(m_phase_cycle)) return false;  // the result bank's rate
    m_drain_used += accesses;
    const std::uint64_t at = m_drain_word, bits = m_store[at];
    if (m_in.clear) {
      set_bank_word(results, at, bits);
    } else if (rmw) {
      set_bank_word(results, at, bank_word(results, at) | bits);  // shared word: OR onto it
      ++traffic.reads;
    } else if (bits != 0) {
      set_bank_word(results, at, bits);  // one lane per word: write the 1 only when blocked
    }
    ++traffic.writes;  // the write slot is taken either way
    traffic.busy_bank_cycles = traffic.reads + traffic.writes;
    ++m_drain_word;
  }
  return true;
}

bool CycleWrapper::try_issue(unsigned g) {
  const RayGroup& group = m_layout.groups[g];
  const std::uint64_t q = m_issued[g];
  const std::uint64_t t = m_phase_cycle;
  if (q >= m_in.split.packets[g]) return false;
  if (t * group.k() / 3 < q + 1) return false;  // the group's rate
  for (unsigned j = 0; j < group.k(); ++j)
    if (group_bank_words(group, j, q + 1) > allowed(t)) return false;  // a ray bank stalls
  const bool clearing = m_in.clear && m_face == 0;
  if (m_layout.results == ResultStore::bank) {
    const unsigned accesses = clearing ? 1 : group.result_accesses();
    if (m_result_used + accesses > allowed(t)) return false;  // the result bank stalls
    m_result_used += accesses;
  }

  Packet p;
  p.issued = m_cycle;
  p.group = g;
  p.index = q;
  p.clearing = clearing;
  p.face = m_face_record;
  p.float_face = m_float_face;
  p.lanes.resize(group.lanes);
  std::uint64_t word[3];
  for (unsigned a = 0; a < 3; ++a) {
    const WordAddress at = ray_word(group, q, a);
    word[a] = bank_word(at.bank, at.word);
    ++m_traffic[at.bank].reads;
    ++m_traffic[at.bank].busy_bank_cycles;
  }
  const bool source = m_in.in_source_sheet(m_face);
  for (unsigned slot = 0; slot < group.lanes; ++slot) {
    const std::uint64_t r = q * group.lanes + slot;
    if (r >= m_in.split.rays[g]) break;
    Lane& lane = p.lanes[slot];
    lane.valid = true;
    lane.ray = m_in.split.first_ray[g] + r;
    lane.masked = source || (lane.ray >= m_own.lo && lane.ray < m_own.hi);
    const pipeline::FixedVec3 end{coordinate_field(word[0], slot, m_layout.field_bits),
                                  coordinate_field(word[1], slot, m_layout.field_bits),
                                  coordinate_field(word[2], slot, m_layout.field_bits)};
    if (m_plugged) {
      ClockedLaneInput& in = m_staged[group.first_lane + slot];
      in.valid = true;
      in.start = m_in.start;
      in.end = end;
      in.face = m_face_record;
      in.t_guard = m_in.t_guard;
    } else if (m_layout.float_format) {
      const pipeline::FloatFormat format = *m_layout.float_format;
      lane.fdirection = pipeline::segment_direction(m_float_start, float_point_from_codes(end.x, end.y, end.z, format),
                                                    format);
    } else {
      lane.direction = pipeline::segment_direction(m_in.start, end);
    }
    ++m_record.lane_rays[group.first_lane + slot];
  }
  m_pipe.push_back(std::move(p));
  ++m_issued[g];
  return true;
}

// Every packet in flight moves one stage; stage values are computed at their stage positions and
// the packet that reaches the end is written back.
void CycleWrapper::advance_pipeline() {
  const std::uint64_t L = m_timing.pipeline_latency;
  const std::uint64_t s1 = (L - 1) / 3, s2 = 2 * (L - 1) / 3, s3 = L - 1;
  const int bits = m_layout.bits;
  while (!m_pipe.empty() && m_cycle - m_pipe.front().issued == L) {
    write_back(m_pipe.front());
    m_pipe.pop_front();
  }
  if (m_plugged) return;  // their arithmetic is theirs: write_back reads their output ports
  for (Packet& p : m_pipe) {
    const std::uint64_t age = m_cycle - p.issued;
    if (age != s1 && age != s2 && age != s3) continue;
    for (Lane& lane : p.lanes) {
      if (!lane.valid) continue;
      if (m_layout.float_format) {
        const pipeline::FloatFormat format = *m_layout.float_format;
        const pipeline::FloatFaceRecord& face = p.float_face;
        if (age == s1) lane.fs1 = pipeline::stage1(face, m_float_start, lane.fdirection, format);
        if (age == s2) lane.fs2 = pipeline::stage2(face, lane.fs1, format);
        if (age == s3) lane.fs3 = pipeline::stage3(face, lane.fdirection, lane.fs1, lane.fs2, format);
        continue;
      }
      if (age == s1) lane.s1 = pipeline::stage1(p.face, m_in.start, lane.direction, bits);
      if (age == s2) lane.s2 = pipeline::stage2(p.face, lane.s1, bits);
      if (age == s3) lane.s3 = pipeline::stage3(p.face, lane.direction, lane.s1, lane.s2, bits, m_in.t_guard);
    }
  }
}

void CycleWrapper::write_back(const Packet& p) {
  const RayGroup& group = m_layout.groups[p.group];
  std::uint64_t hits = 0;
  for (unsigned slot = 0; slot < p.lanes.size(); ++slot) {
    const Lane& lane = p.lanes[slot];
    bool hit = m_layout.float_format ? lane.fs3.hit : lane.s3.hit;
    if (m_plugged && lane.valid) {
      const unsigned at = group.first_lane + slot;
      if (!m_plugged->out_valid(at)) {
        SC_REPORT_ERROR(kMsgType, ("plugged-in lane " + std::to_string(at) + ": no result at cycle " + std::to_string(m_cycle) +
                                   ", " + std::to_string(m_timing.pipeline_latency) + " cycles after its input")
                                      .c_str());
      }
      hit = m_plugged->out_hit(at);
    }
    if (lane.valid && !lane.masked && hit) hits |= std::uint64_t(1) << slot;
  }
  const std::uint64_t at = m_in.split.result_base[p.group] + p.index;
  if (m_layout.results == ResultStore::on_chip) {
    // Block RAM, cleared at START: the entry is read through one port as the packet nears the end of
    // the pipeline and written through the other; no bank access (CLEAR matters only to the drain).
    m_store[at] |= hits;
    return;
  }
  const unsigned results = m_layout.result_bank;
  BankTraffic& traffic = m_traffic[m_layout.result_bank];
  if (p.clearing) {
    set_bank_word(results, at, hits);  // first face of a clearing pass: write, no read
  } else if (group.result_accesses() == 2) {
    set_bank_word(results, at, bank_word(results, at) | hits);  // shared word: read-modify-write
    ++traffic.reads;
  } else if (hits != 0) {
    set_bank_word(results, at, hits);  // one lane per word: write the 1 only when blocked
  }
  ++traffic.writes;  // the write slot is reserved either way
  traffic.busy_bank_cycles = traffic.reads + traffic.writes;
}

void CycleWrapper::finish() {
  m_record.end = sc_core::sc_time_stamp();
  m_record.cycles = m_cycle;
  m_record.rays = m_in.rays;
  m_record.faces = m_in.faces;
  m_record.error = m_in.error;
  m_record.limit = m_limit;
  m_running = false;
  report_traffic(m_traffic);
  complete_pass(m_record);
}

}  // namespace rc::board
