// dartcheck: checks modeling operations on G-maps and O-maps.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <yaml-cpp/exceptions.h>

#include "cli/commands.hpp"
#include "cli/suggest.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "core/limits.hpp"
#include "generators/shapes.hpp"

using namespace dartcheck;

int main(int argc, char** argv) {
  CLI::App app{"dartcheck: verifies modeling operations on generalized and oriented maps"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("dartcheck ") + DARTCHECK_VERSION);
  // Counts and seeds: CLI11 would read "-5" into an unsigned option as 2^64 - 5.
  const CLI::Validator counts([](std::string& text) { return text.starts_with('-') ? "expected a number >= 0, got " + text : std::string(); },
                              "NUMBER >= 0");
  // Input limits (core/limits.hpp), for the whole run, before input is read.
  auto& lim = limits();
  app.add_option("--limit-darts", lim.darts, "largest map read or built, in darts")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--limit-term-length", lim.term_length, "longest embedding term, in characters")->capture_default_str()->check(CLI::PositiveNumber);
  // At most 10,000: a 25,000-deep sum overflowed the checker's recursion on an 8 MiB stack.
  app.add_option("--limit-term-depth", lim.term_depth, "deepest nesting of a term (at most 10000)")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  app.add_option("--limit-word-length", lim.word_length, "longest conjugate word, in letters")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--limit-rule-nodes", lim.rule_nodes, "most nodes in one side of a rule")->capture_default_str()->check(CLI::PositiveNumber);

  cli::ValidateOptions validate;
  auto* v = app.add_subcommand("validate-map", "Check a map against its model: cells and every violation");
  v->add_option("map", validate.target, fmt::format("a map file (.yaml, .jba, .off, .obj) or a shape ({})", shape_usage()))->required();
  v->add_option("--model", validate.model, "model for meshes and shapes (2-gmap, 3-gmap, 2-omap, ...)")->capture_default_str();
  v->add_option("--limit", validate.limit, "violations to print (0 = all)")->capture_default_str()->check(counts);

  cli::ApplyOptions apply;
  auto* a = app.add_subcommand("apply", "Apply a DPO rule at hook darts, validate and write the result");
  a->add_option("catalog", apply.catalog, "YAML catalog or Jerboa .jme modeler")->required();
  a->add_option("--rule", apply.rule, "rule name")->required();
  a->add_option("--map", apply.map, "catalog map name, map file, mesh or shape")->required();
  a->add_option("--hook", apply.hooks, "hook dart, one per hook of the rule (repeat)")->required()->check(counts);
  a->add_option("-o,--output", apply.output, "write the result map (YAML) here");
  a->add_option("--limit", apply.limit, "violations to print (0 = all)")->capture_default_str()->check(counts);

  cli::RunOptions run;
  auto* r = app.add_subcommand("run", "Build every catalog map and check every rule example against its expected outcome");
  r->add_option("catalog", run.catalog, "YAML catalog or Jerboa .jme modeler")->required();

  cli::CheckOptions check;
  auto* c = app.add_subcommand("check", "Static consistency conditions of every rule (002 Def. 11-16), against the catalog's verdicts");
  c->add_option("catalog", check.catalog, "YAML catalog or Jerboa .jme modeler")->required();
  c->add_option("--rule", check.rule, "check only this rule");
  c->add_option("--format", check.format, "text, json, sarif (SARIF 2.1.0, for code scanning) or junit (JUnit XML, for CI test reports)")
      ->capture_default_str()
      ->check(CLI::IsMember({"text", "json", "sarif", "junit"}));
  c->add_option("--baseline", check.baseline, "recorded verdicts from a YAML side file (for a .jme modeler, which records none)");
  c->add_option("--write-baseline", check.write_baseline, "write this run's verdicts (and the rules not checked) as a baseline file");
  c->add_flag("--explain", check.explain, "print the witnesses of every failing condition and the counterexample map");
  c->add_option("--confirm-darts", check.confirm_darts,
                "for a failing rule, try every map of its model with up to this many darts beyond L (0: skip)")
      ->capture_default_str()
      ->check(counts);

  cli::EventsOptions events;
  auto* ev = app.add_subcommand("events", "Topological events of every rule (004): creation, deletion, split, merge, modification per orbit type");
  ev->add_option("catalog", events.catalog, "YAML catalog or Jerboa .jme modeler")->required();
  ev->add_option("--rule", events.rule, "only this rule (needed with --map)");
  ev->add_option("--orbit", events.orbits, "orbit type such as \"<0,1>\" (repeat), or all (default)");
  ev->add_option("--map", events.map, "apply the rule to this map (catalog map name, map file, mesh or shape) and print the event log");
  ev->add_option("--hook", events.hooks, "hook dart, one per hook of the rule (repeat)")->check(counts);
  ev->add_flag("--dynamic", events.dynamic, "also label every dart of both maps and set that log against the static one (exit 3 on a contradiction)");
  ev->add_option("--format", events.format, "text or json")->capture_default_str();

  cli::WordsOptions words;
  auto* w = app.add_subcommand("words", "Normal forms of a word in R_{N,E} (002 Sec. 9.2), or whether two words are congruent");
  w->add_option("model", words.model, "model giving N and E (2-gmap, 3-omap, ...)")->required();
  w->add_option("word", words.word, "a word: digits are dimensions, ~d is the conjugate of d, ε the empty word")->required();
  w->add_option("word2", words.other, "a second word: test w <->* w2 instead");
  w->add_option("--prove", words.prove_darts, "with WORD2: ask Z3 for a map of up to this many darts on which the two paths differ")->check(counts);

  cli::FuzzCommand fuzz;
  auto* f =
      app.add_subcommand("fuzz", "Apply every rule at many matches on enumerated, given and random maps; set failures against the static verdict");
  f->add_option("catalog", fuzz.catalog, "YAML catalog or Jerboa .jme modeler")->required();
  f->add_option("--rule", fuzz.rule, "fuzz only this rule");
  f->add_option("--time", fuzz.time, "time budget for the whole catalog (30s, 500ms, 2m), shared equally by the rules");
  f->add_option("--runs", fuzz.runs, "applications per rule (default 10000 without --time)")->check(counts);
  f->add_option("--event-checks", fuzz.event_checks,
                "applications per consistent rule whose event logs are set against its static events (004; 0: none)")
      ->capture_default_str()
      ->check(counts);
  f->add_option("--baseline", fuzz.baseline, "recorded verdicts from a YAML side file (as check --baseline)");
  f->add_option("--seed", fuzz.seed, "random seed (default: drawn and printed)")->check(counts);
  f->add_option("--max-darts", fuzz.max_darts, "largest random host")->capture_default_str()->check(counts);
  f->add_option("--maps", fuzz.maps, "more hosts: map files (.yaml, Jerboa .jba), meshes (.off, .obj) or shapes (cube, grid:3x4, ...)");
  // -o/--output as every other command; --out, the old spelling, stays.
  f->add_option("-o,--output,--out", fuzz.out, "directory: write each counterexample here (host, match, result and a replay command)");
  f->add_option("--format", fuzz.format, "text, json, or jsonl (a JSON line per rule as it finishes, then a summary line)")
      ->capture_default_str()
      ->check(CLI::IsMember({"text", "json", "jsonl"}));

  cli::ProveCommand prove;
  auto* p =
      app.add_subcommand("prove", "Ask Z3 for a host whose derived map breaks a constraint (bounded), and set the answer against the static verdict");
  p->add_option("catalog", prove.catalog, "YAML catalog or Jerboa .jme modeler")->required();
  p->add_option("--rule", prove.rule, "prove only this rule");
  p->add_option("--baseline", prove.baseline, "recorded verdicts from a YAML side file (as check --baseline)");
  p->add_option("--max-darts", prove.max_darts, "search hosts of up to this many darts")->capture_default_str()->check(counts);
  p->add_option("--scheme-darts", prove.scheme_darts,
                "for rule schemes, hosts of up to this many darts (at most --max-darts): H has that many darts per node of R")
      ->capture_default_str()
      ->check(counts);
  p->add_option("--rlimit", prove.rlimit, "Z3 resource limit per query (deterministic)")->capture_default_str()->check(counts);
  p->add_option("--timeout", prove.timeout, "also stop a query after this many seconds (answers then depend on the machine)")->check(counts);
  p->add_option("-o,--output,--out", prove.out, "directory: write each counterexample on a map of the model here, with a replay command");
  p->add_option("--format", prove.format, "text or json")->capture_default_str();
  p->add_flag("--explain", prove.explain, "print the hosts and derived graphs of theorem-class counterexamples");

  cli::DrawOptions draw;
  auto* dr = app.add_subcommand("draw", "Draw a rule or scheme: L and R side by side, witnesses of failed conditions highlighted");
  dr->add_option("catalog", draw.catalog, "YAML catalog or Jerboa .jme modeler")->required();
  dr->add_option("--rule", draw.rule, "the rule to draw")->required();
  dr->add_option("-o,--output", draw.output, "picture file: .svg, .png, .pdf, or .dot/.gv for the DOT text")->required();
  dr->add_option("--engine", draw.engine, "Graphviz layout engine")->capture_default_str();
  cli::ConvertOptions convert;
  auto* cv = app.add_subcommand("convert", "Write a catalog (a Jerboa .jme modeler, or YAML) as a YAML catalog that checks identically");
  cv->add_option("input", convert.input, ".jme modeler or YAML catalog")->required();
  cv->add_option("-o,--output", convert.output, "the YAML catalog to write")->required();
  cli::InferCommand infer;
  auto* inf = app.add_subcommand("infer", "Infer the rule scheme of one before/after example by folding (000), check it and apply it back");
  inf->add_option("--before", infer.before, "the map before: catalog map name (with --catalog), map file (.yaml, .jba, .off, .obj) or shape")
      ->required();
  inf->add_option("--after", infer.after, "the map after, same forms")->required();
  inf->add_option("--orbit", infer.orbit, "the rule's parameter orbit type, e.g. \"<0,1,2>\"")->required();
  inf->add_option("--kappa", infer.kappa, "preserved darts: identity (same dart ids) or a YAML file of pairs and orbit associations")
      ->capture_default_str();
  inf->add_option("--catalog", infer.catalog, "catalog whose maps --before and --after may name");
  inf->add_option("--model", infer.model, "model for meshes and shapes")->capture_default_str();
  inf->add_option("--start", infer.start, "fold from this dart of the before map only")->check(counts);
  inf->add_flag("--all", infer.all, "try every start dart (one per hook orbit) and list every distinct rule");
  inf->add_flag("--strict", infer.strict, "the paper's algorithm exactly: one relabeling candidate per position, no retry");
  inf->add_option("--undecided", infer.undecided,
                  "positions whose links are all loops in the hook orbit: keep (relabel, warn), free (explicit loops) or fail")
      ->capture_default_str();
  inf->add_option("--name", infer.name, "name of the inferred rule")->capture_default_str();
  inf->add_option("-o,--output", infer.output, "write the rules: .yaml catalog (maps, rules, examples that `run` re-checks) or Jerboa .jme");
  inf->add_option("--format", infer.format, "text or json")->capture_default_str();

  cli::RecombineOptions recombine;
  auto* rc = app.add_subcommand("recombine", "Recombine a tetrahedral mesh into hexahedra by query-modify (001 Sec. 7.1) and check the result");
  rc->add_option("mesh", recombine.mesh, "tetrahedral mesh: TetGen .node/.ele or medit .mesh")->required();
  rc->add_option("--strategy", recombine.strategy, "greedy (first match from each dart) or global (best scaled Jacobian first)")
      ->capture_default_str();
  rc->add_option("--min-quality", recombine.min_quality, "smallest scaled Jacobian a hex must exceed (-1 keeps inverted ones)")
      ->capture_default_str()
      ->check(CLI::Range(-1.0, 1.0));
  rc->add_option("-o,--output", recombine.output, "write the hexes and the remaining tetrahedra as a medit .mesh");
  rc->add_option("--format", recombine.format, "text or json")->capture_default_str();

  cli::QueryOptions query;
  auto* qy = app.add_subcommand("query", "Find query maps in a map by query words (001 Sec. 5): every match, or a selection without overlap");
  qy->add_option("map", query.map, "the map: map file (.yaml, .jba, .off, .obj), tetrahedral mesh (.node, .ele, .mesh), catalog map name or shape")
      ->required();
  qy->add_option("--query", query.queries, "a query map, same forms (repeat); connected");
  qy->add_flag("--hex", query.hex, "add the 322 hex patterns of the tet -> hex recombination (open 3-O-maps)");
  qy->add_option("--start", query.start, "the query dart labeled 1")->capture_default_str()->check(counts);
  qy->add_option("--free", query.free, "condition on the queries' free links: any (*), boundary (ε), interior (ε̄) or no-link (↔)")
      ->capture_default_str();
  qy->add_option("--strategy", query.strategy, "all (every distinct match), greedy or global (largest first), without overlap")
      ->capture_default_str();
  qy->add_option("--catalog", query.catalog, "catalog whose maps the map and queries may name");
  qy->add_option("--model", query.model, "model for meshes and shapes")->capture_default_str();
  qy->add_option("--limit", query.limit, "matches printed")->capture_default_str()->check(counts);
  qy->add_option("--format", query.format, "text or json")->capture_default_str();

  cli::ReportOptions report;
  auto* rp = app.add_subcommand("report", "Write an HTML report of a catalog: verdict table, every rule drawn, every failure pointed at");
  rp->add_option("catalog", report.catalog, "YAML catalog or Jerboa .jme modeler")->required();
  rp->add_option("-o,--output", report.output, "directory for index.html and the SVG pictures")->required();
  rp->add_option("--rule", report.rule, "only this rule");
  rp->add_option("--baseline", report.baseline, "recorded verdicts from a YAML side file (as check --baseline)");
  rp->add_option("--fuzz", report.fuzz, "fuzz every rule within this total time (30s, 2m, ...) and draw the counterexamples");
  rp->add_option("--prove", report.prove_darts, "ask Z3 for counterexamples of up to K darts and draw them")->check(counts);
  rp->add_option("--seed", report.seed, "random seed of --fuzz (default: drawn and printed)")->check(counts);
  rp->add_option("--engine", report.engine, "Graphviz layout engine")->capture_default_str();
  cli::DrawMapOptions draw_map;
  auto* dm = app.add_subcommand("draw-map", "Draw a map: one node per dart, links colored by dimension, invalid darts highlighted");
  dm->add_option("map", draw_map.target, fmt::format("a map file (.yaml, .jba, .off, .obj) or a shape ({})", shape_usage()))->required();
  dm->add_option("-o,--output", draw_map.output, "picture file: .svg, .png, .pdf, or .dot/.gv for the DOT text")->required();
  dm->add_option("--model", draw_map.model, "model for meshes and shapes")->capture_default_str();
  dm->add_option("--engine", draw_map.engine, "Graphviz layout engine (neato or sfdp for large maps)")->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    if (code != 0) cli::suggest_subcommand(app, argc, argv);
    return code == 0 ? 0 : cli::bad_input;
  }
  try {
    if (*v) return cli::validate_map(validate);
    if (*a) return cli::apply(apply);
    if (*r) return cli::run(run);
    if (*w) return cli::words(words);
    if (*ev) return cli::events_command(events);
    if (*inf) return cli::infer(infer);
    if (*rc) return cli::recombine(recombine);
    if (*qy) return cli::query(query);
    if (*c) return cli::check(check);
    if (*f) return cli::fuzz(fuzz);
    if (*p) return cli::prove(prove);
    if (*dr) return cli::draw(draw);
    if (*dm) return cli::draw_map(draw_map);
    if (*rp) return cli::report(report);
    if (*cv) return cli::convert(convert);
  } catch (const InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return cli::bad_input;
  } catch (const OutputError& e) {
    fmt::print(stderr, "error: {}\n", printable(e.what()));
    return cli::output_error;
  } catch (const YAML::Exception& e) {
    // Readers turn YAML errors into positioned InputErrors; this is a last resort.
    fmt::print(stderr, "error: YAML at line {}, column {}: {}\n", e.mark.line + 1, e.mark.column + 1, printable(e.msg));
    return cli::bad_input;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "error: out of memory (the input is larger than this machine can hold; see --limit-darts)\n");
    return cli::bad_input;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", printable(e.what()));
    return cli::bad_input;
  }
  return cli::bad_input;
}
