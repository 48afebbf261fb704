// host_sw/studies/inert_axes.h: a profile axis the timing never reads in a study's configurations is
// named; one that moves any figure is not. Real studies, simulated end to end (small scenes, few steps).
#include "host_sw/studies/inert_axes.h"

#include <gtest/gtest.h>

#include <string>

#include "host_sw/studies/study_file.h"
#include "host_sw/studies/sweep_study.h"

namespace rc {
namespace {

StudyResult small_study(const std::string& fixed, const std::string& axes) {
  const Study s = parse_study_text(R"(
[[scenes]]
paper = { faces = 70, patches = 280 }
[solver]
steps = 3
[axes]
devices = ["xc2v6000"]
lanes = [1, 2]
banks = [6]
)" + axes + (fixed.empty() ? "" : "\n[fixed]\n" + fixed + "\n"),
                                   std::string(RC_SOURCE_DIR) + "/tests/host_sw/studies/data/inline.toml");
  return run_study(s, [](const std::string&) {});
}

// host.cpu_cores without a CPU/FPGA split (the host profile's share is 0): identical rows, named; a
// bank clock, which the transfers and passes read, is not.
TEST(InertAxes, AnAxisTheTimingNeverReadsIsNamed) {
  const StudyResult r = small_study("", "\"host.cpu_cores\" = [1, 2]\n\"banks.clock_mhz\" = [50, 133]\n");
  ASSERT_EQ(r.scenes.size(), 1u);
  ASSERT_EQ(r.scenes[0].rows.size(), 8u);
  const std::vector<std::string> w = inert_axis_warnings(r.scenes[0].rows);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("profile axis host.cpu_cores changed no figure"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("2 values"), std::string::npos) << w[0];
}

// With a split the same axis moves the times (the second processor takes the host's share): no warning.
TEST(InertAxes, TheSameAxisWithASplitIsNotNamed) {
  const StudyResult r = small_study("\"host.cpu_share\" = 0.5", "\"host.cpu_cores\" = [1, 2]\n");
  ASSERT_EQ(r.scenes.size(), 1u);
  EXPECT_TRUE(inert_axis_warnings(r.scenes[0].rows).empty());
}

// Without profile axes there is nothing to name (lanes and banks are the design space itself).
TEST(InertAxes, NoProfileAxisNoWarning) {
  const StudyResult r = small_study("", "");
  EXPECT_TRUE(inert_axis_warnings(r.scenes[0].rows).empty());
}

}  // namespace
}  // namespace rc
