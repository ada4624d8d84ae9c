// The renderers of `dartcheck infer` (000): one line per start dart and
// the rule it gave, as text or as a JSON document (docs/schema/infer).
#pragma once

#include <string>
#include <vector>

#include "inference/infer.hpp"

namespace dartcheck::reports {

/// What was inferred from, for the header and the document.
struct InferRun {
  std::string before, after, orbit;
  std::size_t before_darts = 0, after_darts = 0, preserved = 0;
  std::string kappa;  // how κ was given: "identity", "identity by the .jba files' dart ids", a file
};

/// "inferred, well-formed, verified on the example (App. A)", or what failed.
std::string attempt_outcome(const inference::Attempt& a);

std::string infer_text(const InferRun& run, const std::vector<inference::Attempt>& attempts);
/// The JSON document (docs/schema/infer), as text.
std::string infer_json(const InferRun& run, const inference::KappaGraph& graph, const std::vector<inference::Attempt>& attempts);

}  // namespace dartcheck::reports
