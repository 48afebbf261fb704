// run_timing_study deals its cases to several processes; each outcome must be exactly what one
// process gives. The reference runs in a forked child (SystemC elaborates once per process).
#include <gtest/gtest.h>

#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "host_sw/studies/calibration_variants.h"
#include "host_sw/studies/timing_study.h"
#include "tests/host_sw/platform/system_support.h"
#include "host_sw/outputs/run_report_json.h"

namespace rc::test {
namespace {

std::string dump(const std::vector<TimingOutcome>& outcomes) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const TimingOutcome& o : outcomes) {
    j.push_back({{"label", o.label}, {"seconds", o.simulated_seconds}, {"steps", o.steps}, {"report", to_json(o.report)}});
  }
  return j.dump();
}

std::string in_one_process(const std::vector<TimingCase>& cases) {
  int fds[2];
  EXPECT_EQ(::pipe(fds), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    const std::string text = dump(run_timing_study(cases, 1));
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(fds[1], text.data() + done, text.size() - done);
      if (n <= 0) _exit(3);
      done += static_cast<std::size_t>(n);
    }
    _exit(0);
  }
  ::close(fds[1]);
  std::string text;
  char buffer[65536];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  return text;
}

TEST(TimingStudy, ProcessesChangeNoOutcome) {
  const Scene scene = small_cornell_box();
  SolverOptions so = steps(12);
  const RecordedRun recorded = record_functional_run(scene, so, "fixed", 15, 1);
  const HostProfile host = find_host_profile("athlon-mp-2600");
  std::vector<TimingCase> cases;
  auto add = [&](unsigned lanes, bool concurrent, bool software, const DriverModel& model) {
    TimingCase c;
    c.label = std::to_string(cases.size());
    c.scene = &scene;
    c.solver = so;
    c.recording = &recorded.recording;
    c.software = software;
    c.host_profile = with_driver_model(host, model);
    c.board.lanes = lanes;
    c.board.concurrent = concurrent;
    c.board.host_profile = c.host_profile;
    cases.push_back(c);
  };
  for (const DriverModel& m : serial_driver_variants(host.driver_model)) {
    for (const DriverModel& overlap : with_each_overlap(m)) add(2, true, false, overlap);
    add(1, false, false, m);
  }
  add(1, false, true, host.driver_model);
  const std::string reference = in_one_process(cases);
  const std::vector<TimingOutcome> dealt = run_timing_study(cases, 3);
  ASSERT_EQ(dealt.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) EXPECT_EQ(dealt[i].label, cases[i].label);
  EXPECT_EQ(dump(dealt), reference);
}

// The shard count: one per process while they fit; past that whole rounds of `processes` (a last
// shard alone would leave cores idle), never more than kMaxSystemsPerProcess in one.
TEST(TimingStudy, ShardsComeInWholeRounds) {
  const std::size_t k = kMaxSystemsPerProcess;
  EXPECT_EQ(study_shards(0, 2), 1u);
  EXPECT_EQ(study_shards(1, 2), 1u);
  EXPECT_EQ(study_shards(5, 0), 1u);  // no processes: one
  EXPECT_EQ(study_shards(2 * k, 2), 2u);
  EXPECT_EQ(study_shards(2 * k + 1, 2), 4u);  // 3 needed, 4 make two rounds of 2
  EXPECT_EQ(study_shards(171, 2), 4u);        // rc2000sim paper's systems
  EXPECT_EQ(study_shards(171, 3), 3u);
  EXPECT_EQ(study_shards(171, 1), 3u);
  EXPECT_EQ(study_shards(7 * k, 3), 9u);
  for (std::size_t n : {1u, 63u, 64u, 65u, 200u, 1000u, 4000u}) {
    for (unsigned p : {1u, 2u, 3u, 8u, 16u, 64u, 512u}) {  // no cap on processes (--jobs up to 512)
      const std::size_t shards = study_shards(n, p);
      EXPECT_LE((n + shards - 1) / shards, k) << n << " cases, " << p << " processes";
      EXPECT_TRUE(shards <= p || shards % p == 0) << n << " cases, " << p << " processes";
    }
  }
}

// More systems than one process elaborates: the study is cut into shards of at most
// kMaxSystemsPerProcess. With more shards than processes every shard runs in a child, `processes`
// at a time (1 and 2 below); with as many, this process runs one (3, last: SystemC elaborates once
// per process). Every outcome must be what the case gives beside other neighbours (the reference:
// three runs of consecutive cases, each in one process).
TEST(TimingStudy, ShardsChangeNoOutcome) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(12);
  const RecordedRun recorded = record_functional_run(scene, so, "fixed", 15, 1);
  const std::size_t k = kMaxSystemsPerProcess;
  std::vector<TimingCase> cases;
  for (std::size_t i = 0; i < 2 * k + 8; ++i) {
    TimingCase c;
    c.label = std::to_string(i);
    c.scene = &scene;
    c.solver = steps(6 + static_cast<int>(i % 7));  // unequal costs: the deal mixes the runs
    c.recording = &recorded.recording;
    c.software = i % 5 == 4;
    c.board.lanes = static_cast<board::LaneCount>(1 + i % 3);
    c.board.concurrent = i % 2 == 1;
    cases.push_back(c);
  }
  const auto part = [](const auto& v, std::size_t from, std::size_t to) {
    return std::decay_t<decltype(v)>(v.begin() + static_cast<std::ptrdiff_t>(from), v.begin() + static_cast<std::ptrdiff_t>(to));
  };
  const std::size_t n = cases.size();
  const std::string reference = in_one_process(part(cases, 0, k)) + in_one_process(part(cases, k, 2 * k)) +
                                in_one_process(part(cases, 2 * k, n));
  for (unsigned processes : {1u, 2u, 3u}) {
    const std::vector<TimingOutcome> sharded = run_timing_study(cases, processes);
    ASSERT_EQ(sharded.size(), n);
    EXPECT_EQ(dump(part(sharded, 0, k)) + dump(part(sharded, k, 2 * k)) + dump(part(sharded, 2 * k, n)), reference)
        << processes << " processes";
  }
}

// Many processes, as on a large machine with no cap: more processes than cases gives one case per
// process (this one runs the first, children the others), and every outcome is still what one
// process gives.
TEST(TimingStudy, MoreProcessesThanCasesChangeNoOutcome) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(8);
  const RecordedRun recorded = record_functional_run(scene, so, "fixed", 15, 1);
  std::vector<TimingCase> cases;
  for (std::size_t i = 0; i < 12; ++i) {
    TimingCase c;
    c.label = std::to_string(i);
    c.scene = &scene;
    c.solver = steps(4 + static_cast<int>(i % 5));
    c.recording = &recorded.recording;
    c.software = i % 4 == 3;
    c.board.lanes = static_cast<board::LaneCount>(1 + i % 3);
    c.board.concurrent = i % 2 == 1;
    cases.push_back(c);
  }
  EXPECT_EQ(study_shards(cases.size(), 16), cases.size());
  const std::string reference = in_one_process(cases);
  EXPECT_EQ(dump(run_timing_study(cases, 16)), reference);
}

}  // namespace
}  // namespace rc::test
