// `dartcheck prove`: the solver's answer for every rule and constraint, set
// against the static verdict (proofs/rule_prover.hpp). Counterexamples on
// maps of the model are also replayed by the dynamic checker (apply_rule
// plus check_map), the third opinion, and written as the same files that
// `dartcheck fuzz` writes.
#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "analysis/interrupt.hpp"
#include "analysis/verdict_record.hpp"
#include "cli/options.hpp"
#include "analysis/counterexample_files.hpp"
#include "analysis/fuzz.hpp"
#include "analysis/prove_replay.hpp"
#include "analysis/rule_result.hpp"
#include "reports/rule_result_json.hpp"
#include "reports/rule_result_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "proofs/rule_prover.hpp"

namespace dartcheck::cli {

using namespace analysis;  // the engines the commands call
namespace {

using proofs::Agreement;
using proofs::ClassAnswer;
using proofs::Status;

std::string graph_arcs(const TopoGraph& g) {
  std::vector<std::string> arcs;
  for (const auto& a : g.arcs()) arcs.push_back(fmt::format("{} -{}-> {}", g.name(a.source), a.label, g.name(a.target)));
  return fmt::format("{}", fmt::join(arcs, ", "));
}

}  // namespace

int prove(const ProveCommand& c) {
  Catalog catalog = read_command_catalog(c.catalog, c.rule, c.format);
  const auto baseline_mismatches = c.baseline.empty() ? std::vector<std::string>{} : apply_baseline(catalog, c.baseline);
  const RecordSource source = c.baseline.empty() ? RecordSource::catalog : RecordSource::baseline;
  if (!c.out.empty()) ensure_directory(c.out);  // before the work, not after it
  catch_interrupts();
  if (c.max_darts < 1 || c.max_darts > 256) throw InputError("<command line>", 0, 0, "--max-darts: expected 1 to 256");
  if (c.scheme_darts < 1 || c.scheme_darts > 256) throw InputError("<command line>", 0, 0, "--scheme-darts: expected 1 to 256");
  proofs::ProveOptions o;
  o.max_darts = c.max_darts;
  o.scheme_darts = c.scheme_darts;
  o.rlimit = c.rlimit;
  o.timeout_ms = static_cast<unsigned>(c.timeout * 1000);

  const auto start = std::chrono::steady_clock::now();
  std::vector<RuleResult> results;
  std::size_t selected = 0;
  for (const auto& e : catalog.rules) {
    if (!c.rule.empty() && e.rule.name() != c.rule) continue;
    ++selected;
    if (interrupted()) continue;  // a rule's queries finish; the next ones do not start
    results.push_back(analyse_static(catalog, e, 0, {}, source));
    run_proof(results.back(), o, c.out, c.catalog);
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::size_t counts[4] = {}, scoped = 0;
  for (const auto& r : results) {
    scoped += r.proof->out_of_scope.empty();
    for (auto a : {Agreement::agree, Agreement::disagree, Agreement::unresolved, Agreement::not_compared})
      counts[static_cast<int>(a)] += r.proof->count(a);
  }
  const auto tally = count_results(results);
  const int status = finish_run(results, baseline_mismatches, selected);

  if (c.format == "json") {
    reports::Json doc = reports::json_document("prove");
    doc["catalog"] = c.catalog;
    doc["max_darts"] = o.max_darts;
    doc["rlimit"] = o.rlimit;
    doc["seconds"] = total;
    reports::Json rows = reports::Json::array();
    for (const auto& r : results) rows.push_back(reports::rule_result_json(r));
    doc["rules"] = std::move(rows);
    doc["in_scope"] = scoped;
    doc["agree"] = counts[0];
    doc["disagree"] = counts[1];
    doc["unresolved"] = counts[2];
    doc["not_compared"] = counts[3];
    doc["counts"] = reports::counts_json(tally);
    doc["baseline_mismatches"] = baseline_mismatches;
    fmt::print("{}\n", reports::json_text(std::move(doc)));
    return status;
  }

  for (const auto& result : results) {
    const auto& p = *result.proof;
    fmt::print("{} ({}): ", printable(p.rule), printable(p.model));
    if (!p.out_of_scope.empty()) {
      fmt::print("out of the solver's scope: {}\n", p.out_of_scope);
      continue;
    }
    fmt::print("static {}; {:.2f} s\n", p.static_failures.empty() ? "consistent" : fmt::format("fails {}", fmt::join(p.static_failures, " ")),
               p.seconds);
    for (std::size_t i = 0; i < p.constraints.size(); ++i) {
      const auto& cp = p.constraints[i];
      fmt::print("  {:<11} static {:<5}  theorem: {:<36}  maps: {:<32}  {}\n", cp.constraint.name(),
                 cp.static_holds ? (*cp.static_holds ? "holds" : "fails") : "-",
                 cp.theorem ? answer_text(*cp.theorem)
                 : p.scheme ? "(scheme: maps only)"
                            : "(no theorem)",
                 answer_text(cp.model), proofs::agreement_name(cp.agreement));
      if (!cp.note.empty()) fmt::print("  {:<11} {}\n", "", cp.note);
      if (cp.theorem && cp.theorem->status == Status::counterexample && c.explain)
        fmt::print("  {:<11} theorem host: {}\n  {:<11} H: {}\n", "", graph_arcs(cp.theorem->host_graph), "", graph_arcs(cp.theorem->result_graph));
      if (!result.proof_replays[i].empty()) fmt::print("  {:<11} replay: {}\n", "", printable(result.proof_replays[i]));
    }
  }
  fmt::print(
      "\n{} rules ({} in the solver's scope); {} constraints agree, {} disagree, {} unresolved, {} not compared; up to {} darts, rlimit {}; "
      "{:.1f} s\n",
      results.size(), scoped, counts[0], counts[1], counts[2], counts[3], o.max_darts, o.rlimit, total);
  if (const auto line = reports::mismatch_summary(results); !line.empty()) fmt::print("{}\n", line);
  return status;
}

}  // namespace dartcheck::cli
