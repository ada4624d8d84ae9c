// The embedding part of a rule or rule scheme (003 Sec. 5.2, 6.3): terms
// labeling L's and R's nodes, one per embedding (absent = unlabeled), the
// rule's parameters (closed values such as the translation vector of
// Fig. 17a), and how the rule applies.
//
// - `direct`: the evaluated rule is applied as it stands (003 Sec. 5.2):
//   each labeled node of R gives its value to its own dart only. The
//   conditions of Theorem 2, (A), (B), (C), guarantee a consistent result.
// - `extended`: the rule scheme is instantiated (Def. 13): evaluation,
//   topological extension to full embedding orbits (Def. 11) and embedding
//   propagation through the quotient (Def. 12); a labeled node gives its
//   value to its whole pi-orbit of the result. Theorem 4 asks only (A) and
//   (C) of the scheme and non-overlap (Lemma 3) of the match.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rewriting/term.hpp"

namespace dartcheck {

enum class Instantiation { direct, extended };

struct NodeTerm {
  std::string node, embedding;
  Term term;
  std::string file;
  int line = 0, column = 0;  // of the term's text
};

struct RuleTerms {
  std::vector<EmbeddingSignature> embeddings;  // the catalog's, typed
  std::vector<NodeTerm> left, right;
  std::map<std::string, Value> parameters;
  Instantiation instantiation = Instantiation::extended;

  /// The term labeling `node` of a side ('L' or 'R') for `embedding`.
  const Term* find(char side, const std::string& node, const std::string& embedding) const;
  /// Embeddings some node of L or R labels, in declaration order.
  std::vector<const EmbeddingSignature*> used() const;
};

}  // namespace dartcheck
