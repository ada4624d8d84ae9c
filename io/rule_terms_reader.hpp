// Reading a rule's embedding terms from a YAML catalog (format:
// docs/catalog-format.md, "Embedded rules").
#pragma once

#include <string>
#include <vector>

#include "rewriting/rule.hpp"
#include "rewriting/rule_terms.hpp"

namespace YAML {
class Node;
}

namespace dartcheck {

/// Reads a rule's `labels: {left: {node: {pi: term}}, right: ...}`,
/// `parameters: {v: term}` and `instantiation: direct|extended`. A label
/// key may list several nodes ("a, b, c"). Terms are parsed and
/// type-checked; every error is an InputError at the offending token.
/// `base` (a variant's base rule) gives the sides and parameters the
/// variant does not restate.
RuleTerms read_rule_terms(const std::string& file, const YAML::Node& rule, const Rule& topology, const std::vector<EmbeddingSignature>& embeddings,
                          const RuleTerms* base);

}  // namespace dartcheck
