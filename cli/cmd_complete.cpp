// `dartcheck __complete WHAT [CATALOG]`: the words the bash completion
// (scripts/dartcheck-completion.bash) offers for --rule, --map, --model and
// --cells, read from the catalog on the command line and from the models
// and shapes dartcheck knows. Hidden from --help; prints nothing and exits
// 0 on a catalog it cannot read (a completion never shows an error).
#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/map_sources.hpp"
#include "cli/commands.hpp"
#include "core/model.hpp"

namespace dartcheck::cli {

int complete(const CompleteOptions& o) {
  if (o.what == "models") {
    // The usual ones first; the others are N-gmap... up to dimension 15.
    for (int n = 1; n <= 3; ++n) fmt::print("{}-gmap\n{}-omap\n{}-closed-gmap\n{}-open-omap\n", n, n, n, n);
    return ok;
  }
  if (o.what == "cells") {
    fmt::print("hex\nhex,prism\nhex,pyramid\nhex,prism,pyramid\n");
    return ok;
  }
  if (o.what != "rules" && o.what != "maps") return bad_input;
  std::vector<std::string> words;
  if (o.what == "maps") words = {"cube", "tetrahedron", "stacked-cubes", "polygon:", "grid:", "prism:"};
  if (!o.catalog.empty()) {
    try {
      const Catalog catalog = analysis::read_rule_catalog(o.catalog, "");
      if (o.what == "rules")
        for (const auto& r : catalog.rules) words.push_back(r.rule.name());
      else
        for (const auto& m : catalog.maps) words.push_back(m.name);
    } catch (const std::exception&) {
      // Half-typed command lines name files that are not catalogs: no words.
    }
  }
  // Each once (a catalog map may be named as a shape), in this order.
  for (std::size_t k = 0; k < words.size(); ++k)
    if (std::find(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(k), words[k]) == words.begin() + static_cast<std::ptrdiff_t>(k))
      fmt::print("{}\n", words[k]);
  return ok;
}

}  // namespace dartcheck::cli
