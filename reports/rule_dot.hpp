// A rule or rule scheme as DOT: L and R side by side, preserved elements
// black, deleted red, added green, hooks drawn with a double border; arc
// labels are dimensions, or (word, dimension) pairs for schemes; a
// non-oriented pair of arcs (reverse arcs with one label and conjugate
// words) is one undirected edge. Each preserved node of R sits level with
// its node in L. The witnesses of failed conditions are highlighted and
// carry the attribute witness="true" (nodes and arcs), for tools and
// tests. A Jerboa-style scheme's nodes show their orbit types; the loops
// those types stand for are then drawn only when they are witnesses. An
// embedded rule's nodes list their terms, one line "pi: term" per
// embedding (003 Sec. 6); on witness nodes the lines of the failing
// embeddings are highlighted.
#pragma once

#include <string>
#include <vector>

#include "checkers/rule_conditions.hpp"
#include "rewriting/jerboa_scheme.hpp"
#include "rewriting/rule.hpp"
#include "rewriting/rule_terms.hpp"

namespace dartcheck::reports {

/// The terms to draw under the nodes, and the embeddings whose conditions
/// fail (their lines are highlighted on witness nodes).
struct TermLines {
  const RuleTerms* terms = nullptr;
  std::vector<std::string> failing;
};

/// The witnesses of every condition of `v` that fails.
std::vector<RuleWitness> failed_witnesses(const RuleVerdict& v);

/// A cluster holding L and R (to embed in a larger picture); node ids are
/// prefix + "L:" + name and prefix + "R:" + name.
std::string rule_cluster(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses, const std::string& prefix,
                         const JerboaLabels* labels = nullptr, const TermLines& terms = {});

/// A whole picture of the rule, titled with its name.
std::string rule_dot(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses = {}, const JerboaLabels* labels = nullptr,
                     const TermLines& terms = {});

}  // namespace dartcheck::reports
