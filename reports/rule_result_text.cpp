#include "core/wording.hpp"
#include "reports/rule_result_text.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/prove_replay.hpp"
#include "core/input_error.hpp"

namespace dartcheck::reports {

using namespace analysis;

namespace {

std::string plural(std::size_t n, const char* one, const char* many) { return fmt::format("{} {}", n, n == 1 ? one : many); }

}  // namespace

std::string arcs_text(const TopoGraph& g) {
  std::string s;
  for (const auto& a : g.arcs()) s += fmt::format("{}{} -{}-> {}", s.empty() ? "" : ", ", g.name(a.source), a.label, g.name(a.target));
  return s;
}

std::string prove_text(const ProveRun& run, const std::vector<RuleResult>& results) {
  using proofs::Agreement;
  std::string out;
  std::size_t counts[4] = {}, scoped = 0;
  for (const auto& result : results) {
    const auto& p = *result.proof;
    scoped += p.out_of_scope.empty();
    for (auto a : {Agreement::agree, Agreement::disagree, Agreement::unresolved, Agreement::not_compared}) counts[static_cast<int>(a)] += p.count(a);
    out += fmt::format("{} ({}): ", printable(p.rule), printable(p.model));
    if (!p.out_of_scope.empty()) {
      out += fmt::format("out of the solver's scope: {}\n", p.out_of_scope);
      continue;
    }
    out += fmt::format("static {}; {:.2f} s\n", p.static_failures.empty() ? "consistent" : fmt::format("fails {}", fmt::join(p.static_failures, " ")),
                       p.seconds);
    for (std::size_t i = 0; i < p.constraints.size(); ++i) {
      const auto& cp = p.constraints[i];
      out += fmt::format("  {:<11} static {:<5}  theorem: {:<36}  maps: {:<32}  {}\n", cp.constraint.name(),
                         cp.static_holds ? (*cp.static_holds ? "holds" : "fails") : "-",
                         cp.theorem ? answer_text(*cp.theorem)
                         : p.scheme ? "(scheme: maps only)"
                                    : "(no theorem)",
                         answer_text(cp.model), proofs::agreement_name(cp.agreement));
      if (!cp.note.empty()) out += fmt::format("  {:<11} {}\n", "", cp.note);
      if (cp.theorem && cp.theorem->status == proofs::Status::counterexample && run.explain)
        out += fmt::format("  {:<11} theorem host: {}\n  {:<11} H: {}\n", "", arcs_text(cp.theorem->host_graph), "",
                           arcs_text(cp.theorem->result_graph));
      if (!result.proof_replays[i].empty()) out += fmt::format("  {:<11} replay: {}\n", "", printable(result.proof_replays[i]));
    }
  }
  out += fmt::format(
      "\n{} ({} in the solver's scope); {} agree, {} disagree, {} unresolved, {} not compared; up to {} darts, rlimit {}; "
      "{:.1f} s\n",
      counted(results.size(), "rule"), scoped, counted(counts[0], "constraint"), counts[1], counts[2], counts[3], run.max_darts, run.rlimit,
      run.seconds);
  if (const auto line = mismatch_summary(results); !line.empty()) out += line + "\n";
  return out;
}

std::vector<std::string> mismatch_lines(const std::vector<RuleResult>& results) {
  std::vector<std::string> lines;
  for (const auto& r : results) {
    for (const auto& m : r.mismatches)
      lines.push_back(
          printable(fmt::format("{}: error: {}: {}{}", r.entry->location.str(), r.name(), m.rfind("SOUNDNESS", 0) == 0 ? "" : "MISMATCH: ", m)));
    if (r.events_contradicted())
      lines.push_back(printable(fmt::format("{}: error: {}: {}", r.entry->location.str(), r.name(), event_outcome_text(*r.fuzz))));
  }
  return lines;
}

std::string mismatch_summary(const std::vector<RuleResult>& results) {
  const std::size_t n = count_results(results).mismatches;
  if (n == 0) return "";
  return fmt::format("{} differ{} from the {}", plural(n, "verdict", "verdicts"), n == 1 ? "s" : "", results.front().record_source_name());
}

std::string fuzz_table(const FuzzRun& run, const std::vector<RuleResult>& results) {
  std::string out;
  std::size_t width = 4, applications = 0;
  std::map<FuzzClass, std::size_t> classes;
  for (const auto& r : results) {
    width = std::max(width, printable(r.name()).size());
    ++classes[r.fuzz->verdict];
    applications += r.fuzz->applications;
  }
  out += fmt::format("{:<{}}  {:<18} {}\n", "rule", width, "static", "dynamic");
  for (const auto& result : results) {
    const auto& r = *result.fuzz;
    out += fmt::format("{:<{}}  {:<18} {}\n", printable(result.name()), width, result.verdict_text(), outcome_text(r));
    if (r.event_contradiction) {
      const auto& ev = *r.event_contradiction;
      out += fmt::format("{:<{}}  {} (found in {}; a defect of dartcheck's event analysis, not of the rule)\n", "", width,
                         printable(event_outcome_text(r)), ev.origin);
      for (std::size_t e = 1; e < ev.event_contradictions.size() && e < 4; ++e)
        out += fmt::format("{:<{}}  and: {}\n", "", width, printable(ev.event_contradictions[e]));
      if (ev.event_contradictions.size() > 4) out += fmt::format("{:<{}}  and {} more\n", "", width, ev.event_contradictions.size() - 4);
      if (!result.events_replay.empty()) out += fmt::format("{:<{}}  replay: {}\n", "", width, printable(result.events_replay));
    }
    if (!r.counterexample) continue;
    const auto& cx = *r.counterexample;
    out += fmt::format("{:<{}}  found in {}\n", "", width, cx.origin);
    if (!cx.unrepresentable.empty()) out += fmt::format("{:<{}}  H has no dense form: {}\n", "", width, cx.unrepresentable);
    for (std::size_t e = 0; e < cx.embedding_failures.size() && e < 4; ++e)
      out += fmt::format("{:<{}}  H: {}\n", "", width, cx.embedding_failures[e]);
    if (cx.embedding_failures.size() > 4) out += fmt::format("{:<{}}  H: ... {} more\n", "", width, cx.embedding_failures.size() - 4);
    if (!result.fuzz_replay.empty())
      out += fmt::format("{:<{}}  replay: {}\n", "", width, printable(result.fuzz_replay));
    else if (!result.entry->terms)
      out += fmt::format("{:<{}}  (--out DIR writes the host, the match and H, with a replay command)\n", "", width);
  }
  const std::size_t bugs = classes[FuzzClass::soundness_bug], contradicted = count_results(results).events_contradicted;
  out += fmt::format(
      "\n{}: {} consistent, {} confirmed, {} unconfirmed, {}, {} contradicted; {} in {:.1f} s "
      "({:.0f}/s); seed {}\n",
      counted(results.size(), "rule"), classes[FuzzClass::consistent], classes[FuzzClass::confirmed], classes[FuzzClass::unconfirmed],
      counted(bugs, "soundness bug"), counted(contradicted, "event analysis", "event analyses"), counted(applications, "application"), run.seconds,
      run.seconds > 0 ? double(applications) / run.seconds : 0.0, run.seed);
  if (const auto line = mismatch_summary(results); !line.empty()) out += line + "\n";
  return out;
}

std::string condition_cell(const RuleVerdict& v, RuleCondition kind) {
  std::vector<std::string> bad;
  bool any = false, skipped = false;
  for (const auto& c : v.conditions) {
    if (c.condition != kind) continue;
    any = true;
    if (!c.skipped.empty()) skipped = true;
    if (!c.holds) bad.push_back(c.j >= 0 ? fmt::format("{}{}", c.i, c.j) : std::to_string(c.i));
  }
  if (!any) return "-";
  if (!bad.empty()) return "fails " + fmt::format("{}", fmt::join(bad, ","));
  return skipped ? "skipped" : "ok";
}

std::string check_table(const Catalog& catalog, const std::vector<RuleResult>& results, std::size_t baseline_mismatches, const TableOptions& o) {
  std::string out;
  std::size_t width = 4;
  for (const auto& r : results) width = std::max(width, printable(r.name()).size());
  const bool embedded = !catalog.embeddings.empty();
  std::vector<std::string> ebd_cells;
  std::size_t ebd_width = 10;
  for (const auto& r : results) {
    const auto bad = failing_names(r.embedding);
    ebd_cells.push_back(bad.empty() ? "ok" : fmt::format("fails {}", fmt::join(bad, ",")));
    ebd_width = std::max(ebd_width, ebd_cells.back().size());
  }
  if (!catalog.modeler.empty()) {
    std::vector<std::string> e;
    for (const auto& d : catalog.embeddings) e.push_back(fmt::format("{} <{}>", d.name, fmt::join(d.orbit, ",")));
    out +=
        printable(fmt::format("Jerboa modeler {} ({}): {} rules read, {} skipped; embeddings: {}", catalog.modeler, o.catalog, catalog.rules.size(),
                              catalog.skipped.size(), e.empty() ? std::string("none") : fmt::format("{}", fmt::join(e, ", ")))) +
        "\n\n";
  }
  out += fmt::format("{:<{}}  {:<13} {:<10} {:<10} {:<10} {:<12} {}{:>7}  {}\n", "rule", width, "model", "I", "dangling", "O", "C",
                     embedded ? fmt::format("{:<{}} ", "embeddings", ebd_width) : "", "ms", "verdict");
  for (std::size_t row = 0; row < results.size(); ++row) {
    const auto& r = results[row];
    const auto& v = r.verdict;
    out += fmt::format("{:<{}}  {:<13} {:<10} {:<10} {:<10} {:<12} {}{:>7.2f}  {}{}\n", printable(r.name()), width,
                       printable(r.entry->rule.model().name), condition_cell(v, RuleCondition::incident_arcs),
                       condition_cell(v, RuleCondition::dangling), condition_cell(v, RuleCondition::non_orientation),
                       condition_cell(v, RuleCondition::cycle), embedded ? fmt::format("{:<{}} ", ebd_cells[row], ebd_width) : "", r.static_ms,
                       r.verdict_text(), r.matches_record() ? "" : fmt::format("   (differs from the {}: see stderr)", r.record_source_name()));
    for (const auto& caveat : r.entry->caveats) out += fmt::format("{:<{}}  note: {}\n", "", width, printable(caveat));
    if (r.host_search || r.scheme_search) out += fmt::format("{:<{}}  {}\n", "", width, r.confirmation_text());
    if (o.explain && !r.failures.empty()) {
      for (const auto& cond : v.conditions) {
        if (cond.holds) continue;
        for (const auto& w : cond.witnesses)
          out += fmt::format("{:<{}}    {}{}: {}\n", "", width, cond.name(), w.subcondition ? fmt::format(" sub-condition {}", w.subcondition) : "",
                             printable(w.text));
      }
      for (const auto& e : r.embedding)
        for (const auto& w : e.witnesses)
          out += fmt::format("{:<{}}    {}{}: {}\n", "", width, e.name, e.required ? "" : " (not required)", printable(w.text));
      if (r.scheme_search && r.scheme_search->counterexample)
        out += fmt::format("{:<{}}    host: {} (`dartcheck fuzz --rule {} --out DIR` writes it with a replay command)\n", "", width,
                           r.scheme_search->counterexample->origin, printable(r.name()));
      if (r.host_search && r.host_search->host)
        out += fmt::format("{:<{}}    host G: {}\n{:<{}}    result H: {}\n", "", width, printable(arcs_text(*r.host_search->host)), "", width,
                           printable(arcs_text(*r.host_search->result)));
    }
  }
  const bool whole_catalog = results.size() == catalog.rules.size();
  if (whole_catalog)
    for (const auto& sk : catalog.skipped)
      out += printable(fmt::format("{:<{}}  not checked ({}): {}", sk.name, width, sk.location.str(), sk.why)) + "\n";
  if (embedded)
    out += fmt::format("\nembeddings: {}{}\n", sufficiency_note,
                       catalog.signatures.size() == catalog.embeddings.size() ? "" : "; Jerboa expressions are compared as text, never evaluated");
  const auto counts = count_results(results);
  const std::size_t mismatches = counts.mismatches + baseline_mismatches;
  const std::string_view source = results.empty() ? "catalog" : results.front().record_source_name();
  out += fmt::format("\n{}, {} consistent, {} with failing conditions{}; {} differ{} from the {}\n", plural(counts.rules, "rule", "rules"),
                     counts.consistent, counts.failing,
                     catalog.skipped.empty() || !whole_catalog ? "" : fmt::format(", {} not checked", catalog.skipped.size()),
                     plural(mismatches, "verdict", "verdicts"), mismatches == 1 ? "s" : "", source);
  return out;
}

}  // namespace dartcheck::reports
