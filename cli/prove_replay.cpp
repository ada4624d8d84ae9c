#include "cli/prove_replay.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace dartcheck::cli {

std::optional<Counterexample> replay_solver_map(const CatalogRule& entry, proofs::ConstraintProof& c) {
  if (c.model.status != proofs::Status::counterexample || !c.model.host) return std::nullopt;
  const Map host = proofs::host_map(entry.rule.model(), *c.model.host);
  std::vector<Dart> hooks(entry.rule.hooks().begin(), entry.rule.hooks().end());  // the match is the identity on L's nodes
  Map scratch(entry.rule.model());
  Refusal refusal = Refusal::none;
  auto cx = apply_and_check(entry, host, hooks, scratch, refusal);
  if (!cx) {
    c.agreement = proofs::Agreement::disagree;
    c.note = fmt::format("the dynamic checker finds no failure on the solver's map ({})",
                         refusal == Refusal::none ? "H is valid" : std::string(refusal_name(refusal)));
    return std::nullopt;
  }
  cx->origin = fmt::format("dartcheck prove: a valid {} of {} darts whose H breaks {}", entry.rule.model().name, host.size(),
                           c.constraint.name());
  cx->minimal = c.model.minimal;
  return cx;
}

std::string constraint_stem(const proofs::ConstraintProof& c) {
  std::string s = c.constraint.name();
  std::erase_if(s, [](char ch) { return ch == '(' || ch == ')'; });
  std::replace(s.begin(), s.end(), ',', '-');
  return s;
}

}  // namespace dartcheck::cli
