// dartcheck infer: one before/after example -> the Jerboa-style rule scheme
// that performs it (000), checked by the static checker (Sec. 8.2) and
// applied back to the example (App. A).
#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>

#include "core/error.hpp"
#include "analysis/map_sources.hpp"
#include "cli/commands.hpp"
#include "core/terminal.hpp"
#include "core/wording.hpp"
#include "io/jerboa_jba.hpp"
#include "cli/options.hpp"
#include "reports/infer_report.hpp"
#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "io/jerboa_modeler_writer.hpp"
#include "inference/example_files.hpp"
#include "core/output_file.hpp"
#include "io/catalog.hpp"

namespace dartcheck::cli {

using namespace inference;

namespace {

InputError command_line(const std::string& what) { return UsageError(what); }

// The library's options from the command's, with the combinations that
// make no sense refused as usage errors.
InferOptions infer_options(const InferCommand& o) {
  InferOptions options;
  options.fold.undecided = parse_undecided(o.undecided);
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

}  // namespace

int infer(const InferCommand& o) {
  const InferOptions options = infer_options(o);
  if (!o.output.empty()) {
    const auto ext = std::filesystem::path(o.output).extension().string();
    if (ext != ".yaml" && ext != ".yml" && ext != ".jme") throw command_line(fmt::format("-o: expected a .yaml or .jme file, got '{}'", o.output));
    if (const auto problem = xml_name_problem(o.name); problem && ext == ".jme")
      throw command_line(fmt::format("--name '{}' cannot be written in a .jme (XML 1.0): it holds {}", printable(o.name), *problem));
    check_writable(o.output);  // before the work, not after it
  }
  const Model model = command_model(o.model);
  const std::optional<Catalog> catalog = optional_catalog(o.catalog);
  Map before = analysis::resolve_map(o.before, model, catalog ? &*catalog : nullptr);
  Map after = analysis::resolve_map(o.after, model, catalog ? &*catalog : nullptr);
  std::vector<Dim> orbit;
  try {
    orbit = parse_inference_orbit(o.orbit, before.model());
  } catch (const ValueError& e) {
    throw command_line(fmt::format("--orbit: {}", e.what()));
  }
  // A folding of an invalid example "verifies" a rule whose catalog then fails `run`.
  require_valid_map(before, "--before " + o.before, "inference needs two maps of the model");
  require_valid_map(after, "--after " + o.after, "inference needs two maps of the model");
  const auto [spec, kappa_text] = example_kappa(o.kappa, o.before, o.after, before, after);
  const std::size_t g_size = before.size(), h_size = after.size();
  std::optional<KappaGraph> graph;
  try {
    graph.emplace(make_kappa_graph(std::move(before), std::move(after), spec));
  } catch (const ValueError& e) {
    throw InputError(o.kappa == "identity" ? "<command line>" : o.kappa, 0, 0, e.what());
  }
  std::vector<Attempt> attempts;
  try {
    attempts = infer(*graph, orbit, options);
  } catch (const ValueError& e) {
    throw command_line(fmt::format("--start: {}", e.what()));
  }
  const reports::InferRun run{o.before,           o.after,   orbit_type_str(OrbitType(orbit.begin(), orbit.end())), g_size, h_size,
                              graph->preserved(), kappa_text};
  const bool quiet = terminal().quiet;  // -q: the text report is a summary
  if (o.format == "json")
    fmt::print("{}\n", reports::infer_json(run, *graph, attempts));
  else if (!quiet)
    fmt::print("{}", reports::infer_text(run, attempts));
  // A Jerboa example's values: 000 infers the topology and leaves the
  // embedding computations aside ("the inferred rule scheme will have no
  // embedding computation"; its examples add them by hand), so say so.
  if (o.format != "json" && !quiet && o.after.ends_with(".jba")) {
    std::vector<std::string> names;
    for (const auto& e : read_jba(o.after).embeddings) names.push_back(fmt::format("{} <{}>", e.name, fmt::join(e.orbit, ",")));
    if (!names.empty())
      fmt::print("values of {} ({}): not inferred (000 infers the topology only; write each new orbit's value as an <expr> of the rule, "
                 "docs/jerboa-expressions.md)\n",
                 o.after, fmt::join(names, ", "));
  }
  const auto inferred = std::count_if(attempts.begin(), attempts.end(), [](const Attempt& a) { return a.inferred(); });
  const bool contradiction = std::any_of(attempts.begin(), attempts.end(), [](const Attempt& a) { return a.verification && !a.verification->holds; });
  // Nothing is written when nothing was inferred: an empty catalog is not a result.
  if (!o.output.empty() && inferred > 0) {
    write_inferred(o.output, o.name, *graph, attempts, {o.before, o.after, o.orbit});
    if (!terminal().quiet) fmt::print(o.format == "json" ? stderr : stdout, "written: {} ({} rule{})\n", o.output, inferred, inferred == 1 ? "" : "s");
  } else if (!o.output.empty()) {
    fmt::print(stderr, "not written: {} (no rule inferred)\n", o.output);
  }
  if (quiet && o.format != "json") {  // what makes the exit status non-zero
    if (contradiction) fmt::print(stderr, "dartcheck: error: SOUNDNESS BUG: an inferred rule does not give the example back (run without -q for the details)\n");
    if (inferred == 0)
      fmt::print(stderr, "dartcheck: error: no rule inferred from {} (run without -q for each start's failure)\n", counted(attempts.size(), "start"));
  }
  if (contradiction) return 3;
  return inferred ? 0 : 1;
}

}  // namespace dartcheck::cli
