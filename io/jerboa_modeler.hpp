// Jerboa modeler editor files (.jme): a modeler's rules as Jerboa-style
// rule schemes on its n-G-map model (000 Sec. 4.3, translated as in 002
// Sec. 10.1 by core/jerboa_scheme).
//
// The file is XML: <jerboamodelereditor><modeler name dimension> with
// <embeddings> (<embedding name type orbit="1,2,3">) and <rules>. A rule
// has <left> and <right>, each with <nodes> (<node name orbit="0,-1,3"
// kind="HOOK|SIMPLE" multiplicity="{1}">, optionally <expr ebd="pos">code
// </expr>) and <arcs> (<arc dim a b>, non-oriented, and <arcloop dim node>).
// Orbit labels are positional, relative to the hook's orbit type; -1 is
// the removing symbol '_'. Nodes of L and R are matched by name.
//
// What dartcheck does not represent is said per rule, never dropped: a
// rule with a multiplicity other than {1}, a script, or a structure that
// cannot be a rule scheme (L without a hook, labels of the wrong length) is
// listed in Catalog::skipped with the reason; preconditions, pre/post
// processing code and embedding parameters are kept as caveats of a rule
// that is checked without them. Malformed XML, unknown orbit entries,
// arcs naming missing nodes and dimensions out of range are InputErrors
// with file:line:column.
#pragma once

#include <string>

#include "io/catalog.hpp"

namespace dartcheck {

/// Reads a .jme file as a catalog of the modeler's rules.
Catalog read_jme(const std::string& file);

}  // namespace dartcheck
