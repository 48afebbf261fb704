// Special files given where a file is read: refused by their kind before any read (a FIFO used to
// block forever on open), except an anonymous pipe where the reader takes one (--scene <(...)),
// which is read exactly once, to the size limit.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <csignal>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include "io/input_file.h"

namespace rc::io {
namespace {

namespace fs = std::filesystem;

std::string folder() {
  const fs::path dir = fs::temp_directory_path() / ("rc_special_" + std::to_string(::getpid()) + "_" +
                                                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputFileError& e) {
    return e.what();
  }
  return "";
}

// A pipe whose write end has `bytes` written and is closed; the read end stays open (closed at the end).
struct FilledPipe {
  int fds[2] = {-1, -1};
  explicit FilledPipe(const std::string& bytes) {
    EXPECT_EQ(::pipe(fds), 0);
    EXPECT_EQ(::write(fds[1], bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
    ::close(fds[1]);
  }
  ~FilledPipe() { ::close(fds[0]); }
  std::string path() const { return "/proc/self/fd/" + std::to_string(fds[0]); }
};

TEST(SpecialFiles, ANamedPipeIsRefusedWithoutWaitingForAWriter) {
  const std::string fifo = folder() + "/scene.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  const std::string expected = fifo + ": is a named pipe (FIFO), not a regular file (a scene file must be one)";
  EXPECT_EQ(message_of([&] { read_file(fifo, 1000, "a scene file"); }), expected);
  EXPECT_EQ(message_of([&] { read_file(fifo, 1000, "a scene file", Pipes::read_once); }), expected);
  EXPECT_EQ(message_of([&] { check_regular_file(fifo, 1000, "a scene file"); }), expected);
  EXPECT_FALSE(is_anonymous_pipe(fifo));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

// Issue 39: a FIFO with a process writing into it. The refusal comes at once, and the writer (which
// waits in open() for a reader) is released and ends with a broken pipe instead of waiting forever.
TEST(SpecialFiles, ANamedPipeWithAWriterIsRefusedAndTheWriterReleased) {
  const std::string fifo = folder() + "/scene.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const pid_t writer = ::fork();
  ASSERT_GE(writer, 0);
  if (writer == 0) {
    const int fd = ::open(fifo.c_str(), O_WRONLY);  // blocks until a reader opens the FIFO
    if (fd < 0) ::_exit(2);
    ::signal(SIGPIPE, SIG_DFL);
    const char text[] = "material white reflectance 0.5 0.5 0.5\n";
    for (int i = 0; i < 1000; ++i) {
      if (::write(fd, text, sizeof text - 1) < 0) ::_exit(3);  // EPIPE: no reader
    }
    ::_exit(0);
  }
  // Wait until the writer waits in open() (wait channel wait_for_partner), at most 5 s.
  for (int i = 0; i < 500; ++i) {
    std::ifstream wchan("/proc/" + std::to_string(writer) + "/wchan");
    std::string where;
    std::getline(wchan, where);
    if (where.find("partner") != std::string::npos || where.find("fifo") != std::string::npos) break;  // wait_for_partner
    ::usleep(10 * 1000);
  }
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(message_of([&] { read_file(fifo, 1000, "a scene file", Pipes::read_once); }),
            fifo + ": is a named pipe (FIFO), not a regular file (a scene file must be one)");
  int status = 0;
  pid_t done = 0;
  while ((done = ::waitpid(writer, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() - start < std::chrono::seconds(5)) {
    ::usleep(10 * 1000);
  }
  if (done == 0) {
    ::kill(writer, SIGKILL);
    ::waitpid(writer, &status, 0);
    FAIL() << "the writer still waits on the FIFO after the refusal";
  }
  EXPECT_TRUE((WIFSIGNALED(status) && WTERMSIG(status) == SIGPIPE) || (WIFEXITED(status) && WEXITSTATUS(status) == 3))
      << "status " << status;
}

TEST(SpecialFiles, ASocketIsRefusedByName) {
  const std::string path = folder() + "/s.sock";
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(path.size(), sizeof address.sun_path);
  path.copy(address.sun_path, path.size());
  ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
  EXPECT_EQ(message_of([&] { read_file(path, 1000, "a study file"); }),
            path + ": is a socket, not a regular file (a study file must be one)");
  ::close(fd);
}

TEST(SpecialFiles, AnAnonymousPipeIsReadOnceWhereAllowedAndRefusedElsewhere) {
  const FilledPipe pipe("material w reflectance 0.5 0.5 0.5\n");
  EXPECT_TRUE(is_anonymous_pipe(pipe.path()));
  EXPECT_EQ(message_of([&] { read_file(pipe.path(), 1000, "a device profile"); }),
            pipe.path() + ": is a pipe, not a regular file (a device profile must be one)");
  EXPECT_EQ(read_file(pipe.path(), 1000, "a scene file", Pipes::read_once), "material w reflectance 0.5 0.5 0.5\n");
  // Read once: the pipe is empty now.
  EXPECT_EQ(read_file(pipe.path(), 1000, "a scene file", Pipes::read_once), "");
}

TEST(SpecialFiles, APipeStopsAtTheSizeLimit) {
  const FilledPipe pipe(std::string(2000, 'x'));
  EXPECT_EQ(message_of([&] { read_file(pipe.path(), 1000, "a scene file", Pipes::read_once); }),
            pipe.path() + ": larger than the 1000-byte limit for a scene file");
}

}  // namespace
}  // namespace rc::io
