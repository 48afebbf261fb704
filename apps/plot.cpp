#include "apps/plot.h"

#include <cerrno>
#include <csignal>
#include <filesystem>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host_sw/studies/child_guard.h"
#include "io/config_dir.h"

namespace rc {

namespace {

// The interpreter in a child of this process, reading requests from a pipe on its stdin. Not
// popen(): its shell would stand between this process and the interpreter, and the interpreter
// must end with this process (studies/child_guard.h): SIGTERM lets it remove a half-written
// picture (apps/plots/entry.py) before it exits.
pid_t start_interpreter(const std::string& python, const std::string& script, int& request_fd) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return -1;
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return -1;
  }
  if (pid == 0) {
    die_with_parent(parent, SIGTERM);
    ::dup2(fds[0], STDIN_FILENO);  // dup2 clears close-on-exec on the copy
    std::signal(SIGPIPE, SIG_DFL);
    const char* argv[] = {python.c_str(), script.c_str(), "-", nullptr};
    ::execvp(argv[0], const_cast<char* const*>(argv));
    _exit(127);  // as a shell says "command not found"
  }
  ::close(fds[0]);
  register_child(pid);
  request_fd = fds[1];
  return pid;
}

// An installed rc2000sim draws with its own prefix's scripts (<prefix>/share/rc2000tlm/plots), a
// build tree's with the source tree's, else the configured prefix's (io/config_dir.h).
std::string plot_script_path(const std::string& script) {
  const std::string beside = io::share_dir_of_program();
  if (!beside.empty()) return beside + "/plots/" + script;
  const std::string source = std::string(RC_SOURCE_DIR) + "/apps/plots/" + script;
  if (std::filesystem::exists(source)) return source;
  return io::installed_share_dir() + "/plots/" + script;
}

}  // namespace

PlotProcess::PlotProcess(const std::string& script) {
  const std::string path = plot_script_path(script);
  if (!std::filesystem::exists(path)) {
    std::fprintf(stderr, "warning: %s not found; its pictures are not drawn\n", path.c_str());
    ok_ = false;
    return;
  }
  // Debian's interpreter, which has python3-matplotlib, even when another python3 is first on PATH.
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  command_ = python + " " + path + " -";
  std::signal(SIGPIPE, SIG_IGN);  // a script that died must cost a warning, not the process
  std::fflush(nullptr);           // the child must not inherit unflushed output
  int fd = -1;
  pid_ = start_interpreter(python, path, fd);
  if (pid_ < 0 || (pipe_ = ::fdopen(fd, "w")) == nullptr) {
    if (fd >= 0) ::close(fd);
    std::fprintf(stderr, "warning: could not start %s; its pictures are not drawn\n", command_.c_str());
    ok_ = false;
  }
}

void PlotProcess::draw(const std::string& csv_path, const std::string& output) {
  if (pipe_ == nullptr) return;
  if (std::fprintf(pipe_, "%s\t%s\n", csv_path.c_str(), output.c_str()) < 0 || std::fflush(pipe_) != 0) ok_ = false;
}

bool PlotProcess::finish() {
  if (pipe_ != nullptr) {
    std::fclose(pipe_);  // end of requests: the script finishes its drawings and exits
    pipe_ = nullptr;
  }
  if (pid_ > 0) {
    int status = 0;
    pid_t r;
    while ((r = ::waitpid(pid_, &status, 0)) < 0 && errno == EINTR) {
    }
    unregister_child(pid_);
    pid_ = -1;
    if (r < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) ok_ = false;
    if (!ok_) std::fprintf(stderr, "warning: plotting failed (%s); the CSV is complete\n", command_.c_str());
  }
  return ok_;
}

bool plot(const std::string& script, const std::string& csv_path, const std::string& output) {
  PlotProcess process(script);
  process.draw(csv_path, output);
  return process.finish();
}

}  // namespace rc
