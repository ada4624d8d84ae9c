// A rule or rule scheme as DOT: L and R side by side. What happens to an
// element is its line style (preserved solid, deleted dashed, added bold),
// an arc's colour is its dimension (the papers' 0 black, 1 red, 2 blue,
// 3 green), hooks have a double border, and a legend says all of it. The
// caption names the rule and each failing condition with its first
// witness ("fails I(1): ..."). Arc labels are dimensions, or (word,
// dimension) pairs for schemes; a
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

/// A caption line: `head` ("fails I(1)") and the first witness's sentence,
/// shortened to a line, with how many witnesses follow.
std::string failure_caption(const std::string& head, const std::vector<RuleWitness>& witnesses);

/// One caption line per condition of `v` that fails, in the verdict's order.
std::vector<std::string> failure_captions(const RuleVerdict& v);

/// L and R as two clusters side by side, to put at the top level of a
/// picture (they set its layout engine to neato, and with `titled` its
/// label to the rule's name): every node pinned from one layout of L and R
/// together, so that a preserved node sits at the same place in both. Node
/// ids are prefix + "L:" + name and prefix + "R:" + name.
std::string rule_cluster(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses, const std::string& prefix,
                         const JerboaLabels* labels = nullptr, const TermLines& terms = {}, bool titled = true, bool pinned = true);

/// A whole picture of the rule, titled with its name and `captions` (what
/// fails: failure_captions, EmbeddingPicture::captions).
/// `pinned` false: L and R as plain clusters, for a layout engine of the
/// caller's choice (draw --engine).
std::string rule_dot(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses = {}, const JerboaLabels* labels = nullptr,
                     const TermLines& terms = {}, const std::vector<std::string>& captions = {}, bool pinned = true);

/// The legend of rule pictures: the line styles, the hooks, the witnesses
/// and the model's dimension colours, as an HTML-like label cell; with
/// `maps`, also the fills of the match in G and of the broken darts in H
/// (a counterexample's panels).
std::string rule_legend(const Model& model, bool witnesses, const TermLines& terms, bool maps = false);

/// A caption as lines of at most `width` columns, broken between words
/// (never cut: a caption's point is often at its end).
std::vector<std::string> caption_lines(const std::string& caption, std::size_t width = 90);

}  // namespace dartcheck::reports
