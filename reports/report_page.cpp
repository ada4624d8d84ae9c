#include "core/wording.hpp"
#include "reports/report_page.hpp"

#include "reports/ci_formats.hpp"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/counterexample_files.hpp"
#include "analysis/prove_replay.hpp"
#include "checkers/violation.hpp"
#include "core/output_file.hpp"
#include "events/static_events.hpp"
#include "reports/counterexample_dot.hpp"
#include "reports/embedding_picture.hpp"
#include "reports/html_page.hpp"
#include "reports/render.hpp"
#include "reports/rule_dot.hpp"
#include "reports/rule_result_text.hpp"
#include "reports/svg_figure.hpp"
#include "rewriting/pattern_graphs.hpp"

namespace dartcheck::reports {

using namespace analysis;

namespace fs = std::filesystem;

Pictures::Pictures(std::string dir, std::string engine) : dir_(std::move(dir)), engine_(std::move(engine)) {}

void Pictures::write(const std::string& svg, const std::string& file) {
  const fs::path path = fs::path(dir_) / file;
  ensure_directory(path.parent_path().string());
  write_file(path.string(), svg);
  ++count_;
}

std::string Pictures::link(const std::string& file) {
  // The file name may hold a rule name's %XX escapes (file_stem): the link
  // percent-encodes them again.
  return fmt::format("<p class=\"note\">Picture: <a href=\"{}\">{}</a></p>\n", html_text(uri_path(file)), html_text(file));
}

std::string Pictures::add(const std::string& dot, const std::string& file) {
  const std::string svg = render(dot, "svg", engine_);
  write(svg, file);
  return fmt::format("<div class=\"picture\">{}</div>\n", inline_svg(svg, fmt::format("p{}_", count_))) + link(file);
}

std::string Pictures::add(const CounterexampleFigure& figure, const std::string& file) {
  const std::string head = render(figure.head, "svg", engine_);
  const std::vector<std::string> panels = {render(figure.host, "svg", engine_), render(figure.result, "svg", engine_),
                                           render(figure.rule, "svg", engine_)};
  write(svg_figure(head, panels), file);
  std::string out =
      fmt::format("<div class=\"figure\">\n<div class=\"head\">{}</div>\n<div class=\"panels\">\n", inline_svg(head, fmt::format("p{}h_", count_)));
  for (std::size_t k = 0; k < panels.size(); ++k)
    out += fmt::format("<div class=\"panel\">{}</div>\n", inline_svg(panels[k], fmt::format("p{}_{}_", count_, k)));
  return out + "</div>\n</div>\n" + link(file);
}

namespace {

const JerboaLabels* labels_of(const CatalogRule& e) { return e.jerboa ? &*e.jerboa : nullptr; }

// "H breaks C(0,2) at darts 3, 7; I(1) at dart 5": each broken constraint
// and its first darts, for the picture's caption.
std::string broken_caption(const Counterexample& cx) {
  std::vector<std::pair<std::string, std::vector<std::uint32_t>>> broken;
  for (const auto& viol : cx.violations) {
    const std::string name = constraint_name(viol);
    auto it = std::find_if(broken.begin(), broken.end(), [&](const auto& b) { return b.first == name; });
    if (it == broken.end()) it = broken.insert(broken.end(), {name, {}});
    if (std::find(it->second.begin(), it->second.end(), viol.element) == it->second.end()) it->second.push_back(viol.element);
  }
  std::vector<std::string> parts;
  for (const auto& [name, darts] : broken) {
    constexpr std::size_t shown = 6;
    const std::vector<std::uint32_t> first(darts.begin(), darts.begin() + static_cast<std::ptrdiff_t>(std::min(darts.size(), shown)));
    parts.push_back(
        fmt::format("{} at dart{} {}{}", name, darts.size() == 1 ? "" : "s", fmt::join(first, ", "), darts.size() > shown ? ", ..." : ""));
  }
  for (const auto& e : cx.broken_embeddings) parts.push_back(e);
  return "H " + (parts.empty() ? cx.broken_predicate() : cx.broken_predicate(fmt::format("{}", fmt::join(parts, "; "))));
}

// The three panels of a counterexample: the match (DPO: L's node names on
// their darts; schemes: every dart of each hook's pattern P_v, named by its
// hook's node), the darts H breaks, and the rule.
CounterexampleFigure counterexample_figure(const CatalogRule& e, const RuleVerdict& v, const Counterexample& cx, const std::string& title) {
  CounterexamplePicture p;
  p.title = title;
  p.host = &cx.host;
  p.match_tags.assign(cx.host.size(), "");
  if (!cx.match.empty()) {
    for (const auto& [node, d] : cx.match)
      if (d < cx.host.size()) p.match_tags[d] = node;
    p.match_label = "filled: the match";
  } else {
    const auto pattern = pattern_graphs(e.rule.model(), e.words, cx.host, cx.hooks);
    for (std::size_t k = 0; k < cx.hooks.size(); ++k) {
      const std::string node = e.rule.left().name(e.rule.hooks()[k]);
      if (pattern.ok())
        for (Dart d : pattern.value->darts[k]) p.match_tags[d] = node;
      p.match_tags[cx.hooks[k]] = node + "*";
    }
    p.match_label = pattern.ok() ? "filled: P_v, * the hook" : "filled: the hooks";
  }
  if (cx.result) {
    p.result = &*cx.result;
    p.broken.assign(cx.result->size(), false);
    for (const auto& viol : cx.violations)
      if (viol.element < p.broken.size()) p.broken[viol.element] = true;
    // Embedded rules: the orbits with two values or an unlabeled dart,
    // each dart tagged with its value.
    for (std::size_t d = 0; d < cx.orbit_values.size() && d < p.broken.size(); ++d)
      if (!cx.orbit_values[d].empty()) p.broken[d] = true;
    // Each dart of H named by the rule node it comes from (as G's by the
    // match), then the values of the orbits that broke.
    p.result_tags.assign(cx.result->size(), "");
    for (const auto& [node, d] : cx.comatch)
      if (d < p.result_tags.size()) p.result_tags[d] = node;
    for (std::size_t d = 0; d < cx.orbit_values.size() && d < p.result_tags.size(); ++d)
      if (!cx.orbit_values[d].empty()) p.result_tags[d] += (p.result_tags[d].empty() ? "" : "\n") + cx.orbit_values[d];
    p.broken_label = fmt::format("filled: {}", cx.broken_predicate());
    p.captions.push_back(broken_caption(cx));
  } else {
    p.no_result = cx.unrepresentable;
  }
  if (!cx.result) p.captions.push_back("H has no dense form");
  const auto conditions = failure_captions(v);
  p.captions.insert(p.captions.end(), conditions.begin(), conditions.end());
  return counterexample_figure(e.rule, e.words, failed_witnesses(v), p, labels_of(e));
}

// What a counterexample breaks, one sentence per violation (up to 12).
std::string violations_html(const Counterexample& cx) {
  std::string out = "<ul class=\"witnesses\">\n";
  if (!cx.unrepresentable.empty()) out += fmt::format("<li>H has no dense form: {}</li>\n", html_text(cx.unrepresentable));
  for (std::size_t k = 0; k < cx.violations.size() && k < 12; ++k)
    out += fmt::format("<li>{}</li>\n", html_text(describe(cx.violations[k], fmt::format("dart {}", cx.violations[k].element))));
  if (cx.violations.size() > 12) out += fmt::format("<li>... and {} more</li>\n", cx.violations.size() - 12);
  return out + "</ul>\n";
}

std::string counterexample_html(const RuleResult& r, const Counterexample& cx, const std::string& heading, const std::string& replay,
                                Pictures& pictures, const std::string& file) {
  const auto& e = *r.entry;
  std::string out = fmt::format("<h3>{}</h3>\n<p>{} Found by {}{}.</p>\n", html_text(heading),
                                html_text(fmt::format("A valid {} of {} darts; applied at hook{} {}, H {}.", e.rule.model().name, cx.host.size(),
                                                      cx.hooks.size() == 1 ? "" : "s", fmt::join(cx.hooks, ","), cx.broken_predicate())),
                                html_text(cx.origin), cx.minimal ? " (minimal: no smaller host breaks it)" : "");
  out += pictures.add(counterexample_figure(e, r.verdict, cx, fmt::format("{}: {}", e.rule.name(), heading)), file);
  out += violations_html(cx);
  if (!replay.empty()) out += fmt::format("<p>Replay: <code>{}</code></p>\n", html_text(replay));
  return out;
}

std::string kind_of(const CatalogRule& e) {
  if (e.jerboa) return fmt::format("Jerboa-style rule scheme, parameter orbit type {}", orbit_type_str(e.jerboa->parameter));
  return e.is_scheme() ? "(W,D)-rule scheme" : "DPO rule";
}

std::string fuzz_cell(const FuzzReport& f) {
  switch (f.verdict) {
    case FuzzClass::consistent:  // what the run checked, never "consistent" alone
      return fmt::format("<td class=\"ok\">no counterexample ({}; {})</td>", counted(f.applications, "application"), html_text(f.checked));
    case FuzzClass::confirmed:
      return fmt::format("<td class=\"fails\">confirmed ({} darts)</td>", f.counterexample->host.size());
    case FuzzClass::unconfirmed:
      return "<td class=\"skipped\">unconfirmed</td>";
    case FuzzClass::soundness_bug:
      return "<td class=\"bug\">SOUNDNESS BUG</td>";
  }
  return "<td></td>";
}

// The model-level confirmation in a cell: confirmed (the host's darts), not
// found (up to how many darts), or nothing for a rule it did not run on.
std::string confirmation_cell(const RuleResult& r) {
  if (!r.host_search && !r.scheme_search) return "<td class=\"none\">-</td>";
  if (r.unsound()) return fmt::format("<td class=\"bug\">{}</td>", html_text(r.confirmation_text()));
  const bool found = r.scheme_search ? r.scheme_search->counterexample.has_value() : r.host_search->host.has_value();
  return fmt::format("<td class=\"{}\">{}</td>", found ? "fails" : "skipped", html_text(r.confirmation_text()));
}

// The event contradiction goes next to the verdict, never in its place.
std::string fuzz_cells(const FuzzReport& f) {
  std::string cell = fuzz_cell(f);
  if (f.event_contradiction) cell.insert(cell.size() - 5, "; <span class=\"bug\">EVENT ANALYSIS CONTRADICTED</span>");
  return cell;
}

// The embedding checks of a rule: "-" without any, "ok", or the failing
// ones (a check not required is named but does not fail the cell), the
// first linked to its entry under "Conditions that fail".
std::string embedding_cell(const std::string& rule, const std::vector<EmbeddingCheck>& checks) {
  if (checks.empty()) return "<td class=\"none\">-</td>";
  std::vector<std::string> failing;
  bool required = false;
  std::string target;
  for (const auto& c : checks) {
    if (c.holds) continue;
    failing.push_back(c.required ? c.name : c.name + " (not required)");
    required = required || c.required;
    if (target.empty()) target = html_id(rule + "." + c.name);
  }
  if (failing.empty()) return "<td class=\"ok\">ok</td>";
  return fmt::format("<td class=\"{}\"><a href=\"#{}\">{}</a></td>", required ? "fails" : "skipped", target,
                     html_text(fmt::format("{}", fmt::join(failing, ", "))));
}

std::string prove_cell(const proofs::RuleProof& p) {
  if (!p.out_of_scope.empty()) return "<td class=\"none\">out of scope</td>";
  using proofs::Agreement;
  const auto bad = p.count(Agreement::disagree);
  return fmt::format("<td class=\"{}\">{} agree, {} disagree, {} unresolved, {} not compared</td>", bad ? "bug" : "ok", p.count(Agreement::agree),
                     bad, p.count(Agreement::unresolved), p.count(Agreement::not_compared));
}

}  // namespace

std::string verdict_table_html(const std::vector<RuleResult>& rows, bool fuzzed, bool proved) {
  static constexpr std::pair<RuleCondition, const char*> kinds[] = {{RuleCondition::incident_arcs, "I"},
                                                                    {RuleCondition::dangling, "dangling"},
                                                                    {RuleCondition::non_orientation, "O"},
                                                                    {RuleCondition::cycle, "C"},
                                                                    {RuleCondition::no_loop, "no-loop"}};
  // Embedded rules get a column of their own, so that a rule failing
  // only an embedding condition does not read "ok" in every cell.
  const bool embedded = std::any_of(rows.begin(), rows.end(), [](const RuleResult& r) { return !r.embedding.empty(); });
  std::string out = "<table class=\"verdicts\">\n<tr><th>rule</th><th>model</th>";
  for (const auto& [kind, name] : kinds) out += fmt::format("<th>{}</th>", name);
  if (embedded) out += "<th>embedding</th>";
  // check's model-level confirmation of the failing rules (--confirm-darts).
  const bool confirmed = std::any_of(rows.begin(), rows.end(), [](const RuleResult& r) { return r.host_search || r.scheme_search; });
  out += "<th>static verdict</th><th>recorded</th>";
  if (confirmed) out += "<th>confirmation</th>";
  if (fuzzed) out += "<th>fuzz</th>";
  if (proved) out += "<th>prove</th>";
  out += "</tr>\n";
  for (const auto& r : rows) {
    const auto& e = *r.entry;
    const std::string id = html_id(e.rule.name());
    out += fmt::format("<tr><td><a href=\"#{}\">{}</a></td><td>{}</td>", id, html_text(e.rule.name()), html_text(e.rule.model().name));
    for (const auto& [kind, name] : kinds) {
      const std::string text = condition_cell(r.verdict, kind);
      const std::string cls = text == "ok" ? "ok" : text == "-" ? "none" : text == "skipped" ? "skipped" : "fails";
      // A failing cell links to the first failing condition of its kind.
      std::string target;
      for (const auto& c : r.verdict.conditions)
        if (c.condition == kind && !c.holds && target.empty()) target = html_id(e.rule.name() + "." + c.name());
      out += target.empty() ? fmt::format("<td class=\"{}\">{}</td>", cls, html_text(text))
                            : fmt::format("<td class=\"{}\"><a href=\"#{}\">{}</a></td>", cls, target, html_text(text));
    }
    if (embedded) out += embedding_cell(e.rule.name(), r.embedding);
    out += fmt::format(
        "<td>{}</td><td class=\"{}\">{}</td>", html_text(r.verdict_text()), r.matches_record() ? "ok" : "fails",
        html_text(r.matches_record()      ? std::string("matches")
                  : r.first_run_finding() ? fmt::format("no verdict recorded (the {} records none)", r.record_source_name())
                                          : fmt::format("MISMATCH: {} records {}", r.record_source_name(), r.recorded_text())));
    if (confirmed) out += confirmation_cell(r);
    if (fuzzed) out += r.fuzz ? fuzz_cells(*r.fuzz) : "<td></td>";
    if (proved) out += r.proof ? prove_cell(*r.proof) : "<td></td>";
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

namespace {

// The rule's topological events per orbit type (004 Sec. 3), as
// `dartcheck events` prints them: rule orbits with an event, their
// completeness and the events with their certainty.
std::string events_table(const Operation& op) {
  const auto view = events::event_rule(op);
  if (!view.rule) return fmt::format("<h3>Topological events (004)</h3>\n<p class=\"note\">Not analysed: {}</p>\n", html_text(view.why));
  std::string rows;
  for (const auto& kind : events::all_orbit_kinds(op.rule.model())) {
    const auto k = events::static_events(*view.rule, kind);
    for (int side = 0; side < 2; ++side) {
      const auto& so = side == 0 ? k.left : k.right;
      for (int o = 0; o < static_cast<int>(so.orbits.size()); ++o) {
        std::vector<std::string> claims;
        for (const auto& c : k.claims)
          if (c.orbit == o && (c.event == events::Event::creation) == (side == 1)) claims.push_back(events::claim_summary(*view.rule, k, c));
        if (claims.empty()) continue;
        const auto& ro = so.orbits[static_cast<std::size_t>(o)];
        rows += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n", html_text(kind.str()),
                            html_text(events::rule_orbit_name(*view.rule, k, side == 0, o)),
                            html_text(ro.complete ? "complete" : fmt::format("incomplete ({})", fmt::join(ro.missing, "; "))),
                            html_text(fmt::format("{}", fmt::join(claims, "; "))));
      }
    }
  }
  return "<h3>Topological events (004)</h3>\n<table>\n<tr><th>orbit type</th><th>rule orbit</th><th>complete</th><th>events</th></tr>\n" + rows +
         "</table>\n";
}

// Every failing condition with its witnesses; skipped ones with the reason.
std::string failing_html(const RuleResult& r) {
  const std::string& name = r.name();
  std::string failing;
  for (const auto& c : r.verdict.conditions) {
    if (c.holds && c.skipped.empty()) continue;
    failing += fmt::format("<li id=\"{}\"><b>{}</b> {}", html_id(name + "." + c.name()), html_text(c.name()),
                           c.holds ? "skipped: " + html_text(c.skipped) : "fails");
    if (!c.witnesses.empty()) {
      failing += "\n<ul class=\"witnesses\">\n";
      for (const auto& w : c.witnesses)
        failing +=
            fmt::format("<li>{}in {}: {}</li>\n", w.subcondition ? fmt::format("sub-condition {} ", w.subcondition) : "", w.side, html_text(w.text));
      failing += "</ul>\n";
    }
    failing += "</li>\n";
  }
  for (const auto& c : r.embedding) {
    if (c.holds) continue;
    failing += fmt::format("<li id=\"{}\"><b>{}</b> fails{} ({}: sufficient, not necessary)\n<ul class=\"witnesses\">\n",
                           html_id(name + "." + c.name), html_text(c.name), c.required ? "" : " (not required)", c.source);
    for (const auto& w : c.witnesses) failing += fmt::format("<li>{}</li>\n", html_text(w.text));
    failing += "</ul></li>\n";
  }
  return failing.empty() ? std::string() : "<h3>Conditions that fail</h3>\n<ul>\n" + failing + "</ul>\n";
}

// Each expression's Java, and the term it was read as or why not
// (docs/jerboa-expressions.md).
std::string expressions_html(const std::vector<NodeExpression>& expressions) {
  if (expressions.empty()) return "";
  std::string out;
  out += "<h3>Embedding expressions</h3>\n<ul>\n";
  for (const auto& x : expressions)
    out += fmt::format("<li>{}.{}: <code>{}</code><br>{}</li>\n", html_text(x.node), html_text(x.embedding), html_text(x.code),
                       x.read() ? fmt::format("read as <code>{}</code>", html_text(x.term->str()))
                                : fmt::format("<b>opaque</b>: {} ({})", html_text(x.reason), html_text(x.reason_location.str())));
  out += "</ul>\n";
  return out;
}

// The fuzz stage: its outcome, refusals, counterexample and event
// contradiction.
std::string fuzz_html(const RuleResult& r, Pictures& pictures) {
  const std::string stem = file_stem(r.name());
  std::string out;
  const auto& f = *r.fuzz;
  out += fmt::format("<h3>Fuzz</h3>\n<p>{}</p>\n", html_text(outcome_text(f)));
  if (!f.refusals.empty()) {
    std::vector<std::string> refused;
    for (const auto& [why, n] : f.refusals) refused.push_back(fmt::format("{} {}", n, why));
    out += fmt::format("<p class=\"note\">Refused matches: {}.</p>\n", html_text(fmt::format("{}", fmt::join(refused, ", "))));
  }
  if (f.counterexample)
    out += counterexample_html(r, *f.counterexample, "Fuzz counterexample", r.fuzz_replay, pictures, "counterexamples/" + stem + ".fuzz.svg");
  if (f.event_contradiction) {
    const auto& cx = *f.event_contradiction;
    out += fmt::format(
        "<h4 class=\"bug\">Event analysis contradicted (a defect of dartcheck's event analysis, not of the rule)</h4>\n"
        "<p>At hook{} {} of a {}-dart map ({}):</p>\n<ul>\n",
        cx.hooks.size() > 1 ? "s" : "", fmt::join(cx.hooks, ","), cx.host.size(), html_text(cx.origin));
    for (const auto& c : cx.event_contradictions) out += fmt::format("<li>{}</li>\n", html_text(c));
    out += "</ul>\n";
    if (!r.events_replay.empty()) out += fmt::format("<p>Replay: <code>{}</code></p>\n", html_text(r.events_replay));
  }
  return out;
}

// The solver stage: per constraint its answers and counterexample, per
// embedding its refined verdict.
std::string proof_html(const RuleResult& r, Pictures& pictures) {
  const std::string stem = file_stem(r.name());
  std::string out;
  const auto& p = *r.proof;
  out += "<h3>Prove (Z3)</h3>\n";
  if (!p.out_of_scope.empty()) {
    out += fmt::format("<p>Out of the solver's scope: {}</p>\n", html_text(p.out_of_scope));
  } else {
    out += "<table>\n<tr><th>constraint</th><th>static</th><th>theorem class</th><th>maps of the model</th><th>agreement</th><th>note</th></tr>\n";
    for (const auto& c : p.constraints)
      out += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"{}\">{}</td><td>{}</td></tr>\n", html_text(c.constraint.name()),
                         c.static_holds ? (*c.static_holds ? "holds" : "fails") : "-",
                         html_text(c.theorem  ? answer_text(*c.theorem)
                                   : p.scheme ? "(scheme: maps only)"
                                              : "(no theorem)"),
                         html_text(answer_text(c.model)), c.agreement == proofs::Agreement::disagree ? "bug" : "none", proofs::name_of(c.agreement),
                         html_text(c.note));
    out += "</table>\n";
    for (std::size_t k = 0; k < p.constraints.size(); ++k)
      if (r.proof_maps[k])
        out += counterexample_html(r, *r.proof_maps[k], fmt::format("Solver counterexample for {}", p.constraints[k].constraint.name()),
                                   r.proof_replays[k], pictures, "counterexamples/" + stem + ".prove." + constraint_stem(p.constraints[k]) + ".svg");
  }
  // Embeddings: the refined verdict per embedding (docs/prove.md, Embeddings).
  const auto lines = r.solver_lines();
  if (!lines.empty()) {
    out += "<ul>\n";
    for (const auto& line : lines) out += fmt::format("<li>{}</li>\n", html_text(line));
    for (const auto& replay : r.embedding_replays)
      if (!replay.empty()) out += fmt::format("<li>Replay: <code>{}</code></li>\n", html_text(replay));
    out += "</ul>\n";
  }
  return out;
}

}  // namespace

std::string rule_section_html(const RuleResult& r, Pictures& pictures) {
  const auto& e = *r.entry;
  const std::string name = e.rule.name(), stem = file_stem(name);
  std::string out = fmt::format("<h2 id=\"{}\">{}</h2>\n<p>{} on {}; {}:{}. L has {} nodes, R has {}.</p>\n", html_id(name), html_text(name),
                                html_text(kind_of(e)), html_text(e.rule.model().name), html_text(e.location.file), e.location.line,
                                e.rule.left().node_count(), e.rule.right().node_count());
  if (!e.note.empty()) out += fmt::format("<p class=\"note\">{}</p>\n", html_text(e.note));
  out += fmt::format("<p>Static verdict: <b>{}</b>; recorded: {}{}</p>\n", html_text(r.verdict_text()), html_text(r.recorded_text()),
                     r.matches_record()      ? ""
                     : r.first_run_finding() ? " <span class=\"mismatch\">(a finding: nothing recorded)</span>"
                                             : " <span class=\"mismatch\">(MISMATCH)</span>");
  if (const std::string c = r.confirmation_text(); !c.empty()) out += fmt::format("<p>Model-level confirmation (as check's): {}</p>\n", html_text(c));
  auto embedded = embedding_picture(e, r.embedding);
  auto witnesses = failed_witnesses(r.verdict);
  witnesses.insert(witnesses.end(), embedded.witnesses.begin(), embedded.witnesses.end());
  auto captions = failure_captions(r.verdict);
  captions.insert(captions.end(), embedded.captions.begin(), embedded.captions.end());
  out += pictures.add(rule_dot(e.rule, e.words, witnesses, labels_of(e), embedded.terms, captions), "rules/" + stem + ".svg");

  out += failing_html(r);
  out += expressions_html(e.expressions);
  for (const auto& caveat : e.caveats) out += fmt::format("<p class=\"note\">Not represented: {}</p>\n", html_text(caveat));
  out += events_table(e);

  if (r.fuzz) out += fuzz_html(r, pictures);
  if (r.proof) out += proof_html(r, pictures);
  return out;
}

}  // namespace dartcheck::reports
