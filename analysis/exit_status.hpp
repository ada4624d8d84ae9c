// The exit statuses of every dartcheck command (README, "Exit status"): the
// commands and the library parts that end a run (reports/run_output,
// campaign/merge) return these; a run a signal stopped returns
// analysis::interrupted_exit (130).
#pragma once

namespace dartcheck::exit_status {

enum Exit : int {
  ok = 0,             // success
  violation = 1,      // a violation or a failed expectation
  bad_input = 2,      // bad input or usage
  soundness_bug = 3,  // a rule judged consistent broke a map
  output_error = 4,   // an output that could not be written (core/output_file.hpp)
};

}  // namespace dartcheck::exit_status
