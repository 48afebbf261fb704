// WorkerPool: every worker runs each job exactly once, the caller takes part, and the pool can be
// reused for thousands of jobs (one per radiosity step).
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "host_sw/radiosity/worker_pool.h"

namespace rc {
namespace {

TEST(WorkerPool, EveryWorkerRunsEachJobOnce) {
  for (int workers : {1, 2, 3, 5}) {
    WorkerPool pool(workers);
    ASSERT_EQ(pool.size(), workers);
    std::vector<std::atomic<int>> runs(static_cast<std::size_t>(workers));
    for (int job = 0; job < 500; ++job) {
      pool.start([&](int w) { runs[static_cast<std::size_t>(w)].fetch_add(1); });
      pool.finish();
    }
    for (int w = 0; w < workers; ++w) EXPECT_EQ(runs[static_cast<std::size_t>(w)].load(), 500) << w;
  }
}

TEST(WorkerPool, CallerRunsWorkerZeroInFinish) {
  WorkerPool pool(2);
  std::thread::id worker_zero;
  std::atomic<bool> helper_ran{false};
  pool.start([&](int w) {
    if (w == 0) worker_zero = std::this_thread::get_id();
    else helper_ran = true;
  });
  pool.finish();
  EXPECT_EQ(worker_zero, std::this_thread::get_id());
  EXPECT_TRUE(helper_ran);
}

// The pattern of FastFixedVisibility: items shared out through an atomic counter; every item is
// done once, whoever takes it.
TEST(WorkerPool, SharesWorkThroughACounter) {
  WorkerPool pool(3);
  std::vector<std::atomic<int>> done(10000);
  std::atomic<std::size_t> next{0};
  pool.start([&](int) {
    for (std::size_t i; (i = next.fetch_add(1)) < done.size();) done[i].fetch_add(1);
  });
  pool.finish();
  for (const auto& d : done) ASSERT_EQ(d.load(), 1);
}

TEST(WorkerPool, StartFinishesTheJobBeforeAndFinishAloneDoesNothing) {
  WorkerPool pool(2);
  pool.finish();  // nothing started
  std::atomic<int> first{0}, second{0};
  pool.start([&](int) { first.fetch_add(1); });
  pool.start([&](int) { second.fetch_add(1); });  // the first job completes first, on both workers
  EXPECT_EQ(first.load(), 2);
  pool.finish();
  EXPECT_EQ(second.load(), 2);
}

TEST(WorkerPool, DestructorFinishesARunningJob) {
  std::atomic<int> runs{0};
  {
    WorkerPool pool(3);
    pool.start([&](int) { runs.fetch_add(1); });
  }
  EXPECT_EQ(runs.load(), 3);
}

TEST(WorkerPool, ZeroMeansEveryCoreAndNegativeThrows) {
  WorkerPool pool(0);
  EXPECT_GE(pool.size(), 1);
  EXPECT_THROW(WorkerPool(-1), std::invalid_argument);
}

}  // namespace
}  // namespace rc
