// Maps in YAML: explicit darts and links, readable back bit for bit.
//
//   model: 2-gmap
//   darts: 4
//   links:
//     0: [1, 0, 3, 2]                # the i-arc target of each dart (~: none)
//     1: {pairs: [[1, 2], [3, 0]]}   # or non-oriented pairs, written once
//     2: {loops: all}                # or loops: all darts, or a list
//   pred:                            # oriented dimensions, optional: the
//     1: [3, 0, 1, 2]                # recorded predecessors when they are
//                                    # not the inverse of the links
// An oriented dimension also accepts {cycles: [[0, 1, 2], ...]}.
// The full format is in docs/catalog-format.md.
#pragma once

#include <iosfwd>
#include <string>

#include "core/map.hpp"

namespace dartcheck {

/// Reads the map file `path` (the YAML form below); InputError at the
/// offending node.
Map read_map_file(const std::string& path);
/// The same from YAML text (`name` in messages, as a file's would be).
Map read_map_text(const std::string& name, const std::string& text);

/// Writes the explicit form (raw arrays, pred only where needed).
void write_map(std::ostream& out, const Map& map);
std::string map_to_yaml(const Map& map);

}  // namespace dartcheck
