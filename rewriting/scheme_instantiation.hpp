// The instantiated rule ι(S, P) = π_D(E_D(P) × S) of a rule scheme as an
// explicit DPO rule (002 Def. 19), for the places that want it as a graph:
// the solver's replay of a scheme counterexample through the library's
// DPO derivation, and pictures. Application to maps never builds it
// (the Applier, rewriting/application.hpp).
#pragma once

#include "rewriting/pattern_graphs.hpp"

namespace dartcheck {

/// ι(S, P) for the first hook's pattern: node (p, x) is named "x@d", d the
/// p-th dart of the pattern; arc x -(w,i)-> y of a side gives
/// (p, x) -i-> (p·w, y) for every p. Each connected component of ι(L, P)
/// gets its first node as hook (the rule constructor wants one per
/// component).
Rule instantiate(const Rule& core, const ArcWords& words, const PatternGraphs& pattern);

}  // namespace dartcheck
