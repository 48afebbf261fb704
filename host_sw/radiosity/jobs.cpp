#include "host_sw/radiosity/jobs.h"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace rc {

namespace {

std::atomic<unsigned> g_jobs{0};  // 0: not set

// The CPUs in this process's affinity mask; 0 if it cannot be read.
unsigned affinity_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 0;
  return static_cast<unsigned>(CPU_COUNT(&set));
}

// The tightest cgroup v2 CPU quota over this process's cgroup and its parents, in whole CPUs rounded
// up; 0 when there is none (cgroup v1, no quota, nothing readable).
unsigned cgroup_quota_cpus() {
  std::ifstream self("/proc/self/cgroup");
  std::string line, path;
  while (std::getline(self, line)) {
    if (line.rfind("0::", 0) == 0) path = line.substr(3);
  }
  if (path.empty()) return 0;
  unsigned best = 0;
  for (;;) {
    std::ifstream f("/sys/fs/cgroup" + (path == "/" ? std::string() : path) + "/cpu.max");
    std::string quota;
    double period = 0;
    if (f >> quota >> period && quota != "max" && period > 0) {
      const double q = std::strtod(quota.c_str(), nullptr);
      if (q > 0) {
        const unsigned cpus = std::max(1u, static_cast<unsigned>(std::ceil(q / period)));
        best = best == 0 ? cpus : std::min(best, cpus);
      }
    }
    if (path == "/" || path.empty()) break;
    const std::size_t slash = path.find_last_of('/');
    path = slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
  }
  return best;
}

std::string limits() { return "1.." + std::to_string(kMaxJobs); }

}  // namespace

unsigned usable_cores() {
  unsigned cores = affinity_cpus();
  if (cores == 0) cores = std::thread::hardware_concurrency();
  const unsigned quota = cgroup_quota_cpus();
  if (quota > 0 && (cores == 0 || quota < cores)) cores = quota;
  return std::max(1u, cores);
}

unsigned checked_jobs(long long n, const std::string& what) {
  if (n < 1 || n > kMaxJobs)
    throw std::invalid_argument(what + " must be " + limits() + " (worker processes and threads; default: the " +
                                std::to_string(usable_cores()) + " cores this process may use), got " + std::to_string(n));
  return static_cast<unsigned>(n);
}

unsigned parse_jobs(const std::string& text, const std::string& what) {
  errno = 0;
  char* end = nullptr;
  const long long n = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || end == text.c_str() || *end != '\0' || errno == ERANGE)
    throw std::invalid_argument(what + " must be a whole number " + limits() + ", got '" + text + "'");
  return checked_jobs(n, what);
}

void set_jobs(long long n, const std::string& what) { g_jobs = checked_jobs(n, what); }

unsigned jobs() {
  if (const unsigned set = g_jobs.load()) return set;
  const char* env = std::getenv(kJobsVariable);
  if (env != nullptr && *env != '\0') return parse_jobs(env, kJobsVariable);  // set but empty: as if unset
  return usable_cores();
}

}  // namespace rc
