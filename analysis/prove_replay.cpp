#include "analysis/prove_replay.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace dartcheck::analysis {

std::optional<Counterexample> replay_solver_map(const Operation& entry, proofs::ConstraintProof& c) {
  if (c.model.status != proofs::Status::counterexample || !c.model.host) return std::nullopt;
  const Map host = proofs::host_map(entry.rule.model(), *c.model.host);
  std::vector<Dart> hooks(entry.rule.hooks().begin(), entry.rule.hooks().end());  // the match is the identity on L's nodes
  Map scratch(entry.rule.model());
  Refusal refusal = Refusal::none;
  auto cx = apply_and_check(entry, host, hooks, scratch, refusal);
  if (!cx) {
    c.agreement = proofs::Agreement::disagree;
    c.note = fmt::format("the dynamic checker finds no failure on the solver's map ({})",
                         refusal == Refusal::none ? "H is valid" : std::string(name_of(refusal)));
    return std::nullopt;
  }
  cx->origin = fmt::format("dartcheck prove: a valid {} of {} darts whose H breaks {}", entry.rule.model().name, host.size(), c.constraint.name());
  cx->minimal = c.model.minimal;
  return cx;
}

std::string constraint_stem(const proofs::ConstraintProof& c) {
  std::string s = c.constraint.name();
  std::erase_if(s, [](char ch) { return ch == '(' || ch == ')'; });
  std::replace(s.begin(), s.end(), ',', '-');
  return s;
}

std::string answer_text(const proofs::ClassAnswer& a) {
  switch (a.status) {
    case proofs::Status::counterexample:
      return fmt::format("counterexample at {} darts{}", a.darts, a.minimal ? " (minimal)" : "");
    case proofs::Status::none: {
      // An unsat core holding "holds I(d)" means no H satisfying I(d)
      // breaks the constraint (those that break I(d) are counted there).
      std::vector<std::string> premises;
      for (const auto& c : a.core)
        if (c.starts_with("holds ")) premises.push_back(c.substr(6));
      const std::string among = premises.empty() ? "" : fmt::format(" with {}", fmt::join(premises, ", "));
      return a.proved_for_all() ? fmt::format("none{}, all hosts (bound {})", among, a.bound) : fmt::format("none{} up to {} darts", among, a.darts);
    }
    case proofs::Status::unknown:
      return fmt::format("unknown ({})", a.why);
    case proofs::Status::vacuous:
      return "vacuous";
  }
  return "";
}

}  // namespace dartcheck::analysis
