// Ctrl-C and CI time-outs: SIGINT and SIGTERM set a flag instead of ending
// the process, so that long runs (fuzz, prove, report) stop at their next
// check, keep the results of the rules they finished, write them, and exit
// with `interrupted_exit`. A second signal ends the process at once.
#pragma once

namespace dartcheck::analysis {

inline constexpr int interrupted_exit = 130;  // 128 + SIGINT, as shells report it

/// Installs the handlers (once per process; later calls do nothing).
void catch_interrupts();

/// Whether SIGINT or SIGTERM arrived since catch_interrupts().
bool interrupted();

}  // namespace dartcheck::analysis
