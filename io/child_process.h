// Work that may crash, hang or exhaust memory, done in a child process: a third-party reader fed a
// malformed file (Assimp) must not take the simulator down with it. The child runs `work` and sends
// its bytes back through a pipe; the parent gets them, or how the child ended.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace rc::io {

struct ChildOutcome {
  bool completed = false;  // the child returned from `work` and exited 0: `bytes` is everything it sent
  std::string bytes;
  int signal = 0;          // the signal that ended it, if one did
  int exit_status = 0;     // its exit status otherwise
  bool timed_out = false;  // stopped (SIGKILL) after the time limit
  // "killed by signal 6 (Aborted)", "stopped after 60 s", "exited with status 3": for error messages.
  std::string how_it_ended() const;
};

// Forks; the child runs `work` (an exception in it is reported as exit status 3) and _exits without
// running atexit handlers (so no leak check or SystemC teardown of the parent's state runs twice).
// The child dies of its own faults plainly: inherited handlers of fatal signals and a sanitizer's
// death callback are reset in it, so a fuzzer or test framework in the parent never mistakes the
// child's crash for its own.
// Throws std::runtime_error if the process or pipe cannot be made.
ChildOutcome run_in_child(const std::function<std::string()>& work, std::chrono::seconds time_limit);

}  // namespace rc::io
