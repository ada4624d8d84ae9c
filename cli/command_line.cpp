// The command line of dartcheck: every command's options (CLI11, included
// here only), their parsing, and the one place where errors become exit
// statuses. In the library, not in main.cpp, so that this long compilation
// runs beside the commands' and main.cpp, rebuilt at every revision, is small.
#include "cli/command_line.hpp"

#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "analysis/interrupt.hpp"
#include "cli/commands.hpp"
#include "campaign/jobs.hpp"
#include "cli/number_options.hpp"
#include "cli/suggest.hpp"
#include "reports/versions.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "core/limits.hpp"
#include "core/terminal.hpp"
#include "generators/shapes.hpp"

namespace dartcheck::cli {

namespace {

// A subcommand and what runs it: its options live as long as the function.
using Commands = std::vector<std::pair<CLI::App*, std::function<int()>>>;

// Counts, darts and seeds (cli/number_options.hpp): CLI11 alone would read
// "-5" into an unsigned option as 2^64 - 5 and "010" as 8.
CLI::Validator validator(NumberCheck c) { return CLI::Validator(std::move(c.check), std::move(c.name)); }
CLI::Validator count_option(std::uint64_t low = 0, std::uint64_t high = std::numeric_limits<std::uint64_t>::max()) {
  return validator(cli::count_option(low, high));
}
CLI::Validator real_option(double low, double high) { return validator(cli::real_option(low, high)); }
CLI::Validator counts() { return count_option(); }
CLI::Validator darts() { return count_option(0, no_dart - 1); }
// Bounds past which a search only runs out of time: as prove's --max-darts.
CLI::Validator host_darts() { return count_option(0, 256); }

// --format, one of `choices` (CLI11 names them on a mistake).
void add_format(CLI::App* command, std::string& format, const std::vector<std::string>& choices, const std::string& help) {
  command->add_option("--format", format, help)->capture_default_str()->check(CLI::IsMember(choices));
}

// Hidden (no group): the bash completion's source of rule and map names.
void add_complete(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<CompleteOptions>();
  auto* c = app.add_subcommand("__complete", "words for the bash completion")->group("");
  c->add_option("what", o->what, "rules, maps, models or cells")->required();
  c->add_option("catalog", o->catalog, "the catalog the command line names");
  commands.push_back({c, [o] { return complete(*o); }});
}

void add_validate(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<ValidateOptions>();
  auto* v = app.add_subcommand("validate-map", "Check a map against its model: cells and every violation");
  v->add_option("map", o->target, fmt::format("a map file (.yaml, .jba, .off, .obj) or a shape ({})", shape_usage()))->required();
  v->add_option("--model", o->model, "model for meshes and shapes (2-gmap, 3-gmap, 2-omap, ...)")->capture_default_str();
  v->add_option("--limit", o->limit, "violations to print (0 = all)")->capture_default_str()->transform(counts());
  add_format(v, o->format, {"text", "json"}, "text, or json (docs/schema/validate-map.schema.json)");
  commands.push_back({v, [o] { return validate_map(*o); }});
}

void add_apply(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<ApplyOptions>();
  auto* a = app.add_subcommand("apply", "Apply a rule or rule scheme at hook darts, validate and write the result");
  a->add_option("catalog", o->catalog, "YAML catalog or Jerboa .jme modeler")->required();
  a->add_option("--rule", o->rule, "rule name")->required();
  a->add_option("--map", o->map, "catalog map name, map file, mesh or shape")->required();
  a->add_option("--hook", o->hooks, "hook dart, one per hook of the rule (repeat)")->transform(darts());
  a->add_option("-o,--output", o->output,
                "write the result map here, in the format its extension names: .yaml, .jba (n-G-maps; embeddings carried from a .jba "
                "input), .off, .obj, .vtu, .vtk or .msh (an embedded rule on a mesh with positions)");
  a->add_option(
      "--kappa-out", o->kappa_out,
      "write the dart correspondence G -> H of the preserved darts here (the κ file `infer --kappa` reads; ids move when darts are deleted)");
  a->add_option("--limit", o->limit, "violations to print (0 = all)")->capture_default_str()->transform(counts());
  commands.push_back({a, [o] { return apply(*o); }});
}

void add_run(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<RunOptions>();
  auto* r = app.add_subcommand("run", "Build every catalog map and check every rule example against its expected outcome");
  r->add_option("catalog", o->catalog, "YAML catalog or Jerboa .jme modeler")->required();
  commands.push_back({r, [o] { return run(*o); }});
}

// --shard K/N, as check, fuzz, prove, report and events take it.
void add_shard(CLI::App* command, std::string& shard) {
  command->add_option("--shard", shard,
                      "run only shard K of N (0 <= K < N): the rules whose name hashes to K; merge the shards' --format jsonl with `merge`");
}

// --shard and --jobs (check, fuzz, prove and report).
void add_campaign(CLI::App* command, std::string& shard, std::size_t& jobs) {
  add_shard(command, shard);
  command->add_option("--jobs", jobs, "run as this many shard processes at once and merge them (the output of one job)")
      ->capture_default_str()
      ->transform(count_option(1, 256));
}

// --shard-budget S: the seconds --jobs gives one shard of a timed run
// (campaign/jobs.hpp); hidden, as only run_jobs passes it.
void add_shard_budget(CLI::App* command, std::optional<double>& seconds) {
  command->add_option("--shard-budget", seconds, "seconds of the time budget for this shard (set by --jobs)")->group("");
}

void add_check(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<CheckOptions>();
  auto* c = app.add_subcommand("check", "Static consistency conditions of every rule (002 Def. 11-16), against the catalog's verdicts");
  c->add_option("catalog", o->catalog, "YAML catalog or Jerboa .jme modeler")->required();
  c->add_option("--rule", o->rule, "check only this rule");
  add_format(c, o->format, {"text", "json", "sarif", "junit", "jsonl"},
             "text, json, sarif (SARIF 2.1.0, for code scanning), junit (JUnit XML, for CI test reports) or jsonl (a shard's lines, for merge)");
  add_campaign(c, o->shard, o->jobs);
  c->add_option("--baseline", o->baseline, "recorded verdicts from a YAML side file (for a .jme modeler, which records none)");
  c->add_option("--write-baseline", o->write_baseline, "write this run's verdicts (and the rules not checked) as a baseline file");
  c->add_flag("--explain", o->explain, "print the witnesses of every failing condition and the counterexample map");
  c->add_flag("--solver", o->solver,
              "ask Z3 about each embedding of a rule with terms (hosts up to |L| + 4 darts, two readings): false alarms told from real breaks");
  c->add_option("--confirm-darts", o->confirm_darts, "for a failing rule, try every map of its model with up to this many darts beyond L (0: skip)")
      ->capture_default_str()
      ->transform(host_darts());
  commands.push_back({c, [o] { return check(*o); }});
}

void add_events(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<EventsOptions>();
  auto* ev = app.add_subcommand("events", "Topological events of every rule (004): creation, deletion, split, merge, modification per orbit type");
  ev->add_option("catalog", o->catalog, "YAML catalog or Jerboa .jme modeler")->required();
  ev->add_option("--rule", o->rule, "only this rule (needed with --map)");
  ev->add_option("--orbit", o->orbits, "orbit type such as \"<0,1>\" (repeat), or all (default)");
  ev->add_option("--map", o->map, "apply the rule to this map (catalog map name, map file, mesh or shape) and print the event log");
  ev->add_option("--hook", o->hooks, "hook dart, one per hook of the rule (repeat)")->transform(darts());
  ev->add_flag("--dynamic", o->dynamic, "also label every dart of both maps and set that log against the static one (exit 3 on a contradiction)");
  add_format(ev, o->format, {"text", "json", "jsonl"}, "text, json or jsonl (a shard's lines, for merge)");
  add_shard(ev, o->shard);
  commands.push_back({ev, [o] { return events_command(*o); }});
}

void add_words(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<WordsOptions>();
  auto* w = app.add_subcommand("words", "Normal forms of a word in R_{N,E} (002 Sec. 9.2), or whether two words are congruent");
  w->add_option("model", o->model, "model giving N and E (2-gmap, 3-omap, ...)")->required();
  w->add_option("word", o->word, "a word: digits are dimensions, ~d is the conjugate of d, ε the empty word")->required();
  w->add_option("word2", o->other, "a second word: test w <->* w2 instead");
  w->add_option("--prove", o->prove_darts, "with WORD2: ask Z3 for a map of up to this many darts on which the two paths differ")
      ->transform(host_darts());
  commands.push_back({w, [o] { return words(*o); }});
}

void add_fuzz(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<FuzzCommand>();
  auto* f =
      app.add_subcommand("fuzz", "Apply every rule at many matches on enumerated, given and random maps; set failures against the static verdict");
  f->add_option("catalog", o->catalog, "YAML catalog or Jerboa .jme modeler")->required();
  f->add_option("--rule", o->rule, "fuzz only this rule");
  f->add_option("--time", o->time, "time budget for the whole catalog (30s, 500ms, 2m), shared equally by the rules");
  add_shard_budget(f, o->shard_budget);
  f->add_option("--runs", o->runs, "applications per rule (default 10000 without --time)")->transform(count_option(1));
  f->add_option("--event-checks", o->event_checks,
                "applications per consistent rule whose event logs are set against its static events (004; 0: none)")
      ->capture_default_str()
      ->transform(counts());
  f->add_option("--baseline", o->baseline, "recorded verdicts from a YAML side file (as check --baseline)");
  f->add_option("--seed", o->seed, "random seed (default: drawn and printed)")->transform(counts());
  f->add_option("--max-darts", o->max_darts, "largest random host")->capture_default_str()->transform(count_option(2, no_dart - 1));
  f->add_option("--maps", o->maps, "more hosts: map files (.yaml, Jerboa .jba), meshes (.off, .obj) or shapes (cube, grid:3x4, ...)");
  // -o/--output as every other command; --out, the old spelling, stays.
  f->add_option("-o,--output,--out", o->out, "directory: write each counterexample here (host, match, result and a replay command)");
  add_format(f, o->format, {"text", "json", "jsonl"}, "text, json, or jsonl (a JSON line per rule as it finishes, then a summary line)");
  add_campaign(f, o->shard, o->jobs);
  commands.push_back({f, [o] { return fuzz(*o); }});
}

void add_prove(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<ProveCommand>();
  auto* p =
      app.add_subcommand("prove", "Ask Z3 for a host whose derived map breaks a constraint (bounded), and set the answer against the static verdict");
  p->add_option("catalog", o->catalog, "YAML catalog or Jerboa .jme modeler")->required();
  p->add_option("--rule", o->rule, "prove only this rule");
  p->add_option("--baseline", o->baseline, "recorded verdicts from a YAML side file (as check --baseline)");
  p->add_option("--max-darts", o->max_darts, "search hosts of up to this many darts")->capture_default_str()->transform(count_option(1, 256));
  p->add_option("--scheme-darts", o->scheme_darts,
                "for rule schemes, hosts of up to this many darts (at most --max-darts): H has that many darts per node of R")
      ->capture_default_str()
      ->transform(count_option(1, 256));
  p->add_option("--embedding-darts", o->embedding_darts,
                "for rules with embedding terms, hosts of up to this many darts for the embedding and potential-event queries (0: |L| + 4)")
      ->capture_default_str()
      ->transform(count_option(0, 64));
  p->add_option("--rlimit", o->rlimit, "Z3 resource limit per query (deterministic)")
      ->capture_default_str()
      ->transform(count_option(1, std::numeric_limits<unsigned>::max()));
  // Z3 takes milliseconds in an unsigned: at most 4,294,967 s; 0 is none.
  p->add_option("--timeout", o->timeout, "also stop a query after this many seconds (answers then depend on the machine)")
      ->check(real_option(0, 4'000'000));
  p->add_option("-o,--output,--out", o->out, "directory: write each counterexample on a map of the model here, with a replay command");
  add_format(p, o->format, {"text", "json", "jsonl"}, "text, json or jsonl (a shard's lines, for merge)");
  add_campaign(p, o->shard, o->jobs);
  p->add_flag("--explain", o->explain, "print the hosts and derived graphs of theorem-class counterexamples");
  commands.push_back({p, [o] { return prove(*o); }});
}

void add_draw(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<DrawOptions>();
  auto* dr = app.add_subcommand("draw", "Draw a rule or scheme: L and R side by side, witnesses of failed conditions highlighted");
  dr->add_option("catalog", o->catalog, "YAML catalog or Jerboa .jme modeler")->required();
  dr->add_option("--rule", o->rule, "the rule to draw")->required();
  dr->add_option("-o,--output", o->output, "picture file: .svg, .png, .pdf, or .dot/.gv for the DOT text")->required();
  dr->add_option("--engine", o->engine,
                 "lay L and R out with this Graphviz engine (dot, neato, fdp, ...) instead of pinning each preserved node at one place on both sides");
  commands.push_back({dr, [o] { return draw(*o); }});
}

void add_convert(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<ConvertOptions>();
  auto* cv = app.add_subcommand("convert", "Write a catalog (a Jerboa .jme modeler, or YAML) as a YAML catalog that checks identically");
  cv->add_option("input", o->input, ".jme modeler or YAML catalog")->required();
  cv->add_option("-o,--output", o->output, "the YAML catalog to write")->required();
  commands.push_back({cv, [o] { return convert(*o); }});
}

void add_compile(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<CompileOptions>();
  auto* cc = app.add_subcommand("compile", "Generate C++ that applies the catalog's consistent rules on dartcheck's Map, as the interpreter does");
  cc->add_option("catalog", o->catalog, "YAML catalog or Jerboa .jme modeler")->required();
  cc->add_option("--rule", o->rules, "compile this rule only (repeat for several; refused, naming its failing conditions, if it is not consistent)")
      ->allow_extra_args(false);  // one name per --rule: a catalog after it stays the positional
  cc->add_option("-o,--output", o->output, "the C++ header to write (default: standard output)");
  cc->add_option("--namespace", o->ns, "namespace of the generated functions (default: compiled_ and the catalog's file stem)");
  cc->add_flag("--with-embedding-failures", o->embedding_failures,
               "also compile the rules whose topological conditions hold and an embedding condition fails (003 Thm 4 then does not "
               "apply: the code gives the interpreter's values, conflicts counted, a new dart no term labels left without a value)");
  commands.push_back({cc, [o] { return compile(*o); }});
}

void add_infer(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<InferCommand>();
  auto* inf = app.add_subcommand("infer", "Infer the rule scheme of one before/after example by folding (000), check it and apply it back");
  inf->add_option("--before", o->before, "the map before: catalog map name (with --catalog), map file (.yaml, .jba, .off, .obj) or shape")
      ->required();
  inf->add_option("--after", o->after, "the map after, same forms")->required();
  inf->add_option("--orbit", o->orbit, "the rule's parameter orbit type, e.g. \"<0,1,2>\"")->required();
  inf->add_option("--kappa", o->kappa, "preserved darts: identity (same dart ids) or a YAML file of pairs and orbit associations")
      ->capture_default_str();
  inf->add_option("--catalog", o->catalog, "catalog whose maps --before and --after may name");
  inf->add_option("--model", o->model, "model for meshes and shapes")->capture_default_str();
  inf->add_option("--start", o->start, "fold from this dart of the before map only")->transform(darts());
  inf->add_flag("--all", o->all, "try every start dart (one per hook orbit) and list every distinct rule");
  inf->add_flag("--strict", o->strict, "the paper's algorithm exactly: one relabeling candidate per position, no retry");
  inf->add_flag("--generalize", o->generalize,
                "drop the explicit loops a preserved node has on both sides (free links of the example are left as the host has them); "
                "kept only if the rule stays consistent and gives the example back. The paper keeps the loops");
  inf->add_option("--undecided", o->undecided,
                  "positions whose links are all loops in the hook orbit: keep (relabel, warn), free (explicit loops) or fail")
      ->capture_default_str();
  inf->add_option("--name", o->name, "name of the inferred rule")->capture_default_str();
  inf->add_option("-o,--output", o->output, "write the rules: .yaml catalog (maps, rules, examples that `run` re-checks) or Jerboa .jme");
  add_format(inf, o->format, {"text", "json"}, "text or json");
  commands.push_back({inf, [o] { return infer(*o); }});
}

void add_recombine(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<RecombineOptions>();
  auto* rc = app.add_subcommand("recombine", "Recombine a tetrahedral mesh into hexahedra by query-modify (001 Sec. 7.1) and check the result");
  rc->add_option("mesh", o->mesh, "tetrahedral mesh: TetGen .node/.ele, medit .mesh or gmsh .msh (4.1 or 2.2, ASCII)")->required();
  rc->add_option("--strategy", o->strategy, "greedy (first match from each dart) or global (best scaled Jacobian first)")
      ->capture_default_str()
      ->check(CLI::IsMember({"greedy", "global"}));
  rc->add_option("--search", o->search,
                 "vertices (hexes from mesh vertices and edges) or words (001's query words from every dart, the definition; slower); "
                 "greedy always matches words")
      ->capture_default_str()
      ->check(CLI::IsMember({"vertices", "words"}));
  rc->add_option("--cells", o->cells,
                 "the cells to make: hex, or hex with prism and/or pyramid (comma-separated): after the hexes, pyramids on their quads "
                 "that face two tetrahedra with one apex, prisms from the tetrahedra left, pyramids on the prisms' quads")
      ->capture_default_str();
  rc->add_option("--min-quality", o->min_quality, "smallest scaled Jacobian a cell must exceed (-1 keeps inverted ones)")
      ->capture_default_str()
      ->check(real_option(-1, 1));
  rc->add_flag("--conforming", o->conforming,
               "select only cells that meet the others in nothing, a vertex, an edge or a face of both (a conforming mesh; "
               "the global strategy's vertex search)");
  rc->add_option("-o,--output", o->output,
                 "write the cells and the remaining tetrahedra as .mesh (medit), .vtu or .vtk (VTK: ParaView) or .msh (gmsh), "
                 "with each cell's scaled Jacobian where the format carries cell data");
  rc->add_option("--report", o->report, "write DIR/index.html (the run, the quality's histogram and quantiles) and DIR/quality.svg");
  rc->add_option("--msh-version", o->msh_version, "gmsh's format for -o X.msh: 4.1, or 2.2 for older readers")
      ->capture_default_str()
      ->check(CLI::IsMember({"4.1", "2.2"}));
  add_format(rc, o->format, {"text", "json", "jsonl"}, "text, json or jsonl (one run of a campaign over many meshes, for merge)");
  commands.push_back({rc, [o] { return recombine(*o); }});
}

void add_query(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<QueryOptions>();
  auto* qy = app.add_subcommand("query", "Find query maps in a map by query words (001 Sec. 5): every match, or a selection without overlap");
  qy->add_option("map", o->map, "the map: map file (.yaml, .jba, .off, .obj), tetrahedral mesh (.node, .ele, .mesh, .msh), catalog map name or shape")
      ->required();
  qy->add_option("--query", o->queries, "a query map, same forms (repeat); connected");
  qy->add_flag("--hex", o->hex, "add the 322 hex patterns of the tet -> hex recombination (open 3-O-maps)");
  qy->add_option("--start", o->start, "the query dart labeled 1")->capture_default_str()->transform(darts());
  qy->add_option("--free", o->free, "condition on the queries' free links: any (*), boundary (ε), interior (ε̄) or no-link (↔)")
      ->capture_default_str();
  qy->add_option("--strategy", o->strategy, "all (every distinct match), greedy or global (largest first), without overlap")
      ->capture_default_str()
      ->check(CLI::IsMember({"all", "greedy", "global"}));
  qy->add_option("--catalog", o->catalog, "catalog whose maps the map and queries may name");
  qy->add_option("--model", o->model, "model for meshes and shapes")->capture_default_str();
  qy->add_option("--limit", o->limit, "matches printed")->capture_default_str()->transform(counts());
  qy->add_option("-o,--output", o->output,
                 "on a tetrahedral mesh: write it as .vtu, .vtk or .msh with the shown matches as cell data (match, query, matches)");
  add_format(qy, o->format, {"text", "json", "jsonl"}, "text, json or jsonl (one run of a campaign over many maps, for merge)");
  commands.push_back({qy, [o] { return query(*o); }});
}

void add_report(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<ReportOptions>();
  auto* rp = app.add_subcommand("report", "Write an HTML report of a catalog: verdict table, every rule drawn, every failure pointed at");
  rp->add_option("catalog", o->catalog, "YAML catalog or Jerboa .jme modeler")->required();
  rp->add_option("-o,--output", o->output, "directory for index.html and the SVG pictures")->required();
  rp->add_option("--rule", o->rule, "only this rule");
  rp->add_option("--baseline", o->baseline, "recorded verdicts from a YAML side file (as check --baseline)");
  rp->add_option("--fuzz", o->fuzz, "fuzz every rule within this total time (30s, 2m, ...) and draw the counterexamples");
  add_shard_budget(rp, o->shard_budget);
  rp->add_option("--prove", o->prove_darts, "ask Z3 for counterexamples of up to K darts and draw them")->transform(host_darts());
  rp->add_option("--seed", o->seed, "random seed of --fuzz (default: drawn and printed)")->transform(counts());
  rp->add_option("--confirm-darts", o->confirm_darts, "as check: for a failing rule, try every map of its model with up to this many darts beyond L (0: skip)")
      ->capture_default_str()
      ->transform(host_darts());
  rp->add_option("--engine", o->engine, "Graphviz layout engine")->capture_default_str();
  add_format(rp, o->format, {"html", "jsonl"}, "html (the page in -o DIR) or jsonl (a shard's lines on stdout, for merge)");
  add_campaign(rp, o->shard, o->jobs);
  commands.push_back({rp, [o] { return report(*o); }});
}

void add_merge(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<MergeOptions>();
  auto* m = app.add_subcommand("merge", "Merge the shards of one run (--shard K/N --format jsonl) into one result, in any output format");
  m->add_option("shards", o->request.shards, "the shard files, one per shard, in any order")->required();
  add_format(m, o->format, {"text", "json", "sarif", "junit", "html"}, "text, json, sarif, junit, or html (the report page, in -o DIR)");
  m->add_option("-o,--output", o->request.output, "directory of the html page");
  m->add_option("--catalog", o->request.catalog, "the catalog, where it is now (default: the path the shards name; it must be unchanged)");
  m->add_flag("--explain", o->request.explain, "as check --explain and prove --explain");
  m->add_flag("--incomplete", o->request.incomplete,
              "also merge interrupted, killed, empty or missing shards: the result says how many rules it lacks, exit 130");
  m->add_option("--engine", o->request.engine, "Graphviz layout engine of the html page")->capture_default_str();
  commands.push_back({m, [o] { return merge(*o); }});
}

// An empty value (`--time ''`, `--shard ''`) is refused for every option
// and argument of every command: it used to be read as "not given".
void refuse_empty_values(CLI::App& app) {
  static const CLI::Validator non_empty(
      [](const std::string& value) { return value.empty() ? std::string("expected a value, got an empty string") : std::string(); }, "");
  for (CLI::Option* option : app.get_options())
    if (option->get_type_size() != 0) option->check(non_empty);
  for (CLI::App* command : app.get_subcommands({})) refuse_empty_values(*command);
}

void add_draw_map(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<DrawMapOptions>();
  auto* dm = app.add_subcommand("draw-map", "Draw a map: one node per dart, links colored by dimension, invalid darts highlighted");
  dm->add_option("map", o->target, fmt::format("a map file (.yaml, .jba, .off, .obj) or a shape ({})", shape_usage()))->required();
  dm->add_option("-o,--output", o->output, "picture file: .svg, .png, .pdf, or .dot/.gv for the DOT text")->required();
  dm->add_option("--model", o->model, "model for meshes and shapes")->capture_default_str();
  dm->add_option("--engine", o->engine, "Graphviz layout engine (neato or sfdp for large maps)")->capture_default_str();
  commands.push_back({dm, [o] { return draw_map(*o); }});
}

// `dartcheck --help` lists the commands first, then the options, then the
// input limits, which few runs need; a command's help keeps CLI11's order.
class CommandsFirst : public CLI::Formatter {
 public:
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override {
    if (mode == CLI::AppFormatMode::Sub || app->get_parent() != nullptr) return Formatter::make_help(app, std::move(name), mode);
    return make_description(app) + make_usage(app, std::move(name)) + make_positionals(app) + make_subcommands(app, mode) +
           make_groups(app, mode) + '\n' + make_footer(app);
  }
};

// The global options: input limits (core/limits.hpp), for the whole run,
// set before any input is read.
void add_limits(CLI::App& app) {
  auto& lim = limits();
  app.option_defaults()->group("Input limits");
  app.add_option("--limit-darts", lim.darts, "largest map read or built, in darts")->capture_default_str()->transform(count_option(1, no_dart - 1));
  app.add_option("--limit-file-bytes", lim.file_bytes, "largest input file read, in bytes")->capture_default_str()->transform(count_option(1));
  app.add_option("--limit-term-length", lim.term_length, "longest embedding term, in characters")->capture_default_str()->transform(count_option(1));
  // At most 10,000: a 25,000-deep sum overflowed the checker's recursion on an 8 MiB stack.
  app.add_option("--limit-term-depth", lim.term_depth, "deepest nesting of a term (at most 10000)")
      ->capture_default_str()
      ->transform(count_option(1, 10000));
  app.add_option("--limit-word-length", lim.word_length, "longest conjugate word, in letters")->capture_default_str()->transform(count_option(1));
  app.add_option("--limit-rewrite-words", lim.rewrite_words, "most words met while rewriting one word in a non-confluent R_{N,E}")
      ->capture_default_str()
      ->transform(count_option(1));
  app.add_option("--limit-rule-nodes", lim.rule_nodes, "most nodes in one side of a rule")->capture_default_str()->transform(count_option(1));
}

// The global output options (core/terminal.hpp); like the limits they may
// also follow the command's name.
struct OutputOptions {
  std::string color = "auto";
  bool quiet = false;
};

void add_output_options(CLI::App& app, OutputOptions& o) {
  app.option_defaults()->group("Options");
  app.add_option("--color", o.color, "colour the text on a terminal: auto (not under NO_COLOR or TERM=dumb), always, never")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "always", "never"}));
  app.add_flag("-q,--quiet", o.quiet, "no tables, summaries or progress: only errors, failures and MISMATCH lines (stderr) and the exit status");
}

// Runs the parsed command; the one place where each kind of error
// (core/error.hpp) becomes its exit status (commands.hpp): input, usage and
// a value without its position 2, output 4, a broken invariant 3 (a defect
// of dartcheck, as a soundness bug), anything else 2 with its message.
int run_command(const Commands& commands) {
  try {
    for (const auto& [sub, run] : commands)
      if (*sub) return run();
  } catch (const InputErrors& e) {
    for (const InputError& one : e.all()) fmt::print(stderr, "{}\n", painted_diagnostic(one.diagnostic()));
    if (e.stopped())
      fmt::print(stderr, "{}\n", diagnostic("note", printable(e.file()), 0, 0, fmt::format("stopped after {} errors", e.all().size())));
    return bad_input;
  } catch (const InputError& e) {
    fmt::print(stderr, "{}\n", painted_diagnostic(e.diagnostic()));
    return bad_input;
  } catch (const OutputError& e) {
    fmt::print(stderr, "{}\n", painted_diagnostic(diagnostic("error", "", 0, 0, printable(e.what()))));
    return output_error;
  } catch (const InternalError& e) {
    fmt::print(stderr, "{}\n",
               painted_diagnostic(diagnostic("error", "", 0, 0, fmt::format("internal error (a defect of dartcheck): {}", printable(e.what())))));
    return soundness_bug;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "dartcheck: error: out of memory (the input is larger than this machine can hold; see --limit-darts)\n");
    return bad_input;
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}\n", painted_diagnostic(diagnostic("error", "", 0, 0, printable(e.what()))));
    return bad_input;
  }
  return bad_input;
}

// The parser's names and help texts for cli/suggest's messages.
CommandTable command_table(const CLI::App& app) {
  CommandTable table;
  const auto long_names = [](const CLI::App& a, std::vector<std::string>& out) {
    for (const CLI::Option* o : a.get_options())
      for (const auto& n : o->get_lnames()) out.push_back("--" + n);
  };
  long_names(app, table.options[""]);
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_group().empty()) continue;  // hidden (__complete): never suggested
    table.commands.push_back(sub->get_name());
    auto& names = table.options[sub->get_name()];
    long_names(app, names);
    long_names(*sub, names);
  }
  table.help = [&app](std::string_view command) {
    return command.empty() ? app.help() : app.get_subcommand(std::string(command))->help(app.get_name());
  };
  return table;
}

}  // namespace

int run_command_line(int argc, char** argv, const std::string& version) {
  campaign::set_command_line(argc, argv);  // --jobs runs it again as shards
  CLI::App app{"dartcheck: verifies modeling operations on generalized and oriented maps", "dartcheck"};
  app.require_subcommand(1);
  app.set_version_flag("-V,--version", [&version] {
    std::string text = fmt::format("dartcheck {}\nbuilt with", version);
    for (const auto& [library, release] : reports::library_versions()) text += fmt::format(" {} {},", library, release);
    text.pop_back();  // the last comma
    return text;
  });
  app.fallthrough();  // the global options (limits) also after the command's name
  app.formatter(std::make_shared<CommandsFirst>());
  add_limits(app);
  OutputOptions output;
  add_output_options(app, output);

  Commands commands;
  add_validate(app, commands);
  add_apply(app, commands);
  add_run(app, commands);
  add_check(app, commands);
  add_events(app, commands);
  add_words(app, commands);
  add_fuzz(app, commands);
  add_prove(app, commands);
  add_draw(app, commands);
  add_convert(app, commands);
  add_compile(app, commands);
  add_infer(app, commands);
  add_recombine(app, commands);
  add_query(app, commands);
  add_report(app, commands);
  add_merge(app, commands);
  add_draw_map(app, commands);
  add_complete(app, commands);
  refuse_empty_values(app);

  // SIGINT and SIGTERM end every command within a second, exit 130; the
  // long runs (check, fuzz, prove, report) install their own handler,
  // which stops at the next rule and prints the finished ones.
  analysis::exit_on_interrupt();
  const CommandTable table = command_table(app);
  if (const auto status = help_request(table, argc, argv)) return *status;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    return report_parse_error(table, e.what(), argc, argv);
  }
  set_terminal(output.color == "always" ? ColorChoice::always : output.color == "never" ? ColorChoice::never : ColorChoice::automatic, output.quiet);
  return run_command(commands);
}

}  // namespace dartcheck::cli
