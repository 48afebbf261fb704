// How many cores this process's parallel work may use: the timing study's worker processes
// (host_sw/studies/timing_study.h), the scenes `paper` solves side by side, and the fast
// visibility backend's threads (WorkerPool(0)). One rule and one override for all of them
// (docs/outputs.md, "Cores: --jobs and RC2000SIM_JOBS"):
//   1. set_jobs(N), which `--jobs N` and the Python module's jobs= call, if it was called;
//   2. else the environment variable RC2000SIM_JOBS, if set and not empty (checked like --jobs);
//   3. else usable_cores().
#pragma once

#include <string>

namespace rc {

// The most jobs a process takes: above the hardware threads of the largest two-socket servers (2 x
// 128 cores x 2), and low enough that a study's parent holds one pipe per worker within the usual
// limit of 1,024 open files (and the child guard's table, host_sw/studies/child_guard.cpp, one slot
// each). A larger value is a mistake, refused naming this limit.
inline constexpr long long kMaxJobs = 512;
inline constexpr const char* kJobsVariable = "RC2000SIM_JOBS";

// The cores this process may run on: the CPUs in its affinity mask (sched_getaffinity, which
// taskset, numactl and a cgroup's cpuset narrow; std::thread::hardware_concurrency counts every
// online CPU whatever the mask), cut to a cgroup v2 CPU quota (cpu.max of this process's cgroup and
// its parents, rounded up: `docker --cpus=2` on a 16-core host gives 2). At least 1.
unsigned usable_cores();

// `n` as a job count, or std::invalid_argument "<what> must be 1..512 (...), got <n>".
unsigned checked_jobs(long long n, const std::string& what);
// `text` (RC2000SIM_JOBS's value) as a whole number, checked the same way, naming the variable.
unsigned parse_jobs(const std::string& text, const std::string& what);

// Sets this process's job count (checked: `what` names where it came from, e.g. "--jobs").
void set_jobs(long long n, const std::string& what = "--jobs");
// This process's job count by the rule above; throws std::invalid_argument for a bad RC2000SIM_JOBS.
unsigned jobs();

}  // namespace rc
