// RunReport (host_sw/platform/run_report.h): the typed report of a board run, its one JSON writer, and the
// codec the timing study's worker processes use, which must keep every field exactly.
#include <gtest/gtest.h>

#include "host_sw/platform/run_report_json.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

TEST(RunReport, CodecKeepsEveryFieldAndTheWriterTheDocument) {
  BoardRunOptions o;
  o.lanes = 2;
  o.concurrent = true;
  const Scene scene = small_cornell_box();  // the system keeps a reference to it
  BoardSystem board("board", scene, steps(3), setup(o));
  run_all({&board});
  const RunReport report = board.report(1.25);
  const RunReport back = decode(encode(report));
  EXPECT_EQ(to_json(back).dump(), to_json(report).dump());
  EXPECT_EQ(encode(back), encode(report));
  // The writer's document: the board schema, the timeline identity, the wall-clock fields.
  const nlohmann::ordered_json j = to_json(report);
  EXPECT_EQ(j["schema"], "rc2000sim.board/1");
  EXPECT_DOUBLE_EQ(j["time"]["host_compute_seconds"].get<double>() + j["time"]["driver_cpu_seconds"].get<double>() +
                       j["time"]["pci_transfer_seconds"].get<double>() + j["time"]["waiting_seconds"].get<double>(),
                   report.simulated_seconds);
  EXPECT_EQ(j["wall_seconds"], 1.25);
  EXPECT_EQ(j["host"]["driver_model"], board.cpu().profile().driver_model.name());
  EXPECT_EQ(j["lanes"].size(), 2u);
  EXPECT_THROW(decode(R"({"not": "a report"})"), std::invalid_argument);
}

}  // namespace
}  // namespace rc::test
