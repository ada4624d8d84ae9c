// The embedding checks of a catalog rule, whichever applies: the
// conditions of 003 Theorem 2 / Theorem 4 for a rule whose nodes carry
// terms (checkers/embedding_conditions), Jerboa's presence checks for one
// with opaque expressions (checkers/embedding_presence), none otherwise.
#pragma once

#include <string>
#include <vector>

#include "checkers/rule_conditions.hpp"
#include "io/catalog.hpp"
#include "rewriting/operation.hpp"

namespace dartcheck::analysis {

struct EmbeddingCheck {
  std::string name;  // "A(pos)", "merge(pos)"
  bool holds = true;
  bool required = true;  // false: B(pi) under extended instantiation
  std::vector<RuleWitness> witnesses;
  std::string source;  // "003 Theorem 2", "003 Theorem 4", "Jerboa presence check"
};

std::vector<EmbeddingCheck> embedding_checks(const Catalog& catalog, const Operation& entry);
/// Names of the required checks that fail.
std::vector<std::string> failing_names(const std::vector<EmbeddingCheck>& checks);

/// The sentence every report of embedding checks carries.
inline constexpr const char* sufficiency_note =
    "embedding conditions (003 Theorems 2 and 4, Jerboa's presence checks) are sufficient, not necessary: terms are compared "
    "syntactically, and two different terms may evaluate to equal values";

}  // namespace dartcheck::analysis
