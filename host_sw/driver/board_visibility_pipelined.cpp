// The pipelined driver (docs/board.md, "Pipelined passes"): a step's board segments go to the board in
// chunks of BoardVisibilityOptions::chunk_rays, chunk k into half k mod 2 of every ray bank, of the
// result bank and of the own-surface table (RAY_BASE, RESULT_BASE, TABLE_BASE). The driver packs and
// sends chunk k+1 and writes its START while the wrapper works on chunk k; the wrapper holds that START
// and begins chunk k+1 on the edge that ends chunk k. Then the driver waits for chunk k, reads its
// results back and sends chunk k+2 into the halves chunk k has left. Which chunks are done, the
// driver learns from PASSES, read after each acknowledge has taken effect (the host syncs first: a
// register read returns the value at simulated time), so a pass that ends after the acknowledge raises
// the interrupt again and one that ended before it is counted: none is lost.
#include <algorithm>
#include <stdexcept>

#include "board/register_map.h"
#include "board/word_format.h"
#include "host_sw/driver/board_visibility.h"
#include "host_sw/driver/trace_writer.h"

namespace rc {

namespace reg = board::reg;
using sc_core::sc_time;

namespace {

// Every word of a chunk of `rays` lies in half a bank: each ray bank's, the result words.
bool chunk_fits(const board::BankLayout& layout, std::uint64_t rays) {
  const board::RaySplit split = board::split_rays(layout, rays);
  const std::uint64_t half = layout.bank_words / 2;
  if (!split.fits || split.result_words > half) return false;
  for (std::size_t g = 0; g < layout.groups.size(); ++g) {
    const board::RayGroup& group = layout.groups[g];
    for (unsigned j = 0; j < group.k(); ++j)
      if (board::group_bank_words(group, j, split.packets[g]) > half) return false;
  }
  return true;
}

}  // namespace

void BoardVisibility::check_chunks() const {
  const std::uint64_t chunk = options_.chunk_rays, faces = faces_.size();
  if (stats_.face_sets > 1) {
    throw std::invalid_argument("--chunk-rays: the pipelined driver needs the scene's faces in one face set (" +
                                std::to_string(faces) + " faces; a set holds " + std::to_string(faces_per_set_) + ")");
  }
  const std::uint64_t table_room = layout_.mask_bank ? layout_.bank_words : layout_.bank_words - 9 * faces;
  if (2 * faces > table_room) {
    throw std::invalid_argument("--chunk-rays: two own-surface tables of " + std::to_string(faces) +
                                " words do not fit the " + std::to_string(table_room) + " words left for them");
  }
  if (chunk_fits(layout_, chunk)) return;
  std::uint64_t lo = 0, hi = layout_.max_rays_per_batch;  // the largest chunk that fits: lo
  while (lo < hi) {
    const std::uint64_t mid = hi - (hi - lo) / 2;
    if (chunk_fits(layout_, mid)) {
      lo = mid;
    } else {
      hi = mid - 1;
    }
  }
  throw std::invalid_argument("--chunk-rays " + std::to_string(chunk) + ": a chunk's rays and results must fit half a bank (" +
                              std::to_string(half_words()) + " of " + std::to_string(layout_.bank_words) +
                              " words); at most " + std::to_string(lo) + " rays");
}

void BoardVisibility::start_chunks() {
  const std::size_t chunk = options_.chunk_rays;
  chunks_ = (rays_ + chunk - 1) / chunk;
  stats_.ray_batches += chunks_;
  stats_.max_batches_per_step = std::max<std::uint64_t>(stats_.max_batches_per_step, chunks_);
  passes_done_ = chunk_base_ = passes_started_;  // every earlier pass was waited for
  send_chunk(0);
  next_chunk_ = 1;
  if (options_.cpu_split.cores == 1) charge_cpu_part();  // while the board works its first chunk
  if (options_.concurrent) return;  // the rest in collect(), after the host's form factors
  finish_chunks();
}

void BoardVisibility::finish_chunks() {
  if (chunks_ == 0) return;
  for (; next_chunk_ < chunks_; ++next_chunk_) {
    send_chunk(next_chunk_);
    await_chunk(next_chunk_ - 1);
    read_chunk(next_chunk_ - 1);
  }
  await_chunk(chunks_ - 1);
  read_chunk(chunks_ - 1);
  chunks_ = 0;
  board_part_done();
}

// Pack and send the chunk's rays and own-surface table into its halves, then its registers and START.
void BoardVisibility::send_chunk(std::size_t k) {
  const std::size_t first = chunk_first(k), rays = chunk_size(k);
  const std::uint64_t half = k % 2, window = half * half_words();
  charge_end_points(rays);
  const board::RaySplit& split = split_(rays);
  if (!timing_only_) {
    board::pack_rays(layout_, split, x_.data() + first, y_.data() + first, z_.data() + first, images_);
    blank_images_rays_ = kNoBlankImages;
  } else if (blank_images_rays_ != rays) {
    board::size_ray_images(layout_, split, images_);
    blank_images_rays_ = rays;
  }
  std::uint64_t bytes = 0;
  for (const auto& image : images_) bytes += image.size();
  charge_ray_words(bytes / word_bytes_);
  for (unsigned b = 0; b < images_.size(); ++b) {
    transfer(tlmx::DmaDirection::to_device, images_[b].data(), ports_.board.bank_address(b) + window * word_bytes_,
             images_[b].size(), "rays", timing_only_);
  }
  if (cpu_.profile().driver_model.face_upload == DriverModel::FaceUpload::EveryPass) upload_faces(0);
  const std::uint64_t faces = faces_.size();
  upload_mask(first, rays, 0, half * faces);
  cpu_.charge(DriverWork::Call, 1);
  const sc_time from = cpu_.now();
  if (source_faces_ != source_faces_written_) {
    write_registers(reg::kSourceFaces, {source_faces_});
    source_faces_written_ = source_faces_;
  }
  if (static_cast<std::uint32_t>(options_.t_guard) != t_guard_written_) {
    write_registers(reg::kTGuard, {static_cast<std::uint32_t>(options_.t_guard)});
    t_guard_written_ = static_cast<std::uint32_t>(options_.t_guard);
  }
  // One face set, from face 0: MASK_START is 0 (no ray ends before the set's first sheet).
  write_registers(reg::kRayCount,
                  {static_cast<std::uint32_t>(rays), static_cast<std::uint32_t>(faces), 0u, source_face_,
                   static_cast<std::uint32_t>(start_.x), static_cast<std::uint32_t>(start_.y),
                   static_cast<std::uint32_t>(start_.z), 0u});
  write_registers(reg::kRayBase, {static_cast<std::uint32_t>(window), static_cast<std::uint32_t>(window),
                                  static_cast<std::uint32_t>(half * faces)});
  if (ports_.sideband.before_start) {
    ports_.sideband.before_start(options_.oracle != nullptr ? oracle_answer_.data() + first : nullptr, timing_only_);
  }
  write_registers(reg::kControl, {reg::kStart | reg::kClear});
  ++passes_started_;
  host_event("start chunk", from);
}

// Wait for the interrupt, acknowledge it, and read PASSES, until chunk k of the step is counted done.
void BoardVisibility::await_chunk(std::size_t k) {
  cpu_.charge(DriverWork::Call, 1);
  while (static_cast<std::uint32_t>(passes_done_ - chunk_base_) < k + 1) {
    const sc_time from = cpu_.now();
    wait_for_interrupt();
    stats_.waiting += sc_core::sc_time_stamp() - from;
    host_event("wait for interrupt", from);
    const std::uint32_t status = read_register(reg::kStatus);
    write_registers(reg::kStatus, {reg::kDone | reg::kError});
    cpu_.sync();  // PASSES as of the acknowledge's time or later: a pass that ends after it raises the line again
    passes_done_ = read_register(reg::kPasses);
    if (status & reg::kError) {
      throw std::runtime_error("the board reported error " + std::to_string(read_register(reg::kErrorCode)) +
                               " (register_map.h ErrorCode) for a chunk of at most " +
                               std::to_string(options_.chunk_rays) + " rays and " + std::to_string(faces_.size()) +
                               " faces");
    }
  }
}

void BoardVisibility::read_chunk(std::size_t k) {
  const std::size_t first = chunk_first(k), rays = chunk_size(k);
  const board::RaySplit& split = split_(rays);
  if (timing_only_) {
    result_words_.resize(split.result_words * word_bytes_);  // moved without data: contents immaterial
  } else {
    result_words_.assign(split.result_words * word_bytes_, 0);
  }
  const std::uint64_t window = (k % 2) * half_words();
  transfer(tlmx::DmaDirection::to_host, result_words_.data(),
           ports_.board.bank_address(layout_.result_bank) + window * word_bytes_, result_words_.size(), "results",
           timing_only_);
  if (!timing_only_) board::unpack_results(layout_, split, result_words_.data(), blocked_.data() + first);
  charge_results(rays, split.result_words);
}

}  // namespace rc
