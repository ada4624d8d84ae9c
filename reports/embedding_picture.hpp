// What a rule picture (reports/rule_dot) shows of a rule's embedding
// checks (analysis/embedding_checks).
#pragma once

#include <vector>

#include "analysis/embedding_checks.hpp"
#include "reports/rule_dot.hpp"

namespace dartcheck::reports {

/// What a rule picture shows of the checks (reports/rule_dot): the
/// witnesses of the checks that fail (required or not), the rule's terms,
/// the embeddings of the failing checks ("pos" for "A(pos)"), and one
/// caption line per failing check (rule_dot's `captions`).
struct EmbeddingPicture {
  std::vector<RuleWitness> witnesses;
  TermLines terms;
  std::vector<std::string> captions;
};
EmbeddingPicture embedding_picture(const Operation& entry, const std::vector<analysis::EmbeddingCheck>& checks);

}  // namespace dartcheck::reports
