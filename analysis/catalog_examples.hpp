// The worked examples of a catalog (`dartcheck run`): each rule applied at
// an example's hooks on a catalog map, and the outcome set against the
// one the example expects.
#pragma once

#include <string>
#include <vector>

#include "io/catalog.hpp"

namespace dartcheck::analysis {

/// What an example gave: "valid", "invalid", "wrong cells", "not
/// isomorphic" or the refusal's name, and a detail for the reader.
struct ExampleOutcome {
  std::string got, detail;
};

/// Runs example `e` of rule `r`: the rule applied at its hooks (a scheme
/// instantiated there, 002 Sec. 6.3, a DPO rule matched from it) on a
/// copy of the named map (`built[k]` is catalog.maps[k] built), then H's
/// validity, cell counts and isomorphism as the example asks.
ExampleOutcome run_example(const Catalog& catalog, const std::vector<Map>& built, const CatalogRule& r, const Example& e);

}  // namespace dartcheck::analysis
