// Plain-text rendering of validity reports and cell counts.
#pragma once

#include <cstdio>
#include <string>

#include "checkers/violation.hpp"
#include "core/map.hpp"

namespace dartcheck::reports {

/// Prints cells and every violation (up to `limit`, 0 = all, saying how
/// many were left out).
void print_validity(std::FILE* out, const Map& map, const ValidityReport& report, std::size_t limit);

/// "8 vertices, 12 edges, 6 faces"
std::string cells_sentence(const Map& map);

}  // namespace dartcheck::reports
