// dartcheck infer: one before/after example -> the Jerboa-style rule scheme
// that performs it (000), checked by the static checker (Sec. 8.2) and
// applied back to the example (App. A).
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>

#include "analysis/map_sources.hpp"
#include "cli/commands.hpp"
#include "cli/report_text.hpp"
#include "reports/json_document.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "inference/infer.hpp"
#include "inference/kappa_file.hpp"
#include "io/catalog.hpp"
#include "io/catalog_writer.hpp"
#include "io/jerboa_modeler_writer.hpp"

namespace dartcheck::cli {

using namespace inference;

namespace {

InputError command_line(const std::string& what) { return InputError("<command line>", 0, 0, what); }

std::string outcome(const Attempt& a) {
  if (a.failure) return fmt::format("{}: {}", failure_name(a.failure->kind), a.failure->text);
  if (!a.not_a_rule.empty()) return a.not_a_rule;
  if (!a.ill_formed.empty()) return fmt::format("ill-formed, discarded (Sec. 8.2): {} fail", fmt::join(a.ill_formed, ", "));
  if (a.duplicate_of >= 0) return "the same scheme as an earlier start";
  if (a.verification && !a.verification->holds) return fmt::format("VERIFICATION FAILED (App. A): {}", a.verification->why);
  return "inferred, well-formed, verified on the example (App. A)";
}

std::string side_text(const TopoGraph& g, const std::vector<ConjWord>& words, const std::vector<OrbitType>& labels) {
  std::vector<std::string> nodes, arcs;
  for (NodeId v = 0; v < g.node_count(); ++v) nodes.push_back(fmt::format("{} {}", g.name(v), orbit_type_str(labels[v])));
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    const auto& a = g.arc(e);
    if (!arc_word(words, e).empty() || a.source > a.target) continue;
    arcs.push_back(fmt::format("{} -{}- {}", g.name(a.source), a.label, g.name(a.target)));
  }
  return fmt::format("{}{}", fmt::join(nodes, ", "), arcs.empty() ? "" : fmt::format("; arcs {}", fmt::join(arcs, ", ")));
}

std::string undecided_text(const GraphScheme& s, const InferredRule* rule) {
  std::vector<std::string> out;
  for (const auto& u : s.undecided)
    out.push_back(fmt::format("{}{} position {} (dimension {}) -> {}", rule ? "" : "folding node ",
                              rule ? rule->names[static_cast<std::size_t>(u.node)] : fmt::format("n{}", u.node), u.position, s.orbit[u.position],
                              u.chosen ? std::to_string(*u.chosen) : std::string("_ with explicit loops")));
  return fmt::format("{}", fmt::join(out, "; "));
}

void write_output(const InferCommand& o, const KappaGraph& graph, const std::vector<Attempt>& attempts) {
  std::vector<const Attempt*> found;
  for (const auto& a : attempts)
    if (a.inferred()) found.push_back(&a);
  const auto ext = std::filesystem::path(o.output).extension().string();
  if (ext == ".jme") {
    std::vector<const Operation*> ops;
    for (const auto* a : found) ops.push_back(&a->rule->operation);
    std::ostringstream out;
    write_jme(out, o.name, graph.model().dimension(), ops);
    write_file(o.output, out.str());
    return;
  }
  Catalog c;
  c.file = o.output;
  c.maps.push_back({"before", graph.model(), graph.before(), {}, {}, {}});
  c.maps.push_back({"after", graph.model(), graph.after(), {}, {}, {}});
  for (const auto* a : found) {
    CatalogRule r{
        a->rule->operation,
        fmt::format("inferred by dartcheck infer from dart {} of {} on {}", a->start, o.before, orbit_type_str(a->rule->operation.jerboa->parameter)),
        {},
        {},
        std::vector<std::string>{},
        {}};
    Example e;
    e.map = "before";
    e.hooks = {a->start};
    e.expect = "valid";
    e.isomorphic_to = "after";
    r.examples.push_back(e);
    c.rules.push_back(std::move(r));
  }
  write_file(o.output, catalog_yaml(c, fmt::format("inferred by dartcheck infer: before {}, after {}, orbit {}", o.before, o.after, o.orbit)));
}

}  // namespace

int infer(const InferCommand& o) {
  if (o.format != "text" && o.format != "json") throw command_line(fmt::format("--format: expected text or json, got '{}'", o.format));
  UndecidedPolicy policy;
  if (o.undecided == "keep")
    policy = UndecidedPolicy::keep;
  else if (o.undecided == "free")
    policy = UndecidedPolicy::free;
  else if (o.undecided == "fail")
    policy = UndecidedPolicy::fail;
  else
    throw command_line(fmt::format("--undecided: expected keep, free or fail, got '{}'", o.undecided));
  if (o.strict && policy != UndecidedPolicy::keep)
    throw command_line("--strict is the paper's algorithm, which relabels undecided positions: it takes no --undecided");
  if (o.start && o.all) throw command_line("--start and --all exclude each other");
  if (!o.output.empty()) {
    const auto ext = std::filesystem::path(o.output).extension().string();
    if (ext != ".yaml" && ext != ".yml" && ext != ".jme") throw command_line(fmt::format("-o: expected a .yaml or .jme file, got '{}'", o.output));
    check_writable(o.output);  // before the work, not after it
  }
  const auto model = Model::by_name(o.model);
  if (!model) throw command_line(fmt::format("--model: unknown model '{}' (expected {})", o.model, Model::known_names()));
  std::optional<Catalog> catalog;
  if (!o.catalog.empty()) catalog = read_catalog(o.catalog);
  Map before = analysis::resolve_map(o.before, *model, catalog ? &*catalog : nullptr);
  Map after = analysis::resolve_map(o.after, *model, catalog ? &*catalog : nullptr);
  std::vector<Dim> orbit;
  try {
    orbit = parse_inference_orbit(o.orbit, before.model());
  } catch (const std::invalid_argument& e) {
    throw command_line(fmt::format("--orbit: {}", e.what()));
  }
  KappaSpec spec;
  if (o.kappa == "identity")
    spec.identity = true;
  else
    spec = read_kappa_file(o.kappa, before.model());
  const std::size_t g_size = before.size(), h_size = after.size();
  std::optional<KappaGraph> graph;
  try {
    graph.emplace(make_kappa_graph(std::move(before), std::move(after), spec));
  } catch (const std::invalid_argument& e) {
    throw InputError(o.kappa == "identity" ? "<command line>" : o.kappa, 0, 0, e.what());
  }
  InferOptions options;
  options.fold = {o.strict, policy};
  options.start = o.start;
  options.all = o.all;
  options.name = o.name;
  std::vector<Attempt> attempts;
  try {
    attempts = infer(*graph, orbit, options);
  } catch (const std::invalid_argument& e) {
    throw command_line(fmt::format("--start: {}", e.what()));
  }
  int inferred = 0, contradictions = 0;
  for (const auto& a : attempts) {
    inferred += a.inferred();
    contradictions += a.verification && !a.verification->holds;
  }
  if (o.format == "json") {
    using reports::Json;
    Json rows = Json::array();
    for (const auto& a : attempts) {
      Json row{{"start", a.start}, {"outcome", outcome(a)}, {"inferred", a.inferred()}, {"seconds", a.seconds}};
      if (a.failure)
        row["failure"] = Json{{"kind", failure_name(a.failure->kind)},
                              {"node", fmt::format("n{}", a.failure->node)},
                              {"dimension", a.failure->dim == kappa_arc ? std::string("kappa") : std::to_string(a.failure->dim)},
                              {"dart", graph->name(a.failure->dart)}};
      if (a.rule) {
        const auto& op = a.rule->operation;
        row["left_nodes"] = op.rule.left().node_count();
        row["right_nodes"] = op.rule.right().node_count();
        row["preserved"] = a.rule->preserved;
        row["left"] = side_text(op.rule.left(), op.words.left, op.jerboa->left);
        row["right"] = side_text(op.rule.right(), op.words.right, op.jerboa->right);
      }
      if (a.scheme && !a.scheme->undecided.empty()) row["undecided"] = undecided_text(*a.scheme, a.rule ? &*a.rule : nullptr);
      rows.push_back(std::move(row));
    }
    Json doc = reports::json_document("infer");
    doc["orbit"] = o.orbit;
    doc["before_darts"] = g_size;
    doc["after_darts"] = h_size;
    doc["preserved_darts"] = graph->preserved();
    doc["inferred"] = inferred;
    doc["attempts"] = std::move(rows);
    fmt::print("{}\n", reports::json_text(std::move(doc)));
  } else {
    fmt::print("infer {} from {} ({} darts) to {} ({} darts), {} preserved darts\n", orbit_type_str(OrbitType(orbit.begin(), orbit.end())), o.before,
               g_size, o.after, h_size, graph->preserved());
    for (const auto& a : attempts) {
      fmt::print("  start {}: {} ({:.3f} ms)\n", a.start, outcome(a), a.seconds * 1e3);
      if (!a.inferred()) continue;
      const auto& op = a.rule->operation;
      fmt::print("    rule {}: |L| = {}, |R| = {}, {} preserved\n", op.rule.name(), op.rule.left().node_count(), op.rule.right().node_count(),
                 a.rule->preserved);
      fmt::print("    L: {}\n    R: {}\n", side_text(op.rule.left(), op.words.left, op.jerboa->left),
                 side_text(op.rule.right(), op.words.right, op.jerboa->right));
      if (!a.scheme->undecided.empty())
        fmt::print("    warning: positions the example does not decide (every link of that dimension in the hook orbit is a loop): {}\n",
                   undecided_text(*a.scheme, &*a.rule));
    }
    fmt::print("{} rule(s) inferred from {} start(s)\n", inferred, attempts.size());
  }
  if (!o.output.empty()) write_output(o, *graph, attempts);
  if (contradictions) return 3;
  return inferred ? 0 : 1;
}

}  // namespace dartcheck::cli
