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

// "; did you mean 'X'?" for the closest of `names`, or "" (also when the
// name was typed right and something else is wrong: a shape of another
// dimension).
std::string did_you_mean(const std::string& typed, const std::vector<std::string>& names) {
  const std::string best = closest_name(typed, names);
  return best.empty() || best == typed ? std::string() : fmt::format("; did you mean '{}'?", printable(best));
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
  throw UsageError(fmt::format("--rule: no rule named '{}' in {}{} (`dartcheck check {}` lists its {})", printable(rule), file,
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
  const bool schemes = std::any_of(catalog.rules.begin(), catalog.rules.end(), [](const CatalogRule& e) { return e.is_scheme(); });
  if (confirm_darts > 0 && schemes)
    for (const auto& source : catalog.maps) maps.push_back(build_source(source));
  return maps;
}

std::optional<std::vector<std::array<double, 3>>> dart_points(const std::string& target, const Model& model) {
  const auto ext = std::filesystem::path(target).extension().string();
  std::vector<std::array<double, 3>> out;
  if (is_mesh_path(target)) {
    for (Dim i : model.dims)
      if (model.is_oriented(i)) return std::nullopt;  // mesh_with_positions builds G-maps
    const EmbeddedMap m = mesh_with_positions(model, read_mesh(target), EmbeddingSignature{"pos", ValueType::point3, {1, 2}});
    for (Dart d = 0; d < m.map.size(); ++d) {
      const Value* v = m.embeddings[0].value(d);
      if (!v) return std::nullopt;
      out.push_back(v->x);
    }
    return out;
  }
  if (ext != ".jba") return std::nullopt;
  const JbaFile f = read_jba(target);
  for (MapEmbedding e : f.embeddings) {
    e.type = "point3";  // Vec3, Point3 or a modeler's own class: three numbers or not
    std::string why;
    const auto typed = typed_embedding(e, &why);
    if (!typed) continue;
    out.clear();
    for (Dart d = 0; d < f.map.size() && out.size() == d; ++d)
      if (const Value* v = typed->value(d)) out.push_back(v->x);
    if (out.size() == f.map.size()) return out;
  }
  return std::nullopt;
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
    throw UsageError(fmt::format("'{}' is not a catalog map, a map file or a shape: {}{}{}", printable(target), e.what(),
                                 maps.empty() ? std::string() : fmt::format("; the catalog's maps: {}", maps), did_you_mean(target, names)));
  }
}

std::string describe_target(const std::string& target, const Map& map) {
  return fmt::format("{} ({}, {} darts)", target, map.model().name, map.size());
}

}  // namespace dartcheck::analysis
