// Progress on stderr for long runs: silent for the first two seconds, then, on a terminal, one line
// rewritten in place at most twice a second; when stderr is not a terminal (a pipe, a log file), a
// line of its own at most every five seconds, so that a log shows how far a run got.
//
// A heartbeat keeps it alive where no update comes: a single step of a large scene can take minutes
// (one float step of a 100,000-face scene), and the solver reports only between steps. A helper
// thread repeats the last message with how long it has stood ("step 1, 0.00% converged; 40 s since")
// at the same rate, and says "working" before any message, so progress appears within seconds,
// piped or not (issue 39).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

#include <unistd.h>

namespace rc {

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled)
      : enabled_(enabled), terminal_(isatty(fileno(stderr)) != 0), start_(Clock::now()), last_(start_), changed_(start_) {
    if (enabled_) heartbeat_ = std::thread([this] { beat(); });
  }
  ~ProgressLine() {
    if (heartbeat_.joinable()) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
      }
      wake_.notify_all();
      heartbeat_.join();
    }
  }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  template <typename... Args>
  void update(const char* format, Args... args) {
    if (!enabled_) return;
    std::string text;
    if constexpr (sizeof...(args) == 0) {
      text = format;  // a plain message: not a format (it may hold a '%')
    } else {
      char buffer[512];
      std::snprintf(buffer, sizeof buffer, format, args...);
      text = buffer;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    const auto now = Clock::now();
    message_ = std::move(text);
    changed_ = now;
    paused_ = false;
    if (due(now)) show(message_, now);
  }
  void finish() {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    paused_ = true;  // the heartbeat stays quiet until the next update
    if (shown_ && terminal_) std::fprintf(stderr, "\n");
    shown_ = false;
  }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;

  std::chrono::milliseconds interval() const {
    return terminal_ ? std::chrono::milliseconds(500) : std::chrono::milliseconds(5000);
  }
  bool due(Clock::time_point now) const {
    return now - start_ >= std::chrono::seconds(2) && (!shown_any_ || now - last_ >= interval());
  }
  // Under mutex_.
  void show(const std::string& text, Clock::time_point now) {
    last_ = now;
    shown_ = shown_any_ = true;
    if (terminal_) std::fputs("\r", stderr);
    std::fputs(text.c_str(), stderr);
    std::fputs(terminal_ ? "\x1b[K" : "\n", stderr);  // a terminal: clear what a longer line left
    std::fflush(stderr);
  }
  void beat() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
      wake_.wait_for(lock, std::chrono::milliseconds(250));
      if (stop_) break;
      const auto now = Clock::now();
      if (paused_ || !due(now) || now - changed_ < interval()) continue;
      const long standing = static_cast<long>(std::chrono::duration<double>(now - changed_).count());
      show(message_.empty() ? "working: " + std::to_string(standing) + " s"
                            : message_ + "; " + std::to_string(standing) + " s since",
           now);
    }
  }

  bool enabled_;
  bool terminal_;
  bool shown_ = false;      // a line is on the terminal, to end at finish()
  bool shown_any_ = false;
  bool paused_ = false;     // after finish(), until the next update
  bool stop_ = false;
  Clock::time_point start_, last_, changed_;  // construction, the last line shown, the last update
  std::string message_;                       // the last update's text
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread heartbeat_;
};

}  // namespace rc
