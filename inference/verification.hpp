// The check of 000 App. A on one example: the inferred scheme applied to G
// at the start dart gives H back, by an isomorphism that extends κ. The
// folding's theorem says it always does; a failure here is a bug in the
// folding, the translation or the scheme engine (dartcheck infer exits 3).
#pragma once

#include <string>

#include "inference/inferred_rule.hpp"
#include "inference/kappa_graph.hpp"

namespace dartcheck::inference {

struct Verification {
  bool holds = false;
  std::string why;  // what differs, when it does not hold
};

/// Applies `rule` to a copy of G at `start` with the scheme engine and
/// compares the result with H through the folding's own correspondence:
/// the instantiated match must be the folding's L darts, the bijection
/// "comatch (y, q) -> dart (b_q, y) of H" an isomorphism onto H, and every
/// preserved dart of G must land where κ sends it. O(|G| + |H|).
Verification verify(const KappaGraph& graph, const GraphScheme& scheme, const InferredRule& rule, Dart start);

}  // namespace dartcheck::inference
