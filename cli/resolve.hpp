// Turning what a user names on the command line into maps.
#pragma once

#include <string>

#include "core/catalog.hpp"
#include "core/map.hpp"

namespace dartcheck::cli {

/// Reads the catalog a command works on, after checking --format (text or
/// json) and that --rule, if given, names one of its rules.
Catalog read_command_catalog(const std::string& file, const std::string& rule, const std::string& format);

/// Builds a catalog map: explicit, shape or mesh. Errors carry the map's
/// position in the catalog.
Map build_source(const MapSource& source);

/// A map named by TARGET: a name in `catalog` (if given), a .yaml/.yml map
/// file, an .off/.obj mesh, or a shape spec such as grid:3x4. `model` is
/// used for meshes and shapes. Throws InputError.
Map resolve_map(const std::string& target, const Model& model, const Catalog* catalog);

/// A short human label for a target ("cube (2-gmap)").
std::string describe_target(const std::string& target, const Map& map);

/// Seconds in "30s", "500ms", "2m", "1h" or a bare number of seconds;
/// InputError naming `option` otherwise.
double parse_duration(const std::string& text, const std::string& option);

}  // namespace dartcheck::cli
