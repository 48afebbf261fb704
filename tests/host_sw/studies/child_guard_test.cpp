// child_guard (studies/child_guard.h): children end with their parent. Each test forks a "parent"
// process (so the test process's own signal handlers stay untouched), which forks a "child" that
// sleeps; the parent reports the child's pid through a pipe and is then interrupted or killed. The
// whole command-level check is tests/scripts/sweep_interrupt_test.sh.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "host_sw/studies/child_guard.h"

namespace rc {
namespace {

// Gone, or a zombie waiting for whoever adopted it: either way it runs no more.
bool ended(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_text, name, state;
  if (!(stat >> pid_text >> name >> state)) return true;
  return state == "Z" || state == "X";
}

bool ends_within(pid_t pid, std::chrono::milliseconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!ended(pid)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

struct Family {
  pid_t parent = -1, child = -1;
};

// Forks the parent, which forks a sleeping child (ended by `child_signal` when the parent dies) and
// registers it if `registered`, then writes the child's pid and waits for a signal.
Family start_family(bool registered, int child_signal) {
  int fds[2];
  if (::pipe(fds) != 0) return {};
  const pid_t parent = ::fork();
  if (parent == 0) {
    ::close(fds[0]);
    // The guard installs its handlers only over default actions; whoever ran the test may have
    // left one ignored.
    for (int s : {SIGINT, SIGTERM, SIGHUP}) std::signal(s, SIG_DFL);
    const pid_t me = ::getpid();
    const pid_t child = ::fork();
    if (child == 0) {
      die_with_parent(me, child_signal);
      for (;;) ::pause();
    }
    if (registered) register_child(child);
    if (::write(fds[1], &child, sizeof child) != sizeof child) _exit(3);
    for (;;) ::pause();
  }
  ::close(fds[1]);
  Family f;
  f.parent = parent;
  if (::read(fds[0], &f.child, sizeof f.child) != sizeof f.child) f.child = -1;
  ::close(fds[0]);
  return f;
}

int end_status(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status) ? WTERMSIG(status) : -1;
}

// SIGTERM, SIGINT, SIGHUP: the parent ends its registered child, reaps it, and only then dies of
// the signal itself; so when the parent's death is seen, the child is already gone. The child has no
// death signal from the kernel here (0), so only the guard can have ended it.
TEST(ChildGuard, AnInterruptedParentEndsItsChildrenBeforeItDies) {
  for (int signal : {SIGTERM, SIGINT, SIGHUP}) {
    const Family f = start_family(true, 0);
    ASSERT_GT(f.child, 0);
    ::kill(f.parent, signal);
    EXPECT_EQ(end_status(f.parent), signal) << "the parent dies of the signal, as without a handler";
    EXPECT_TRUE(ended(f.child)) << "signal " << signal << ": the child outlived its parent";
    if (!ended(f.child)) ::kill(f.child, SIGKILL);  // a failure must not leave it holding the output open
  }
}

// SIGKILL runs no handler: the kernel sends the child its signal (PR_SET_PDEATHSIG) at the parent's
// death. Unregistered children rely on it too.
TEST(ChildGuard, AKilledParentsChildrenAreEndedByTheKernel) {
  for (bool registered : {true, false}) {
    const Family f = start_family(registered, SIGTERM);
    ASSERT_GT(f.child, 0);
    ::kill(f.parent, SIGKILL);
    EXPECT_EQ(end_status(f.parent), SIGKILL);
    EXPECT_TRUE(ends_within(f.child, std::chrono::seconds(5))) << "registered " << registered;
    if (!ended(f.child)) ::kill(f.child, SIGKILL);
  }
}

// A child forked after its parent died never runs on: die_with_parent finds it adopted and exits.
TEST(ChildGuard, AChildWhoseParentIsAlreadyGoneExitsAtOnce) {
  const pid_t child = ::fork();
  if (child == 0) {
    die_with_parent(::getppid() + 1000000, SIGKILL);  // not its parent: as if the parent had died
    _exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGKILL);
}

}  // namespace
}  // namespace rc
