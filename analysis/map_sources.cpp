#include "analysis/map_sources.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>

#include "core/closest_name.hpp"
#include "core/input_error.hpp"
#include "core/shell_quote.hpp"
#include "io/jerboa_jba.hpp"
#include "io/map_io.hpp"
#include "io/mesh_io.hpp"
#include "generators/mesh_map.hpp"
#include "generators/shapes.hpp"

namespace dartcheck::analysis {

namespace {

// "; did you mean 'X'?" for the closest of `names`, or "".
std::string did_you_mean(const std::string& typed, const std::vector<std::string>& names) {
  const std::string best = closest_name(typed, names);
  return best.empty() ? std::string() : fmt::format("; did you mean '{}'?", printable(best));
}

}  // namespace

Catalog read_rule_catalog(const std::string& file, const std::string& rule) {
  Catalog catalog = read_catalog(file);
  if (!rule.empty()) require_rule(catalog, file, rule);
  return catalog;
}

const CatalogRule& require_rule(const Catalog& catalog, const std::string& file, const std::string& rule) {
  if (const CatalogRule* found = catalog.find_rule(rule)) return *found;
  std::vector<std::string> names;
  for (const auto& e : catalog.rules) names.push_back(e.rule.name());
  throw InputError("<command line>", 0, 0,
                   fmt::format("--rule: no rule named '{}' in {}{} (`dartcheck check {}` lists its {})", printable(rule), file,
                               did_you_mean(rule, names), shell_quote(file), names.size() == 1 ? "rule" : fmt::format("{} rules", names.size())));
}

Map build_source(const MapSource& s) {
  if (s.map) return *s.map;
  if (!s.mesh.empty()) return load_mesh(s.model, s.mesh);
  try {
    return build_shape(s.model, parse_shape(s.shape));
  } catch (const BuildError& e) {
    throw InputError(s.location.file, s.location.line, s.location.column, fmt::format("map '{}': {}", s.name, e.what()));
  }
}

std::vector<Map> confirmation_maps(const Catalog& catalog, std::size_t confirm_darts) {
  std::vector<Map> maps;
  const bool schemes = std::any_of(catalog.rules.begin(), catalog.rules.end(), [](const CatalogRule& e) { return e.words.scheme; });
  if (confirm_darts > 0 && schemes)
    for (const auto& source : catalog.maps) maps.push_back(build_source(source));
  return maps;
}

Map resolve_map(const std::string& target, const Model& model, const Catalog* catalog) {
  if (catalog)
    if (const MapSource* s = catalog->find_map(target)) return build_source(*s);
  const bool exists = std::filesystem::exists(target);
  if (is_mesh_path(target)) return load_mesh(model, target);
  const auto ext = std::filesystem::path(target).extension().string();
  if (ext == ".yaml" || ext == ".yml") return read_map_file(target);
  if (ext == ".jba") return read_jba(target).map;  // the file names its dimension
  if (exists) throw InputError(target, 0, 0, "unknown map file type (expected .yaml, .yml, .off, .obj or .jba)");
  try {
    return build_shape(model, parse_shape(target));
  } catch (const BuildError& e) {
    // The names it may have meant: the catalog's maps and the shapes' names.
    std::vector<std::string> names{"cube", "tetrahedron", "stacked-cubes", "polygon:4", "grid:2x2", "prism:3"};
    std::string maps;
    if (catalog)
      for (const auto& m : catalog->maps) {
        names.push_back(m.name);
        maps += (maps.empty() ? "" : ", ") + printable(m.name);
      }
    throw InputError("<command line>", 0, 0,
                     fmt::format("'{}' is not a catalog map, a map file or a shape: {}{}{}", printable(target), e.what(),
                                 maps.empty() ? std::string() : fmt::format("; the catalog's maps: {}", maps), did_you_mean(target, names)));
  }
}

std::string describe_target(const std::string& target, const Map& map) {
  return fmt::format("{} ({}, {} darts)", target, map.model().name, map.size());
}

}  // namespace dartcheck::analysis
