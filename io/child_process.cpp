#include "io/child_process.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

// Declared by the sanitizer runtimes (sanitizer/common_interface_defs.h); weak, so a build without
// a sanitizer links and sees a null address.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace rc::io {

namespace {

constexpr int kWorkThrew = 3;

// The child's faults are the parent's to report, so the child dies of them plainly: the handlers it
// inherited for fatal signals (a fuzzer's, which would record the parent's input as a crash; a
// sanitizer's, which would print a report for a reader we already expect to fail; a test
// framework's) are reset, and a sanitizer's death callback (libFuzzer writes a crash file from it) is
// removed.
void die_plainly() {
  for (const int s : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGTRAP, SIGALRM, SIGXCPU, SIGXFSZ}) {
    std::signal(s, SIG_DFL);
  }
  if (__sanitizer_set_death_callback != nullptr) __sanitizer_set_death_callback(nullptr);
}

// Everything, retrying short writes; false if the reader went away.
bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

[[noreturn]] void child(int fd, const std::function<std::string()>& work) {
  die_plainly();
  int status = 0;
  try {
    if (!write_all(fd, work())) status = 2;
  } catch (...) {
    status = kWorkThrew;
  }
  ::_exit(status);
}

// Reads until end of file or the deadline; false on the deadline.
bool read_until_eof(int fd, std::chrono::steady_clock::time_point deadline, std::string& into) {
  char chunk[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    into.append(chunk, static_cast<std::size_t>(n));
  }
}

}  // namespace

std::string ChildOutcome::how_it_ended() const {
  if (timed_out) return "stopped after its time limit";
  if (signal != 0) return "killed by signal " + std::to_string(signal) + " (" + ::strsignal(signal) + ")";
  if (exit_status == kWorkThrew) return "ended by an exception";
  return "exited with status " + std::to_string(exit_status);
}

ChildOutcome run_in_child(const std::function<std::string()>& work, std::chrono::seconds time_limit) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("cannot start a child process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], work);
  }
  ::close(fds[1]);
  ChildOutcome out;
  const bool finished = read_until_eof(fds[0], std::chrono::steady_clock::now() + time_limit, out.bytes);
  ::close(fds[0]);
  if (!finished) {
    ::kill(pid, SIGKILL);
    out.timed_out = true;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) out.signal = WTERMSIG(status);
  if (WIFEXITED(status)) out.exit_status = WEXITSTATUS(status);
  out.completed = !out.timed_out && WIFEXITED(status) && out.exit_status == 0;
  if (out.timed_out) out.signal = 0;
  return out;
}

}  // namespace rc::io
