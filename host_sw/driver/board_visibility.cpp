#include "host_sw/driver/board_visibility.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "board/register_map.h"
#include "board/word_format.h"
#include "host_sw/driver/trace_writer.h"

namespace rc {

namespace reg = board::reg;
using sc_core::sc_time;

BoardVisibility::BoardVisibility(BoardPorts ports, HostCpuModel& cpu, BoardVisibilityOptions options, TraceWriter* trace)
    : ports_(std::move(ports)),
      pci_(ports_.pci),
      cpu_(cpu),
      options_(options),
      trace_(trace),
      layout_(ports_.board.layout),
      word_bytes_(ports_.board.layout.word_bits / 8),
      rays_per_batch_(ports_.board.layout.max_rays_per_batch),
      faces_per_set_(ports_.board.layout.max_faces_per_set) {
  // Batches and sets divide the work below; make_bank_layout refuses banks too small for one of each
  // (bank_capacity_problem), so an empty limit here is a bug, not a bad profile.
  if (rays_per_batch_ == 0 || faces_per_set_ == 0) {
    throw std::logic_error("BoardVisibility: the bank layout holds " + std::to_string(rays_per_batch_) +
                           " rays per batch and " + std::to_string(faces_per_set_) +
                           " faces per set; make_bank_layout should have refused banks of " +
                           std::to_string(layout_.bank_words) + " words");
  }
  if (options_.oracle != nullptr && ports_.board.model != board::WrapperModel::fast) {
    throw std::invalid_argument("a visibility oracle needs the fast wrapper model (the cycle-level one always computes)");
  }
  pipeline::validate_t_guard(options_.t_guard);
  if (options_.t_guard != 0 && layout_.float_format) {
    throw std::invalid_argument("a t guard band needs fixed-point lanes; float lanes (" + layout_.float_format->to_string() +
                                ") have no LSB to count");
  }
  if (options_.cpu_split.on() && options_.oracle == nullptr && options_.cpu_kernel == nullptr) {
    throw std::invalid_argument("a CPU/FPGA split needs a host kernel bit-identical to the lanes (cpu_kernel or oracle)");
  }
  pio_extension_.access_bytes = word_bytes_;
  pio_extension_.read_round_trip = cpu_.profile().driver_model.pio_read_round_trip;
}

std::size_t BoardVisibility::batch_size(std::size_t b) const {
  return std::min(rays_, batch_first(b) + rays_per_batch_) - batch_first(b);
}

std::size_t BoardVisibility::set_size(std::size_t s) const {
  return std::min(faces_.size(), set_first(s) + faces_per_set_) - set_first(s);
}

// ---- faces ------------------------------------------------------------------------------------------

void BoardVisibility::load_triangles(const std::vector<Triangle>& faces) {
  const int bits = layout_.bits;
  if (faces.size() > faces_per_set_ && !options_.allow_batching) {
    throw std::invalid_argument("the scene has " + std::to_string(faces.size()) + " faces but one face set holds " +
                                std::to_string(faces_per_set_) + " (face bank " +
                                std::to_string(ports_.board.bank_capacity_bytes) +
                                " bytes); allow batching to split them into sets");
  }
  faces_.clear();
  faces_.reserve(faces.size());
  if (layout_.float_format) {  // float lanes: each value's bit pattern (word_format.h)
    const pipeline::FloatFormat format = *layout_.float_format;
    for (const Triangle& t : faces) {
      const pipeline::FloatFaceRecord r = pipeline::make_float_face_record(t, format);
      auto code = [&](double v) { return static_cast<std::int64_t>(board::float_code(v, format)); };
      faces_.push_back({{code(r.v0.x), code(r.v0.y), code(r.v0.z)},
                        {code(r.edge1.x), code(r.edge1.y), code(r.edge1.z)},
                        {code(r.edge2.x), code(r.edge2.y), code(r.edge2.z)}});
    }
  } else {
    for (const Triangle& t : faces) faces_.push_back(pipeline::make_face_record(t, bits));  // charged per upload
  }
  if (options_.oracle != nullptr) options_.oracle->load_faces(faces, sheets());
  if (options_.cpu_kernel != nullptr && options_.cpu_kernel != options_.oracle) options_.cpu_kernel->load_faces(faces, sheets());
  stats_.face_sets = faces_.empty() ? 0 : (faces_.size() + faces_per_set_ - 1) / faces_per_set_;
  resident_set_ = -1;
  mask_key_ = {};  // new faces, new sheets: a table made for the old ones is not theirs
  if (pipelined()) check_chunks();
  if (stats_.face_sets == 1) upload_faces(0);  // resident for the whole run
}

// A set already in the face bank is sent again (DriverModel::FaceUpload::EveryPass) as a transfer
// that carries no bytes: the bank holds exactly those words already, so only time and traffic count.
void BoardVisibility::upload_faces(std::size_t set) {
  const std::size_t n = set_size(set);
  charge_faces(n);
  const bool resident = resident_set_ == static_cast<long>(set);
  if (resident) {
    face_words_.resize(n * 9 * word_bytes_);  // contents immaterial (they are the set's words already)
  } else {
    face_words_.assign(n * 9 * word_bytes_, 0);
    std::uint64_t words[9];
    for (std::size_t f = 0; f < n; ++f) {
      board::face_record_words(faces_[set_first(set) + f], words);
      for (unsigned i = 0; i < 9; ++i) board::store_word(face_words_.data(), f * 9 + i, word_bytes_, words[i]);
    }
  }
  transfer(tlmx::DmaDirection::to_device, face_words_.data(), ports_.board.bank_address(layout_.face_bank),
           face_words_.size(), "faces", resident);
  resident_set_ = static_cast<long>(set);
  ++stats_.face_set_uploads;
}

// ---- one step -----------------------------------------------------------------------------------------

// A point as the lanes take it: quantised to 0.N codes, or (float lanes) rounded to the format
// (round_point) and held as the values' bit patterns.
pipeline::FixedVec3 BoardVisibility::end_point_code(const Vec3& p) const {
  if (!layout_.float_format) return pipeline::quantize_point(p, layout_.bits);
  const pipeline::FloatFormat format = *layout_.float_format;
  const pipeline::FloatVec3 v = pipeline::round_point(p, format);
  return {static_cast<std::int64_t>(board::float_code(v.x, format)), static_cast<std::int64_t>(board::float_code(v.y, format)),
          static_cast<std::int64_t>(board::float_code(v.z, format))};
}

// Rays grouped by end face in face order (the solver already sends them so; otherwise a stable
// counting sort), quantised into the hardware's format.
void BoardVisibility::order_segments(const SegmentBatch& batch) {
  rays_ = batch.size();
  identity_order_ = std::is_sorted(batch.end_faces.begin(), batch.end_faces.end());
  order_.resize(rays_);
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  if (!identity_order_)
    std::stable_sort(order_.begin(), order_.end(),
                     [&](std::size_t a, std::size_t b) { return batch.end_faces[a] < batch.end_faces[b]; });
  end_faces_.resize(rays_);
  x_.resize(rays_);
  y_.resize(rays_);
  z_.resize(rays_);
  for (std::size_t i = 0; i < rays_; ++i) {
    const std::size_t s = order_[i];
    const pipeline::FixedVec3 e = end_point_code(batch.ends[s]);
    end_faces_[i] = batch.end_faces[s];
    x_[i] = e.x;
    y_[i] = e.y;
    z_[i] = e.z;
  }
  start_ = end_point_code(batch.start);
  set_source(batch.source_face);
}

// SOURCE_FACE and SOURCE_FACES: the shooter's sheet (scenes/sheets.h), or no face.
void BoardVisibility::set_source(int source_face) {
  if (source_face < 0) {
    source_face_ = reg::kNoFace;
    source_faces_ = 1;
    return;
  }
  source_face_ = static_cast<std::uint32_t>(sheets().first(source_face));
  source_faces_ = static_cast<std::uint32_t>(sheets().size_of(source_face));
}

// Batches of rays, each against every face set; the set already in the face bank goes first.
void BoardVisibility::plan_passes() {
  passes_.clear();
  next_pass_ = 0;
  const std::size_t batches = (rays_ + rays_per_batch_ - 1) / rays_per_batch_;
  const std::size_t sets = stats_.face_sets;
  long resident = resident_set_;
  for (std::size_t b = 0; b < batches; ++b) {
    std::vector<std::size_t> order;
    if (resident >= 0) order.push_back(static_cast<std::size_t>(resident));
    for (std::size_t s = 0; s < sets; ++s)
      if (static_cast<long>(s) != resident) order.push_back(s);
    for (std::size_t i = 0; i < order.size(); ++i) passes_.push_back({b, order[i], i == 0, i + 1 == order.size()});
    if (!order.empty()) resident = static_cast<long>(order.back());  // what the next batch finds in the bank
  }
  stats_.ray_batches += batches;
  stats_.max_batches_per_step = std::max<std::uint64_t>(stats_.max_batches_per_step, batches);
}

void BoardVisibility::submit(const SegmentBatch& batch) {
  timing_only_ = false;
  batch.check();
  const std::size_t board_rays = batch.size() - cpu_segments_of(batch.size());
  if (board_rays > rays_per_batch_ && !options_.allow_batching) {
    throw std::invalid_argument("a step has " + std::to_string(board_rays) + " segments but one batch holds " +
                                std::to_string(rays_per_batch_) + " (ray and result banks of " +
                                std::to_string(ports_.board.bank_capacity_bytes) +
                                " bytes); allow batching to split them");
  }
  begin_step(batch.size());
  order_segments(batch);
  blocked_.assign(rays_, 0);
  if (options_.oracle != nullptr) ask_oracle(batch);
  answer_cpu_part(batch);
  rays_ = total_rays_ - cpu_rays_;
  if (!pipelined()) charge_end_points(rays_);  // pipelined: per chunk, while the board works
  run_step();
  if (!options_.concurrent) cpu_.join_second_cpu();  // the serial driver returns with every answer
}

// Timing replay: a step of `segments` segments with blank data. The rays are "grouped" trivially,
// the buffers moved have their real sizes, and the lanes copy an all-clear answer.
void BoardVisibility::submit_timing_only(std::size_t segments, int source_face) {
  if (ports_.board.model != board::WrapperModel::fast) {
    throw std::invalid_argument("timing replay needs the fast wrapper model");
  }
  begin_step(segments);
  if (!timing_only_ || rays_ != segments - cpu_rays_) {  // a replay's steps mostly have the same size: set up once
    // Since the last real step, order_ is the identity and end_faces_ and blocked_ are zeros at any
    // size: only entries beyond what they held are new (so a step of another size clears nothing).
    if (!timing_only_) {
      order_.clear();
      end_faces_.clear();
      blocked_.clear();
    }
    rays_ = segments - cpu_rays_;
    const std::size_t had = order_.size();
    order_.resize(rays_);
    if (rays_ > had) std::iota(order_.begin() + static_cast<long>(had), order_.end(), had);
    end_faces_.resize(rays_, 0);
    blocked_.resize(rays_, 0);
  }
  start_ = {0, 0, 0};
  set_source(source_face);
  if (!pipelined()) charge_end_points(rays_);
  timing_only_ = true;
  run_step();
  if (!options_.concurrent) cpu_.join_second_cpu();
}

void BoardVisibility::collect_timing_only() {
  finish_step();
  cpu_.join_second_cpu();
}

void BoardVisibility::run_step() {
  if (rays_ == 0 || faces_.empty()) {
    passes_.clear();
    next_pass_ = 0;
    chunks_ = 0;
    if (options_.cpu_split.cores == 1) charge_cpu_part();
    return;
  }
  if (pipelined()) return start_chunks();
  plan_passes();
  start_pass(passes_[0]);
  if (options_.cpu_split.cores == 1) charge_cpu_part();  // while the board works its first pass
  if (options_.concurrent) return;  // the rest in collect(), after the host's form factors
  finish_pass(passes_[0]);
  for (std::size_t p = 1; p < passes_.size(); ++p) {
    start_pass(passes_[p]);
    finish_pass(passes_[p]);
  }
  next_pass_ = passes_.size();
  board_part_done();
}

void BoardVisibility::collect(std::vector<std::uint8_t>& blocked) {
  finish_step();
  cpu_.join_second_cpu();
  blocked.assign(total_rays_, 0);
  for (std::size_t i = 0; i < total_rays_; ++i) blocked[order_[i]] = blocked_[i];
}

void BoardVisibility::finish_step() {
  if (pipelined()) return finish_chunks();
  if (next_pass_ < passes_.size()) {
    finish_pass(passes_[next_pass_]);  // started by submit()
    for (++next_pass_; next_pass_ < passes_.size(); ++next_pass_) {
      start_pass(passes_[next_pass_]);
      finish_pass(passes_[next_pass_]);
    }
    board_part_done();
  }
}

// The oracle answers in segment order; the banks hold the rays in end-face order.
void BoardVisibility::ask_oracle(const SegmentBatch& batch) {
  std::vector<std::uint8_t> answer;
  options_.oracle->submit(batch);
  options_.oracle->collect(answer);
  oracle_answer_.resize(rays_);
  for (std::size_t i = 0; i < rays_; ++i) oracle_answer_[i] = answer[order_[i]];
}

// ---- one pass ----------------------------------------------------------------------------------------

void BoardVisibility::upload_rays(std::size_t batch) {
  const std::size_t first = batch_first(batch);
  const board::RaySplit& split = split_(batch_size(batch));
  if (!timing_only_) {
    board::pack_rays(layout_, split, x_.data() + first, y_.data() + first, z_.data() + first, images_);
    blank_images_rays_ = kNoBlankImages;
  } else if (blank_images_rays_ != batch_size(batch)) {  // only their sizes matter: made once per size
    board::size_ray_images(layout_, split, images_);
    blank_images_rays_ = batch_size(batch);
  }
  std::uint64_t bytes = 0;
  for (const auto& image : images_) bytes += image.size();
  charge_ray_words(bytes / word_bytes_);
  for (unsigned b = 0; b < images_.size(); ++b) {
    transfer(tlmx::DmaDirection::to_device, images_[b].data(), ports_.board.bank_address(b), images_[b].size(), "rays",
             timing_only_);
  }
}

// The own-surface table (board/word_format.h), one word per face of the set: the batch's rays that
// end on the face's sheet, with reg::kSameSheet on a face that continues its predecessor's sheet in
// the set. A one-sided face is its own sheet: its word is the count of rays ending on it, the paper's
// own-face table. MASK_START (start_pass) is the first ray ending on the set's first face's sheet.
void BoardVisibility::upload_mask(std::size_t first_ray, std::size_t ray_count, std::size_t set, std::uint64_t table_base) {
  const std::size_t n = set_size(set);
  // A timing replay's rays all end on face 0 (submit_timing_only), so its table depends on these three
  // alone: made once, then sent again as it is (still for real: the wrapper reads and checks it).
  const MaskKey key{first_ray, ray_count, set};
  if (!timing_only_ || !(mask_key_ == key)) {
    fill_mask(first_ray, ray_count, set);
    mask_key_ = timing_only_ ? key : MaskKey{};
  }
  const std::uint64_t address = (layout_.mask_bank ? ports_.board.bank_address(*layout_.mask_bank)
                                                   : ports_.board.bank_address(layout_.face_bank) + n * 9 * word_bytes_) +
                                table_base * word_bytes_;
  transfer(tlmx::DmaDirection::to_device, mask_words_.data(), address, mask_words_.size(), "own-face table");  // the trace's name since before sheets
}

void BoardVisibility::fill_mask(std::size_t first_ray, std::size_t ray_count, std::size_t set) {
  const auto begin = end_faces_.begin() + static_cast<long>(first_ray);
  const auto end = begin + static_cast<long>(ray_count);
  const int f0 = static_cast<int>(set_first(set));
  const std::size_t n = set_size(set);
  const int f1 = f0 + static_cast<int>(n);
  const FaceSheets& sheets = this->sheets();
  mask_words_.assign(n * word_bytes_, 0);
  // One run of rays ending on one sheet at a time: O(sheets with rays x log rays), not O(faces x log rays).
  // A sheet that starts in the set holds rays ending beyond it (on its faces after the set) too.
  for (auto it = std::lower_bound(begin, end, sheets.first(f0)); it != end && sheets.first(*it) < f1;) {
    const int first = sheets.first(*it), last = sheets.end(*it);
    const auto next = std::lower_bound(it, end, last);
    const auto rays = static_cast<std::uint32_t>(next - it);
    if (rays > reg::kSheetRays) throw std::logic_error("more rays end on one sheet than the own-surface table counts");
    for (int g = std::max(first, f0); g < std::min(last, f1); ++g) {
      const std::uint32_t same = g > std::max(first, f0) ? reg::kSameSheet : 0u;
      board::store_word(mask_words_.data(), static_cast<std::size_t>(g - f0), word_bytes_, rays | same);
    }
    it = next;
  }
}

void BoardVisibility::start_pass(const Pass& pass) {
  if (pass.first_of_batch) upload_rays(pass.batch);
  const bool faces_every_pass = cpu_.profile().driver_model.face_upload == DriverModel::FaceUpload::EveryPass;
  if (resident_set_ != static_cast<long>(pass.set) || faces_every_pass) upload_faces(pass.set);
  upload_mask(batch_first(pass.batch), batch_size(pass.batch), pass.set);
  const auto begin = end_faces_.begin() + static_cast<long>(batch_first(pass.batch));
  const auto mask_start = std::lower_bound(begin, begin + static_cast<long>(batch_size(pass.batch)),
                                           sheets().first(static_cast<int>(set_first(pass.set)))) - begin;
  cpu_.charge(DriverWork::Call, 1);
  const sc_time from = cpu_.now();
  if (source_faces_ != source_faces_written_) {  // a parameter register keeps its value: written on change
    write_registers(reg::kSourceFaces, {source_faces_});
    source_faces_written_ = source_faces_;
  }
  if (static_cast<std::uint32_t>(options_.t_guard) != t_guard_written_) {  // written once, before the first pass
    write_registers(reg::kTGuard, {static_cast<std::uint32_t>(options_.t_guard)});
    t_guard_written_ = static_cast<std::uint32_t>(options_.t_guard);
  }
  write_registers(reg::kRayCount,
                  {static_cast<std::uint32_t>(batch_size(pass.batch)), static_cast<std::uint32_t>(set_size(pass.set)),
                   static_cast<std::uint32_t>(set_first(pass.set)), source_face_, static_cast<std::uint32_t>(start_.x),
                   static_cast<std::uint32_t>(start_.y), static_cast<std::uint32_t>(start_.z),
                   static_cast<std::uint32_t>(mask_start)});
  if (ports_.sideband.before_start) {
    ports_.sideband.before_start(options_.oracle != nullptr ? oracle_answer_.data() + batch_first(pass.batch) : nullptr,
                                 timing_only_);
  }
  cpu_.clear_intervals();  // host compute from here on may overlap the pass
  write_registers(reg::kControl, {reg::kStart | (pass.first_of_batch ? reg::kClear : 0u)});
  ++passes_started_;
  host_event("start pass", from);
}

void BoardVisibility::finish_pass(const Pass& pass) {
  cpu_.charge(DriverWork::Call, 1);
  const sc_time from = cpu_.now();
  wait_for_interrupt();
  stats_.waiting += sc_core::sc_time_stamp() - from;
  host_event("wait for interrupt", from);
  if (tracing()) trace_->instant(track("irq"), "seen by host", sc_core::sc_time_stamp());
  const std::uint32_t status = read_register(reg::kStatus);
  write_registers(reg::kStatus, {reg::kDone | reg::kError});  // acknowledge: lowers the interrupt
  if (status & reg::kError) {
    throw std::runtime_error("the board reported error " + std::to_string(read_register(reg::kErrorCode)) +
                             " (register_map.h ErrorCode) for a pass of " + std::to_string(batch_size(pass.batch)) +
                             " rays and " + std::to_string(set_size(pass.set)) + " faces");
  }
  stats_.overlap += cpu_.overlap(last_record_.start, last_record_.end);
  if (pass.last_of_batch) read_results(pass.batch);
}

void BoardVisibility::read_results(std::size_t batch) {
  const board::RaySplit& split = split_(batch_size(batch));
  if (timing_only_) {
    result_words_.resize(split.result_words * word_bytes_);  // moved without data: contents immaterial
  } else {
    result_words_.assign(split.result_words * word_bytes_, 0);
  }
  transfer(tlmx::DmaDirection::to_host, result_words_.data(), ports_.board.bank_address(layout_.result_bank),
           result_words_.size(), "results", timing_only_);
  if (!timing_only_) board::unpack_results(layout_, split, result_words_.data(), blocked_.data() + batch_first(batch));
  charge_results(batch_size(batch), split.result_words);
}

// ---- the driver's CPU work, in the profile's cost unit ---------------------------------------------

bool BoardVisibility::dual_cpu() const {
  return options_.concurrent && cpu_.profile().driver_model.overlap == DriverModel::Overlap::DualCpu;
}

bool BoardVisibility::per_word() const {
  return cpu_.profile().driver_model.cost_unit == DriverModel::CostUnit::PerWord;
}

void BoardVisibility::charge_end_points(std::size_t rays) {
  if (per_word()) {
    cpu_.charge(DriverWork::CoordinateConvert, 3 * rays);
  } else {
    cpu_.charge(DriverWork::SegmentPack, rays);
  }
}

void BoardVisibility::charge_ray_words(std::uint64_t words) {
  if (per_word() && words != 0) cpu_.charge(DriverWork::WordStore, words);
}

void BoardVisibility::charge_faces(std::size_t faces) {
  if (faces == 0) return;
  if (per_word()) {
    cpu_.charge(DriverWork::CoordinateConvert, 9 * faces);
    cpu_.charge(DriverWork::WordStore, 9 * faces);
  } else {
    cpu_.charge(DriverWork::FacePack, faces);
  }
}

void BoardVisibility::charge_results(std::size_t rays, std::uint64_t result_words) {
  if (per_word()) {
    cpu_.charge(DriverWork::WordLoad, result_words);
  } else {
    cpu_.charge(DriverWork::ResultUnpack, rays);
  }
}

// Runs in the wrapper's thread when a pass completes.
void BoardVisibility::pass_finished(const board::PassRecord& r) {
  last_record_ = r;
  ++stats_.passes;
  stats_.tests += r.rays * r.faces;
  stats_.fpga_busy += r.end - r.start;
  if (last_limit_ == nullptr || last_limit_name_ != r.limit) {  // a run's passes mostly share one limit
    last_limit_ = &stats_.limits[r.limit];  // a map's elements stay where they are
    last_limit_name_ = r.limit;
  }
  PassLimitTally& limit = *last_limit_;
  ++limit.passes;
  limit.fpga_busy += r.end - r.start;
  if (!tracing()) return;
  for (std::size_t l = 0; l < r.lane_rays.size(); ++l) {
    trace_->complete(track("lane ") + std::to_string(l), "pass", r.start, r.end,
                     {{"rays", r.lane_rays[l]}, {"faces", r.faces}, {"cycles", r.cycles}, {"limit", r.limit}});
  }
  trace_->instant(track("irq"), "raised by board", r.end);
}

}  // namespace rc
