// The operation under test: what the engines (checkers, fuzz, proofs,
// reports, and the seed systems) take, whichever file it was read from (a
// YAML catalog, a Jerboa modeler): a rule or rule scheme with its arc words,
// Jerboa labels, embedding terms and opaque embedding expressions.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "rewriting/jerboa_scheme.hpp"
#include "rewriting/rule.hpp"
#include "rewriting/rule_terms.hpp"

namespace dartcheck {

/// An embedding operation pi : <o> -> tau (003 Sec. 5.1). The value type
/// is kept as the text the file gives (a Jerboa Java class, "point3", ...).
struct EmbeddingDecl {
  std::string name, type;
  std::vector<Dim> orbit;
  SourceLocation location;
};

/// An embedding expression carried by a node of R (Jerboa's
/// <expr ebd="pos">code</expr>), as io/jerboa_expression reads it: a term
/// when its Java lies in the part dartcheck reads, opaque otherwise (the
/// reason, and where in the file). The presence checks only need it there.
struct NodeExpression {
  std::string node, embedding, code;
  SourceLocation location;
  std::optional<Term> term;  // read
  std::string reason;        // opaque: why
  SourceLocation reason_location;
  bool read() const { return term.has_value(); }
};

/// A rule or rule scheme and everything the engines need to apply and
/// check it.
struct Operation {
  Rule rule;
  /// The W-labels of a rule scheme (002 Sec. 6); `words.scheme` is false
  /// for a DPO rule.
  ArcWords words;
  /// The orbit types of a Jerboa-style scheme's nodes (000 Sec. 4.3),
  /// already translated into `words`' loops; unset in the (W,D) notation.
  std::optional<JerboaLabels> jerboa;
  /// Embedding expressions on R's nodes (Jerboa modelers).
  std::vector<NodeExpression> expressions;
  /// What an import left out of this rule while keeping it (an ignored
  /// precondition, embedding parameters...), one sentence each.
  std::vector<std::string> caveats;
  /// Embedding terms on L's and R's nodes (003 Sec. 6); unset for a
  /// purely topological rule.
  std::optional<RuleTerms> terms;

  /// A rule scheme (002 Sec. 6), applied by instantiation over P_v, or a
  /// DPO rule (002 Def. 2): the one answer every engine and renderer reads.
  bool is_scheme() const { return words.scheme; }
};

}  // namespace dartcheck
