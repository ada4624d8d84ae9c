// Plain-text rendering of validity reports and cell counts.
#pragma once

#include <cstdio>
#include <string>

#include "checkers/violation.hpp"
#include "core/map.hpp"
#include "io/jerboa_jba.hpp"

namespace dartcheck::reports {

/// Prints cells and every violation (up to `limit`, 0 = all, saying how
/// many were left out).
void print_validity(std::FILE* out, const Map& map, const ValidityReport& report, std::size_t limit);

/// A Jerboa G-map: the map's constraints, then each embedding's
/// consistency (003 Def. 6), one line per orbit with two values or
/// unlabeled darts (up to `limit`); whether it is a valid, consistently
/// embedded G-map.
bool print_jba_validity(std::FILE* out, const JbaFile& file, std::size_t limit);

/// validate-map -q: each violation (up to `limit`) and, for a .jba, each
/// embedding conflict as a `target: error: ...` line; whether the map is
/// valid (and consistently embedded).
bool print_validity_diagnostics(std::FILE* out, const std::string& target, const Map& map, const ValidityReport& report, std::size_t limit,
                                const JbaFile* jba);

/// Valid, and every embedding of the .jba consistent (003 Def. 6).
bool consistently_embedded(const JbaFile& file, const ValidityReport& report);

/// "8 vertices, 12 edges, 6 faces"
std::string cells_sentence(const Map& map);

}  // namespace dartcheck::reports
