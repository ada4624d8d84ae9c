// A rule's result as a shard writes it and merge reads it back: every
// stage that costs time (model-level confirmation, fuzz, proof) without
// loss, so that merge renders exactly what the unsharded run renders. The
// static stage is not in the record: it is deterministic and takes
// milliseconds, so merge recomputes it from the catalog (and compares the
// failing conditions with the record's, to catch a catalog that changed).
#pragma once

#include <stdexcept>

#include "analysis/rule_result.hpp"
#include "reports/json_document.hpp"

namespace dartcheck::campaign {

/// A record that is not what a shard writes: the JSON path and what was
/// expected ("record.fuzz.counterexample.host.links[2]: a dart < 12").
class RecordError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The record of `r`'s costly stages, its static failures and time.
reports::Json result_record(const analysis::RuleResult& r);

/// Puts the stages of `record` into `r`, whose static stage is computed
/// already. Throws RecordError on a malformed record, and when the record's
/// static failures differ from `r`'s (the catalog changed).
void restore_record(analysis::RuleResult& r, const reports::Json& record);

}  // namespace dartcheck::campaign
