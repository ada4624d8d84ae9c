// The maps a catalog, a file or a shape name: what the commands and the
// fuzz engine run rules on.
#pragma once

#include <array>
#include <optional>

#include <string>

#include "io/catalog.hpp"
#include "core/map.hpp"

namespace dartcheck::analysis {

/// The catalog a command works on; InputError if `rule` (--rule), when
/// given, names none of its rules.
Catalog read_rule_catalog(const std::string& file, const std::string& rule);

/// The rule named `rule` of `catalog` (read from `file`), or an InputError
/// that names the closest rule name (did you mean) and how to list them.
const CatalogRule& require_rule(const Catalog& catalog, const std::string& file, const std::string& rule);

/// Builds a catalog map: explicit, shape or mesh. Errors carry the map's
/// position in the catalog.
Map build_source(const MapSource& source);

/// The maps a rule scheme's model-level confirmation runs on (check and
/// report): the catalog's maps when it has a scheme, none otherwise or
/// when `confirm_darts` is 0 (no confirmation).
std::vector<Map> confirmation_maps(const Catalog& catalog, std::size_t confirm_darts);

/// A map named by TARGET: a name in `catalog` (if given), a .yaml/.yml map
/// file, an .off/.obj mesh, or a shape spec such as grid:3x4. `model` is
/// used for meshes and shapes. Throws InputError.
Map resolve_map(const std::string& target, const Model& model, const Catalog* catalog);

/// The position of each dart's vertex when TARGET is a file that has them
/// (an .off/.obj mesh: its vertices; a .jba: its first embedding whose
/// values are three numbers), in resolve_map's numbering; nullopt otherwise
/// (a shape, a YAML map, a catalog map). Throws InputError for a file that
/// does not read.
std::optional<std::vector<std::array<double, 3>>> dart_points(const std::string& target, const Model& model);

/// A short human label for a target ("cube (2-gmap)").
std::string describe_target(const std::string& target, const Map& map);

}  // namespace dartcheck::analysis
