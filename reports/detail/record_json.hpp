// What a rule's record holds beyond its report (rule_result_json with
// JsonDetail::record): the structures a report shows as text or not at
// all, every field as stored, so that campaign/detail/result_record reads
// the result back without loss. Maps keep their predecessor records as
// stored: a counterexample's H may hold records that disagree.
#pragma once

#include <optional>
#include <vector>

#include "analysis/fuzz.hpp"
#include "checkers/violation.hpp"
#include "core/map.hpp"
#include "core/graph.hpp"
#include "proofs/solver_types.hpp"
#include "reports/json_document.hpp"

namespace dartcheck::reports::detail {

Json map_json(const Map& m);
Json graph_json(const TopoGraph& g);
Json violations_json(const std::vector<Violation>& vs);
Json symbolic_host_json(const proofs::SymbolicHost& h);

/// Adds every field of `cx` to the report's object `j` (host and result
/// maps, match, comatch, violations, values), under the names the reader
/// expects.
void add_counterexample_record(Json& j, const analysis::Counterexample& cx);

/// `f(*v)`, or null.
template <class T, class F>
Json optional_json(const std::optional<T>& v, F&& f) {
  return v ? f(*v) : Json(nullptr);
}

}  // namespace dartcheck::reports::detail
