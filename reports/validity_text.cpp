#include "reports/validity_text.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/orbit.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include <fmt/ranges.h>

namespace dartcheck::reports {

std::string cells_sentence(const Map& map) {
  static const char* names[] = {"vertices", "edges", "faces", "volumes"};
  const CellCounts c = count_cells(map);
  std::string s;
  for (std::size_t k = 0; k < c.cells.size(); ++k)
    s += fmt::format("{}{} {}", k ? ", " : "", c.cells[k], k < 4 ? std::string(names[k]) : fmt::format("{}-cells", k));
  s += fmt::format("; {} connected component{}", c.components, c.components == 1 ? "" : "s");
  if (c.cells.size() == 3) s += fmt::format("; Euler characteristic {}", c.euler());
  return s;
}

void print_validity(std::FILE* out, const Map& map, const ValidityReport& r, std::size_t limit) {
  std::string links;
  for (const LinkCount& c : count_links(map)) links += fmt::format("{}{}: {} arcs ({} loops)", links.empty() ? "" : ", ", c.dim, c.arcs, c.loops);
  fmt::print(out, "links: {}\n", links);
  if (r.valid()) {
    fmt::print(out, "cells: {}\n", cells_sentence(map));
    fmt::print(out, "valid {}: 0 violations\n", map.model().name);
    return;
  }
  fmt::print(out, "INVALID {}: {} violation{}\n", map.model().name, r.violations.size(), r.violations.size() == 1 ? "" : "s");
  const std::size_t shown = limit == 0 ? r.violations.size() : std::min(limit, r.violations.size());
  for (std::size_t k = 0; k < shown; ++k) {
    const auto& v = r.violations[k];
    fmt::print(out, "  dart {}: {}\n", v.element, describe(v, fmt::format("dart {}", v.element)));
  }
  if (shown < r.violations.size()) fmt::print(out, "  ... and {} more (use --limit 0 to list all)\n", r.violations.size() - shown);
}

bool print_validity_diagnostics(std::FILE* out, const std::string& target, const Map& map, const ValidityReport& r, std::size_t limit,
                                const JbaFile* jba) {
  const std::size_t shown = limit == 0 ? r.violations.size() : std::min(limit, r.violations.size());
  for (std::size_t k = 0; k < shown; ++k) {
    const auto& v = r.violations[k];
    fmt::print(out, "{}: error: dart {}: {}\n", printable(target), v.element, describe(v, fmt::format("dart {}", v.element)));
  }
  if (!jba) return r.valid();
  for (const auto& e : jba->embeddings) {
    const auto c = check_embedding(map, e);
    for (std::size_t k = 0; k < c.conflicts.size() && (limit == 0 || k < limit); ++k)
      fmt::print(out, "{}: error: embedding {}: {}\n", printable(target), printable(e.name), printable(c.conflicts[k].describe(e)));
  }
  return consistently_embedded(*jba, r);
}

bool consistently_embedded(const JbaFile& f, const ValidityReport& report) {
  if (!report.valid()) return false;
  for (const auto& e : f.embeddings)
    if (!check_embedding(f.map, e).consistent()) return false;
  return true;
}

bool print_jba_validity(std::FILE* out, const JbaFile& f, std::size_t limit) {
  const auto report = check_map(f.map);
  print_validity(out, f.map, report, limit);
  bool consistent = true;
  for (const auto& e : f.embeddings) {
    const auto c = check_embedding(f.map, e);
    fmt::print(out, "embedding {} <{}> ({}): {} orbits, {} with a value, {} inconsistent\n", e.name, fmt::join(e.orbit, ","), e.type, c.orbits,
               c.labeled, c.conflicts.size());
    for (std::size_t k = 0; k < c.conflicts.size() && (limit == 0 || k < limit); ++k) fmt::print(out, "  {}\n", c.conflicts[k].describe(e));
    if (limit && c.conflicts.size() > limit) fmt::print(out, "  ... {} more (--limit 0 shows all)\n", c.conflicts.size() - limit);
    consistent = consistent && c.consistent();
  }
  fmt::print(out, "{}\n", report.valid() && consistent ? "valid embedded G-map" : "INVALID embedded G-map");
  return report.valid() && consistent;
}

}  // namespace dartcheck::reports
