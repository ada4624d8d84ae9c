// What a long stage says while it runs (prove's solver queries, report's
// proving): on a terminal, one status line rewritten in place naming the
// unit at work; otherwise (a CI log) one line per finished unit, so that
// neither stays silent for the half-minute a large catalog takes.
#pragma once

#include <cstddef>
#include <string>

#include "proofs/rule_prover.hpp"

namespace dartcheck::analysis {

class StageProgress {
 public:
  /// `units` to go through; `terminal`: whether stderr is one.
  StageProgress(std::size_t units, bool terminal);
  ~StageProgress();  // clears the status line
  /// Clears the status line (before anything else is printed: a result,
  /// the final table); the next start() draws it again.
  void clear();
  StageProgress(const StageProgress&) = delete;
  StageProgress& operator=(const StageProgress&) = delete;

  /// Unit k (0-based) starts: "[k+1/N] what" on a terminal.
  void start(std::size_t k, const std::string& what);
  /// Unit k finished: "[k+1/N] line" as a line of its own off a terminal.
  void finished(std::size_t k, const std::string& line);

 private:
  std::size_t units_;
  bool terminal_;
  bool drawn_ = false;  // a status line is on the terminal
};

/// A rule's proof in one line: "rule: 5 agree, 0 disagree, 1 unresolved,
/// 2.31 s", or why it is out of the solver's scope.
std::string proof_line(const proofs::RuleProof& p);

}  // namespace dartcheck::analysis
