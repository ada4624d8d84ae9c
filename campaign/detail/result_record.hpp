// A rule's result as a shard writes it and merge reads it back: the rule's
// JSON as the report writes it, with what the report leaves out
// (reports::JsonDetail::record), so that every stage that costs time
// (model-level confirmation, fuzz, proof, potential events) reads back
// without loss and merge renders exactly what the unsharded run renders.
// The static stage is read from the catalog instead: it is deterministic
// and takes milliseconds, so merge recomputes it (and compares the failing
// conditions with the record's, to catch a catalog that changed).
#pragma once

#include <stdexcept>

#include "core/error.hpp"
#include "analysis/rule_result.hpp"
#include "reports/json_document.hpp"
#include "reports/rule_result_json.hpp"

namespace dartcheck::campaign {

/// A record that is not what a shard writes: the JSON path and what was
/// expected ("record.fuzz.counterexample.host.links[2]: a dart < 12").
class RecordError : public Error {
 public:
  using Error::Error;
};

/// The record of `r`: its JSON with every stage's data.
inline reports::Json result_record(const analysis::RuleResult& r) { return reports::rule_result_json(r, reports::JsonDetail::record); }

/// Puts the stages of `record` into `r`, whose static stage is computed
/// already. Throws RecordError on a malformed record, and when the record's
/// static failures differ from `r`'s (the catalog changed).
void restore_record(analysis::RuleResult& r, const reports::Json& record);

}  // namespace dartcheck::campaign
