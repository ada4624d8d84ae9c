// Checks of command-line options that several commands share.
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "analysis/rule_result.hpp"
#include "campaign/shard.hpp"
#include "core/number_text.hpp"
#include "io/catalog.hpp"

namespace dartcheck::cli {

/// --model: a model by its name; InputError listing the known ones.
Model command_model(const std::string& name);

/// --catalog, when given: the catalog whose maps the other options may name.
std::optional<Catalog> optional_catalog(const std::string& file);

/// Wall-clock seconds since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// --hook gives one dart per hook of the rule (none for a rule without
/// hooks), each a dart of the map; InputError naming the hooks or the
/// dart otherwise.
void check_hooks(const CatalogRule& rule, const std::vector<Dart>& hooks, const Map& map, const std::string& map_name);

}  // namespace dartcheck::cli
