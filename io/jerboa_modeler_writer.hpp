// Writes Jerboa-style rule schemes as a Jerboa modeler editor file (.jme)
// with the elements and attributes Jerboa's editor writes (node positions,
// paramstopo, modeler attributes),
// the format io/jerboa_modeler.hpp reads: node labels positional with -1
// for '_', the first hook of L marked HOOK, explicit arcs as <arc> (one
// per non-oriented pair) and <arcloop>. Reading the file back gives the
// same rules (tests/io check it).
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "rewriting/operation.hpp"

namespace dartcheck {

/// Why `name` cannot be written in an XML 1.0 file (a control character
/// other than tab and line ends, U+FFFE or U+FFFF, or invalid UTF-8: no
/// escape makes them well-formed), or nullopt.
std::optional<std::string> xml_name_problem(std::string_view name);

/// Writes a modeler named `modeler` of dimension n (the rules' n-G-map
/// model) holding `rules`, which must all carry Jerboa labels. Throws
/// ValueError for a rule without them or with an explicit arc
/// whose reverse is missing (Jerboa's arcs are non-oriented), and for a
/// name XML cannot hold (xml_name_problem).
void write_jme(std::ostream& out, const std::string& modeler, int dimension, const std::vector<const Operation*>& rules);

}  // namespace dartcheck
