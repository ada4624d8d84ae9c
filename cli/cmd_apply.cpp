// dartcheck apply: one rule at hook darts of a map, the result's validity
// (and, for an embedded rule, its embedding consistency), and the files
// asked for; reports/apply_output renders what the run finds.
#include <map>
#include <random>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/exit_status.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "core/terminal.hpp"
#include "core/output_file.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_embedding.hpp"
#include "io/jerboa_expression.hpp"
#include "io/jerboa_jba.hpp"
#include "io/kappa_file.hpp"
#include "io/map_io.hpp"
#include "io/mesh_io.hpp"
#include "io/mesh_writer.hpp"
#include "reports/apply_output.hpp"
#include "reports/validity_text.hpp"
#include "rewriting/application.hpp"

#include "analysis/map_sources.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "io/catalog.hpp"

namespace dartcheck::cli {

using namespace exit_status;

namespace {

// An embedded rule (003): the host's values come from the mesh file
// (positions) or are drawn per orbit (seed 1); the rule's new values are
// printed, and H is checked for validity and embedding consistency.
// A .jba host's embeddings, typed (a Jerboa class as the .jme reads it);
// values that do not parse as their type are carried as text. An
// embedding of the rule that the file names otherwise (cube.jba's
// `point` for a modeler's `pos`) is the file's only one with its orbit
// and value type; `file_name` says what to write it back as.
struct JbaHost {
  JbaFile file;
  std::map<std::string, std::string> file_name;  // the host's embedding -> the file's, where they differ
};

JbaHost jba_host(const ApplyOptions& o, const RuleTerms& terms, EmbeddedMap& host) {
  JbaHost j{read_jba(o.map), {}};
  for (const MapEmbedding& m : j.file.embeddings) {
    MapEmbedding typed = m;
    if (const auto t = jerboa_value_type(m.type)) typed.type = std::string(name_of(*t));
    std::string why;
    std::optional<Embedding> e = typed_embedding(typed, &why);
    if (!e) {
      typed.type = "string";
      e = typed_embedding(typed, &why);
      fmt::print("values: {} carried as text ({})\n", m.name, why);
    }
    // A value type other than the rule's: kept out of the rule's way,
    // carried to the darts H keeps, and written back.
    const auto clash = std::find_if(terms.embeddings.begin(), terms.embeddings.end(), [&](const auto& x) { return x.name == m.name; });
    if (clash != terms.embeddings.end() && clash->type != e->signature.type) {
      e->signature.name = m.name + " (the file's)";
      j.file_name[e->signature.name] = m.name;
      fmt::print("values: the file's {} are not {} values: the rule computes its own {}, and the file's are kept on the darts H keeps\n", m.name,
                 name_of(clash->type), m.name);
    }
    host.embeddings.push_back(std::move(*e));
  }
  for (const auto& sig : terms.embeddings) {
    if (host.find(sig.name)) continue;
    Embedding* only = nullptr;
    int candidates = 0;
    for (Embedding& e : host.embeddings)
      if (e.signature.orbit == sig.orbit && e.signature.type == sig.type &&
          std::none_of(terms.embeddings.begin(), terms.embeddings.end(), [&](const EmbeddingSignature& x) { return x.name == e.signature.name; })) {
        only = &e;
        ++candidates;
      }
    if (candidates != 1) continue;
    j.file_name[sig.name] = only->signature.name;
    fmt::print("values: {} read from the file's {} (the only embedding with its orbit <{}> and type {})\n", sig.name, only->signature.name,
               fmt::join(sig.orbit, ","), name_of(sig.type));
    only->signature.name = sig.name;
  }
  return j;
}

// The result as a .jba: the file's embeddings under their own names, with
// the values H holds; embeddings the file did not have are not written.
void write_jba_result(const ApplyOptions& o, const JbaHost& j, const EmbeddedMap& h) {
  JbaFile out{j.file.name, h.map, {}, {}};
  for (const MapEmbedding& m : j.file.embeddings) {
    std::string ours = m.name;
    for (const auto& [host_name, file_name] : j.file_name)
      if (file_name == m.name) ours = host_name;
    const Embedding* e = h.find(ours);
    MapEmbedding w{m.name, m.type, m.orbit, std::vector<std::optional<std::string>>(h.map.size()), {}};
    std::size_t labeled = 0;
    for (Dart d = 0; d < h.map.size(); ++d)
      if (const Value* v = e ? e->value(d) : nullptr) {
        w.values[d] = jba_value(*v);
        ++labeled;
      }
    fmt::print("embedding {}: {} of {} darts labeled\n", m.name, labeled, h.map.size());
    out.embeddings.push_back(std::move(w));
  }
  std::ostringstream text;  // refused (not an n-G-map) before a file exists
  write_jba(text, out, o.output);
  write_file(o.output, text.str());
  if (!terminal().quiet) fmt::print("written: {}\n", o.output);
}

// The preserved darts (G dart, H dart) of an application.
std::vector<std::pair<Dart, Dart>> preserved_pairs(const Renumbering& c, std::size_t g_size) {
  std::vector<std::pair<Dart, Dart>> pairs;
  for (Dart d = 0; d < g_size; ++d)
    if (const Dart e = c.to_h(d); e != no_dart) pairs.emplace_back(d, e);
  return pairs;
}

// H as YAML; when the application deleted darts, with the preserved
// darts' correspondence (`preserved:`), which infer's identity κ reads:
// a created dart may have taken a deleted dart's id (docs/inference.md).
std::string result_yaml(const Map& h, const std::vector<std::pair<Dart, Dart>>& preserved, std::size_t g_size) {
  std::ostringstream text;
  write_map(text, h);
  return text.str() + (preserved.size() < g_size ? preserved_text(preserved) : std::string());
}

int apply_terms(const ApplyOptions& o, const CatalogRule& rule, Map map) {
  const RuleTerms& terms = *rule.terms;
  std::mt19937 rng(1);
  std::optional<EmbeddedMap> host;
  std::optional<JbaHost> jba;
  if (o.map.ends_with(".jba")) {
    host.emplace(std::move(map));
    jba = jba_host(o, terms, *host);
  } else if (is_mesh_path(o.map))
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
    fmt::print("values: {} drawn at random, one per <{}>-orbit (seed 1){}\n", e.name, fmt::join(e.orbit, ","),
               jba ? ": the file has no such embedding, and -o .jba does not write it" : "");
  }
  const std::size_t g_size = host->map.size();  // for the dart correspondence of a YAML result
  auto result = Applier(rule).apply(*host, o.hooks);
  if (!result.ok()) {
    fmt::print("{}", reports::not_applied_text(result.refusal, result.why));
    return violation;
  }
  fmt::print("{}", reports::embedded_application_text(*result.value, terms.instantiation, host->map.size()));
  const auto report = check_map(host->map);
  reports::print_validity(stdout, host->map, report, o.limit);
  bool consistent = result.value->conflicts.empty();
  for (const Embedding& e : host->embeddings) {
    const auto c = check_embedding(host->map, e, true);
    // A file's embedding the modeler does not declare: the rule cannot
    // give it values, so its new darts are reported but do not fail H.
    const bool foreign = std::none_of(terms.embeddings.begin(), terms.embeddings.end(), [&](const auto& x) { return x.name == e.signature.name; });
    fmt::print("{}", reports::embedding_check_text(e, c, foreign, o.limit));
    if (!foreign || c.consistent()) consistent &= c.consistent();
  }
  if (!o.output.empty() && o.output.ends_with(".jba")) {
    if (!jba) jba = JbaHost{{"dartcheck", Map(rule.rule.model()), {}, {}}, {}};
    if (jba->file.embeddings.empty())
      for (const Embedding& e : host->embeddings)  // a host of another format: every embedding is written
        jba->file.embeddings.push_back({e.signature.name, std::string(name_of(e.signature.type)), e.signature.orbit, {}, {}});
    write_jba_result(o, *jba, *host);
  } else if (!o.output.empty() && is_polygon_mesh_output(o.output)) {
    // The positions: the first point embedding of the rule.
    const Embedding* pos = nullptr;
    for (const Embedding& e : host->embeddings)
      if (!pos && (e.signature.type == ValueType::point3 || e.signature.type == ValueType::point2)) pos = &e;
    if (!pos) throw UsageError(fmt::format("-o: '{}': the map has no point embedding for the positions", o.output));
    std::ostringstream text;  // refused (a vertex without a position) before a file exists
    write_mesh(text, *host, pos->signature.name, o.output);
    write_file(o.output, text.str());
    if (!terminal().quiet) fmt::print("written: {} (positions from {})\n", o.output, pos->signature.name);
  } else if (!o.output.empty()) {
    // The correspondence G -> H of the application itself.
    const Renumbering traced = result.value->topology.renumbering(rule.rule, host->map.size());
    write_file(o.output, result_yaml(host->map, preserved_pairs(traced, g_size), g_size));
    if (!terminal().quiet) fmt::print("written: {} (topology only; the values are printed above)\n", o.output);
  }
  return report.valid() && consistent ? ok : violation;
}

// The preserved darts' correspondence G -> H: said when ids moved (the
// compaction after a deletion), written with --kappa-out.
void write_kappa(const ApplyOptions& o, const Renumbering& c, std::size_t g_size) {
  const std::vector<std::pair<Dart, Dart>> pairs = preserved_pairs(c, g_size);
  std::size_t moved = 0;
  for (const auto& [d, e] : pairs) moved += e != d;
  fmt::print("{}", reports::renumbered_text(moved, pairs.size(), !o.kappa_out.empty()));
  if (o.kappa_out.empty()) return;
  write_file(o.kappa_out, kappa_file_text(pairs, {"The dart correspondence of one application (dartcheck apply --kappa-out):",
                                                  "before dart (host), after dart (result), for every preserved dart."}));
  if (!terminal().quiet) fmt::print("written: {} ({} preserved darts)\n", o.kappa_out, pairs.size());
}

// -o X.jba: the result as a Jerboa G-map, with the embeddings a .jba input
// carried. A topological rule computes no values: preserved and unmatched
// darts keep theirs (through the dart correspondence of the application,
// events/application_trace), new darts have none, and the summary says
// how many are labeled.
int apply_to_jba(const ApplyOptions& o, const CatalogRule& rule, Map map) {
  JbaFile in{"dartcheck", Map(rule.rule.model()), {}, {}};
  if (o.map.ends_with(".jba")) in = read_jba(o.map);
  const Map before = map;
  auto traced = Applier(rule).apply(map, o.hooks);
  if (!traced.ok()) {
    fmt::print("{}", reports::not_applied_text(traced.refusal, traced.why));
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
  reports::print_validity(stdout, map, report, o.limit);
  write_kappa(o, c, before.size());
  std::ostringstream text;  // refused (not an n-G-map) before a file exists
  write_jba(text, out, o.output);
  write_file(o.output, text.str());
  if (!terminal().quiet) fmt::print("written: {}\n", o.output);
  return report.valid() ? ok : violation;
}

// A DPO rule matched from the hooks, or a scheme instantiated on the
// hooks' pattern graph (002 Sec. 6.3): the topology as YAML.
int apply_topology(const ApplyOptions& o, const CatalogRule& rule, Map map) {
  const std::size_t before_size = map.size();
  auto result = Applier(rule).apply(map, o.hooks);
  if (!result.ok()) {
    fmt::print("{}", reports::not_applied_text(result.refusal, result.why));
    return violation;
  }
  const Application& a = *result.value;
  fmt::print("{}", reports::application_text(rule.rule, a, map.size()));
  const auto report = check_map(map);
  reports::print_validity(stdout, map, report, o.limit);
  const Renumbering c = a.renumbering(rule.rule, map.size());
  if (!o.output.empty()) {
    write_file(o.output, result_yaml(map, preserved_pairs(c, before_size), before_size));
    if (!terminal().quiet) fmt::print("written: {}\n", o.output);
  }
  write_kappa(o, c, before_size);
  return report.valid() ? ok : violation;
}

// The rule on the host, as the output asks.
int run_apply(const ApplyOptions& o, const CatalogRule& rule, Map map) {
  const bool jba_out = o.output.ends_with(".jba"), mesh_out = is_polygon_mesh_output(o.output);
  if (rule.terms && !o.kappa_out.empty()) {
    // infer reads G-maps without values: the correspondence of the topology.
    if (jba_out || mesh_out) throw UsageError("--kappa-out: the result is written as YAML (the topology infer reads); use -o X.yaml");
    fmt::print("values: not computed (--kappa-out applies the rule's topology, which infer reads)\n");
    return apply_topology(o, rule, std::move(map));
  }
  if (rule.terms) return apply_terms(o, rule, std::move(map));
  if (jba_out) return apply_to_jba(o, rule, std::move(map));
  if (mesh_out)
    throw UsageError(
        fmt::format("-o: '{}': a mesh needs positions, and rule '{}' computes none: apply an embedded rule with a point embedding, "
                    "or write .yaml",
                    o.output, o.rule));
  return apply_topology(o, rule, std::move(map));
}

}  // namespace

int apply(const ApplyOptions& o) {
  // The writers are YAML, Jerboa .jba and polygon meshes: a result under
  // another extension would be a file that its readers reject.
  if (!o.output.empty() && !o.output.ends_with(".jba") && !is_polygon_mesh_output(o.output) && !o.output.ends_with(".yaml") && !o.output.ends_with(".yml"))
    throw UsageError(
        fmt::format("-o: '{}': dartcheck writes result maps as YAML (.yaml, .yml), Jerboa .jba, or meshes (.off, .obj, .vtu, .vtk, .msh)", o.output));
  check_distinct_outputs({{"-o", o.output}, {"--kappa-out", o.kappa_out}});
  for (const auto* out : {&o.output, &o.kappa_out})
    if (!out->empty()) check_writable(*out);  // before the work, not after it
  const Catalog catalog = read_catalog(o.catalog);
  const CatalogRule* rule = &analysis::require_rule(catalog, o.catalog, o.rule);
  Map map = analysis::resolve_map(o.map, rule->rule.model(), &catalog);
  if (!(map.model() == rule->rule.model()))
    throw UsageError(fmt::format("--map {} is a {} but rule '{}' rewrites {}", o.map, map.model().name, o.rule, rule->rule.model().name));
  check_hooks(*rule, o.hooks, map, o.map);
  fmt::print("rule: {} ({})\nhost: {}\n", o.rule, rule->rule.model().name, analysis::describe_target(o.map, map));
  return run_apply(o, *rule, std::move(map));
}

}  // namespace dartcheck::cli
