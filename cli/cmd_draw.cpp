// `dartcheck draw` (a rule or scheme, witnesses of its failed conditions
// highlighted) and `dartcheck draw-map` (a map, links colored by
// dimension, invalid darts highlighted): one picture each, rendered by
// libgvc in the format the output file's extension names.

#include <fmt/format.h>

#include "checkers/graph_constraints.hpp"
#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "core/terminal.hpp"
#include "reports/embedding_picture.hpp"
#include "cli/options.hpp"
#include "analysis/embedding_checks.hpp"
#include "analysis/map_sources.hpp"
#include "rewriting/graph_derivation.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "reports/graph_dot.hpp"
#include "reports/map_layout.hpp"
#include "reports/render.hpp"
#include "reports/rule_dot.hpp"

namespace dartcheck::cli {

using namespace analysis;  // the engines the commands call
int draw(const DrawOptions& o) {
  const Catalog catalog = read_rule_catalog(o.catalog, o.rule);
  const CatalogRule* entry = catalog.find_rule(o.rule);
  const RuleVerdict verdict = check_rule(entry->rule, entry->words);
  auto witnesses = reports::failed_witnesses(verdict);
  const auto embedded = reports::embedding_picture(*entry, embedding_checks(catalog, *entry));
  witnesses.insert(witnesses.end(), embedded.witnesses.begin(), embedded.witnesses.end());
  auto captions = reports::failure_captions(verdict);
  captions.insert(captions.end(), embedded.captions.begin(), embedded.captions.end());
  const bool pinned = o.engine.empty();
  const std::string dot =
      reports::rule_dot(entry->rule, entry->words, witnesses, entry->jerboa ? &*entry->jerboa : nullptr, embedded.terms, captions, pinned);
  const std::size_t bytes = reports::write_picture(dot, o.output, pinned ? "neato" : o.engine);
  if (!terminal().quiet) fmt::print("wrote {} ({} bytes)\n", o.output, bytes);
  return ok;
}

// Maps up to this size are laid out by dot as given (a rule's example, a
// counterexample): each dart's links read along its rank.
constexpr std::size_t skeleton_darts = 16;

int draw_map(const DrawMapOptions& o) {
  const Model model = command_model(o.model);
  const Map map = resolve_map(o.target, model, nullptr);
  const auto report = check_map(map);
  reports::GraphPicture p;
  p.title = fmt::format("{} ({}, {} darts)", o.target, map.model().name, map.size());
  p.highlight.assign(map.size(), false);
  for (const auto& v : report.violations)
    if (v.element < map.size()) p.highlight[v.element] = true;
  if (!report.valid()) p.highlight_label = fmt::format("filled: {} violations", report.violations.size());
  // A map with vertex positions (a mesh, a .jba) is drawn as an exploded
  // view, its darts pinned where they lie: neato honours the pins.
  std::string engine = o.engine;
  if (const auto points = dart_points(o.target, model); points && points->size() == map.size()) {
    p.positions = reports::exploded_layout(map, *points);
    if (engine == "dot") engine = "neato";
  } else if (engine == "dot" && map.size() > skeleton_darts) {
    // Without positions, the vertices are placed by the skeleton's
    // layout first: past a few dozen darts dot's ranks are a tangle.
    p.positions = reports::exploded_layout(map, reports::skeleton_points(map));
    engine = "neato";
  }
  const std::size_t bytes = reports::write_picture(reports::graph_dot(to_graph(map), map.model(), p), o.output, engine);
  if (!terminal().quiet) fmt::print("wrote {} ({} bytes)\n", o.output, bytes);
  if (report.valid()) return ok;
  // Every non-zero exit says why.
  fmt::print(stderr, "INVALID {}: {} violation{} (drawn filled; validate-map lists them)\n", map.model().name, report.violations.size(),
             report.violations.size() == 1 ? "" : "s");
  return violation;
}

}  // namespace dartcheck::cli
