#include "host_sw/visibility/visibility_recording.h"

#include <stdexcept>
#include <string>

#include "host_sw/visibility/packed_flags.h"

namespace rc {

std::uint64_t brute_force_tests(const SegmentBatch& batch, std::size_t faces, const FaceSheets& sheets) {
  if (sheets.one_sided()) {
    // Every sheet one face: a segment ending on the source face skips that face alone, every
    // other segment two; one face or none leaves nothing to test.
    if (faces < 2) return 0;
    std::uint64_t on_source = 0;
    for (const int f : batch.end_faces) on_source += f == batch.source_face;
    return batch.size() * (faces - 2) + on_source;
  }
  std::uint64_t tests = 0;
  for (std::size_t s = 0; s < batch.size(); ++s) {
    const std::size_t own = own_surface_faces(sheets, batch.source_face, batch.end_faces[s]);
    tests += faces > own ? faces - own : 0;
  }
  return tests;
}

void VisibilityRecording::add_step(const std::vector<std::uint8_t>& blocked, const std::vector<std::uint8_t>& needed,
                                   int source_face, std::uint64_t brute_force_tests, std::uint64_t host_tests) {
  if (!needed.empty() && needed.size() != blocked.size()) {
    throw std::invalid_argument("a step has " + std::to_string(blocked.size()) + " answers but " +
                                std::to_string(needed.size()) + " needed flags");
  }
  const std::size_t n = blocked.size(), whole = n / 8;
  offsets_.push_back(total_);
  sizes_.push_back(static_cast<std::uint32_t>(n));
  bits_.resize((total_ + n + 7) / 8, 0);
  std::uint32_t needed_count = 0, blocked_count = 0;
  // Eight segments at a time: their flags (blocked and needed) as one byte, which lands on bits
  // total_ + 8k .. total_ + 8k + 7 of the stream, i.e. across two bytes unless total_ is a
  // multiple of 8.
  const std::size_t at = total_ / 8;
  const unsigned shift = static_cast<unsigned>(total_ % 8);
  for (std::size_t k = 0; k < whole; ++k) {
    std::uint8_t flags = pack_flags8(&blocked[8 * k]);
    if (needed.empty()) {
      needed_count += 8;
    } else {
      const std::uint8_t mask = pack_flags8(&needed[8 * k]);
      needed_count += count_flags8(mask);
      flags &= mask;
    }
    blocked_count += count_flags8(flags);
    bits_[at + k] |= std::uint8_t(flags << shift);
    if (shift != 0) bits_[at + k + 1] |= std::uint8_t(flags >> (8 - shift));
  }
  for (std::size_t i = 8 * whole; i < n; ++i) {
    if (!needed.empty() && !needed[i]) continue;
    ++needed_count;
    if (!blocked[i]) continue;
    ++blocked_count;
    bits_[(total_ + i) / 8] |= std::uint8_t(1u << ((total_ + i) % 8));
  }
  needed_.push_back(needed_count);
  blocked_.push_back(blocked_count);
  source_faces_.push_back(source_face);
  tests_.push_back(brute_force_tests);
  host_tests_.push_back(host_tests);
  total_ += n;
}

void VisibilityRecording::step_flags(std::size_t step, std::vector<std::uint8_t>& blocked) const {
  const std::uint64_t first = offsets_.at(step);
  const std::size_t n = sizes_[step];
  blocked.resize(n);
  std::size_t i = 0;
  const unsigned shift = static_cast<unsigned>(first % 8);
  for (; i + 8 <= n; i += 8) {  // eight flags at a time, from one or two bytes of the stream
    const std::size_t at = (first + i) / 8;
    std::uint8_t bits = std::uint8_t(bits_[at] >> shift);
    if (shift != 0) bits = std::uint8_t(bits | bits_[at + 1] << (8 - shift));
    unpack_flags8(bits, &blocked[i]);
  }
  for (; i < n; ++i) blocked[i] = (bits_[(first + i) / 8] >> ((first + i) % 8)) & 1u;
}

void RecordingVisibility::load_triangles(const std::vector<Triangle>& faces) {
  faces_ = faces.size();
  answer_.load_faces(faces, sheets());
}

void RecordingVisibility::submit(const SegmentBatch& batch) {
  source_face_ = batch.source_face;
  needed_ = batch.needed;
  tests_ = brute_force_tests(batch, faces_, sheets());
  if (host_tests_) host_tests_before_ = host_tests_();
  answer_.submit(batch);
}

void RecordingVisibility::collect(std::vector<std::uint8_t>& blocked) {
  answer_.collect(blocked);
  recording_.add_step(blocked, needed_, source_face_, tests_, host_tests_ ? host_tests_() - host_tests_before_ : 0);
}

void ReplayVisibility::load_triangles(const std::vector<Triangle>& faces) {
  faces_ = faces.size();
  next_step_ = 0;
}

void ReplayVisibility::submit(const SegmentBatch& batch) {
  if (next_step_ >= recording_.steps() || recording_.segments(next_step_) != batch.size()) {
    throw std::logic_error("replay diverged at step " + std::to_string(next_step_ + 1) + ": the batch has " +
                           std::to_string(batch.size()) + " segments, the recording " +
                           (next_step_ < recording_.steps() ? std::to_string(recording_.segments(next_step_))
                                                            : std::string("has no such step")));
  }
  recording_.step_flags(next_step_++, blocked_);
  tests_ += brute_force_tests(batch, faces_, sheets());
}

void ReplayVisibility::collect(std::vector<std::uint8_t>& blocked) { blocked = blocked_; }

}  // namespace rc
