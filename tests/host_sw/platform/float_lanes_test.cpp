// Float lanes in the whole system (docs/board.md, "Float lanes"): the driver rounds end points and
// face records to the format and sends their bit patterns, the lanes run the float pipeline, and the
// radiosity is bit for bit that of the software `float:E,M` backend (FloatPipelineVisibility) solving
// the same steps. The `float:E,M` backend as the lanes' oracle changes no result and no time.
#include "tests/host_sw/platform/system_support.h"

#include "host_sw/visibility/float_pipeline_visibility.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc::test {
namespace {

SolverResult cpu_float_pipeline(const Scene& scene, const SolverOptions& options, pipeline::FloatFormat format) {
  FloatPipelineVisibility v(format);
  return ProgressiveRadiosity(scene, v, options).run();
}

// Cornell box, 70 faces, 40 steps, float:5,10, 2 lanes: the lanes computing every ray against every
// face; the same with small banks (several face sets and ray batches a step); and with the software
// backend's answer as the oracle (what `rc2000sim run --impl board --arith float:5,10` does).
TEST(BoardSystem, FloatLanesBitIdenticalToCpuFloatPipeline) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(40);
  const pipeline::FloatFormat format(5, 10);
  BoardRunOptions o;
  o.lanes = 2;
  o.float_format = format;
  BoardSystem computed("computed", scene, so, setup(o));
  BoardRunOptions small = o;
  small.bank_capacity_bytes = 256;  // 64 words: 7 faces a set, 128 rays a batch
  small.concurrent = true;
  BoardSystem batched("batched", scene, so, setup(small));
  const std::unique_ptr<VisibilityBackend> oracle = make_functional_answer(format.to_string(), 15);
  o.oracle = oracle.get();
  BoardSystem with_oracle("with_oracle", scene, so, setup(o));
  run_all({&computed, &batched, &with_oracle});

  const SolverResult cpu = cpu_float_pipeline(scene, so, format);
  EXPECT_GT(cpu.blocked_segments, 0u);
  for (const BoardSystem* s : {&computed, &batched, &with_oracle}) {
    EXPECT_EQ(s->result().steps, 40);
    EXPECT_EQ(s->result().blocked_segments, cpu.blocked_segments);
    expect_identical(s->result().radiosity, cpu.radiosity);
  }
  EXPECT_GE(batched.driver().stats().face_sets, 2u);
  EXPECT_GE(batched.driver().stats().max_batches_per_step, 2u);
  // The oracle changes the simulator's work only.
  EXPECT_EQ(with_oracle.end_time(), computed.end_time());
  EXPECT_EQ(with_oracle.driver().stats().fpga_busy, computed.driver().stats().fpga_busy);
  EXPECT_EQ(with_oracle.driver().stats().tests, computed.driver().stats().tests);
  // Two 16-bit values a 32-bit word, at fit_float_design's clock.
  EXPECT_EQ(computed.board.layout().coords_per_word, 2u);
  EXPECT_EQ(computed.board.params().fit.bits, 16);
  EXPECT_EQ(computed.report().board.device.bits, 0);  // no fractional width
}

// The CPU/FPGA split with float lanes: the CPU's share is answered by the `float:E,M` kernel the
// system makes (no oracle), bit for bit the lanes' arithmetic.
TEST(BoardSystem, FloatLanesWithCpuSplitBitIdenticalToCpuFloatPipeline) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(20);
  const pipeline::FloatFormat format(5, 10);
  BoardRunOptions o;
  o.lanes = 2;
  o.float_format = format;
  o.cpu_split = parse_cpu_split("0.4", 2);
  BoardSystem fixed_share("fixed_share", scene, so, setup(o));
  o.concurrent = true;
  o.cpu_split = parse_cpu_split("balanced", 1);
  BoardSystem balanced("balanced", scene, so, setup(o));
  run_all({&fixed_share, &balanced});

  const SolverResult cpu = cpu_float_pipeline(scene, so, format);
  for (const BoardSystem* s : {&fixed_share, &balanced}) {
    EXPECT_GT(s->driver().stats().cpu_segments, 0u);
    EXPECT_EQ(s->result().blocked_segments, cpu.blocked_segments);
    expect_identical(s->result().radiosity, cpu.radiosity);
  }
}

}  // namespace
}  // namespace rc::test
