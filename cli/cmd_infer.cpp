// dartcheck infer: one before/after example -> the Jerboa-style rule scheme
// that performs it (000), checked by the static checker (Sec. 8.2) and
// applied back to the example (App. A).
#include <algorithm>
#include <sstream>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>

#include "analysis/map_sources.hpp"
#include "cli/commands.hpp"
#include "reports/validity_text.hpp"
#include "reports/infer_report.hpp"
#include "checkers/map_validity.hpp"
#include "io/jerboa_jba.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "inference/infer.hpp"
#include "io/kappa_file.hpp"
#include "io/catalog.hpp"
#include "io/catalog_writer.hpp"
#include "io/jerboa_modeler_writer.hpp"

namespace dartcheck::cli {

using namespace inference;

namespace {

InputError command_line(const std::string& what) { return InputError("<command line>", 0, 0, what); }

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

// κ from --kappa. "identity" pairs dart ids: for two Jerboa .jba
// snapshots the files' own ids (Jerboa keeps them across an operation);
// for dartcheck's dense maps, indices, which only correspond when no dart
// was deleted (apply compacts ids then: its --kappa-out writes the pairs).
std::pair<KappaSpec, std::string> kappa_spec(const InferCommand& o, const Map& before, const Map& after) {
  if (o.kappa != "identity") return {read_kappa_file(o.kappa, before.model()), o.kappa};
  KappaSpec spec;
  if (o.before.ends_with(".jba") && o.after.ends_with(".jba")) {
    const auto g = read_jba(o.before).ids, h = read_jba(o.after).ids;
    std::unordered_map<std::string, Dart> index;
    for (Dart d = 0; d < h.size(); ++d) index.emplace(h[d], d);
    for (Dart d = 0; d < g.size(); ++d)
      if (const auto it = index.find(g[d]); it != index.end()) spec.pairs.emplace_back(d, it->second);
    return {spec, "identity by the .jba files' dart ids"};
  }
  if (after.size() < before.size())
    throw command_line(fmt::format(
        "--kappa identity: the after map has fewer darts ({}) than the before map ({}), so the operation deleted darts, and dartcheck's maps "
        "number darts densely: ids moved, and identity would pair the wrong darts. Write the correspondence with `dartcheck apply ... "
        "--kappa-out KAPPA.yaml` and pass --kappa KAPPA.yaml (or give Jerboa .jba snapshots, whose ids are kept)",
        after.size(), before.size()));
  spec.identity = true;
  return {spec, "identity: same dart index"};
}

// The library's options from the command's, with the combinations that
// make no sense refused as usage errors.
InferOptions infer_options(const InferCommand& o) {
  InferOptions options;
  if (o.undecided == "keep")
    options.fold.undecided = UndecidedPolicy::keep;
  else if (o.undecided == "free")
    options.fold.undecided = UndecidedPolicy::free;
  else if (o.undecided == "fail")
    options.fold.undecided = UndecidedPolicy::fail;
  else
    throw command_line(fmt::format("--undecided: expected keep, free or fail, got '{}'", o.undecided));
  if (o.strict && options.fold.undecided != UndecidedPolicy::keep)
    throw command_line("--strict is the paper's algorithm, which relabels undecided positions: it takes no --undecided");
  if (o.start && o.all) throw command_line("--start and --all exclude each other");
  options.fold.strict = o.strict;
  options.start = o.start;
  options.all = o.all;
  options.keep_rejected = !o.all;  // --all on a large example: only rules are kept in full
  options.name = o.name;
  options.generalize = o.generalize;
  return options;
}

// Both maps must be maps of the model: a folding of an invalid example
// "verifies" a rule whose catalog then fails `run`.
void require_valid(const std::string& what, const Map& map) {
  const auto report = check_map(map);
  if (report.valid()) return;
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < report.violations.size() && k < 5; ++k)
    lines.push_back(describe(report.violations[k], fmt::format("dart {}", report.violations[k].element)));
  throw InputError(
      what, 0, 0,
      fmt::format("not a valid {} ({} violation{}: {}{}): inference needs two maps of the model", map.model().name, report.violations.size(),
                  report.violations.size() == 1 ? "" : "s", fmt::join(lines, "; "), report.violations.size() > 5 ? "; ..." : ""));
}

}  // namespace

int infer(const InferCommand& o) {
  if (o.format != "text" && o.format != "json") throw command_line(fmt::format("--format: expected text or json, got '{}'", o.format));
  const InferOptions options = infer_options(o);
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
  require_valid(o.before, before);
  require_valid(o.after, after);
  const auto [spec, kappa_text] = kappa_spec(o, before, after);
  const std::size_t g_size = before.size(), h_size = after.size();
  std::optional<KappaGraph> graph;
  try {
    graph.emplace(make_kappa_graph(std::move(before), std::move(after), spec));
  } catch (const std::invalid_argument& e) {
    throw InputError(o.kappa == "identity" ? "<command line>" : o.kappa, 0, 0, e.what());
  }
  std::vector<Attempt> attempts;
  try {
    attempts = infer(*graph, orbit, options);
  } catch (const std::invalid_argument& e) {
    throw command_line(fmt::format("--start: {}", e.what()));
  }
  const reports::InferRun run{o.before,           o.after,   orbit_type_str(OrbitType(orbit.begin(), orbit.end())), g_size, h_size,
                              graph->preserved(), kappa_text};
  if (o.format == "json")
    fmt::print("{}\n", reports::json_text(reports::infer_document(run, *graph, attempts)));
  else
    fmt::print("{}", reports::infer_text(run, attempts));
  const auto inferred = std::count_if(attempts.begin(), attempts.end(), [](const Attempt& a) { return a.inferred(); });
  const bool contradiction = std::any_of(attempts.begin(), attempts.end(), [](const Attempt& a) { return a.verification && !a.verification->holds; });
  // Nothing is written when nothing was inferred: an empty catalog is not a result.
  if (!o.output.empty() && inferred > 0) {
    write_output(o, *graph, attempts);
    fmt::print(o.format == "json" ? stderr : stdout, "written: {} ({} rule{})\n", o.output, inferred, inferred == 1 ? "" : "s");
  } else if (!o.output.empty()) {
    fmt::print(stderr, "not written: {} (no rule inferred)\n", o.output);
  }
  if (contradiction) return 3;
  return inferred ? 0 : 1;
}

}  // namespace dartcheck::cli
