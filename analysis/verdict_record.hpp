// Comparing a rule's verdicts with the verdict its catalog records.
#pragma once

#include <string>
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

/// Whether a broken map found dynamically (fuzz, prove) contradicts the
/// verdict the catalog records: it records 'consistent' (no failing
/// condition), yet the rule broke a map.
bool contradicts_record(const CatalogRule& entry, bool broke_a_map);

/// Replaces the verdicts `catalog` records with those of the baseline
/// `file` (io/baseline.hpp), as `check`, `fuzz`, `prove` and `report`
/// read it. Returns one sentence per disagreement between the baseline and
/// what is checked now (a rule recorded as not checked that is read now,
/// and the reverse). Throws InputError at a baseline entry that names a
/// rule the catalog does not have.
std::vector<std::string> apply_baseline(Catalog& catalog, const std::string& file);

}  // namespace dartcheck::analysis
