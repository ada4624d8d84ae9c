// A catalog as YAML (docs/catalog-format.md), for `dartcheck convert`: the
// rules of an imported Jerboa modeler in the Jerboa node notation (orbit
// types on nodes, explicit arcs only), embeddings, expressions, caveats and
// skipped rules, so that the YAML file checks exactly like its source.
// Explicit maps and the rules' examples are written too (`dartcheck infer`
// writes its before/after maps and the example that ties them).
#pragma once

#include <string>

#include "io/catalog.hpp"

namespace dartcheck {

/// `description` replaces the default "converted by dartcheck from FILE".
std::string catalog_yaml(const Catalog& catalog, const std::string& description = {});

}  // namespace dartcheck
