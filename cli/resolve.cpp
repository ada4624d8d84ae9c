#include "cli/resolve.hpp"

#include <filesystem>
#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/jerboa_jba.hpp"
#include "core/map_io.hpp"
#include "core/mesh_io.hpp"
#include "generators/mesh_map.hpp"
#include "generators/shapes.hpp"

namespace dartcheck::cli {

Catalog read_command_catalog(const std::string& file, const std::string& rule, const std::string& format) {
  if (format != "text" && format != "json")
    throw InputError("<command line>", 0, 0, fmt::format("--format: expected text or json, got '{}'", format));
  Catalog catalog = read_catalog(file);
  if (!rule.empty() && !catalog.find_rule(rule))
    throw InputError("<command line>", 0, 0, fmt::format("--rule: no rule named '{}' in {}", rule, file));
  return catalog;
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

Map resolve_map(const std::string& target, const Model& model, const Catalog* catalog) {
  if (catalog)
    if (const MapSource* s = catalog->find_map(target)) return build_source(*s);
  const bool exists = std::filesystem::exists(target);
  if (is_mesh_path(target)) return load_mesh(model, target);
  const auto ext = std::filesystem::path(target).extension().string();
  if (ext == ".yaml" || ext == ".yml") return read_map(target, load_yaml_file(target));
  if (ext == ".jba") return read_jba(target).map;  // the file names its dimension
  if (exists) throw InputError(target, 0, 0, "unknown map file type (expected .yaml, .yml, .off, .obj or .jba)");
  try {
    return build_shape(model, parse_shape(target));
  } catch (const BuildError& e) {
    throw InputError("<command line>", 0, 0,
                     fmt::format("'{}' is not a catalog map, a map file or a shape: {}", target, e.what()));
  }
}

std::string describe_target(const std::string& target, const Map& map) { return fmt::format("{} ({}, {} darts)", target, map.model().name, map.size()); }

double parse_duration(const std::string& text, const std::string& option) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const std::string unit = text.substr(used);
  double scale = unit.empty() || unit == "s" ? 1 : unit == "ms" ? 1e-3 : unit == "m" || unit == "min" ? 60 : unit == "h" ? 3600 : -1;
  if (used == 0 || scale < 0 || !(v > 0))
    throw InputError("<command line>", 0, 0, fmt::format("{}: expected a positive duration such as 30s, 500ms or 2m, got '{}'", option, text));
  return v * scale;
}

}  // namespace dartcheck::cli
