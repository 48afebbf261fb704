// Progress on stderr for long runs: silent for the first two seconds, then a line at most twice a second.
#pragma once

#include <chrono>
#include <cstdio>

namespace rc {

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled), start_(Clock::now()), last_(start_) {}

  template <typename... Args>
  void update(const char* format, Args... args) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (now - start_ < std::chrono::seconds(2) || now - last_ < std::chrono::milliseconds(500)) return;
    last_ = now;
    shown_ = true;
    std::fprintf(stderr, "\r");
    if constexpr (sizeof...(args) == 0) {
      std::fputs(format, stderr);  // a plain message: not a format (it may hold a '%')
    } else {
      std::fprintf(stderr, format, args...);
    }
    std::fflush(stderr);
  }
  void finish() {
    if (shown_) std::fprintf(stderr, "\n");
    shown_ = false;
  }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool shown_ = false;
  Clock::time_point start_, last_;
};

}  // namespace rc
