#include "analysis/rule_result.hpp"

#include <algorithm>
#include <array>
#include <chrono>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/counterexample_files.hpp"
#include "analysis/embedded_fuzz.hpp"
#include "analysis/prove_replay.hpp"
#include "analysis/verdict_record.hpp"
#include "core/wording.hpp"

namespace dartcheck::analysis {

namespace {

// A counterexample breaks the map (not only the rule's announced events).
bool breaks_map(const Counterexample& cx) {
  return !cx.violations.empty() || !cx.unrepresentable.empty() || !cx.broken_embeddings.empty() || !cx.embedding_failures.empty();
}

bool solver_broke_a_map(const proofs::RuleProof& p) {
  // Only a host that is a map of the model counts: a theorem-class host need not be one.
  return std::any_of(p.constraints.begin(), p.constraints.end(),
                     [](const proofs::ConstraintProof& c) { return c.model.status == proofs::Status::counterexample; });
}

}  // namespace

bool RuleResult::topological_failure() const {
  return std::any_of(verdict.conditions.begin(), verdict.conditions.end(), [](const ConditionVerdict& c) { return !c.holds; });
}

bool RuleResult::unsound() const {
  // Model-level confirmation of a scheme: a broken constraint whose
  // conditions all hold (embedding failures count against the embedding
  // conditions).
  if (scheme_search && scheme_search->counterexample) {
    const auto& cx = *scheme_search->counterexample;
    if (!topological_failure() && (!cx.violations.empty() || !cx.unrepresentable.empty() || failing_names(embedding).empty())) return true;
  }
  if (fuzz && fuzz->verdict == FuzzClass::soundness_bug) return true;
  if (!solver_fuzz_contradiction().empty()) return true;
  return proof && (proof->count(proofs::Agreement::disagree) > 0 || proof->embedding_disagreements() > 0);
}

bool RuleResult::broke_a_map() const {
  if (host_search && host_search->host) return true;
  if (scheme_search && scheme_search->counterexample && breaks_map(*scheme_search->counterexample)) return true;
  if (fuzz && fuzz->counterexample && breaks_map(*fuzz->counterexample)) return true;
  return proof && solver_broke_a_map(*proof);
}

std::string RuleResult::verdict_text() const { return failures.empty() ? "consistent" : fmt::format("fails {}", fmt::join(failures, " ")); }

std::string RuleResult::recorded_text() const {
  if (!entry->expected_failures) return "none recorded";
  return entry->expected_failures->empty() ? "consistent" : fmt::format("fails {}", fmt::join(*entry->expected_failures, " "));
}

std::string_view RuleResult::record_source_name() const { return record_source == RecordSource::baseline ? "baseline" : "catalog"; }

std::string RuleResult::solver_fuzz_contradiction() const {
  if (!proof || !proof->embedding || !fuzz || !fuzz->counterexample) return {};
  const Counterexample& cx = *fuzz->counterexample;
  for (const auto& a : proof->embedding->answers) {
    if (a.status != proofs::EmbeddingAnswer::Status::none || cx.host.size() > a.darts) continue;
    if (std::find(cx.broken_embeddings.begin(), cx.broken_embeddings.end(), a.embedding) == cx.broken_embeddings.end()) continue;
    return fmt::format("the solver found no host up to {} darts breaking {} ({} reading), yet fuzz broke it on a {}-dart host{}", a.darts,
                       a.embedding, proofs::name_of(a.reading), cx.host.size(),
                       a.reading == proofs::Reading::arithmetic ? " (the reals and the library's doubles may round apart: docs/prove.md)" : "");
  }
  return {};
}

namespace {

// The solver's class of one embedding from its two readings (io/baseline's
// names), shared by the refined verdict's text and the baseline.
enum class SolverClass { breaks, other_algebra, holds, false_alarm, unknown };
constexpr std::array<const char*, 5> solver_class_text{"breaks", "other algebra", "holds", "false alarm", "unknown"};

SolverClass solver_class(const proofs::EmbeddingAnswer& uf, const proofs::EmbeddingAnswer& ar) {
  using Status = proofs::EmbeddingAnswer::Status;
  if (ar.status == Status::counterexample) return SolverClass::breaks;
  if (uf.status == Status::counterexample && ar.status == Status::none) return SolverClass::other_algebra;
  if (uf.status == Status::none) return uf.static_failures.empty() ? SolverClass::holds : SolverClass::false_alarm;
  return SolverClass::unknown;
}

// Calls f(uninterpreted, arithmetic) for each embedding's pair of answers.
template <class F>
void for_each_reading_pair(const RuleResult& r, F f) {
  if (!r.proof || !r.proof->embedding) return;
  const auto& answers = r.proof->embedding->answers;
  for (std::size_t i = 0; i + 1 < answers.size(); i += 2) f(answers[i], answers[i + 1]);
}

}  // namespace

std::vector<std::pair<std::string, std::string>> RuleResult::solver_classes() const {
  std::vector<std::pair<std::string, std::string>> out;
  for_each_reading_pair(*this, [&](const auto& uf, const auto& ar) {
    out.emplace_back(uf.embedding, solver_class_text[static_cast<std::size_t>(solver_class(uf, ar))]);
  });
  return out;
}

std::vector<std::string> RuleResult::solver_lines() const {
  std::vector<std::string> out;
  for_each_reading_pair(*this, [&](const proofs::EmbeddingAnswer& uf, const proofs::EmbeddingAnswer& ar) {
    const std::string head = uf.static_failures.empty() ? fmt::format("{} holds", uf.condition())
                                                        : fmt::format("fails {} syntactically", fmt::join(uf.static_failures, ", "));
    const std::string ops =
        uf.functions.empty() ? std::string("whatever the values") : fmt::format("for every interpretation of {}", fmt::join(uf.functions, ", "));
    std::string z3;
    if (uf.disagree || ar.disagree) {
      z3 = fmt::format("DISAGREE: {}", uf.disagree ? uf.note : ar.note);
    } else {
      switch (solver_class(uf, ar)) {
        case SolverClass::breaks:
          z3 = fmt::format("a {}-dart host breaks {} in dartcheck's algebra{}", ar.darts, ar.embedding, ar.replayed ? " (replayed)" : " (NOT replayed)");
          break;
        case SolverClass::other_algebra:
          z3 = fmt::format("no host up to {} darts breaks {} in real arithmetic; another interpretation of {} would, on {} darts", ar.darts,
                           ar.embedding, fmt::join(uf.functions, ", "), uf.darts);
          break;
        case SolverClass::holds:
        case SolverClass::false_alarm:
          z3 = fmt::format("no host up to {} darts breaks {}, {}", uf.darts, uf.embedding, ops);
          break;
        case SolverClass::unknown:
          z3 = fmt::format("unknown ({})", ar.status == proofs::EmbeddingAnswer::Status::unknown ? ar.why : uf.why);
          break;
      }
    }
    out.push_back(fmt::format("solver: {}; Z3: {}", head, z3));
  });
  return out;
}

std::string RuleResult::confirmation_text() const {
  const std::string& model = entry->rule.model().name;
  if (scheme_search) {
    const auto& f = *scheme_search;
    if (f.counterexample) {
      const auto& cx = *f.counterexample;
      return fmt::format("{}confirmed: applied at dart{} {} of a {}-dart {}, it {}", unsound() ? "SOUNDNESS BUG: judged consistent, yet " : "",
                         cx.hooks.size() > 1 ? "s" : "", fmt::join(cx.hooks, ","), cx.host.size(), model, cx.broken_predicate());
    }
    if (f.applications == 0) return fmt::format("never applicable on {} of up to {} darts", counted(f.hosts, model + " map"), f.largest_host);
    return fmt::format("no model-level counterexample in {} on {} of up to {} darts", counted(f.applications, "application"),
                       counted(f.hosts, model + " map"), f.largest_host);
  }
  if (!host_search) return "";
  const auto& s = *host_search;
  if (s.host) {
    std::vector<std::string> what;
    for (const auto& v : s.violations) what.push_back(constraint_name(v));
    std::sort(what.begin(), what.end());
    what.erase(std::unique(what.begin(), what.end()), what.end());
    return fmt::format("confirmed: a {}-dart {} breaks {}", s.host->node_count(), model, fmt::join(what, ", "));
  }
  if (!s.matched) return fmt::format("L matches no {} of up to {} darts", model, s.largest_host);
  return fmt::format("no model-level counterexample up to {} darts{}", s.largest_host, s.exhausted ? "" : " (search budget reached)");
}

RuleResult analyse_static(const Catalog& catalog, const CatalogRule& entry, std::size_t confirm_darts, const std::vector<Map>& catalog_maps,
                          RecordSource source) {
  RuleResult r;
  r.entry = &entry;
  r.record_source = source;
  const auto t0 = std::chrono::steady_clock::now();
  r.verdict = check_rule(entry.rule, entry.words);
  r.embedding = embedding_checks(catalog, entry);
  r.static_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  r.failures = static_failures(r.verdict);
  for (const auto& name : failing_names(r.embedding)) r.failures.push_back(name);
  // An embedded DPO rule that fails an embedding condition is fuzzed with
  // its values too: the failure ends confirmed or not found, as a scheme's.
  const bool embedding_failure = entry.terms && !failing_names(r.embedding).empty();
  if (confirm_darts > 0 && (entry.is_scheme() || embedding_failure)) {
    // Schemes, consistent or not, run on every small map of their model,
    // the catalog's maps and random valid maps (the fuzzer with a small
    // fixed budget): a failure is confirmed or reported as not found; a
    // consistent scheme that breaks a map is a soundness bug.
    std::vector<Map> extra;
    for (const Map& m : catalog_maps)
      if (m.model() == entry.rule.model()) extra.push_back(m);
    FuzzOptions fo;
    fo.seed = 1;
    fo.runs = scheme_confirmation_runs;
    fo.max_darts = scheme_confirmation_darts;
    fo.event_checks = 0;  // check is about consistency; events are `fuzz` and `events`
    fo.static_check = [&](const Operation&) { return r.verdict; };
    r.scheme_search = fuzz_rule(entry, extra, fo);
  } else if (confirm_darts > 0 && r.topological_failure()) {
    r.host_search = search_hosts(entry.rule, entry.rule.model(), confirm_darts, {}, 200'000);
  }
  compare_with_record(r);
  return r;
}

void run_embedding_solver(RuleResult& r, const std::function<bool()>& stop) {
  const CatalogRule& e = *r.entry;
  if (!e.terms) return;
  proofs::RuleProof p;
  p.rule = e.rule.name();
  p.model = e.rule.model().name;
  p.scheme = e.is_scheme();
  proofs::EmbeddingProveOptions o;
  o.max_darts = proofs::embedding_host_darts(e.rule, 0);
  o.stop = stop;
  p.embedding = proofs::prove_embeddings(e, o);
  p.interrupted = p.embedding->interrupted;
  p.seconds = p.embedding->seconds;
  r.embedding_replays.assign(p.embedding->answers.size(), std::string());  // nowhere to write: none replays
  add_proof(r, std::move(p), {}, {});
}

void add_proof(RuleResult& r, proofs::RuleProof proof, std::vector<std::string> replays, std::vector<std::optional<Counterexample>> maps) {
  r.proof = std::move(proof);
  r.proof_replays = std::move(replays);
  r.proof_maps = std::move(maps);
  compare_with_record(r);
}

void add_fuzz(RuleResult& r, FuzzReport report, std::uint64_t seed, const std::string& out_dir, const std::string& catalog_file,
              const std::string& suffix) {
  const CatalogRule& entry = *r.entry;
  const std::vector<std::pair<std::string, std::string>> fields{{"seed", std::to_string(seed)}, {"class", std::string(name_of(report.verdict))}};
  r.fuzz_replay.clear();
  r.events_replay.clear();
  if (report.counterexample && entry.terms)
    r.fuzz_replay = embedded_replay(catalog_file, report, seed);
  else if (report.counterexample && !out_dir.empty())
    r.fuzz_replay = write_counterexample(out_dir, file_stem(report.rule) + suffix, catalog_file, report.rule, fields, report.static_failures,
                                         *report.counterexample);
  if (report.event_contradiction && !out_dir.empty())
    r.events_replay = write_counterexample(out_dir, file_stem(report.rule) + suffix + ".events", catalog_file, report.rule,
                                           {{"seed", std::to_string(seed)}, {"class", "EVENT ANALYSIS CONTRADICTED"}}, report.static_failures,
                                           *report.event_contradiction, ReplayCommand::events);
  r.fuzz = std::move(report);
  compare_with_record(r);
}

void run_proof(RuleResult& r, const proofs::ProveOptions& options, const std::string& out_dir, const std::string& catalog_file,
               const std::string& suffix) {
  const CatalogRule& e = *r.entry;
  auto proof = proofs::prove_rule(e, options);
  std::vector<std::string> replays;
  std::vector<std::optional<Counterexample>> maps;
  for (auto& c : proof.constraints) {
    // The third opinion on a map counterexample: the library's derivation.
    maps.push_back(replay_solver_map(e, c));
    replays.push_back(
        maps.back() && !out_dir.empty()
            ? write_counterexample(out_dir, file_stem(e.rule.name()) + suffix + "." + constraint_stem(c), catalog_file, e.rule.name(),
                                   {{"constraint", c.constraint.name()}, {"class", "counterexample on a map of the model (dartcheck prove)"}},
                                   proof.static_failures, *maps.back())
            : std::string());
  }
  // Embedding counterexamples with values (the arithmetic reading) as files
  // that `apply` and `validate-map` replay.
  std::vector<std::string> embedding_replays;
  if (proof.embedding)
    for (const auto& a : proof.embedding->answers)
      embedding_replays.push_back(a.status == proofs::EmbeddingAnswer::Status::counterexample && a.reading == proofs::Reading::arithmetic && a.host &&
                                          !out_dir.empty()
                                      ? write_embedding_counterexample(out_dir, file_stem(e.rule.name()) + suffix + "." + file_stem(a.embedding), catalog_file,
                                                                       e.rule.name(), *a.host, a.hooks)
                                      : std::string());
  r.embedding_replays = std::move(embedding_replays);
  // Potential events (004) decided on the same hosts as the embeddings.
  const std::size_t k = proofs::embedding_host_darts(e.rule, options.embedding_darts);
  r.potential_events.reset();
  if (!proof.interrupted) {
    r.potential_events = decide_potential_events(e, k, options.stop);
    proof.interrupted = proof.interrupted || r.potential_events->interrupted;
  }
  r.potential_event_replays.clear();
  for (std::size_t i = 0; r.potential_events && i < r.potential_events->events.size(); ++i) {
    const auto& pe = r.potential_events->events[i];
    r.potential_event_replays.push_back(pe.host && !out_dir.empty()
                                            ? write_event_witness(out_dir, fmt::format("{}{}.event{}", file_stem(e.rule.name()), suffix, i), catalog_file,
                                                                  e.rule.name(), *pe.host, pe.hooks)
                                            : std::string());
  }
  add_proof(r, std::move(proof), std::move(replays), std::move(maps));
}

void compare_with_record(RuleResult& r) {
  const CatalogRule& e = *r.entry;
  r.mismatches.clear();
  const std::string_view source = r.record_source_name();
  r.verdict_differs = !matches_record(e, r.verdict, r.embedding);
  if (r.verdict_differs)
    r.mismatches.push_back(e.expected_failures
                               ? fmt::format("the static verdict is '{}', the {} records '{}'", r.verdict_text(), source, r.recorded_text())
                               : fmt::format("{}, and the {} records no verdict for it", r.verdict_text(), source));
  if (contradicts_record(e, r.broke_a_map())) {
    std::vector<std::string> how;
    if (r.host_search && r.host_search->host) how.push_back("the model-level search");
    if (r.scheme_search && r.scheme_search->counterexample && breaks_map(*r.scheme_search->counterexample)) how.push_back("the model-level search");
    if (r.fuzz && r.fuzz->counterexample && breaks_map(*r.fuzz->counterexample)) how.push_back("fuzz");
    if (r.proof && solver_broke_a_map(*r.proof)) how.push_back("the solver");
    how.erase(std::unique(how.begin(), how.end()), how.end());
    r.mismatches.push_back(fmt::format("the {} records 'consistent', but {} broke a map", source, fmt::join(how, " and ")));
  }
  // A baseline's solver classes, where this run asked the solver.
  if (e.expected_solver && r.proof && r.proof->embedding) {
    const auto now = r.solver_classes();
    if (now != *e.expected_solver) {
      auto text = [](const std::vector<std::pair<std::string, std::string>>& v) {
        std::vector<std::string> parts;
        for (const auto& [embedding, cls] : v) parts.push_back(embedding + ": " + cls);
        return fmt::format("{{{}}}", fmt::join(parts, ", "));
      };
      r.mismatches.push_back(fmt::format("the solver finds {}, the baseline records {} ({})", text(now), text(*e.expected_solver), e.solver_location.str()));
    }
  }
  if (const auto c = r.solver_fuzz_contradiction(); !c.empty())
    r.mismatches.push_back("DISAGREE: " + c);
  else if (r.unsound())
    r.mismatches.push_back("SOUNDNESS BUG: a stage contradicts the static verdict where a theorem says they agree");
}

ResultCounts count_results(const std::vector<RuleResult>& results) {
  ResultCounts c;
  for (const auto& r : results) {
    ++c.rules;
    (r.consistent() ? c.consistent : c.failing) += 1;
    c.mismatches += !r.matches_record();
    c.first_run_findings += r.first_run_finding();
    c.unsound += r.unsound();
    c.events_contradicted += r.events_contradicted();
  }
  return c;
}

}  // namespace dartcheck::analysis
