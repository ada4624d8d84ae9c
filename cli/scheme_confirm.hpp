// Model-level search for a rule scheme: apply it at every dart of random
// valid maps of its model, smallest first, and check every result. The
// dynamic counterpart of `dartcheck check`'s static verdict on schemes
// (Theorems 4-6 speak of pattern graphs; this asks the user's question,
// "does it ever break a real map?").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/catalog.hpp"

namespace dartcheck::cli {

struct SchemeSearch {
  std::string not_run;            // why the search did not run, if it did not
  std::size_t maps = 0;           // hosts tried
  std::size_t largest = 0;        // darts of the largest host tried
  std::size_t applications = 0;   // derivations that took place
  std::optional<Map> host;        // first counterexample (the smallest found)
  Dart hook = 0;
  std::vector<std::string> broken;  // constraints H breaks, or "not-representable"
};

/// Hosts: `extra` maps (usually the catalog's maps of the same model) and
/// `random_maps` random valid maps of growing size (fixed seeds, so the
/// search is reproducible). For a custom model, which has no generator:
/// every map of the model on 1 to `small_darts` darts (checkers/host_search).
SchemeSearch search_scheme_hosts(const CatalogRule& scheme, const std::vector<Map>& extra, std::size_t random_maps,
                                 std::size_t small_darts = 5);

std::string describe(const SchemeSearch& s, const std::string& model);

}  // namespace dartcheck::cli
