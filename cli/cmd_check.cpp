// `dartcheck check`: the static conditions of every rule of a catalog, as a
// table of rules x conditions, compared with the verdicts the catalog
// records. A failing rule is also run on every small map of its model
// that contains L (checkers/host_search), so the report says whether the
// failure is confirmed on a real map or only per constraint.
#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "checkers/host_search.hpp"
#include "checkers/rule_conditions.hpp"
#include "cli/commands.hpp"
#include "analysis/verdict_record.hpp"
#include "cli/options.hpp"
#include "cli/report_text.hpp"
#include "reports/html_page.hpp"
#include "analysis/map_sources.hpp"
#include "analysis/fuzz.hpp"
#include "io/baseline.hpp"
#include "io/catalog.hpp"
#include "core/input_error.hpp"

namespace dartcheck::cli {

using namespace analysis;  // the engines the commands call
namespace {

struct Checked {
  const CatalogRule* entry;
  RuleVerdict verdict;
  std::vector<std::string> failures;  // topological conditions, then embedding checks
  std::vector<EmbeddingCheck> embedding;  // catalogs that declare embeddings
  std::optional<HostSearch> search;  // failing DPO rules only
  std::optional<FuzzReport> scheme_search;  // every scheme
  bool unsound = false;  // judged consistent, yet broke a map
  double millis = 0;
  bool matches_record = true;
};

std::string arcs_text(const TopoGraph& g) {
  std::string s;
  for (const auto& a : g.arcs()) s += fmt::format("{}{} -{}-> {}", s.empty() ? "" : ", ", g.name(a.source), a.label, g.name(a.target));
  return s;
}

std::string model_level(const Checked& c) {
  if (c.scheme_search) {
    const auto& f = *c.scheme_search;
    if (f.counterexample) {
      const auto& cx = *f.counterexample;
      return fmt::format("{}confirmed: applied at dart{} {} of a {}-dart {}, it breaks ({})", c.unsound ? "SOUNDNESS BUG: judged consistent, yet " : "",
                         cx.hooks.size() > 1 ? "s" : "", fmt::join(cx.hooks, ","), cx.host.size(), c.entry->rule.model().name,
                         fmt::join(cx.broken(), ", "));
    }
    if (f.applications == 0) return fmt::format("never applicable on {} {} maps of up to {} darts", f.hosts, c.entry->rule.model().name, f.largest_host);
    return fmt::format("no model-level counterexample in {} applications on {} {} maps of up to {} darts", f.applications, f.hosts,
                       c.entry->rule.model().name, f.largest_host);
  }
  if (!c.search) return "";
  const auto& s = *c.search;
  if (s.host) {
    std::vector<std::string> what;
    for (const auto& v : s.violations) what.push_back(constraint_name(v));
    std::sort(what.begin(), what.end());
    what.erase(std::unique(what.begin(), what.end()), what.end());
    return fmt::format("confirmed: a {}-dart {} breaks ({})", s.host->node_count(), c.entry->rule.model().name, fmt::join(what, ", "));
  }
  if (!s.matched) return fmt::format("L matches no {} of up to {} darts", c.entry->rule.model().name, s.largest_host);
  return fmt::format("no model-level counterexample up to {} darts{}", s.largest_host, s.exhausted ? "" : " (search budget reached)");
}

std::string recorded_text(const CatalogRule& e) {
  if (!e.expected_failures) return "no verdict recorded";
  return e.expected_failures->empty() ? "consistent" : fmt::format("{}", fmt::join(*e.expected_failures, " "));
}

// One SARIF result per failing condition (witness sentences as the
// message), at the rule's line in the catalog: level "error" when the
// catalog does not record that failure, "note" when it does; plus an
// error for a recorded failure that does not occur and for a soundness
// bug. SARIF 2.1.0, as GitHub code scanning reads it.
void print_sarif(const std::string& file, const std::vector<Checked>& rows) {
  std::vector<std::string> results;
  std::vector<std::string> rule_ids;
  auto location = [&](const SourceLocation& at) {
    return fmt::format("[{{\"physicalLocation\": {{\"artifactLocation\": {{\"uri\": \"{}\"}}, \"region\": {{\"startLine\": {}, \"startColumn\": {}}}}}}}]",
                       json_escape(at.file.empty() ? file : at.file), std::max(at.line, 1), std::max(at.column, 1));
  };
  auto result = [&](const std::string& id, bool error, const std::string& text, const CatalogRule& e) {
    if (std::find(rule_ids.begin(), rule_ids.end(), id) == rule_ids.end()) rule_ids.push_back(id);
    results.push_back(fmt::format("{{\"ruleId\": \"{}\", \"level\": \"{}\", \"message\": {{\"text\": \"{}\"}}, \"locations\": {}, "
                                  "\"properties\": {{\"rule\": \"{}\", \"recorded\": \"{}\"}}}}",
                                  json_escape(id), error ? "error" : "note", json_escape(text), location(e.location), json_escape(e.rule.name()),
                                  json_escape(recorded_text(e))));
  };
  for (const Checked& c : rows) {
    const CatalogRule& e = *c.entry;
    const auto recorded = [&](const std::string& name) {
      return e.expected_failures && std::find(e.expected_failures->begin(), e.expected_failures->end(), name) != e.expected_failures->end();
    };
    for (const auto& v : c.verdict.conditions) {
      if (v.holds) continue;
      std::vector<std::string> texts;
      for (const auto& w : v.witnesses) texts.push_back(w.text);
      result(v.name(), !recorded(v.name()), fmt::format("rule {}: {} fails: {}", e.rule.name(), v.name(), fmt::join(texts, "; ")), e);
    }
    for (const auto& name : failing_names(c.embedding)) result(name, !recorded(name), fmt::format("rule {}: {} fails", e.rule.name(), name), e);
    if (e.expected_failures)
      for (const auto& name : *e.expected_failures)
        if (std::find(c.failures.begin(), c.failures.end(), name) == c.failures.end())
          result("verdict", true, fmt::format("rule {}: the catalog records {} failing, but it holds", e.rule.name(), name), e);
    if (c.unsound) result("soundness", true, fmt::format("rule {}: {}", e.rule.name(), model_level(c)), e);
  }
  std::vector<std::string> rules;
  for (const auto& id : rule_ids)
    rules.push_back(fmt::format("{{\"id\": \"{}\", \"shortDescription\": {{\"text\": \"{}\"}}}}", json_escape(id),
                                id == "verdict"     ? "a failure the catalog records does not occur"
                                : id == "soundness" ? "a rule judged consistent broke a map"
                                                    : "a consistency condition of 002 (Def. 11-16, 21-27) or an embedding condition of 003 fails"));
  fmt::print("{{\"$schema\": \"https://json.schemastore.org/sarif-2.1.0.json\", \"version\": \"2.1.0\", \"runs\": [{{\"tool\": {{\"driver\": "
             "{{\"name\": \"dartcheck\", \"version\": \"{}\", \"rules\": [{}]}}}}, \"results\": [\n{}\n]}}]}}\n",
             DARTCHECK_VERSION, fmt::join(rules, ", "), fmt::join(results, ",\n"));
}

// JUnit XML: one test case per rule, failing when its verdict differs from
// the catalog's record (what makes `check` exit 1).
void print_junit(const std::string& file, const std::vector<Checked>& rows, std::size_t mismatches) {
  double total = 0;
  for (const Checked& c : rows) total += c.millis;
  fmt::print("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"dartcheck check\" tests=\"{}\" failures=\"{}\" time=\"{:.3f}\">\n"
             "<testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n",
             rows.size(), mismatches, total / 1000, reports::html_text(file), rows.size(), mismatches, total / 1000);
  for (const Checked& c : rows) {
    const CatalogRule& e = *c.entry;
    const std::string verdict = c.failures.empty() ? "consistent" : fmt::format("fails {}", fmt::join(c.failures, " "));
    fmt::print("  <testcase name=\"{}\" classname=\"{}\" file=\"{}\" line=\"{}\" time=\"{:.6f}\">", reports::html_text(e.rule.name()),
               reports::html_text(e.rule.model().name), reports::html_text(e.location.file.empty() ? file : e.location.file), e.location.line, c.millis / 1000);
    if (!c.matches_record)
      fmt::print("\n    <failure message=\"{}\" type=\"verdict\">{}: {}; catalog records {}</failure>\n  ",
                 reports::html_text(fmt::format("{}, catalog records {}", verdict, recorded_text(e))), reports::html_text(e.location.str()), reports::html_text(verdict),
                 reports::html_text(recorded_text(e)));
    fmt::print("<system-out>{}</system-out></testcase>\n", reports::html_text(verdict + (model_level(c).empty() ? "" : "; " + model_level(c))));
  }
  fmt::print("</testsuite>\n</testsuites>\n");
}

}  // namespace

int check(const CheckOptions& o) {
  // SARIF and JUnit are check's own formats (code scanning and CI test
  // reports); the catalog is read as for text.
  const bool ci_format = o.format == "sarif" || o.format == "junit";
  Catalog catalog = read_command_catalog(o.catalog, o.rule, ci_format ? "text" : o.format);
  // A baseline replaces the recorded verdicts; its rules not checked
  // (unreadable) must be exactly those the reader skipped.
  std::vector<std::string> baseline_mismatches;
  if (!o.baseline.empty()) {
    const Baseline b = read_baseline(o.baseline);
    for (const auto& e : b.entries) {
      CatalogRule* r = nullptr;
      for (auto& x : catalog.rules)
        if (x.rule.name() == e.rule) r = &x;
      const bool skipped = std::any_of(catalog.skipped.begin(), catalog.skipped.end(), [&](const SkippedRule& s) { return s.name == e.rule; });
      if (!r && !skipped) throw InputError(e.location.file, e.location.line, e.location.column, fmt::format("the baseline names rule '{}', which {} does not have", e.rule, o.catalog));
      if (r && !e.failures)
        baseline_mismatches.push_back(fmt::format("{}: the baseline records rule '{}' as not checked, but it is read now", e.location.str(), e.rule));
      else if (r)
        r->expected_failures = e.failures, r->verdict_location = e.location;
      if (skipped && e.failures)
        baseline_mismatches.push_back(fmt::format("{}: the baseline records a verdict for rule '{}', which is not checked now", e.location.str(), e.rule));
    }
    for (const auto& s : catalog.skipped)
      if (!b.find(s.name))
        baseline_mismatches.push_back(fmt::format("rule '{}' is not checked ({}) and the baseline {} does not record it", s.name, s.why, o.baseline));
  }

  // The catalog's maps, built on first use.
  std::vector<std::optional<Map>> maps(catalog.maps.size());
  auto built_map = [&](std::size_t k) -> const Map& {
    if (!maps[k]) maps[k] = build_source(catalog.maps[k]);
    return *maps[k];
  };
  std::vector<Checked> rows;
  for (const auto& entry : catalog.rules) {
    if (!o.rule.empty() && entry.rule.name() != o.rule) continue;
    Checked c{&entry, {}, {}, {}, {}, {}, false, 0, true};
    const auto t0 = std::chrono::steady_clock::now();
    c.verdict = check_rule(entry.rule, entry.words);
    c.embedding = embedding_checks(catalog, entry);
    c.millis = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    for (const auto& v : c.verdict.conditions)
      if (!v.holds) c.failures.push_back(v.name());
    const bool topological_failure = !c.failures.empty();
    for (const auto& name : failing_names(c.embedding)) c.failures.push_back(name);
    c.matches_record = matches_record(entry, c.verdict, c.embedding);
    if (o.confirm_darts > 0 && entry.words.scheme) {
      // Schemes, consistent or not, run on every small map of their
      // model, the catalog's maps and random valid maps (the fuzzer with
      // a small fixed budget): a failure is confirmed or reported as not
      // found; a consistent scheme that breaks a map is a soundness bug
      // of the checker.
      std::vector<Map> extra;
      for (std::size_t k = 0; k < catalog.maps.size(); ++k)
        if (catalog.maps[k].model == entry.rule.model()) extra.push_back(built_map(k));
      FuzzOptions fo;
      fo.runs = 2000;
      fo.max_darts = 64;
      fo.event_checks = 0;  // check is about consistency; events are `fuzz` and `events`
      fo.static_check = [&](const Operation&) { return c.verdict; };
      c.scheme_search = fuzz_rule(entry, extra, fo);
      // Unsound: a broken constraint whose conditions all hold (embedding
      // failures count against the embedding conditions).
      if (const auto& cx = c.scheme_search->counterexample)
        c.unsound = !topological_failure && (!cx->violations.empty() || !cx->unrepresentable.empty() || failing_names(c.embedding).empty());
      if (c.unsound) c.matches_record = false;
    } else if (topological_failure && o.confirm_darts > 0) {
      c.search = search_hosts(entry.rule, entry.rule.model(), o.confirm_darts, {}, 200'000);
    }
    rows.push_back(std::move(c));
  }
  const auto mismatches = std::count_if(rows.begin(), rows.end(), [](const Checked& c) { return !c.matches_record; }) +
                          static_cast<std::ptrdiff_t>(baseline_mismatches.size());
  for (const auto& m : baseline_mismatches) fmt::print(stderr, "baseline: {}\n", m);
  if (!o.write_baseline.empty()) {
    std::vector<BaselineEntry> entries;
    for (const Checked& c : rows) entries.push_back({c.entry->rule.name(), c.failures, {}});
    for (const auto& s : catalog.skipped) entries.push_back({s.name, std::nullopt, {}});
    std::ofstream out(o.write_baseline);
    if (!out) throw InputError("<command line>", 0, 0, fmt::format("--write-baseline: cannot write '{}'", o.write_baseline));
    write_baseline(out, o.catalog, entries);
    fmt::print(stderr, "wrote {} ({} verdicts, {} not checked)\n", o.write_baseline, rows.size(), catalog.skipped.size());
  }

  if (o.format == "sarif") {
    print_sarif(o.catalog, rows);
    return mismatches ? violation : ok;
  }
  if (o.format == "junit") {
    print_junit(o.catalog, rows, mismatches);
    return mismatches ? violation : ok;
  }
  if (o.format == "json") {
    fmt::print("{{\"catalog\": \"{}\", \"rules\": [\n", json_escape(o.catalog));
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const auto& c = rows[k];
      fmt::print("  {{\"name\": \"{}\", \"model\": \"{}\", \"consistent\": {}, \"failures\": {}, \"expected\": {}, \"matches_record\": {},",
                 json_escape(c.entry->rule.name()), c.entry->rule.model().name, c.failures.empty() ? "true" : "false",
                 json_strings(c.failures), c.entry->expected_failures ? json_strings(*c.entry->expected_failures) : "null",
                 c.matches_record ? "true" : "false");
      fmt::print(" \"model_level\": \"{}\", \"conditions\": [", json_escape(model_level(c)));
      for (std::size_t m = 0; m < c.verdict.conditions.size(); ++m) {
        const auto& v = c.verdict.conditions[m];
        fmt::print("{}\n    {{\"condition\": \"{}\", \"holds\": {}, \"skipped\": \"{}\", \"witnesses\": [", m ? "," : "", v.name(),
                   v.holds ? "true" : "false", json_escape(v.skipped));
        for (std::size_t w = 0; w < v.witnesses.size(); ++w) {
          const auto& x = v.witnesses[w];
          fmt::print("{}{{\"subcondition\": {}, \"side\": \"{}\", \"nodes\": {}, \"arcs\": {}, \"words\": {}, \"text\": \"{}\"}}",
                     w ? ", " : "", x.subcondition, x.side, json_strings(x.nodes), json_strings(x.arcs), json_strings(x.words),
                     json_escape(x.text));
        }
        fmt::print("]}}");
      }
      fmt::print("], \"embedding_checks\": [");
      for (std::size_t m = 0; m < c.embedding.size(); ++m) {
        const auto& e = c.embedding[m];
        std::vector<std::string> texts;
        for (const auto& w : e.witnesses) texts.push_back(w.text);
        fmt::print("{}{{\"check\": \"{}\", \"holds\": {}, \"required\": {}, \"source\": \"{}\", \"witnesses\": {}}}", m ? ", " : "",
                   json_escape(e.name), e.holds, e.required, e.source, json_strings(texts));
      }
      fmt::print("], \"caveats\": {}}}{}\n", json_strings(c.entry->caveats), k + 1 < rows.size() ? "," : "");
    }
    fmt::print("], \"skipped\": [");
    for (std::size_t k = 0; k < catalog.skipped.size(); ++k)
      fmt::print("{}{{\"name\": \"{}\", \"verdict\": \"not checked\", \"why\": \"{}\", \"at\": \"{}\"}}", k ? ", " : "", json_escape(catalog.skipped[k].name),
                 json_escape(catalog.skipped[k].why), json_escape(catalog.skipped[k].location.str()));
    fmt::print("], \"mismatches\": {}}}\n", mismatches);
    return mismatches ? violation : ok;
  }

  std::size_t width = 4;
  for (const auto& c : rows) width = std::max(width, c.entry->rule.name().size());
  const bool embedded = !catalog.embeddings.empty();
  std::vector<std::string> ebd_cells;
  std::size_t ebd_width = 10;
  for (const auto& c : rows) {
    const auto bad = failing_names(c.embedding);
    ebd_cells.push_back(bad.empty() ? "ok" : fmt::format("fails {}", fmt::join(bad, ",")));
    ebd_width = std::max(ebd_width, ebd_cells.back().size());
  }
  if (!catalog.modeler.empty())
    fmt::print("Jerboa modeler {} ({}): {} rules read, {} skipped; embeddings: {}\n\n", catalog.modeler, o.catalog, catalog.rules.size(),
               catalog.skipped.size(), [&] {
                 std::vector<std::string> e;
                 for (const auto& d : catalog.embeddings) e.push_back(fmt::format("{} <{}>", d.name, fmt::join(d.orbit, ",")));
                 return e.empty() ? std::string("none") : fmt::format("{}", fmt::join(e, ", "));
               }());
  fmt::print("{:<{}}  {:<13} {:<10} {:<10} {:<10} {:<12} {}{:>7}  {}\n", "rule", width, "model", "I", "dangling", "O", "C",
             embedded ? fmt::format("{:<{}} ", "embeddings", ebd_width) : "", "ms", "verdict");
  std::size_t row = 0;
  for (const auto& c : rows) {
    const auto& v = c.verdict;
    const std::string verdict = c.failures.empty() ? "consistent" : fmt::format("fails {}", fmt::join(c.failures, " "));
    std::string record;
    if (!c.matches_record)
      record = c.entry->expected_failures
                   ? fmt::format("   MISMATCH: {} records {}", o.baseline.empty() ? "catalog" : "baseline", recorded_text(*c.entry))
                   : "   MISMATCH: no verdict recorded, so every condition must hold";
    fmt::print("{:<{}}  {:<13} {:<10} {:<10} {:<10} {:<12} {}{:>7.2f}  {}{}\n", c.entry->rule.name(), width, c.entry->rule.model().name,
               cell(v, RuleCondition::incident_arcs), cell(v, RuleCondition::dangling), cell(v, RuleCondition::non_orientation),
               cell(v, RuleCondition::cycle), embedded ? fmt::format("{:<{}} ", ebd_cells[row], ebd_width) : "", c.millis, verdict, record);
    ++row;
    for (const auto& caveat : c.entry->caveats) fmt::print("{:<{}}  note: {}\n", "", width, caveat);
    if (c.search || c.scheme_search) fmt::print("{:<{}}  {}\n", "", width, model_level(c));
    if (o.explain && !c.failures.empty()) {
      for (const auto& cond : v.conditions) {
        if (cond.holds) continue;
        for (const auto& w : cond.witnesses)
          fmt::print("{:<{}}    {}{}: {}\n", "", width, cond.name(), w.subcondition ? fmt::format(" sub-condition {}", w.subcondition) : "",
                     w.text);
      }
      for (const auto& e : c.embedding)
        for (const auto& w : e.witnesses) fmt::print("{:<{}}    {}{}: {}\n", "", width, e.name, e.required ? "" : " (not required)", w.text);
      if (c.scheme_search && c.scheme_search->counterexample)
        fmt::print("{:<{}}    host: {} (`dartcheck fuzz --rule {} --out DIR` writes it with a replay command)\n", "", width,
                   c.scheme_search->counterexample->origin, c.entry->rule.name());
      if (c.search && c.search->host)
        fmt::print("{:<{}}    host G: {}\n{:<{}}    result H: {}\n", "", width, arcs_text(*c.search->host), "", width,
                   arcs_text(*c.search->result));
    }
  }
  for (const auto& sk : catalog.skipped)
    if (o.rule.empty()) fmt::print("{:<{}}  not checked ({}): {}\n", sk.name, width, sk.location.str(), sk.why);
  if (embedded)
    fmt::print("\nembeddings: {}{}\n", sufficiency_note,
               catalog.signatures.size() == catalog.embeddings.size() ? "" : "; Jerboa expressions are compared as text, never evaluated");
  fmt::print("\n{} rules, {} consistent, {} with failing conditions{}; {} verdict{} differ{} from the {}\n", rows.size(),
             std::count_if(rows.begin(), rows.end(), [](const Checked& c) { return c.failures.empty(); }),
             std::count_if(rows.begin(), rows.end(), [](const Checked& c) { return !c.failures.empty(); }),
             catalog.skipped.empty() || !o.rule.empty() ? "" : fmt::format(", {} not checked", catalog.skipped.size()), mismatches,
             mismatches == 1 ? "" : "s", mismatches == 1 ? "s" : "", o.baseline.empty() ? "catalog" : "baseline");
  // Writing a baseline records the present verdicts: not a failure.
  return mismatches && o.write_baseline.empty() ? violation : ok;
}

}  // namespace dartcheck::cli
