// A fixed set of helper threads, created once and reused for every job, that run one job at a
// time alongside the calling thread. Starting a job costs a wake-up, not a thread creation, so a
// radiosity step of a few hundred microseconds can still be split across cores.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rc {

class WorkerPool {
 public:
  // `workers` counts the calling thread too: workers - 1 helper threads are started here.
  // 0 means jobs() (host_sw/radiosity/jobs.h: --jobs, RC2000SIM_JOBS or the usable cores).
  // Throws std::invalid_argument if negative.
  explicit WorkerPool(int workers);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int size() const { return static_cast<int>(helpers_.size()) + 1; }

  // Hands job to every helper, which runs job(w) with its index w = 1 .. size() - 1, and returns
  // at once. The job shares its work out itself (e.g. through an atomic counter). It must not
  // throw. Finishes a job still running first.
  void start(std::function<void(int)> job);
  // Runs job(0) on the calling thread, then waits until every helper has returned from the job.
  // Does nothing if no job was started.
  void finish();

 private:
  void helper_loop(int worker);

  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::function<void(int)> job_;
  std::uint64_t generation_ = 0;  // bumped once per job; helpers run each generation once
  int busy_ = 0;                  // helpers still inside the current job
  bool running_ = false;          // a job was started and not finished
  bool stop_ = false;
};

}  // namespace rc
