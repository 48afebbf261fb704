#include "host_sw/studies/child_guard.h"

#include <atomic>
#include <cerrno>
#include <ctime>
#include <mutex>

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host_sw/radiosity/jobs.h"

namespace rc {

namespace {

// The handler may only touch lock-free atomics: a fixed table of slots, 0 when free: room for what
// any command starts at once (a plot script and up to kMaxJobs study workers, host_sw/radiosity/jobs.h).
constexpr int kSlots = static_cast<int>(kMaxJobs) + 8;
std::atomic<pid_t> g_children[kSlots];
std::atomic<pid_t> g_owner{0};  // the process that installed the handlers
static_assert(std::atomic<pid_t>::is_always_lock_free, "the signal handler needs lock-free pids");

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

void sleep_milliseconds(long ms) {
  timespec t{0, ms * 1000000L};
  while (nanosleep(&t, &t) != 0 && errno == EINTR) {
  }
}

// True once `pid` has ended and been reaped (by this call or by the thread that owns it).
bool reaped(pid_t pid) {
  int status = 0;
  const pid_t r = waitpid(pid, &status, WNOHANG);
  return r == pid || (r < 0 && errno == ECHILD);
}

// Async-signal-safe: kill, waitpid, nanosleep, sigaction and getpid only.
void end_children_and_die(int signal) {
  const int saved_errno = errno;
  if (g_owner.load() == getpid()) {
    for (auto& slot : g_children) {
      const pid_t pid = slot.load();
      if (pid > 0) kill(pid, SIGTERM);
    }
    for (auto& slot : g_children) {
      const pid_t pid = slot.load();
      if (pid <= 0) continue;
      int waited = 0;
      while (!reaped(pid) && waited < kChildGraceMilliseconds) {
        sleep_milliseconds(10);
        waited += 10;
      }
      if (waited >= kChildGraceMilliseconds) {
        kill(pid, SIGKILL);
        waitpid(pid, nullptr, 0);
      }
      slot.store(0);
    }
  }
  // Die of the signal as if no handler had been there (the exit status a shell reports, 128 + n):
  // default action, then the signal again, delivered once this handler returns and unblocks it.
  struct sigaction plain {};
  plain.sa_handler = SIG_DFL;
  sigemptyset(&plain.sa_mask);
  sigaction(signal, &plain, nullptr);
  kill(getpid(), signal);
  errno = saved_errno;
}

void install_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    g_owner.store(getpid());
    for (int s : kSignals) {
      struct sigaction current {};
      if (sigaction(s, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
      struct sigaction handler {};
      handler.sa_handler = end_children_and_die;
      sigemptyset(&handler.sa_mask);
      for (int other : kSignals) sigaddset(&handler.sa_mask, other);  // one interruption at a time
      sigaction(s, &handler, nullptr);
    }
  });
}

}  // namespace

void die_with_parent(pid_t parent, int signal) {
  if (prctl(PR_SET_PDEATHSIG, signal) != 0 || getppid() != parent) _exit(128 + signal);
}

void register_child(pid_t pid) {
  install_handlers();
  for (auto& slot : g_children) {
    pid_t empty = 0;
    if (slot.compare_exchange_strong(empty, pid)) return;
  }
  // Not reachable in practice (see kSlots); the kernel's PR_SET_PDEATHSIG still ends the child.
}

void unregister_child(pid_t pid) {
  for (auto& slot : g_children) {
    pid_t mine = pid;
    if (slot.compare_exchange_strong(mine, 0)) return;
  }
}

}  // namespace rc
