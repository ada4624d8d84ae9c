#include "reports/apply_output.hpp"

#include <random>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/exit_status.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_embedding.hpp"
#include "io/jerboa_jba.hpp"
#include "io/kappa_file.hpp"
#include "io/map_io.hpp"
#include "io/mesh_io.hpp"
#include "io/mesh_writer.hpp"
#include "reports/validity_text.hpp"
#include "rewriting/application.hpp"
#include "rewriting/embedded_application.hpp"

namespace dartcheck::reports {

using namespace exit_status;

namespace {

// An embedded rule (003): the host's values come from the mesh file
// (positions) or are drawn per orbit (seed 1); the rule's new values are
// printed, and H is checked for validity and embedding consistency.
int apply_terms(const ApplyRequest& o, const CatalogRule& rule, Map map) {
  const RuleTerms& terms = *rule.terms;
  std::mt19937 rng(1);
  std::optional<EmbeddedMap> host;
  if (is_mesh_path(o.map))
    for (const auto& e : terms.embeddings)
      if (!host && (e.type == ValueType::point2 || e.type == ValueType::point3)) {
        host = mesh_with_positions(rule.rule.model(), read_mesh(o.map), e);
        fmt::print("values: {} from the mesh's vertex positions\n", e.name);
      }
  if (!host) host.emplace(std::move(map));
  for (const auto& e : terms.embeddings) {
    if (host->find(e.name)) continue;
    Embedding& added = host->embeddings[host->add_embedding(e)];
    const EmbeddedMap drawn = embed_randomly(host->map, {e}, rng);
    added = drawn.embeddings[0];
    fmt::print("values: {} drawn at random, one per <{}>-orbit (seed 1)\n", e.name, fmt::join(e.orbit, ","));
  }
  auto result = apply_embedded(rule.rule, rule.words, terms, *host, o.hooks);
  if (!result.ok()) {
    fmt::print("not applied ({}): {}\n", refusal_name(result.refusal), result.why);
    return violation;
  }
  fmt::print("applied ({} instantiation): {} darts matched, {} added; result has {} darts\n",
             terms.instantiation == Instantiation::direct ? "direct" : "extended", result.value->matched, result.value->added, host->map.size());
  for (const auto& w : result.value->written) fmt::print("  {}.{} = {} (dart {})\n", w.node, w.embedding, w.value.str(), w.dart);
  for (const auto& c : result.value->conflicts) fmt::print("  conflict: {}\n", c);
  const auto report = check_map(host->map);
  print_validity(stdout, host->map, report, o.limit);
  bool consistent = result.value->conflicts.empty();
  for (const Embedding& e : host->embeddings) {
    const auto c = check_embedding(host->map, e, true);
    fmt::print("embedding {} <{}>: {} orbits, {}\n", e.signature.name, fmt::join(e.signature.orbit, ","), c.orbits,
               c.consistent() ? "consistent (every dart labeled, one value per orbit)" : fmt::format("{} inconsistent orbits", c.conflicts.size()));
    for (std::size_t k = 0; k < c.conflicts.size() && (o.limit == 0 || k < o.limit); ++k)
      fmt::print("  {}\n", c.conflicts[k].describe(e.signature.name, e.signature.orbit));
    consistent &= c.consistent();
  }
  if (!o.output.empty() && is_mesh_path(o.output)) {
    // The positions: the first point embedding of the rule.
    const Embedding* pos = nullptr;
    for (const Embedding& e : host->embeddings)
      if (!pos && (e.signature.type == ValueType::point3 || e.signature.type == ValueType::point2)) pos = &e;
    if (!pos) throw InputError("<command line>", 0, 0, fmt::format("-o: '{}': the map has no point embedding for the positions", o.output));
    std::ostringstream text;  // refused (a vertex without a position) before a file exists
    write_mesh(text, *host, pos->signature.name, o.output);
    write_file(o.output, text.str());
    fmt::print("written: {} (positions from {})\n", o.output, pos->signature.name);
  } else if (!o.output.empty()) {
    std::ostringstream text;
    write_map(text, host->map);
    write_file(o.output, text.str());
    fmt::print("written: {} (topology only; the values are printed above)\n", o.output);
  }
  return report.valid() && consistent ? ok : violation;
}

// The preserved darts' correspondence G -> H: said when ids moved (the
// compaction after a deletion), written with --kappa-out.
void write_kappa(const ApplyRequest& o, const Renumbering& c, std::size_t g_size) {
  std::vector<std::pair<Dart, Dart>> pairs;
  std::size_t moved = 0;
  for (Dart d = 0; d < g_size; ++d)
    if (const Dart e = c.to_h(d); e != no_dart) {
      pairs.emplace_back(d, e);
      moved += e != d;
    }
  if (moved)
    fmt::print("darts renumbered: {} of the {} preserved darts have another id in the result{}\n", moved, pairs.size(),
               o.kappa_out.empty() ? " (--kappa-out FILE writes the correspondence for infer --kappa)" : "");
  if (o.kappa_out.empty()) return;
  write_file(o.kappa_out, kappa_file_text(pairs, {"The dart correspondence of one application (dartcheck apply --kappa-out):",
                                                  "before dart (host), after dart (result), for every preserved dart."}));
  fmt::print("written: {} ({} preserved darts)\n", o.kappa_out, pairs.size());
}

// -o X.jba: the result as a Jerboa G-map, with the embeddings a .jba input
// carried. A topological rule computes no values: preserved and unmatched
// darts keep theirs (through the dart correspondence of the application,
// events/application_trace), new darts have none, and the summary says
// how many are labeled.
int apply_to_jba(const ApplyRequest& o, const CatalogRule& rule, Map map) {
  JbaFile in{"dartcheck", Map(rule.rule.model()), {}, {}};
  if (o.map.ends_with(".jba")) in = read_jba(o.map);
  const Map before = map;
  auto traced = dartcheck::apply(rule, map, o.hooks);
  if (!traced.ok()) {
    fmt::print("not applied ({}): {}\n", refusal_name(traced.refusal), traced.why);
    return violation;
  }
  fmt::print("applied: {} -> {} darts\n", before.size(), map.size());
  const Renumbering c = traced.value->renumbering(rule.rule, map.size());
  JbaFile out{in.name, map, {}, {}};
  for (const auto& e : in.embeddings) {
    MapEmbedding carried{e.name, e.type, e.orbit, std::vector<std::optional<std::string>>(map.size()), {}};
    std::size_t labeled = 0;
    for (Dart h = 0; h < map.size(); ++h)
      if (const Dart g = c.to_g(h); g != no_dart && g < e.values.size() && e.values[g]) {
        carried.values[h] = e.values[g];
        ++labeled;
      }
    fmt::print("embedding {}: {} of {} darts keep their value; new darts have none (a topological rule computes no values)\n", e.name, labeled,
               map.size());
    out.embeddings.push_back(std::move(carried));
  }
  const auto report = check_map(map);
  print_validity(stdout, map, report, o.limit);
  write_kappa(o, c, before.size());
  std::ostringstream text;  // refused (not an n-G-map) before a file exists
  write_jba(text, out, o.output);
  write_file(o.output, text.str());
  fmt::print("written: {}\n", o.output);
  return report.valid() ? ok : violation;
}

// A DPO rule matched from the hooks, or a scheme instantiated on the
// hooks' pattern graph (002 Sec. 6.3): the topology as YAML.
int apply_topology(const ApplyRequest& o, const CatalogRule& rule, Map map) {
  const std::size_t before_size = map.size();
  auto result = dartcheck::apply(rule, map, o.hooks);
  if (!result.ok()) {
    fmt::print("not applied ({}): {}\n", refusal_name(result.refusal), result.why);
    return violation;
  }
  const Application& a = *result.value;
  std::string comatch;
  for (NodeId v = 0; v < rule.rule.right().node_count(); ++v)
    comatch += fmt::format("{}{}={}", v ? " " : "", rule.rule.right().name(v), fmt::join(a.comatch[v], ","));
  if (a.pattern)
    fmt::print("applied scheme: pattern graph of {} darts; result has {} darts; comatch {}\n", a.match.empty() ? 0 : a.match[0].size(), map.size(),
               comatch);
  else
    fmt::print("applied: result has {} darts; comatch {}\n", map.size(), comatch);
  const auto report = check_map(map);
  print_validity(stdout, map, report, o.limit);
  if (!o.output.empty()) {
    std::ostringstream text;
    write_map(text, map);
    write_file(o.output, text.str());
    fmt::print("written: {}\n", o.output);
  }
  write_kappa(o, a.renumbering(rule.rule, map.size()), before_size);
  return report.valid() ? ok : violation;
}

}  // namespace

int apply_and_write(const ApplyRequest& o, const CatalogRule& rule, Map map) {
  const bool jba_out = o.output.ends_with(".jba"), mesh_out = is_mesh_path(o.output);
  if (rule.terms) {
    if (!o.kappa_out.empty()) throw InputError("<command line>", 0, 0, "--kappa-out: for topological rules (infer reads G-maps without values)");
    if (jba_out) throw InputError("<command line>", 0, 0, "-o: an embedded rule's result is written as YAML (its values are printed); use .yaml");
    return apply_terms(o, rule, std::move(map));
  }
  if (jba_out) return apply_to_jba(o, rule, std::move(map));
  if (mesh_out)
    throw InputError("<command line>", 0, 0,
                     fmt::format("-o: '{}': a mesh needs positions, and rule '{}' computes none: apply an embedded rule with a point embedding, "
                                 "or write .yaml",
                                 o.output, o.rule));
  return apply_topology(o, rule, std::move(map));
}

}  // namespace dartcheck::reports
