#include "core/terminal.hpp"
#include "core/wording.hpp"
#include "reports/rule_result_text.hpp"

#include "core/shell_quote.hpp"

#include <algorithm>
#include <filesystem>
#include <array>
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

namespace {

// `fields` after `head`, two spaces apart, a field that would pass the
// terminal's width starting a line of its own under the first (and
// wrapping at spaces when it is wider than that line).
std::string fields_under(const std::string& head, const std::vector<std::string>& fields) {
  const std::size_t indent = columns(head), width = terminal().width;
  std::string out = head;
  std::size_t at = indent;
  for (std::size_t k = 0; k < fields.size(); ++k) {
    if (k > 0 && at + 2 + columns(fields[k]) <= width) {
      out += "  ";
      out += fields[k];
      at += 2 + columns(fields[k]);
      continue;
    }
    if (k > 0) {
      out += '\n';
      out.append(indent, ' ');
    }
    const auto lines = wrap_words(fields[k], std::max<std::size_t>(20, width > indent ? width - indent : 0));
    for (std::size_t l = 0; l < lines.size(); ++l) {
      if (l > 0) {
        out += '\n';
        out.append(indent, ' ');
      }
      out += lines[l];
    }
    at = indent + columns(lines.back());
  }
  return out + "\n";
}

}  // namespace

namespace {

// One row per embedding: its static conditions and the solver's two
// readings, with what a counterexample breaks and how it replays.
std::string embedding_proof_text(const proofs::EmbeddingProof& e, const std::vector<std::string>& replays) {
  std::string out;
  for (std::size_t i = 0; i + 1 < e.answers.size(); i += 2) {
    std::string row = fmt::format("  {} static {}", e.answers[i].condition(),
                                  e.answers[i].static_failures.empty() ? "holds" : fmt::format("fails {}", fmt::join(e.answers[i].static_failures, " ")));
    for (const auto* a : {&e.answers[i], &e.answers[i + 1]}) {
      row += fmt::format("; {}: {}", proofs::name_of(a->reading), proofs::name_of(a->status));
      if (a->status == proofs::EmbeddingAnswer::Status::counterexample)
        row += fmt::format(" on {} darts{}", a->darts, a->reading == proofs::Reading::arithmetic ? (a->replayed ? " (replayed)" : " (NOT replayed)") : "");
      else if (a->status == proofs::EmbeddingAnswer::Status::none)
        row += fmt::format(" up to {} darts", a->darts);
      if (a->disagree) row += " DISAGREE";
    }
    out += hanging("", row, 4);
    for (const auto* a : {&e.answers[i], &e.answers[i + 1]}) {
      const std::string reading(proofs::name_of(a->reading));
      if (!a->why.empty()) out += hanging("", fmt::format("    {}: {}", reading, a->why), 6);
      if (!a->note.empty()) out += hanging("", fmt::format("    {}: {}", reading, a->note), 6);
      if (!a->uninterpreted.empty()) out += hanging("", fmt::format("    {}: left uninterpreted: {}", reading, fmt::join(a->uninterpreted, "; ")), 6);
      const std::size_t k = static_cast<std::size_t>(a - e.answers.data());
      if (k < replays.size() && !replays[k].empty()) out += hanging("", fmt::format("    replay: {}", replays[k]), 6);
    }
  }
  if (!e.answers.empty())
    out += fmt::format("  embeddings: {} hosts, {} applications, {} queries ({} cached), {:.2f} s\n", e.hosts, e.applications, e.queries, e.cached,
                       e.seconds);
  return out;
}

// 004's potential events, each with its witness or "never up to K".
std::string potential_events_text(const RuleResult& r) {
  if (!r.potential_events || r.potential_events->events.empty()) return {};
  const auto& p = *r.potential_events;
  std::string out;
  for (std::size_t i = 0; i < p.events.size(); ++i) {
    const auto& e = p.events[i];
    out += hanging("", fmt::format("  event {} {}: {}", e.kind, e.claim,
                                   e.happens ? fmt::format("happens on a {}-dart host", e.darts) : fmt::format("never up to {} darts", e.darts)),
                   6);
    if (i < r.potential_event_replays.size() && !r.potential_event_replays[i].empty())
      out += hanging("", fmt::format("    replay: {}", printable(r.potential_event_replays[i])), 6);
  }
  if (!p.not_decided.empty()) out += hanging("", fmt::format("  events: {}", p.not_decided), 4);
  out += fmt::format("  events: {} hosts, {} applications, {:.2f} s\n", p.hosts, p.applications, p.seconds);
  return out;
}

}  // namespace

std::string prove_rule_text(const ProveRun& run, const RuleResult& result) {
  const auto& p = *result.proof;
  const std::string name = fmt::format("{} ({}):", printable(p.rule), printable(p.model));
  const std::string embeddings =
      (p.embedding ? embedding_proof_text(*p.embedding, result.embedding_replays) : std::string()) + potential_events_text(result);
  if (!p.out_of_scope.empty()) return hanging(name, fmt::format("out of the solver's scope: {}", p.out_of_scope), 2) + embeddings;
  std::string out = hanging(
      name, fmt::format("static {}; {:.2f} s", p.static_failures.empty() ? "consistent" : fmt::format("fails {}", fmt::join(p.static_failures, " ")), p.seconds),
      2);
  for (std::size_t i = 0; i < p.constraints.size(); ++i) {
    const auto& cp = p.constraints[i];
    // The theorem's answer, the maps' answer and the agreement: padded
    // columns when the row fits the terminal, else each field where it
    // fits, the next lines indented under the first field.
    const std::string theorem = cp.theorem ? answer_text(*cp.theorem) : p.scheme ? "(scheme: maps only)" : "(no theorem)";
    const std::string head = fmt::format("  {:<11} static {:<5}  ", cp.constraint.name(), cp.static_holds ? (*cp.static_holds ? "holds" : "fails") : "-");
    const std::string row = fmt::format("theorem: {:<36}  maps: {:<32}  {}", theorem, answer_text(cp.model), proofs::name_of(cp.agreement));
    out += columns(head) + columns(row) <= terminal().width
               ? head + row + "\n"
               : fields_under(head, {fmt::format("theorem: {}", theorem), fmt::format("maps: {}", answer_text(cp.model)),
                                     std::string(proofs::name_of(cp.agreement))});
    if (!cp.note.empty()) out += hanging("", cp.note, 14);
    if (cp.theorem && cp.theorem->status == proofs::Status::counterexample && run.explain)
      out += hanging(fmt::format("  {:<11} theorem host: ", ""), arcs_text(cp.theorem->host_graph), 28) +
             hanging(fmt::format("  {:<11} H: ", ""), arcs_text(cp.theorem->result_graph), 17);
    if (!result.proof_replays[i].empty()) out += fmt::format("  {:<11} replay: {}\n", "", printable(result.proof_replays[i]));
  }
  return out + embeddings;
}

std::string prove_totals_text(const ProveRun& run, const std::vector<RuleResult>& results) {
  using proofs::Agreement;
  std::size_t counts[4] = {}, scoped = 0;
  for (const auto& result : results) {
    const auto& p = *result.proof;
    scoped += p.out_of_scope.empty();
    for (auto a : {Agreement::agree, Agreement::disagree, Agreement::unresolved, Agreement::not_compared}) counts[static_cast<int>(a)] += p.count(a);
  }
  std::string out = fmt::format(
      "\n{} ({} in the solver's scope); {} agree, {} disagree, {} unresolved, {} not compared; up to {} darts, rlimit {}; "
      "{:.1f} s\n",
      counted(results.size(), "rule"), scoped, counted(counts[0], "constraint"), counts[1], counts[2], counts[3], run.max_darts, run.rlimit,
      run.seconds);
  if (const auto line = mismatch_summary(results); !line.empty()) out += line + "\n";
  return out;
}

std::string prove_text(const ProveRun& run, const std::vector<RuleResult>& results) {
  std::string out;
  for (const auto& result : results) out += prove_rule_text(run, result);
  return out + prove_totals_text(run, results);
}

std::vector<std::string> mismatch_lines(const std::vector<RuleResult>& results, bool recording) {
  std::vector<std::string> lines;
  for (const auto& r : results) {
    for (std::size_t k = 0; k < r.mismatches.size(); ++k) {
      const std::string& m = r.mismatches[k];
      const bool verdict = k == 0 && r.verdict_differs;
      if (verdict && recording) continue;  // --write-baseline records this verdict
      // A first run's finding is not a changed verdict: no "MISMATCH".
      const char* tag = m.rfind("SOUNDNESS", 0) == 0 || (verdict && r.first_run_finding()) ? "" : "MISMATCH: ";
      lines.push_back(printable(fmt::format("{}: error: {}: {}{}", r.entry->location.str(), r.name(), tag, m)));
    }
    if (r.events_contradicted())
      lines.push_back(printable(fmt::format("{}: error: {}: {}", r.entry->location.str(), r.name(), event_outcome_text(*r.fuzz))));
  }
  return lines;
}

std::size_t changed_verdicts(const std::vector<RuleResult>& results) {
  return static_cast<std::size_t>(std::count_if(results.begin(), results.end(), [](const RuleResult& r) {
    return !r.matches_record() && !(r.first_run_finding() && r.mismatches.size() == 1);
  }));
}

std::string mismatch_summary(const std::vector<RuleResult>& results) {
  const std::size_t n = changed_verdicts(results), findings = count_results(results).first_run_findings;
  std::string out;
  if (n > 0) out = fmt::format("{} differ{} from the {}", plural(n, "verdict", "verdicts"), n == 1 ? "s" : "", results.front().record_source_name());
  if (findings > 0)
    out += fmt::format("{}{} fail{} with no verdict recorded", out.empty() ? "" : "; ", plural(findings, "rule", "rules"), findings == 1 ? "s" : "");
  return out;
}

std::string first_run_hint(const std::vector<RuleResult>& results) {
  const std::size_t findings = count_results(results).first_run_findings;
  if (findings == 0) return {};
  const std::string file = results.front().entry->location.file;
  const std::string stem = std::filesystem::path(file).replace_extension().string() + ".baseline.yaml";
  return printable(fmt::format("{}: note: no verdict is recorded for {} failing {}: a first run. `dartcheck check {} --write-baseline {}` "
                               "records this run's verdicts; `--baseline {}` then reports only what changes",
                               file, findings, findings == 1 ? "rule" : "rules", shell_quote(file), shell_quote(stem), shell_quote(stem)));
}

namespace {

// The rows of check's table and their column widths, fitted to the
// terminal (core/terminal.hpp): each column as wide as its longest cell;
// when a row would overflow, the rule column narrows and a longer name
// gets a line of its own above its row. Lines under a row wrap at the
// width, indented under the cells.
struct CheckColumns {
  std::vector<std::string> names, models, verdicts;
  std::vector<std::array<std::string, 5>> cells;  // I, dangling, O, C, embeddings
  std::size_t name = 4, model = 5, verdict = 7;
  std::array<std::size_t, 5> cell{1, 8, 1, 1, 10};
  bool embedded = false;
  bool compact = false;  // too narrow for the condition columns: the verdict names the failures

  std::size_t fixed() const {
    if (compact) return 2 + model + 1 + 7 + 2;
    std::size_t w = 2 + model + 1 + cell[0] + 1 + cell[1] + 1 + cell[2] + 1 + cell[3] + 1 + 7 + 2;
    return embedded ? w + cell[4] + 1 : w;
  }
};

std::string padded(const std::string& text, std::size_t width) {
  const std::size_t n = columns(text);
  return n >= width ? text : text + std::string(width - n, ' ');
}

// A cell's text padded, then coloured by what it says (colour codes take no
// columns, so they go on after the padding).
std::string cell_text(const std::string& text, std::size_t width, bool colour) {
  const bool failing = text.rfind("fails", 0) == 0;
  return failing ? paint(padded(text, width), Tone::warning, colour) : padded(text, width);
}

// `text` under a row (or, at indent 0, a paragraph of its own): wrapped at
// the terminal's width, indented by `indent`.
std::string row_note(std::size_t indent, const std::string& text) { return hanging("", text, indent); }

}  // namespace

std::string fuzz_search_options(std::optional<std::size_t> runs, std::size_t max_darts, std::size_t event_checks, const std::vector<std::string>& maps) {
  const analysis::FuzzOptions defaults;
  std::string out;
  if (runs && *runs != defaults.runs) out += fmt::format(" --runs {}", *runs);
  if (max_darts != defaults.max_darts) out += fmt::format(" --max-darts {}", max_darts);
  if (event_checks != defaults.event_checks) out += fmt::format(" --event-checks {}", event_checks);
  if (!maps.empty()) {
    out += " --maps";
    for (const auto& m : maps) out += fmt::format(" {}", shell_quote(m));
  }
  return out;
}

std::string fuzz_table(const FuzzRun& run, const std::vector<RuleResult>& results) {
  std::string out;
  std::size_t name = 4, verdict = 6, applications = 0;
  std::map<FuzzClass, std::size_t> classes;
  for (const auto& r : results) {
    name = std::max(name, columns(printable(r.name())));
    verdict = std::max(verdict, columns(r.verdict_text()));
    ++classes[r.fuzz->verdict];
    applications += r.fuzz->applications;
  }
  // Fitted like check's table: the dynamic column keeps at least 40
  // columns and wraps under itself; the names give up the rest, a longer
  // name getting a line of its own. Replay commands are never wrapped.
  const std::size_t width = terminal().width, dynamic_room = 40;
  if (name + 2 + verdict + 1 + dynamic_room > width)
    name = std::max<std::size_t>(12, width > verdict + 3 + dynamic_room ? width - verdict - 3 - dynamic_room : 0);
  const std::size_t dynamic_at = name + 2 + verdict + 1, indent = name + 2;
  const std::string under(indent, ' ');
  out += fmt::format("{}  {} dynamic\n", padded("rule", name), padded("static", verdict));
  for (const auto& result : results) {
    const auto& r = *result.fuzz;
    const std::string rule = printable(result.name());
    if (columns(rule) > name) out += rule + "\n";
    const auto lines = wrap_words(outcome_text(r), width > dynamic_at + 20 ? width - dynamic_at : 20);
    for (std::size_t k = 0; k < lines.size(); ++k)
      out += k == 0 ? fmt::format("{}  {} {}\n", padded(columns(rule) > name ? "" : rule, name), padded(result.verdict_text(), verdict), lines[k])
                    : std::string(dynamic_at, ' ') + lines[k] + "\n";
    if (r.event_contradiction) {
      const auto& ev = *r.event_contradiction;
      out += row_note(indent, fmt::format("{} (found in {}; a defect of dartcheck's event analysis, not of the rule)",
                                          printable(event_outcome_text(r)), ev.origin));
      for (std::size_t e = 1; e < ev.event_contradictions.size() && e < 4; ++e)
        out += row_note(indent, "and: " + printable(ev.event_contradictions[e]));
      if (ev.event_contradictions.size() > 4) out += fmt::format("{}and {} more\n", under, ev.event_contradictions.size() - 4);
      if (!result.events_replay.empty()) out += fmt::format("{}replay: {}\n", under, printable(result.events_replay));
    }
    if (!r.counterexample) continue;
    const auto& cx = *r.counterexample;
    out += row_note(indent, "found in " + cx.origin);
    if (!cx.unrepresentable.empty()) out += row_note(indent, "H has no dense form: " + cx.unrepresentable);
    for (std::size_t e = 0; e < cx.embedding_failures.size() && e < 4; ++e) out += row_note(indent, "H: " + cx.embedding_failures[e]);
    if (cx.embedding_failures.size() > 4) out += fmt::format("{}H: ... {} more\n", under, cx.embedding_failures.size() - 4);
    if (!result.fuzz_replay.empty())
      out += fmt::format("{}replay: {}\n", under, printable(result.fuzz_replay));
    else if (!result.entry->terms)  // a command to paste, never wrapped: the rule's seed comes from the run's seed and its name
      out += fmt::format("{}to write the host, the match and H with a replay command, run: {}\n", under,
                         printable(fmt::format("dartcheck fuzz {} --rule {} --seed {}{} -o DIR", shell_quote(run.catalog), shell_quote(result.name()),
                                               run.seed, run.search_options)));
  }
  const std::size_t bugs = classes[FuzzClass::soundness_bug], contradicted = count_results(results).events_contradicted;
  // The time by the wall clock, and the rate by it; a merge's shards'
  // summed time apart (a --jobs run works more seconds than it lasts).
  std::string time = fmt::format("{:.1f} s{} ({:.0f}/s)", run.seconds, run.wall_clock ? "" : " summed over the shards",
                                 run.seconds > 0 ? double(applications) / run.seconds : 0.0);
  if (run.shard_seconds && run.wall_clock) time += fmt::format(", the shards working {:.1f} s in all", *run.shard_seconds);
  out += fmt::format("\n{}: {} consistent statically with no counterexample, {} confirmed, {} unconfirmed, {}, {} contradicted; {} in {}; seed {}\n",
                     counted(results.size(), "rule"), classes[FuzzClass::consistent], classes[FuzzClass::confirmed], classes[FuzzClass::unconfirmed],
                     counted(bugs, "soundness bug"), counted(contradicted, "event analysis", "event analyses"), counted(applications, "application"),
                     time, run.seed);
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

namespace {

// The table's cells and column widths, fitted to the terminal: the
// verdict column keeps at least 20 columns (a longer verdict wraps under
// itself); the names give up the rest.
CheckColumns check_columns(const Catalog& catalog, const std::vector<RuleResult>& results, std::size_t width) {
  CheckColumns t;
  t.embedded = !catalog.embeddings.empty();
  for (const auto& r : results) {
    const auto bad = failing_names(r.embedding);
    t.names.push_back(printable(r.name()));
    t.models.push_back(printable(r.entry->rule.model().name));
    t.verdicts.push_back(r.verdict_text());
    t.cells.push_back({condition_cell(r.verdict, RuleCondition::incident_arcs), condition_cell(r.verdict, RuleCondition::dangling),
                       condition_cell(r.verdict, RuleCondition::non_orientation), condition_cell(r.verdict, RuleCondition::cycle),
                       bad.empty() ? "ok" : fmt::format("fails {}", fmt::join(bad, ","))});
    t.name = std::max(t.name, columns(t.names.back()));
    t.model = std::max(t.model, columns(t.models.back()));
    t.verdict = std::max(t.verdict, columns(t.verdicts.back()));
    for (std::size_t c = 0; c < 5; ++c) t.cell[c] = std::max(t.cell[c], columns(t.cells.back()[c]));
  }
  const std::size_t verdict_room = std::min<std::size_t>(t.verdict, 20);
  t.compact = 12 + t.fixed() + verdict_room > width;
  if (t.name + t.fixed() + verdict_room > width)
    t.name = std::max<std::size_t>(12, width > t.fixed() + verdict_room ? width - t.fixed() - verdict_room : 0);
  return t;
}

// What follows a rule's row: a differing verdict, caveats, expressions,
// the confirmation, the solver, and with --explain the witnesses.
std::string rule_notes(const RuleResult& r, const TableOptions& o, std::size_t indent, bool colour) {
  std::string out;
  const auto& v = r.verdict;
  if (!r.matches_record())
    out += paint(row_note(indent, r.first_run_finding() && r.mismatches.size() == 1
                                      ? fmt::format("no verdict recorded in the {}: see stderr", r.record_source_name())
                                      : fmt::format("differs from the {}: see stderr", r.record_source_name())),
                 Tone::error, colour);
  for (const auto& caveat : r.entry->caveats) out += row_note(indent, "note: " + printable(caveat));
  for (const auto& x : r.entry->expressions) {
    if (!x.read())
      out += row_note(indent, printable(fmt::format("opaque: {}.{}: {} ({})", x.node, x.embedding, x.reason, x.reason_location.str())));
    else if (o.explain)
      out += row_note(indent, printable(fmt::format("read: {}.{} = {}", x.node, x.embedding, x.term->str())));
  }
  if (r.host_search || r.scheme_search) out += row_note(indent, r.confirmation_text());
  for (const auto& line : r.solver_lines()) out += row_note(indent, printable(line));
  if (o.explain && !r.failures.empty()) {
    for (const auto& cond : v.conditions) {
      if (cond.holds) continue;
      for (const auto& w : cond.witnesses)
        out += row_note(indent + 2, fmt::format("{}{}: {}", cond.name(), w.subcondition ? fmt::format(" sub-condition {}", w.subcondition) : "",
                                                printable(w.text)));
    }
    for (const auto& e : r.embedding)
      for (const auto& w : e.witnesses)
        out += row_note(indent + 2, fmt::format("{}{}: {}", e.name, e.required ? "" : " (not required)", printable(w.text)));
    if (r.scheme_search && r.scheme_search->counterexample) {
      out += row_note(indent + 2, fmt::format("host: {}", printable(r.scheme_search->counterexample->origin)));
      // A command to paste, never wrapped: the same search, written out.
      out += fmt::format("{:{}}to write it with the match, H and a replay command, run: {}\n", "", indent + 2,
                         printable(fmt::format("dartcheck fuzz {} --rule {} --seed 1{} -o DIR", shell_quote(o.catalog), shell_quote(r.name()),
                                               fuzz_search_options(scheme_confirmation_runs, scheme_confirmation_darts, 0, {}))));
    }
    if (r.host_search && r.host_search->host) {
      out += row_note(indent + 2, "host G: " + printable(arcs_text(*r.host_search->host)));
      out += row_note(indent + 2, "result H: " + printable(arcs_text(*r.host_search->result)));
    }
  }
  return out;
}

// After the rows: the rules not checked, the embeddings' note, the
// expressions read, and the one summary line.
std::string check_summary(const Catalog& catalog, const std::vector<RuleResult>& results, std::size_t baseline_mismatches, const CheckColumns& t) {
  std::string out;
  const bool whole_catalog = results.size() == catalog.rules.size();
  if (whole_catalog)
    for (const auto& sk : catalog.skipped)
      out += printable(fmt::format("{}  not checked ({}): {}", padded(sk.name, t.name), sk.location.str(), sk.why)) + "\n";
  // Jerboa's expressions: how many were read as terms (docs/jerboa-expressions.md).
  std::size_t read = 0, opaque = 0;
  for (const auto& r : catalog.rules)
    for (const auto& x : r.expressions) ++(x.read() ? read : opaque);
  if (t.embedded) {
    out += '\n';
    out +=
        row_note(0, fmt::format("embeddings: {}{}", sufficiency_note,
                                opaque ? "; a rule with an opaque expression gets Jerboa's presence checks, its expressions compared as text" : ""));
  }
  if (read + opaque)
    out += fmt::format("\n{}: {} expressions read, {} opaque\n", catalog.modeler.empty() ? catalog.file : catalog.modeler, read, opaque);
  const auto counts = count_results(results);
  const std::size_t mismatches = changed_verdicts(results) + baseline_mismatches;
  const std::string_view source = results.empty() ? "catalog" : results.front().record_source_name();
  // The summary stays on one line, for the logs that grep it.
  out += fmt::format("\n{}, {} consistent, {} with failing conditions{}; {} differ{} from the {}{}\n", plural(counts.rules, "rule", "rules"),
                     counts.consistent, counts.failing,
                     catalog.skipped.empty() || !whole_catalog ? "" : fmt::format(", {} not checked", catalog.skipped.size()),
                     plural(mismatches, "verdict", "verdicts"), mismatches == 1 ? "s" : "", source,
                     counts.first_run_findings ? fmt::format(", {} with none recorded", counts.first_run_findings) : std::string());
  return out;
}

}  // namespace

std::string check_table(const Catalog& catalog, const std::vector<RuleResult>& results, std::size_t baseline_mismatches, const TableOptions& o) {
  std::string out;
  const bool colour = terminal().color_stdout;
  const std::size_t width = terminal().width;
  CheckColumns t = check_columns(catalog, results, width);
  const std::size_t indent = t.name + 2;
  if (!catalog.modeler.empty()) {
    std::vector<std::string> e;
    for (const auto& d : catalog.embeddings) e.push_back(fmt::format("{} <{}>", d.name, fmt::join(d.orbit, ",")));
    out += row_note(0, printable(fmt::format("Jerboa modeler {} ({}): {} rules read, {} skipped; embeddings: {}", catalog.modeler, o.catalog,
                                             catalog.rules.size(), catalog.skipped.size(),
                                             e.empty() ? std::string("none") : fmt::format("{}", fmt::join(e, ", "))))) +
           "\n";
  }
  const auto row = [&](const std::string& name, const std::string& model, const std::array<std::string, 5>& cells, const std::string& ms,
                       const std::string& verdict, bool paint_cells) {
    std::string line = padded(name, t.name) + "  " + padded(model, t.model) + " ";
    for (std::size_t c = 0; c < 4 && !t.compact; ++c) line += cell_text(cells[c], t.cell[c], paint_cells && colour) + " ";
    if (t.embedded && !t.compact) line += cell_text(cells[4], t.cell[4], paint_cells && colour) + " ";
    return line + fmt::format("{:>7}  ", ms) + verdict + "\n";
  };
  // The verdict's lines: one when it fits after the cells, else wrapped
  // under its own column.
  const auto verdict_lines = [&](const std::string& text, Tone tone) {
    const std::size_t start = t.name + t.fixed();
    std::vector<std::string> lines = wrap_words(text, std::max<std::size_t>(width > start ? width - start : 0, 16));
    for (auto& line : lines) line = paint(line, tone, colour);
    return lines;
  };
  out += row("rule", "model", {"I", "dangling", "O", "C", "embeddings"}, "ms", "verdict", false);
  for (std::size_t k = 0; k < results.size(); ++k) {
    const auto& r = results[k];
    const std::vector<std::string> verdict = verdict_lines(t.verdicts[k], r.failures.empty() ? Tone::good : Tone::warning);
    const bool own_line = columns(t.names[k]) > t.name;
    if (own_line) out += t.names[k] + "\n";
    out += row(own_line ? "" : t.names[k], t.models[k], t.cells[k], fmt::format("{:.2f}", r.static_ms), verdict.front(), true);
    for (std::size_t l = 1; l < verdict.size(); ++l) out += std::string(t.name + t.fixed(), ' ') + verdict[l] + "\n";
    out += rule_notes(r, o, indent, colour);
  }
  out += check_summary(catalog, results, baseline_mismatches, t);
  return out;
}

}  // namespace dartcheck::reports
