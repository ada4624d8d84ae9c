// The dartcheck subcommands. Each returns the process exit status:
// 0 success, 1 a violation or a failed expectation, 2 bad input, 3 a
// soundness bug (a rule judged consistent broke a map), 4 an output that
// could not be written (core/output_file.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/exit_status.hpp"
#include "campaign/merge.hpp"
#include "reports/output_format.hpp"
#include "core/map.hpp"

namespace dartcheck::cli {

using namespace exit_status;  // ok, violation, bad_input, soundness_bug, output_error

/// The hidden completion helper (cmd_complete.cpp): WHAT is rules, maps,
/// models or cells.
struct CompleteOptions {
  std::string what, catalog;
};
int complete(const CompleteOptions& o);

struct ValidateOptions {
  std::string target;
  std::string model = "2-gmap";
  std::size_t limit = 50;
  std::string format = "text";
};
int validate_map(const ValidateOptions& o);

struct DrawOptions {
  std::string catalog, rule, output;
  std::string engine;  // empty: preserved nodes pinned at one place on both sides (neato)
};
/// A rule's picture; 0, or 2 on bad input.
int draw(const DrawOptions& o);

struct ConvertOptions {
  std::string input, output;
};
/// Writes the catalog (e.g. a Jerboa .jme modeler) as a YAML catalog.
int convert(const ConvertOptions& o);

struct CompileOptions {
  std::string catalog, output;
  std::vector<std::string> rules;  // only these (repeatable --rule)
  std::string ns;  // the generated code's namespace (default: compiled_ and the catalog's stem)
  bool embedding_failures = false;  // also rules whose topology holds and an embedding condition fails
};
/// The consistent rules as C++ (compiler/rule_compiler.hpp); 1 if a
/// --rule named is not consistent, 2 if it cannot be compiled.
int compile(const CompileOptions& o);

struct ReportOptions {
  std::string catalog, rule, output, engine = "dot";
  std::string format = "html";  // html (the page in `output`), or jsonl (a shard's lines on stdout)
  std::string shard;            // "K/N": only the rules of shard K (campaign/shard.hpp)
  std::size_t jobs = 1;         // processes, each a shard, merged (campaign/jobs.hpp)
  std::string baseline;         // recorded verdicts from a YAML side file (io/baseline.hpp)
  std::string fuzz;             // a duration: fuzz every rule within it (empty: no fuzzing)
  std::optional<double> shard_budget;  // --jobs's share of `fuzz` for this shard (hidden)
  std::size_t prove_darts = 0;  // ask Z3 for counterexamples of up to this many darts (0: no)
  std::optional<std::uint64_t> seed;
  std::size_t confirm_darts = 2;  // as check --confirm-darts
};
/// DIR/index.html and the SVG pictures; 3 on a soundness bug or a
/// solver disagreement, 1 if a static verdict differs from the catalog's,
/// 0 otherwise.
int report(const ReportOptions& o);

struct DrawMapOptions {
  std::string target, output, model = "2-gmap", engine = "dot";
};
/// A map's picture; 1 if the map is invalid (its failing darts are
/// highlighted).
int draw_map(const DrawMapOptions& o);

/// What `dartcheck apply` was asked: the map as the user named it (a mesh
/// gives an embedded rule its positions), the hooks, and the outputs.
struct ApplyOptions {
  std::string catalog, rule, map, output, kappa_out;
  std::vector<Dart> hooks;
  std::size_t limit = 50;  // violations printed (0: all)
};
int apply(const ApplyOptions& o);

struct RunOptions {
  std::string catalog;
};
int run(const RunOptions& o);

struct CheckOptions {
  std::string catalog, rule, format = "text";
  std::string shard;           // "K/N": only the rules of shard K (campaign/shard.hpp)
  std::size_t jobs = 1;        // processes, each a shard, merged (campaign/jobs.hpp)
  std::string baseline;        // recorded verdicts from a YAML side file (io/baseline.hpp), for .jme modelers
  std::string write_baseline;  // write this run's verdicts as a baseline
  bool explain = false;
  std::size_t confirm_darts = 2;  // extra darts beyond L for the model-level search (0: none)
  bool solver = false;             // Z3 on each embedding (proofs/embedding_prover): the refined verdict
};
/// Exit 0 iff every rule's failing conditions equal the recorded verdict
/// (all conditions hold where none is recorded), 1 otherwise.
int check(const CheckOptions& o);

struct EventsOptions {
  std::string catalog, rule, map, format = "text";
  std::string shard;                // "K/N": only the rules of shard K (campaign/shard.hpp)
  std::vector<std::string> orbits;  // "<0,1>" ...; empty or "all": every orbit type
  std::vector<Dart> hooks;
  bool dynamic = false;
};
/// The events of every rule's orbits (004 Sec. 3); with a map, the event
/// log of one application. 1 if the rule does not apply or has no event
/// view, 3 if --dynamic contradicts a certain static event.
int events_command(const EventsOptions& o);

struct InferCommand {
  std::string before, after, orbit, kappa = "identity", model = "2-gmap", catalog, output, format = "text", undecided = "keep", name = "inferred";
  std::optional<Dart> start;
  bool all = false, strict = false, generalize = false;
};
/// Operation inference by folding (000): 0 if a rule was inferred, 1 if
/// none, 3 if an inferred rule does not give the after map back (App. A).
int infer(const InferCommand& o);

struct RecombineOptions {
  std::string mesh, strategy = "global", search = "vertices", output, format = "text", cells = "hex";
  std::string msh_version = "4.1";  // gmsh's format for -o X.msh
  std::string report;               // a directory for index.html and quality.svg
  double min_quality = 0.0;  // cells must have a scaled Jacobian above it
  bool conforming = false;   // cells meet only in a vertex, an edge or a face of both
};
/// Tetrahedra -> hexahedra (001 Sec. 7.1), and prisms and pyramids with
/// --cells; 3 if the result is not a valid map of 36 darts per hex, 24 per
/// prism, 18 per pyramid and 12 per tetrahedron.
int recombine(const RecombineOptions& o);

struct QueryOptions {
  std::string map, model = "2-gmap", catalog, free = "any", strategy = "all", format = "text", output;
  std::vector<std::string> queries;
  bool hex = false;
  Dart start = 0;
  std::size_t limit = 20;
};
/// Query words (001 Sec. 5) on a map: every match, or a greedy/global
/// selection; 0 if something matched, 1 if nothing did.
int query(const QueryOptions& o);

struct WordsOptions {
  std::string model, word;
  std::optional<std::string> other;
  std::size_t prove_darts = 0;  // also ask Z3 for a separating map of up to this many darts (0: no)
};
/// Exit 0 for normal forms or congruent words, 1 for words not shown
/// congruent, 3 if Z3 separates words R_{N,E} calls congruent.
int words(const WordsOptions& o);

struct FuzzCommand {
  std::string catalog, rule, time, out, format = "text";
  std::string shard;     // "K/N": only the rules of shard K (campaign/shard.hpp)
  std::size_t jobs = 1;  // processes, each a shard, merged (campaign/jobs.hpp)
  std::string baseline;  // recorded verdicts from a YAML side file (io/baseline.hpp)
  std::optional<std::size_t> runs;
  std::optional<std::uint64_t> seed;
  std::size_t max_darts = 128;
  std::size_t event_checks = 2'000;  // applications per consistent rule whose event logs are cross-checked (004)
  std::vector<std::string> maps;
  std::optional<double> shard_budget;  // --jobs's share of `time` for this shard (hidden)
};
/// Exit 3 if a rule judged consistent broke a map or contradicted its
/// static events, 0 otherwise (a
/// confirmed or unconfirmed failure agrees with the static verdict).
int fuzz(const FuzzCommand& c);

struct ProveCommand {
  std::string catalog, rule, out, format = "text";
  std::string shard;     // "K/N": only the rules of shard K (campaign/shard.hpp)
  std::size_t jobs = 1;  // processes, each a shard, merged (campaign/jobs.hpp)
  std::string baseline;  // recorded verdicts from a YAML side file (io/baseline.hpp)
  std::size_t max_darts = 10;
  std::size_t scheme_darts = 6;
  unsigned rlimit = 200'000'000;
  double timeout = 0;  // seconds of wall clock per query on top of rlimit (0: none)
  std::size_t embedding_darts = 0;  // hosts of the embedding and potential-event queries (0: |L| + 4)
  bool explain = false;
};
/// Exit 3 if some solver answer contradicts the static verdict where a
/// theorem says they must agree (or a counterexample does not replay), 0
/// otherwise.
int prove(const ProveCommand& c);

/// `merge` is the campaign layer's (campaign/merge.hpp); --format is read
/// as text and resolved here.
struct MergeOptions {
  campaign::MergeRequest request;
  std::string format = "text";
};
inline int merge(const MergeOptions& o) {
  campaign::MergeRequest r = o.request;
  r.format = reports::output_format(o.format);
  return campaign::merge_shards(r);
}

}  // namespace dartcheck::cli
