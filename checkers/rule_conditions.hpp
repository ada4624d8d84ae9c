// Static consistency conditions on DPO rules (002 Def. 11-16) and, through
// the words on their arcs, on rule schemes (Def. 22, 24, 26-27; Algorithms
// 1-3).
//
// A rule scheme is checked on its core (the rule of its D-labels) plus the
// words: a DPO rule is the special case where every word is ε, for which
// the word conditions hold trivially. One checker serves both.
#pragma once

#include <string>
#include <vector>

#include "core/conjugate_words.hpp"
#include "rewriting/rule.hpp"

namespace dartcheck {

enum class RuleCondition {
  incident_arcs,    // Def. 11: weak incident arcs condition I_r(i)-weak
  dangling,         // Def. 12: L satisfies I(i) on deleted nodes
  non_orientation,  // Def. 13 / Def. 24: O_r(i)
  cycle,            // Def. 16 / Def. 27: C_r(i,j)
  no_loop,          // closed G-maps: no added arc is a loop
};

/// "I(2)", "dangling(0)", "O(1)", "C(0,2)", "no-loop(1)".
std::string condition_name(RuleCondition c, Dim i, Dim j = -1);

/// Where a condition fails, for a person and for a report that draws it.
struct RuleWitness {
  int subcondition = 0;            // the numbered sub-condition of the definition, 0 if none
  char side = 'L';                 // 'L' or 'R': the side the elements belong to
  std::vector<std::string> nodes;  // node names
  std::vector<std::string> arcs;   // "a -1-> b", with "(w,1)" labels for schemes
  std::vector<std::string> words;  // W-labels involved (schemes)
  std::string text;                // the sentence
};

struct ConditionVerdict {
  RuleCondition condition;
  Dim i;
  Dim j = -1;
  bool holds = true;
  /// Set when the condition was not evaluated: the cycle condition assumes
  /// a D-combinatorial rule (Assumption 3).
  std::string skipped;
  std::vector<RuleWitness> witnesses;
  std::string name() const { return condition_name(condition, i, j); }
};

struct RuleVerdict {
  std::vector<ConditionVerdict> conditions;
  bool consistent() const;
  const ConditionVerdict* find(const std::string& name) const;
};

/// An arc label as witnesses write it: "1", or "(w,1)" in a scheme.
std::string label_text(Dim d, const ConjWord& w, bool scheme);
/// An arc as witnesses write it: "a -1-> b", "a -(~1,2)-> b".
std::string arc_text(const TopoGraph& g, ArcId e, const std::vector<ConjWord>& words, bool scheme);

/// The conditions of one kind for one dimension (or pair).
ConditionVerdict check_incident_arcs(const Rule& rule, Dim i, const ArcWords& words = {});
ConditionVerdict check_dangling(const Rule& rule, Dim i, const ArcWords& words = {});
ConditionVerdict check_non_orientation(const Rule& rule, Dim i, const ArcWords& words = {});
/// `complete` applies the ij-completion of Sec. 5.2.1 first (Assumption 4);
/// without it the optimal paths are those of the rule as written, which is
/// what Example 10 describes.
ConditionVerdict check_cycle(const Rule& rule, Dim i, Dim j, const ArcWords& words = {}, bool complete = true);

/// Every condition the rule's model requires: I and dangling on D, O on N,
/// C on E, no-loop on D for loop-free models.
RuleVerdict check_rule(const Rule& rule, const ArcWords& words = {});

}  // namespace dartcheck
