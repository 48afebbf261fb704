#include "host_sw/visibility/shooter_memo_visibility.h"

#include <stdexcept>
#include <string>

#include "host_sw/visibility/packed_flags.h"

namespace rc {

void ShooterMemoVisibility::load_triangles(const std::vector<Triangle>& faces) {
  memo_.clear();  // another run: shooter ids promise nothing across it
  bytes_ = 0;
  reuse_ = nullptr;
  pending_shooter_ = -1;
  answer_->load_faces(faces, sheets());
}

void ShooterMemoVisibility::submit(const SegmentBatch& batch) {
  reuse_ = nullptr;
  pending_shooter_ = -1;
  const int shooter = batch.shooter;
  if (shooter >= 0 && static_cast<std::size_t>(shooter) < memo_.size() && !memo_[shooter].bits.empty()) {
    const Answer& a = memo_[shooter];
    if (a.start != batch.start || a.source_face != batch.source_face || a.segments != batch.size()) {
      throw std::logic_error("shooter " + std::to_string(shooter) +
                             " sent a different batch than before; its answers cannot be reused");
    }
    reuse_ = &a;
    ++reused_;
    return;
  }
  ++answered_;
  answer_->submit(batch);
  if (shooter >= 0 && bytes_ + (batch.size() + 7) / 8 <= max_bytes_) {
    if (memo_.size() <= static_cast<std::size_t>(shooter)) memo_.resize(static_cast<std::size_t>(shooter) + 1);
    Answer& a = memo_[shooter];
    a.start = batch.start;
    a.source_face = batch.source_face;
    a.segments = batch.size();
    pending_shooter_ = shooter;
  }
}

void ShooterMemoVisibility::collect(std::vector<std::uint8_t>& blocked) {
  if (reuse_ != nullptr) {
    const std::size_t n = reuse_->segments, whole = n / 8;
    blocked.resize(n);
    for (std::size_t k = 0; k < whole; ++k) unpack_flags8(reuse_->bits[k], &blocked[8 * k]);
    for (std::size_t i = 8 * whole; i < n; ++i) blocked[i] = (reuse_->bits[i / 8] >> (i % 8)) & 1u;
    return;
  }
  answer_->collect(blocked);
  if (pending_shooter_ < 0) return;
  Answer& a = memo_[static_cast<std::size_t>(pending_shooter_)];
  const std::size_t n = blocked.size(), whole = n / 8;
  a.bits.assign((n + 7) / 8 + 1, 0);  // one spare byte: never empty once remembered
  for (std::size_t k = 0; k < whole; ++k) a.bits[k] = pack_flags8(&blocked[8 * k]);
  for (std::size_t i = 8 * whole; i < n; ++i) {
    if (blocked[i]) a.bits[i / 8] |= std::uint8_t(1u << (i % 8));
  }
  bytes_ += a.bits.size();
  pending_shooter_ = -1;
}

}  // namespace rc
