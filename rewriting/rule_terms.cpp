#include "rewriting/rule_terms.hpp"

#include <algorithm>

namespace dartcheck {

const Term* RuleTerms::find(char side, const std::string& node, const std::string& embedding) const {
  for (const NodeTerm& t : side == 'L' ? left : right)
    if (t.node == node && t.embedding == embedding) return &t.term;
  return nullptr;
}

std::vector<const EmbeddingSignature*> RuleTerms::used() const {
  std::vector<const EmbeddingSignature*> r;
  for (const auto& e : embeddings) {
    bool any = false;
    for (const auto* side : {&left, &right})
      for (const NodeTerm& t : *side) any |= t.embedding == e.name;
    if (any) r.push_back(&e);
  }
  return r;
}

}  // namespace dartcheck
