#include "io/input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rc::io {

namespace {

// RC2000SIM_LOG_READS set (to anything): each file read is named on stderr, "read <what>: <path>",
// so a test counts how often a command reads each profile (tests/scripts/profile_reads_test.sh).
void log_read(const std::string& what, const std::string& path) {
  static const bool on = std::getenv("RC2000SIM_LOG_READS") != nullptr;
  if (on) std::fprintf(stderr, "read %s: %s\n", what.c_str(), path.c_str());
}

std::string too_large(const std::string& path, std::uint64_t limit_bytes, const std::string& what) {
  return path + ": larger than the " + std::to_string(limit_bytes) + "-byte limit for " + what;
}

// stat() the path; a directory or a missing file is named here, before any read.
struct stat stat_or_throw(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputFileError(path + ": cannot open (" + std::strerror(errno) + ")");
  if (S_ISDIR(st.st_mode)) throw InputFileError(path + ": is a directory, not a file");
  return st;
}

// Anonymous pipes live on the kernel's pipe file system: the device of a pipe we make ourselves.
bool on_pipe_file_system(const struct stat& st) {
  static const dev_t pipe_device = [] {
    int fds[2];
    if (::pipe(fds) != 0) return dev_t{0};
    struct stat own {};
    const bool ok = ::fstat(fds[0], &own) == 0;
    ::close(fds[0]);
    ::close(fds[1]);
    return ok ? own.st_dev : dev_t{0};
  }();
  return S_ISFIFO(st.st_mode) && pipe_device != 0 && st.st_dev == pipe_device;
}

const char* special_kind(const struct stat& st) {
  if (S_ISFIFO(st.st_mode)) return on_pipe_file_system(st) ? "pipe" : "named pipe (FIFO)";
  if (S_ISCHR(st.st_mode)) return "character device";
  if (S_ISBLK(st.st_mode)) return "block device";
  if (S_ISSOCK(st.st_mode)) return "socket";
  return "special file";
}

// A named pipe is refused without reading it. A process already writing into it waits in open()
// for a reader, and would wait forever (a shell's `cat room.scene > f.fifo &` never ends, nor a
// script's `wait` on it): opening the read end without blocking and closing it at once lets that
// open() return, and the writer's first write fails with a broken pipe, so it ends too.
void release_writers(const std::string& path, const struct stat& st) {
  if (!S_ISFIFO(st.st_mode) || on_pipe_file_system(st)) return;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd >= 0) ::close(fd);
}

[[noreturn]] void refuse_special(const std::string& path, const struct stat& st, const std::string& what) {
  release_writers(path, st);
  throw InputFileError(path + ": is a " + special_kind(st) + ", not a regular file (" + what + " must be one)");
}

}  // namespace

bool is_anonymous_pipe(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && on_pipe_file_system(st);
}

std::string read_file(const std::string& path, std::uint64_t limit_bytes, const std::string& what, Pipes pipes) {
  const struct stat st = stat_or_throw(path);
  const bool pipe_read_once = pipes == Pipes::read_once && on_pipe_file_system(st);
  if (!S_ISREG(st.st_mode) && !pipe_read_once) refuse_special(path, st, what);
  if (static_cast<std::uint64_t>(st.st_size) > limit_bytes) throw InputFileError(too_large(path, limit_bytes, what));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputFileError(path + ": cannot open (" + std::strerror(errno) + ")");
  // A pipe has no size, and a file may grow while it is read: stop one byte past the limit.
  std::string text;
  char chunk[1 << 16];
  while (in) {
    in.read(chunk, sizeof chunk);
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > limit_bytes) throw InputFileError(too_large(path, limit_bytes, what));
  }
  if (in.bad()) throw InputFileError(path + ": read failed");
  log_read(what, path);
  return text;
}

void check_regular_file(const std::string& path, std::uint64_t limit_bytes, const std::string& what) {
  const struct stat st = stat_or_throw(path);
  if (!S_ISREG(st.st_mode)) refuse_special(path, st, what);
  if (static_cast<std::uint64_t>(st.st_size) > limit_bytes) throw InputFileError(too_large(path, limit_bytes, what));
}

}  // namespace rc::io
