// The host graphs a proof quantifies over (002 Sec. 4-5).
//
// Each of Theorems 1-3 quantifies over its own class of hosts, larger than
// the maps of the model: Theorem 1 over D-graphs satisfying I(i) alone,
// Theorem 2 over D-combinatorial graphs satisfying O(i), Theorem 3 over
// D-combinatorial graphs satisfying C(i,j). Cross-checking the "iff" of a
// theorem needs its class; the user's question ("can this rule break one
// of my maps?") needs the maps of the model. A HostClass says which
// dimensions a solver query encodes as link functions and which
// constraints those links satisfy.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checkers/rule_conditions.hpp"
#include "rewriting/rule.hpp"

namespace dartcheck::proofs {

/// A constraint of the derived graph H that a query negates: I(i), O(i),
/// C(i,j) or no-loop(i), named like the static condition it mirrors.
struct HConstraint {
  RuleCondition kind;  // incident_arcs, non_orientation, cycle or no_loop
  Dim i;
  Dim j = -1;
  std::string name() const { return condition_name(kind, i, j); }
  friend bool operator==(const HConstraint&, const HConstraint&) = default;
};

/// The constraints a map of the model satisfies, hence those a proof asks
/// about: I on D, O on N, C on E, no-loop on D for loop-free models.
std::vector<HConstraint> model_constraints(const Model& m);

struct HostClass {
  enum class Kind { theorem, model };
  Kind kind = Kind::model;
  int theorem = 0;  // 1, 2 or 3 for a theorem's class
  std::string name;
  /// Dimensions encoded as link functions (one arc out and in per dart, or
  /// at most one for `partial` ones).
  DimSet symbolic = 0;
  DimSet partial = 0;
  DimSet involutive = 0;  // O(i): the link is its own inverse
  std::vector<std::pair<Dim, Dim>> cycles;
  bool loop_free = false;
  /// Dimensions outside `symbolic`: true if the host is D-combinatorial on
  /// them (Theorems 2, 3), false if it holds exactly L's arcs there
  /// (Theorem 1: other labels are unconstrained, and extra arcs could only
  /// break the dangling condition).
  bool others_combinatorial = false;
};

/// The class of the theorem that speaks of constraint c (none for no-loop,
/// which no theorem covers).
std::optional<HostClass> theorem_class(const HConstraint& c);
/// The valid maps of the model.
HostClass model_class(const Model& m);

/// Why no host of the class can contain L with a derivation, judged on the
/// dimensions the class does not encode (empty if some host may).
std::string unmatchable_outside(const Rule& rule, const HostClass& c);

/// The static condition that a theorem pairs with constraint c.
const ConditionVerdict* static_condition(const RuleVerdict& v, const HConstraint& c);

/// True when the rule is D-combinatorial (Def. 12: I(D)-weak and L
/// satisfying I on deleted nodes), the premise of Theorems 2 and 3.
bool combinatorial(const RuleVerdict& v);

}  // namespace dartcheck::proofs
