// The dynamic checker's opinion on a solver counterexample over maps of the
// model (`dartcheck prove`, `dartcheck report --prove`): the solver's host
// as a dense map, the rule applied there by apply_rule / apply_scheme, H
// checked by check_map; and the words both commands print for an answer.
#pragma once

#include <optional>
#include <string>

#include "analysis/fuzz.hpp"
#include "proofs/rule_prover.hpp"

namespace dartcheck::analysis {

/// The replayed counterexample, or nullopt when the answer holds none.
/// When the dynamic checker finds no failure on the solver's map, the
/// constraint's agreement becomes `disagree` with a note saying why.
std::optional<Counterexample> replay_solver_map(const Operation& entry, proofs::ConstraintProof& c);

/// A solver answer in a few words: "counterexample at 4 darts (minimal)",
/// "none with I(1) up to 8 darts", "none, all hosts (bound 6)", ...
std::string answer_text(const proofs::ClassAnswer& a);

/// "C0-2" for C(0,2): the constraint's part of a file name.
std::string constraint_stem(const proofs::ConstraintProof& c);

}  // namespace dartcheck::analysis
