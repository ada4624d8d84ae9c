// apply's run: one application of a catalog rule at hook darts, the
// result's validity (and, for an embedded rule, its embedding
// consistency), the files asked for, printed as it goes.
#pragma once

#include <string>
#include <vector>

#include "core/map.hpp"
#include "io/catalog.hpp"

namespace dartcheck::reports {

/// What `dartcheck apply` was asked: the map as the user named it (a mesh
/// gives an embedded rule its positions), the hooks, and the outputs.
struct ApplyRequest {
  std::string catalog, rule, map, output, kappa_out;
  std::vector<Dart> hooks;
  std::size_t limit = 50;  // violations printed (0: all)
};

/// Applies `rule` to `host` (resolved from `request.map`, hooks checked)
/// and writes -o as the rule allows: YAML always, Jerboa .jba for a
/// topological rule (values carried through the dart correspondence),
/// OFF/OBJ for an embedded rule with a point embedding. Throws InputError
/// for an output the rule cannot give. Returns 0 if the rule applied and
/// H is valid (and consistently embedded), 1 otherwise.
int apply_and_write(const ApplyRequest& request, const CatalogRule& rule, Map host);

}  // namespace dartcheck::reports
