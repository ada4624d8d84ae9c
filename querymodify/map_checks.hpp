// Validity of 001's 3-maps (Def. 1 with the ε extension): dartcheck's
// open O-map constraints, except that a face whose darts are all 3-free
// is exempt from C(1,3).
//
// dartcheck's `n-open-omap` (002 Sec. 3.2) relaxes only the incident-arcs
// condition on n and keeps C(i,n) on every dart, so any n-free dart breaks
// C(1,n) for n >= 3: a tetrahedral mesh with a boundary is not a valid
// 3-open-omap there. 001, like CGAL's combinatorial maps, reads β1∘β3 as
// an involution where β3 is defined: a face is wholly 3-sewn or wholly
// 3-free. This check keeps every violation check_map reports except C(i,n)
// at a dart that and whose i-successor are both n-free; a partly sewn face
// still fails (its free dart next to a sewn one keeps its violation).
#pragma once

#include "checkers/map_validity.hpp"

namespace dartcheck::querymodify {

ValidityReport check_3map(const Map& m);

}  // namespace dartcheck::querymodify
