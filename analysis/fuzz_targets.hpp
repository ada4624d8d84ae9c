// What a fuzz run starts from: the rules it fuzzes and the hosts beyond
// the random and enumerated ones, the catalog's maps of the rules' models
// and the maps the user names (fuzz --maps).
#pragma once

#include <string>
#include <vector>

#include "io/catalog.hpp"

namespace dartcheck::analysis {

struct FuzzTargets {
  std::vector<const Operation*> rules;
  std::vector<const CatalogRule*> entries;  // the same rules, as the catalog holds them
  std::vector<Map> seeds;
};

/// The rules of `catalog` (only `rule` if not empty) and the seed hosts:
/// the catalog's maps of their models, then each of `maps` (a map file,
/// which names its model, or a mesh or shape, built for every model of
/// the rules that it fits; a note on stderr for a model it does not).
/// InputError for a map that fits no model or is not a valid map: fuzzing
/// needs valid hosts.
FuzzTargets fuzz_targets(const Catalog& catalog, const std::string& rule, const std::vector<std::string>& maps);

}  // namespace dartcheck::analysis
