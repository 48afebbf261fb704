// FloatPipelineVisibility: the floating-point pipeline as a CPU visibility backend. It answers
// exactly what a brute-force loop of the float pipeline's segment_hits answers under the own-face
// rule, the factory builds it from "float:E,M", and on the Cornell Box its blocked flags match the
// double-precision backend: all of them at single precision, all but a measured few in 16 bits.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <stdexcept>
#include <tuple>

#include "host_sw/visibility/float_pipeline_visibility.h"
#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/visibility/visibility_factory.h"
#include "tests/common/simple_scenes.h"
#include "tests/host_sw/visibility/random_batch.h"

namespace rc {
namespace {

using test::RandomBatch;
using test::random_batch;

std::vector<std::uint8_t> brute_force(const RandomBatch& s, pipeline::FloatFormat format) {
  const pipeline::FloatVec3 start = pipeline::round_point(s.batch.start, format);
  std::vector<std::uint8_t> blocked(s.batch.size(), 0);
  for (std::size_t i = 0; i < s.batch.size(); ++i) {
    const pipeline::FloatVec3 end = pipeline::round_point(s.batch.ends[i], format);
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      if (is_own_surface(FaceSheets{}, s.batch, i, static_cast<int>(f))) continue;
      blocked[i] |= pipeline::segment_hits(pipeline::make_float_face_record(s.faces[f], format), start,
                                           end, format);
    }
  }
  return blocked;
}

std::vector<std::uint8_t> answer(VisibilityBackend& v, const std::vector<Triangle>& faces,
                                 const SegmentBatch& batch) {
  v.load_faces(faces);
  v.submit(batch);
  std::vector<std::uint8_t> blocked;
  v.collect(blocked);
  return blocked;
}

TEST(FloatPipelineVisibility, MatchesBruteForceFloatPipelineInEveryFormat) {
  for (double scale : {1.0, 500.0}) {
    const RandomBatch s = random_batch(40, 300, 1, scale);  // world coordinates: no [0, 1) requirement
    for (const char* name : {"float:8,23", "float:5,10", "float:6,9", "float:4,5"}) {
      const pipeline::FloatFormat format = pipeline::parse_float_format(name);
      FloatPipelineVisibility v(format);
      const std::vector<std::uint8_t> expected = brute_force(s, format);
      EXPECT_EQ(answer(v, s.faces, s.batch), expected) << name << " at scale " << scale;
      std::size_t count = 0;
      for (auto b : expected) count += b;
      if (format == pipeline::FloatFormat(8, 23)) {
        EXPECT_GT(count, 10u) << "scene too sparse to test anything";
        EXPECT_LT(count, s.batch.size());
      }
    }
  }
}

TEST(FloatPipelineVisibility, OwnFacesNeverBlockAndTestsAreCounted) {
  const std::vector<Triangle> faces = {
      {{0.1, 0.1, 0.1}, {0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}},  // 0: source
      {{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.1, 0.9, 0.5}},  // 1: blocker
      {{0.1, 0.1, 0.9}, {0.9, 0.1, 0.9}, {0.1, 0.9, 0.9}},  // 2: receiver
  };
  FloatPipelineVisibility v(pipeline::FloatFormat(5, 10));
  SegmentBatch batch;
  batch.source_face = 0;
  batch.start = {0.3, 0.3, 0.1};
  batch.ends = {{0.3, 0.3, 0.9}, {0.3, 0.3, 0.9}, {0.3, 0.3, 0.9}};
  batch.end_faces = {2, 1, 0};
  EXPECT_EQ(answer(v, faces, batch), (std::vector<std::uint8_t>{1, 0, 1}));
  // The source face 0 is skipped for all; of faces 1 and 2 each segment skips its end face (the
  // third ends on the source face, so it is tested against both).
  EXPECT_EQ(v.tests_performed(), 1u + 1u + 2u);
  batch.end_faces = {-1};
  batch.ends.resize(1);
  batch.ends.push_back({0.3, 0.3, 0.9});
  EXPECT_THROW(v.submit(batch), std::invalid_argument);  // end_faces does not match ends
}

TEST(FloatPipelineVisibility, FactoryBuildsItFromTheFormatName) {
  const auto v = make_software_visibility("float:6,9", 15);
  EXPECT_EQ(v->name(), "float:6,9");
  EXPECT_EQ(make_software_visibility("float", 15)->name(), "float");  // double stays double
  EXPECT_EQ(make_software_visibility("fixed", 15)->name(), "fixed");
  EXPECT_EQ(make_functional_answer("float:8,23", 15)->tests_performed(), 0u);
  EXPECT_THROW(make_software_visibility("float:8", 15), std::invalid_argument);
  EXPECT_THROW(make_software_visibility("float:11,52", 15), std::invalid_argument);
  EXPECT_THROW(make_software_visibility("double", 15), std::invalid_argument);
}

// Both backends see the solver's own batches; the solver follows the double backend.
class SideBySide : public VisibilityBackend {
 public:
  explicit SideBySide(pipeline::FloatFormat format) : pipeline_(format) {}
  std::string name() const override { return "side-by-side"; }
  void load_triangles(const std::vector<Triangle>& faces) override {
    pipeline_.load_faces(faces, sheets());
    double_.load_faces(faces, sheets());
  }
  void submit(const SegmentBatch& batch) override {
    pipeline_.submit(batch);
    double_.submit(batch);
  }
  void collect(std::vector<std::uint8_t>& blocked) override {
    std::vector<std::uint8_t> mine;
    pipeline_.collect(mine);
    double_.collect(blocked);
    ASSERT_EQ(mine.size(), blocked.size());
    for (std::size_t i = 0; i < blocked.size(); ++i) {
      ++segments;
      blocked_by_double += blocked[i];
      false_blocked += mine[i] && !blocked[i];
      false_clear += !mine[i] && blocked[i];
    }
  }
  std::uint64_t tests_performed() const override { return double_.tests_performed(); }

  std::size_t segments = 0, blocked_by_double = 0, false_blocked = 0, false_clear = 0;

 private:
  FloatPipelineVisibility pipeline_;
  FloatVisibility double_;
};

// Measured (this test's own figures, docs/pipeline.md): on the 70-face Cornell Box over 385 steps
// (66,814 segments, 16,952 blocked by double), single precision disagrees with double on none;
// half on 24 false blocked + 12 false clear (0.054%); float:6,9 on 118 + 47 (0.25%). The bounds
// are the measurements (the arithmetic is deterministic), so any change in it shows here.
TEST(FloatPipelineVisibility, CornellBoxAgreesWithDoubleWithinTheMeasuredBound) {
  const Scene scene = test::cornell_box(1, 70, 0);  // 70 faces, 280 patches
  for (const auto& [format, max_false_blocked, max_false_clear] :
       {std::tuple{pipeline::FloatFormat(8, 23), 0u, 0u}, std::tuple{pipeline::FloatFormat(5, 10), 24u, 12u},
        std::tuple{pipeline::FloatFormat(6, 9), 118u, 47u}}) {
    SideBySide both(format);
    SolverOptions options;
    options.fixed_steps = 385;
    ProgressiveRadiosity(scene, both, options).run();
    std::printf("%s: %zu segments, %zu blocked (double), %zu false blocked, %zu false clear\n",
                format.to_string().c_str(), both.segments, both.blocked_by_double, both.false_blocked,
                both.false_clear);
    EXPECT_GT(both.blocked_by_double, 1000u);
    EXPECT_LE(both.false_blocked, max_false_blocked) << format.to_string();
    EXPECT_LE(both.false_clear, max_false_clear) << format.to_string();
  }
}

}  // namespace
}  // namespace rc
