// The job count (host_sw/radiosity/jobs.h): one rule for the studies' processes and the fast
// backend's threads, its override, and the refusals that name the option and the limit.
#include <gtest/gtest.h>

#include <sched.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

#include "host_sw/radiosity/jobs.h"
#include "host_sw/radiosity/worker_pool.h"

namespace rc {
namespace {

std::string refusal(long long n) {
  try {
    (void)checked_jobs(n, "--jobs");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string parse_refusal(const std::string& text) {
  try {
    (void)parse_jobs(text, kJobsVariable);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Jobs, UsableCoresAreTheAffinityMaskAtMost) {
  cpu_set_t set;
  CPU_ZERO(&set);
  ASSERT_EQ(sched_getaffinity(0, sizeof set, &set), 0);
  const unsigned cores = usable_cores();
  EXPECT_GE(cores, 1u);
  EXPECT_LE(cores, static_cast<unsigned>(CPU_COUNT(&set)));
  if (std::thread::hardware_concurrency() > 0) {
    EXPECT_LE(cores, std::thread::hardware_concurrency());
  }
}

TEST(Jobs, OutOfRangeIsRefusedNamingTheOptionAndTheLimit) {
  for (long long n : {0LL, -1LL, kMaxJobs + 1, 1LL << 40}) {
    const std::string e = refusal(n);
    EXPECT_EQ(e.rfind("--jobs must be 1..512 (", 0), 0u) << e;
    EXPECT_NE(e.find(", got " + std::to_string(n)), std::string::npos) << e;
  }
  EXPECT_EQ(checked_jobs(1, "--jobs"), 1u);
  EXPECT_EQ(checked_jobs(kMaxJobs, "--jobs"), 512u);
  EXPECT_EQ(parse_jobs("8", kJobsVariable), 8u);
  for (const char* bad : {"", "x", "4x", "2.5", " ", "99999999999999999999"})
    EXPECT_EQ(parse_refusal(bad), std::string("RC2000SIM_JOBS must be a whole number 1..512, got '") + bad + "'") << bad;
  EXPECT_EQ(parse_refusal("0").rfind("RC2000SIM_JOBS must be 1..512 (", 0), 0u);
}

// One process-wide rule, in order: the usable cores; RC2000SIM_JOBS (empty: as if unset; bad:
// refused naming it); set_jobs (--jobs) over the variable; WorkerPool(0) takes the rule's count.
// One test, because set_jobs lasts for the process.
TEST(Jobs, TheOverrideOrderAndTheWorkerPool) {
  ::unsetenv(kJobsVariable);
  EXPECT_EQ(jobs(), usable_cores());
  ::setenv(kJobsVariable, "", 1);
  EXPECT_EQ(jobs(), usable_cores());
  ::setenv(kJobsVariable, "3", 1);
  EXPECT_EQ(jobs(), 3u);
  EXPECT_EQ(WorkerPool(0).size(), 3);
  ::setenv(kJobsVariable, "0", 1);
  EXPECT_THROW((void)jobs(), std::invalid_argument);
  EXPECT_THROW(set_jobs(0), std::invalid_argument);
  set_jobs(5);
  EXPECT_EQ(jobs(), 5u);  // --jobs wins over a bad variable, which is then never read
  EXPECT_EQ(WorkerPool(0).size(), 5);
  EXPECT_EQ(WorkerPool(2).size(), 2);
  ::unsetenv(kJobsVariable);
}

}  // namespace
}  // namespace rc
