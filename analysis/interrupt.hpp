// Ctrl-C and CI time-outs: SIGINT and SIGTERM set a flag instead of ending
// the process, so that long runs (fuzz, prove, report) stop at their next
// check, keep the results of the rules they finished, write them, and exit
// with `interrupted_exit`. A second signal, a second or more after the first,
// ends the process at once (timeout(1) delivers one request twice). A run
// that does not look at the flag within `grace_seconds` of the signal (one
// long rule, map or example between its checks) is ended then as if it had
// not caught the signal: every signal is obeyed within seconds.
#pragma once

#include <string_view>

namespace dartcheck::analysis {

inline constexpr int interrupted_exit = 130;  // 128 + SIGINT, as shells report it
inline constexpr unsigned grace_seconds = 2;

/// Installs the handlers (once per process; later calls do nothing).
void catch_interrupts();

/// For the commands that have nothing finished to print when a signal
/// comes (one map, one mesh, one word): print "interrupted" and exit with
/// `interrupted_exit` at once. Installed by main for every command, even
/// where the signal was inherited as ignored (a background job of a
/// script); catch_interrupts() replaces it.
void exit_on_interrupt();

/// A line that exit_on_interrupt()'s handler prints after "interrupted",
/// for an output the command promised and will not write (a baseline
/// interrupted while its catalog is read). Copied into a fixed buffer, so
/// that the handler stays async-signal-safe; cut at 1,023 bytes.
void say_on_early_interrupt(std::string_view line);

/// Whether SIGINT or SIGTERM arrived since catch_interrupts(). The first
/// call that answers yes ends the grace period: the caller is stopping.
bool interrupted();

/// For a parent of shard processes (--jobs): a second signal, a second or
/// more after the first, is counted instead of ending the process at once,
/// so that the parent can kill its shards and remove its files first.
void count_second_interrupt();

/// Whether a second signal arrived under count_second_interrupt().
bool interrupted_twice();

}  // namespace dartcheck::analysis
