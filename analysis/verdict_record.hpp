// Comparing a rule's verdicts with the verdict its catalog records.
#pragma once

#include <vector>

#include "analysis/embedding_checks.hpp"
#include "checkers/rule_conditions.hpp"
#include "io/catalog.hpp"

namespace dartcheck::analysis {

/// Whether the static verdict's failing conditions, with the failing
/// embedding checks (analysis/embedding_checks), are exactly those the catalog records (none,
/// when it records none). Throws InputError at the verdict when it names a
/// condition the rule does not have.
bool matches_record(const CatalogRule& entry, const RuleVerdict& v, const std::vector<EmbeddingCheck>& embedding = {});

}  // namespace dartcheck::analysis
