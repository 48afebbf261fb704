// Child processes that end with this one (issue 27, docs/reliability.md "Round three: commands"). A
// plot script or a study worker left running after its command was interrupted kept writing into the
// output folder for a minute, over the files of the next run there. Two mechanisms, because a parent
// can die in two ways:
// - caught (SIGINT, SIGTERM, SIGHUP): this process ends each registered child (SIGTERM, then SIGKILL
//   after kChildGraceMilliseconds), waits for it, and only then dies of the signal as it would have,
//   so nothing a child writes comes after the parent's end;
// - not catchable (SIGKILL, a crash): the kernel signals the child itself (PR_SET_PDEATHSIG, set by
//   die_with_parent in the child).
#pragma once

#include <csignal>

#include <sys/types.h>

namespace rc {

// How long an interrupted parent waits for a child's own clean-up (a plot script removes its
// half-written picture) before it kills the child outright.
constexpr int kChildGraceMilliseconds = 2000;

// In a child, right after fork(): the kernel sends it `signal` when the thread that forked it ends
// (call fork() from a thread that lives as long as the child should: the main thread). If `parent`
// is already gone (it died between fork() and here), the child exits at once.
void die_with_parent(pid_t parent, int signal);

// While registered, `pid` is ended when this process is interrupted (above). The handlers of SIGINT,
// SIGTERM and SIGHUP are installed by the first registration, each only where the signal still has
// its default action (a signal the user ignores, e.g. under nohup, stays ignored). A forked child
// that inherits the handlers and the list ends no one: it dies of the signal plainly.
void register_child(pid_t pid);
void unregister_child(pid_t pid);

}  // namespace rc
