// The files around one inference run: κ as the user gives it (a κ file, or
// "identity" by dart ids), and the inferred rules written back as a YAML
// catalog (with the example that `run` re-checks) or a Jerboa modeler.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "inference/infer.hpp"
#include "io/kappa_file.hpp"

namespace dartcheck::inference {

/// κ from --kappa and a sentence saying where it came from. "identity"
/// pairs dart ids: for two Jerboa .jba snapshots the files' own ids
/// (Jerboa keeps them across an operation); for dartcheck's dense maps,
/// indices, which only correspond when no dart was deleted (InputError
/// otherwise: `apply --kappa-out` writes the pairs then). Any other text
/// is a κ file.
std::pair<KappaSpec, std::string> example_kappa(const std::string& kappa, const std::string& before_file, const std::string& after_file,
                                                const Map& before, const Map& after);

/// --undecided as the folding's policy (keep, free or fail); InputError otherwise.
UndecidedPolicy parse_undecided(const std::string& text);

/// What the written rules say of their example.
struct ExampleLabels {
  std::string before, after, orbit;
};

/// Writes the inferred rules of `attempts` to `file`: a Jerboa modeler
/// (.jme) named `modeler`, or a YAML catalog holding the before and after
/// maps and, per rule, the example "before at its start dart gives a map
/// isomorphic to after". Throws OutputError.
void write_inferred(const std::string& file, const std::string& modeler, const KappaGraph& graph, const std::vector<Attempt>& attempts,
                    const ExampleLabels& labels);

}  // namespace dartcheck::inference
