// Recordings keep each step's flags as bits and a brute-force test count per step; the fast
// paths (eight flags at a time, a count without a pass over the segments where every sheet is
// one face) are checked here against the plain per-segment definitions on random steps.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "tests/host_sw/visibility/fast_test_support.h"
#include "host_sw/visibility/packed_flags.h"
#include "host_sw/visibility/shooter_memo_visibility.h"
#include "host_sw/visibility/visibility_recording.h"

namespace rc {
namespace {

// Sheets of random sizes 1..3 over `faces` faces (contiguous, named by their first face).
FaceSheets random_sheets(int faces, std::mt19937_64& rng) {
  std::vector<int> first(static_cast<std::size_t>(faces));
  for (int f = 0; f < faces;) {
    const int size = 1 + static_cast<int>(rng() % 3);
    for (int k = 0; k < size && f < faces; ++k, ++f) first[static_cast<std::size_t>(f)] = f - k;
  }
  return FaceSheets(first);
}

// The recording's definition, per segment: the faces minus the segment's own surfaces' faces
// (own_surface_faces; for faces inside the list, the faces the brute force tests).
std::uint64_t per_segment_tests(const SegmentBatch& batch, std::size_t faces, const FaceSheets& sheets) {
  std::uint64_t tests = 0;
  for (std::size_t s = 0; s < batch.size(); ++s) {
    const std::size_t own = own_surface_faces(sheets, batch.source_face, batch.end_faces[s]);
    tests += faces > own ? faces - own : 0;
  }
  return tests;
}

// For faces inside the list: every face but the segment's own surfaces, face by face.
std::uint64_t face_by_face_tests(const SegmentBatch& batch, std::size_t faces, const FaceSheets& sheets) {
  std::uint64_t tests = 0;
  for (std::size_t s = 0; s < batch.size(); ++s) {
    for (std::size_t f = 0; f < faces; ++f) tests += !is_own_surface(sheets, batch, s, static_cast<int>(f));
  }
  return tests;
}

TEST(VisibilityRecording, BruteForceTestsCountEveryFaceButTheOwnSurfaces) {
  std::mt19937_64 rng(29);
  for (int trial = 0; trial < 400; ++trial) {
    const int faces = static_cast<int>(rng() % 40);
    const bool one_sided = trial % 2 == 0;
    const FaceSheets sheets = one_sided || faces == 0 ? FaceSheets{} : random_sheets(faces, rng);
    SegmentBatch batch;
    // Source and end faces anywhere in [-1, faces]: -1 and faces lie outside the map.
    const auto any_face = [&] { return static_cast<int>(rng() % static_cast<unsigned>(faces + 2)) - 1; };
    batch.source_face = any_face();
    const std::size_t n = rng() % 50;
    for (std::size_t s = 0; s < n; ++s) {
      batch.ends.push_back({0.5, 0.5, 0.5});
      batch.end_faces.push_back(rng() % 4 == 0 ? batch.source_face : any_face());
    }
    const auto count = static_cast<std::size_t>(faces);
    EXPECT_EQ(brute_force_tests(batch, count, sheets), per_segment_tests(batch, count, sheets))
        << "trial " << trial << ", " << faces << " faces";
    // Inside the face list the count is the brute force's, face by face.
    SegmentBatch inside = batch;
    if (inside.source_face < 0 || inside.source_face >= faces) inside.source_face = faces - 1;
    for (int& f : inside.end_faces) {
      if (f < 0 || f >= faces) f = 0;
    }
    if (faces > 1) {
      EXPECT_EQ(brute_force_tests(inside, count, sheets), face_by_face_tests(inside, count, sheets))
          << "trial " << trial << ", " << faces << " faces";
    }
  }
}

TEST(VisibilityRecording, FlagsPackEightToAByteAndBack) {
  for (unsigned bits = 0; bits < 256; ++bits) {
    std::uint8_t flags[8];
    unpack_flags8(static_cast<std::uint8_t>(bits), flags);
    for (int j = 0; j < 8; ++j) ASSERT_EQ(flags[j], (bits >> j) & 1u) << bits;
    ASSERT_EQ(pack_flags8(flags), bits);
    ASSERT_EQ(count_flags8(static_cast<std::uint8_t>(bits)), static_cast<unsigned>(__builtin_popcount(bits)));
  }
  std::mt19937_64 rng(8);
  for (int trial = 0; trial < 10000; ++trial) {  // any non-zero byte is a set flag
    std::uint8_t flags[8];
    unsigned expected = 0;
    for (int j = 0; j < 8; ++j) {
      flags[j] = rng() % 2 ? 0 : static_cast<std::uint8_t>(rng());
      expected |= (flags[j] != 0 ? 1u : 0u) << j;
    }
    ASSERT_EQ(pack_flags8(flags), expected);
  }
}

// Steps of every length (aligned and not on the bit stream), with and without needed masks, and
// flags that are any non-zero byte: each step's flags, needed and blocked counts as defined.
TEST(VisibilityRecording, StepsKeepTheirFlagsAndCounts) {
  std::mt19937_64 rng(5);
  VisibilityRecording recording;
  std::vector<std::vector<std::uint8_t>> expected;
  std::vector<std::size_t> needed_counts, blocked_counts;
  for (int step = 0; step < 300; ++step) {
    const std::size_t n = rng() % 70;
    std::vector<std::uint8_t> blocked(n), needed;
    if (step % 3 != 0) needed.resize(n);
    for (std::uint8_t& b : blocked) b = rng() % 3 == 0 ? static_cast<std::uint8_t>(1 + rng() % 255) : 0;
    for (std::uint8_t& m : needed) m = rng() % 4 == 0 ? 0 : static_cast<std::uint8_t>(1 + rng() % 255);
    std::vector<std::uint8_t> flags(n);
    std::size_t needed_count = 0, blocked_count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const bool is_needed = needed.empty() || needed[i] != 0;
      needed_count += is_needed;
      flags[i] = is_needed && blocked[i] != 0;
      blocked_count += flags[i];
    }
    recording.add_step(blocked, needed, step, static_cast<std::uint64_t>(step) * 3);
    expected.push_back(flags);
    needed_counts.push_back(needed_count);
    blocked_counts.push_back(blocked_count);
  }
  ASSERT_EQ(recording.steps(), expected.size());
  std::vector<std::uint8_t> flags;
  for (std::size_t step = 0; step < expected.size(); ++step) {
    recording.step_flags(step, flags);
    EXPECT_EQ(flags, expected[step]) << "step " << step;
    EXPECT_EQ(recording.needed(step), needed_counts[step]) << "step " << step;
    EXPECT_EQ(recording.blocked(step), blocked_counts[step]) << "step " << step;
    EXPECT_EQ(recording.brute_force_tests(step), step * 3);
  }
}

// Answers whatever it is told to, so that a memo's replay can be compared with the first answer.
class ScriptedVisibility : public VisibilityBackend {
 public:
  std::vector<std::uint8_t> next;
  std::string name() const override { return "scripted"; }
  void load_triangles(const std::vector<Triangle>&) override {}
  void submit(const SegmentBatch&) override {}
  void collect(std::vector<std::uint8_t>& blocked) override { blocked = next; }
  std::uint64_t tests_performed() const override { return 0; }
};

TEST(VisibilityRecording, AShootersRememberedAnswerComesBackBitForBit) {
  std::mt19937_64 rng(3);
  auto scripted = std::make_unique<ScriptedVisibility>();
  ScriptedVisibility& script = *scripted;
  ShooterMemoVisibility memo(std::move(scripted));
  memo.load_faces({});
  std::vector<SegmentBatch> batches;
  std::vector<std::vector<std::uint8_t>> answers;
  for (int shooter = 0; shooter < 100; ++shooter) {
    SegmentBatch b;
    b.shooter = shooter;
    b.ends.assign(rng() % 90, Vec3{0.5, 0.5, 0.5});
    b.end_faces.assign(b.size(), 0);
    std::vector<std::uint8_t> answer(b.size());
    for (std::uint8_t& a : answer) a = rng() % 2;
    script.next = answer;
    std::vector<std::uint8_t> got;
    memo.submit(b);
    memo.collect(got);
    ASSERT_EQ(got, answer);
    batches.push_back(b);
    answers.push_back(answer);
  }
  script.next.clear();  // a reuse that asked the backend would get nothing
  for (std::size_t k = 0; k < batches.size(); ++k) {
    std::vector<std::uint8_t> got;
    memo.submit(batches[k]);
    memo.collect(got);
    EXPECT_EQ(got, answers[k]) << "shooter " << k;
  }
  EXPECT_EQ(memo.batches_reused(), batches.size());
}

// The fast backend's count of what the brute force would test, with sheets of several faces,
// end faces outside the face list and no source face: the brute force's own count.
TEST(VisibilityRecording, FastCountsTheBruteForcesTestsWithSheets) {
  std::mt19937_64 rng(11);
  test::Workload w = test::random_workload(60, 4, 300, 0.2, 17);
  w.batches[1].end_faces[0] = -1;
  w.batches[1].end_faces[1] = 60;
  w.batches[2].source_face = -1;
  for (const bool one_sided : {true, false}) {
    const FaceSheets sheets = one_sided ? FaceSheets{} : random_sheets(60, rng);
    FixedPointVisibility brute(15);
    FastFixedVisibility fast(15, 2);
    brute.load_faces(w.faces, sheets);
    fast.load_faces(w.faces, sheets);
    for (const SegmentBatch& b : w.batches) {
      std::vector<std::uint8_t> expected, flags;
      brute.submit(b);
      brute.collect(expected);
      fast.submit(b);
      fast.collect(flags);
      EXPECT_EQ(flags, expected);
      EXPECT_EQ(fast.brute_force_tests(), brute.tests_performed()) << (one_sided ? "one-sided" : "sheets");
      EXPECT_EQ(brute_force_tests(b, w.faces.size(), sheets), per_segment_tests(b, w.faces.size(), sheets));
    }
  }
}

}  // namespace
}  // namespace rc
