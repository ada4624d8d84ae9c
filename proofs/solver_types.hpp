// What the solver's encodings answer, as plain data: the public headers of
// proofs/ that cli/ and analysis/ include stop here, so z3++.h (4,000 lines)
// stays in proofs' .cpp files and its encodings' own headers.
#pragma once

#include <string>

#include <cstddef>
#include <utility>
#include <vector>

#include "core/map.hpp"

namespace dartcheck::proofs {

/// A host the solver found: `size` darts and the links of the encoded
/// dimensions (no_dart for none).
struct SymbolicHost {
  std::size_t size = 0;
  std::vector<std::pair<Dim, std::vector<Dart>>> links;
  const std::vector<Dart>* find(Dim d) const;
};

enum class Answer { sat, unsat, unknown };

/// Deliberate faults, for the tests that check that a wrong encoding is
/// caught (a planted bug must produce disagreements).
enum class EncodingFault { none, drop_dangling };

/// The version of the Z3 library in use ("4.8.12").
std::string solver_version();

}  // namespace dartcheck::proofs
