#include "analysis/stage_progress.hpp"

#include <fmt/format.h>

#include "core/terminal.hpp"

namespace dartcheck::analysis {

StageProgress::StageProgress(std::size_t units, bool terminal) : units_(units), terminal_(terminal) {}

StageProgress::~StageProgress() { clear(); }

void StageProgress::clear() {
  if (terminal_ && drawn_ && !terminal().quiet) fmt::print(stderr, "\r\033[K");
  drawn_ = false;
}

void StageProgress::start(std::size_t k, const std::string& what) {
  if (terminal_ && !terminal().quiet) fmt::print(stderr, "\r\033[K[{}/{}] {}", k + 1, units_, what);
  drawn_ = true;
}

void StageProgress::finished(std::size_t k, const std::string& line) {
  if (!terminal_ && !terminal().quiet) fmt::print(stderr, "[{}/{}] {}\n", k + 1, units_, line);
}

std::string proof_line(const proofs::RuleProof& p) {
  using proofs::Agreement;
  if (!p.out_of_scope.empty()) return fmt::format("{}: out of scope ({})", p.rule, p.out_of_scope);
  const std::size_t not_compared = p.count(Agreement::not_compared);
  return fmt::format("{}: {} agree, {} disagree, {} unresolved{}, {:.2f} s{}", p.rule, p.count(Agreement::agree), p.count(Agreement::disagree),
                     p.count(Agreement::unresolved), not_compared ? fmt::format(", {} not compared", not_compared) : "", p.seconds,
                     p.interrupted ? " (interrupted)" : "");
}

}  // namespace dartcheck::analysis
