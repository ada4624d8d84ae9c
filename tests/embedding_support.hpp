// Shared by the embedding tests: the embedding catalog, the two embedding
// signatures of the hand-written tests, and value printing for GoogleTest.
#pragma once

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "analysis/embedding_checks.hpp"
#include "checkers/embedding_conditions.hpp"
#include "checkers/rule_conditions.hpp"
#include "io/catalog.hpp"
#include "rewriting/value.hpp"

namespace dartcheck {

// GoogleTest prints values as text, not bytes (found by argument-dependent
// lookup, so in namespace dartcheck).
inline void PrintTo(const Value& v, std::ostream* os) { *os << v.str(); }

namespace testing_support {

inline const std::string embedding_catalog_file = std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml";
inline const std::vector<EmbeddingSignature> signatures = {{"pos", ValueType::point2, {1, 2}}, {"col", ValueType::color, {0, 1}}};

inline const Catalog& embedding_catalog() {
  static const Catalog c = read_catalog(embedding_catalog_file);
  return c;
}

inline const Catalog& subdivision_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/subdivision-operations.yaml");
  return c;
}

/// The failing topological and term conditions of a rule with terms, sorted.
inline std::vector<std::string> static_failures_of(const Operation& r) {
  std::vector<std::string> f;
  for (const auto& c : check_rule(r.rule, r.words).conditions)
    if (!c.holds) f.push_back(c.name());
  for (const auto& n : failing_names(check_term_conditions(r.rule, r.words, *r.terms))) f.push_back(n);
  std::sort(f.begin(), f.end());
  return f;
}

}  // namespace testing_support
}  // namespace dartcheck
