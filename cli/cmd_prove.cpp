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
#include "cli/report_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"
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

std::string answer_json(const ClassAnswer& a) {
  std::string s = fmt::format(
      "{{\"class\": \"{}\", \"status\": \"{}\", \"darts\": {}, \"minimal\": {}, \"bound\": {}, \"proved_for_all\": {}, \"core\": {}, "
      "\"why\": \"{}\", \"seconds\": {:.4f}",
      json_escape(a.class_name), proofs::status_name(a.status), a.darts, a.minimal, a.bound, a.proved_for_all(), json_strings(a.core),
      json_escape(a.why), a.seconds);
  if (a.status == Status::counterexample)
    s += fmt::format(", \"replayed\": {}, \"host\": \"{}\", \"result\": \"{}\"", a.replayed, json_escape(graph_arcs(a.host_graph)),
                     json_escape(graph_arcs(a.result_graph)));
  return s + "}";
}

// The third opinion on a map counterexample, written as files when `out`
// is given. Returns the replay command if files were written.
std::string confirm_dynamically(const CatalogRule& entry, proofs::ConstraintProof& c, const std::string& out, const std::string& catalog,
                                const std::vector<std::string>& static_failures) {
  auto cx = replay_solver_map(entry, c);
  if (!cx || out.empty()) return {};
  return write_counterexample(out, file_stem(entry.rule.name()) + "." + constraint_stem(c), catalog, entry.rule.name(),
                              {{"constraint", c.constraint.name()}, {"class", "counterexample on a map of the model (dartcheck prove)"}},
                              static_failures, *cx);
}

}  // namespace

int prove(const ProveCommand& c) {
  const Catalog catalog = read_command_catalog(c.catalog, c.rule, c.format);
  catch_interrupts();
  if (c.max_darts < 1 || c.max_darts > 256) throw InputError("<command line>", 0, 0, "--max-darts: expected 1 to 256");
  if (c.scheme_darts < 1 || c.scheme_darts > 256) throw InputError("<command line>", 0, 0, "--scheme-darts: expected 1 to 256");
  proofs::ProveOptions o;
  o.max_darts = c.max_darts;
  o.scheme_darts = c.scheme_darts;
  o.rlimit = c.rlimit;
  o.timeout_ms = static_cast<unsigned>(c.timeout * 1000);

  const auto start = std::chrono::steady_clock::now();
  std::vector<proofs::RuleProof> proofs;
  std::vector<std::vector<std::string>> replays;
  std::size_t selected = 0;
  for (const auto& e : catalog.rules) {
    if (!c.rule.empty() && e.rule.name() != c.rule) continue;
    ++selected;
    if (interrupted()) continue;  // a rule's queries finish; the next ones do not start
    proofs.push_back(proofs::prove_rule(e, o));
    replays.emplace_back();
    for (auto& cp : proofs.back().constraints) replays.back().push_back(confirm_dynamically(e, cp, c.out, c.catalog, proofs.back().static_failures));
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::size_t counts[4] = {}, scoped = 0;
  for (const auto& p : proofs) {
    scoped += p.out_of_scope.empty();
    for (auto a : {Agreement::agree, Agreement::disagree, Agreement::unresolved, Agreement::not_compared})
      counts[static_cast<int>(a)] += p.count(a);
  }
  const std::size_t disagreements = counts[static_cast<int>(Agreement::disagree)];
  // A map the solver breaks contradicts a recorded 'consistent' (exit 1, as check).
  std::vector<std::string> contradictions;
  {
    std::size_t k = 0;
    for (const auto& e : catalog.rules) {
      if (!c.rule.empty() && e.rule.name() != c.rule) continue;
      if (k == proofs.size()) break;
      const auto& p = proofs[k++];
      // Only a host that is a map of the model counts: a theorem-class host
      // need not be one.
      const bool broken = std::any_of(p.constraints.begin(), p.constraints.end(),
                                      [](const proofs::ConstraintProof& cp) { return cp.model.status == Status::counterexample; });
      if (contradicts_record(e, broken)) contradictions.push_back(contradiction_line(e, "the solver found a host it breaks"));
    }
  }
  for (const auto& line : contradictions) fmt::print(stderr, "MISMATCH: {}\n", line);
  int status = disagreements ? soundness_bug : contradictions.empty() ? ok : violation;
  // Interrupted (SIGINT, SIGTERM): the finished rules' results are kept.
  if (interrupted()) {
    fmt::print(stderr, "interrupted: {} of {} rule{} finished; the results above are theirs\n", proofs.size(), selected, selected == 1 ? "" : "s");
    if (status != soundness_bug) status = interrupted_exit;
  }

  if (c.format == "json") {
    fmt::print("{{\"catalog\": \"{}\", \"max_darts\": {}, \"rlimit\": {}, \"seconds\": {:.3f}, \"rules\": [\n", json_escape(c.catalog), o.max_darts,
               o.rlimit, total);
    for (std::size_t k = 0; k < proofs.size(); ++k) {
      const auto& p = proofs[k];
      fmt::print("  {{\"name\": \"{}\", \"model\": \"{}\", \"out_of_scope\": \"{}\", \"static_failures\": {}, \"seconds\": {:.4f}, \"constraints\": [",
                 json_escape(p.rule), p.model, json_escape(p.out_of_scope), json_strings(p.static_failures), p.seconds);
      for (std::size_t i = 0; i < p.constraints.size(); ++i) {
        const auto& cp = p.constraints[i];
        fmt::print("{}\n    {{\"constraint\": \"{}\", \"static\": \"{}\", \"theorem\": {}, \"model\": {}, \"agreement\": \"{}\", \"note\": \"{}\", "
                   "\"replay\": \"{}\"}}",
                   i ? "," : "", cp.constraint.name(), cp.static_holds ? (*cp.static_holds ? "holds" : "fails") : "none",
                   cp.theorem ? answer_json(*cp.theorem) : "null", answer_json(cp.model), proofs::agreement_name(cp.agreement),
                   json_escape(cp.note), json_escape(replays[k][i]));
      }
      fmt::print("]}}{}\n", k + 1 < proofs.size() ? "," : "");
    }
    fmt::print("], \"in_scope\": {}, \"agree\": {}, \"disagree\": {}, \"unresolved\": {}, \"not_compared\": {}}}\n", scoped, counts[0], counts[1],
               counts[2], counts[3]);
    return status;
  }

  for (std::size_t k = 0; k < proofs.size(); ++k) {
    const auto& p = proofs[k];
    fmt::print("{} ({}): ", p.rule, p.model);
    if (!p.out_of_scope.empty()) {
      fmt::print("out of the solver's scope: {}\n", p.out_of_scope);
      continue;
    }
    fmt::print("static {}; {:.2f} s\n", p.static_failures.empty() ? "consistent" : fmt::format("fails {}", fmt::join(p.static_failures, " ")),
               p.seconds);
    for (std::size_t i = 0; i < p.constraints.size(); ++i) {
      const auto& cp = p.constraints[i];
      fmt::print("  {:<11} static {:<5}  theorem: {:<36}  maps: {:<32}  {}\n", cp.constraint.name(),
                 cp.static_holds ? (*cp.static_holds ? "holds" : "fails") : "-", cp.theorem ? answer_text(*cp.theorem) : p.scheme ? "(scheme: maps only)" : "(no theorem)",
                 answer_text(cp.model), proofs::agreement_name(cp.agreement));
      if (!cp.note.empty()) fmt::print("  {:<11} {}\n", "", cp.note);
      if (cp.theorem && cp.theorem->status == Status::counterexample && c.explain)
        fmt::print("  {:<11} theorem host: {}\n  {:<11} H: {}\n", "", graph_arcs(cp.theorem->host_graph), "", graph_arcs(cp.theorem->result_graph));
      if (!replays[k][i].empty()) fmt::print("  {:<11} replay: {}\n", "", replays[k][i]);
    }
  }
  fmt::print("\n{} rules ({} in the solver's scope); {} constraints agree, {} disagree, {} unresolved, {} not compared; up to {} darts, rlimit {}; "
             "{:.1f} s\n",
             proofs.size(), scoped, counts[0], counts[1], counts[2], counts[3], o.max_darts, o.rlimit, total);
  if (!contradictions.empty())
    fmt::print("{}\n", contradiction_summary(contradictions.size()));
  return status;
}

}  // namespace dartcheck::cli
