// Progress on stderr for long runs: silent for the first two seconds, then, on a terminal, one line
// rewritten in place at most twice a second; when stderr is not a terminal (a pipe, a log file), a
// line of its own at most every five seconds, so that a log shows how far a run got.
#pragma once

#include <chrono>
#include <cstdio>

#include <unistd.h>

namespace rc {

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled)
      : enabled_(enabled), terminal_(isatty(fileno(stderr)) != 0), start_(Clock::now()), last_(start_) {}

  template <typename... Args>
  void update(const char* format, Args... args) {
    if (!enabled_) return;
    const auto now = Clock::now();
    const auto interval = terminal_ ? std::chrono::milliseconds(500) : std::chrono::milliseconds(5000);
    if (now - start_ < std::chrono::seconds(2) || (shown_any_ && now - last_ < interval)) return;
    last_ = now;
    shown_ = shown_any_ = true;
    if (terminal_) std::fprintf(stderr, "\r");
    if constexpr (sizeof...(args) == 0) {
      std::fputs(format, stderr);  // a plain message: not a format (it may hold a '%')
    } else {
      std::fprintf(stderr, format, args...);
    }
    if (!terminal_) std::fputc('\n', stderr);
    std::fflush(stderr);
  }
  void finish() {
    if (shown_ && terminal_) std::fprintf(stderr, "\n");
    shown_ = false;
  }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool terminal_;
  bool shown_ = false;      // a line is on the terminal, to end at finish()
  bool shown_any_ = false;
  Clock::time_point start_, last_;
};

}  // namespace rc
