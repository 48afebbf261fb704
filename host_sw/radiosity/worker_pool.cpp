#include "host_sw/radiosity/worker_pool.h"

#include "host_sw/radiosity/jobs.h"

#include <algorithm>
#include <stdexcept>

namespace rc {

WorkerPool::WorkerPool(int workers) {
  if (workers < 0) throw std::invalid_argument("thread count must not be negative (0 = the process's jobs)");
  if (workers == 0) workers = static_cast<int>(jobs());
  helpers_.reserve(static_cast<std::size_t>(workers - 1));
  for (int w = 1; w < workers; ++w) helpers_.emplace_back([this, w] { helper_loop(w); });
}

WorkerPool::~WorkerPool() {
  finish();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : helpers_) t.join();
}

void WorkerPool::start(std::function<void(int)> job) {
  finish();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = std::move(job);
    busy_ = static_cast<int>(helpers_.size());
    running_ = true;
    ++generation_;
  }
  wake_.notify_all();
}

void WorkerPool::finish() {
  std::function<void(int)> job;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!running_) return;
    job = job_;
  }
  job(0);
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return busy_ == 0; });
  running_ = false;
  job_ = nullptr;
}

void WorkerPool::helper_loop(int worker) {
  std::uint64_t seen = 0;
  for (;;) {
    std::function<void(int)> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
    }
    job(worker);
    std::lock_guard<std::mutex> lock(mutex_);
    if (--busy_ == 0) done_.notify_all();
  }
}

}  // namespace rc
