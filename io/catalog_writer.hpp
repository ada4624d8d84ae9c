// A catalog as YAML (docs/catalog-format.md), for `dartcheck convert`: the
// rules of an imported Jerboa modeler in the Jerboa node notation (orbit
// types on nodes, explicit arcs only), embeddings, expressions, caveats and
// skipped rules, so that the YAML file checks exactly like its source.
// Maps and examples are not written (imports have none).
#pragma once

#include <string>

#include "io/catalog.hpp"

namespace dartcheck {

std::string catalog_yaml(const Catalog& catalog);

}  // namespace dartcheck
