// run_timing_study deals its cases to several processes; each outcome must be exactly what one
// process gives. The reference runs in a forked child (SystemC elaborates once per process).
#include <gtest/gtest.h>

#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "host_sw/studies/calibration_variants.h"
#include "host_sw/studies/timing_study.h"
#include "tests/host_sw/platform/system_support.h"

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

}  // namespace
}  // namespace rc::test
