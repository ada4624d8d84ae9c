#include <fmt/format.h>

#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "io/jerboa_jba.hpp"
#include "cli/commands.hpp"
#include "reports/validity_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"

namespace dartcheck::cli {

using reports::print_validity;

using namespace analysis;  // the engines the commands call
namespace {

// A Jerboa G-map: the map's constraints, then each embedding's consistency
// (003 Def. 6), one line per orbit with two values or unlabeled darts.
int validate_jba(const ValidateOptions& o) {
  const JbaFile f = read_jba(o.target);
  fmt::print("map: {} (Jerboa, written by {})\n", describe_target(o.target, f.map), f.name);
  const auto report = check_map(f.map);
  print_validity(stdout, f.map, report, o.limit);
  bool consistent = true;
  for (const auto& e : f.embeddings) {
    const auto c = check_embedding(f.map, e);
    fmt::print("embedding {} <{}> ({}): {} orbits, {} with a value, {} inconsistent\n", e.name, fmt::join(e.orbit, ","), e.type, c.orbits, c.labeled,
               c.conflicts.size());
    for (std::size_t k = 0; k < c.conflicts.size() && (o.limit == 0 || k < o.limit); ++k) fmt::print("  {}\n", c.conflicts[k].describe(e));
    if (o.limit && c.conflicts.size() > o.limit) fmt::print("  ... {} more (--limit 0 shows all)\n", c.conflicts.size() - o.limit);
    consistent = consistent && c.consistent();
  }
  fmt::print("{}\n", report.valid() && consistent ? "valid embedded G-map" : "INVALID embedded G-map");
  return report.valid() && consistent ? ok : violation;
}

}  // namespace

int validate_map(const ValidateOptions& o) {
  const auto model = Model::by_name(o.model);
  if (!model) throw InputError("<command line>", 0, 0, fmt::format("--model: unknown model '{}' (expected {})", o.model, Model::known_names()));
  if (o.target.ends_with(".jba")) return validate_jba(o);
  const Map map = resolve_map(o.target, *model, nullptr);
  fmt::print("map: {}\n", describe_target(o.target, map));
  const auto report = check_map(map);
  print_validity(stdout, map, report, o.limit);
  return report.valid() ? ok : violation;
}

}  // namespace dartcheck::cli
