// The paper-faithful solver sends every patch but the shooter, in patch order; it rebuilds only the
// part of the batch that changed since the previous shooter. Every batch it submits is checked
// here against the definition, through 300 shooters and a second run of the same solver.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "host_sw/radiosity/radiosity.h"
#include "tests/common/simple_scenes.h"

namespace rc {
namespace {

// Answers "clear" and checks that each batch holds every patch but its shooter, in order.
class EveryReceiverCheck : public VisibilityBackend {
 public:
  explicit EveryReceiverCheck(const Scene& scene) : scene_(scene) {}
  std::string name() const override { return "check"; }
  void load_triangles(const std::vector<Triangle>&) override {}
  void submit(const SegmentBatch& batch) override {
    const std::size_t n = scene_.patches.size();
    ASSERT_GE(batch.shooter, 0);
    ASSERT_EQ(batch.size(), n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const std::size_t patch = k < static_cast<std::size_t>(batch.shooter) ? k : k + 1;
      ASSERT_EQ(batch.ends[k], scene_.patches[patch].centre) << "entry " << k << ", shooter " << batch.shooter;
      ASSERT_EQ(batch.end_faces[k], scene_.patches[patch].face) << "entry " << k << ", shooter " << batch.shooter;
    }
    size_ = batch.size();
    ++batches;
  }
  void collect(std::vector<std::uint8_t>& blocked) override { blocked.assign(size_, 0); }
  std::uint64_t tests_performed() const override { return 0; }
  int batches = 0;

 private:
  const Scene& scene_;
  std::size_t size_ = 0;
};

TEST(EveryReceiverBatch, EachBatchIsEveryPatchButTheShooterInOrder) {
  const Scene scene = test::cornell_box(1);
  SolverOptions every;
  every.cull_receivers = false;
  every.fixed_steps = 300;
  EveryReceiverCheck check(scene);
  ProgressiveRadiosity solver(scene, check, every);
  solver.run();
  EXPECT_EQ(check.batches, 300);
  solver.run();  // a second run starts from its own first shooter
  EXPECT_EQ(check.batches, 600);
}

}  // namespace
}  // namespace rc
