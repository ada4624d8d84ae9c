#include "reports/rule_result_json.hpp"
#include "reports/detail/record_json.hpp"
#include "reports/json_document.hpp"

#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dartcheck::reports {

using namespace analysis;

namespace {

Json location_json(const SourceLocation& at) { return Json{{"file", at.file}, {"line", at.line}, {"column", at.column}}; }

Json condition_json(const ConditionVerdict& v) {
  Json witnesses = Json::array();
  for (const auto& w : v.witnesses)
    witnesses.push_back(Json{{"subcondition", w.subcondition},
                             {"side", std::string(1, w.side)},
                             {"nodes", w.nodes},
                             {"arcs", w.arcs},
                             {"words", w.words},
                             {"text", w.text}});
  Json j{{"condition", v.name()}, {"holds", v.holds}};
  j["skipped"] = v.skipped.empty() ? Json(nullptr) : Json(v.skipped);
  j["witnesses"] = std::move(witnesses);
  return j;
}

Json embedding_json(const EmbeddingCheck& e) {
  std::vector<std::string> texts;
  for (const auto& w : e.witnesses) texts.push_back(w.text);
  return Json{{"check", e.name}, {"holds", e.holds}, {"required", e.required}, {"source", e.source}, {"witnesses", texts}};
}

using detail::optional_json;

bool with_record(JsonDetail level) { return level == JsonDetail::record; }

Json answer_json(const proofs::ClassAnswer& a, JsonDetail level) {
  Json j{{"class", a.class_name}, {"status", proofs::name_of(a.status)},  {"darts", a.darts}, {"minimal", a.minimal},
         {"bound", a.bound},      {"proved_for_all", a.proved_for_all()}, {"core", a.core},   {"why", a.why},
         {"seconds", a.seconds}};
  if (a.status == proofs::Status::counterexample) {
    j["replayed"] = a.replayed;
    j["host"] = arcs_text(a.host_graph);
    j["result"] = arcs_text(a.result_graph);
  }
  if (with_record(level)) {
    j["replayed"] = a.replayed;
    j["replay_failure"] = a.replay_failure;
    j["symbolic_host"] = optional_json(a.host, detail::symbolic_host_json);
    j["host_graph"] = detail::graph_json(a.host_graph);
    j["result_graph"] = detail::graph_json(a.result_graph);
  }
  return j;
}

// A counterexample of fuzz (or of a scheme's confirmation).
Json fuzz_counterexample_json(const Counterexample& cx, const std::string& replay, JsonDetail level) {
  Json j{{"darts", cx.host.size()},
         {"hooks", cx.hooks},
         {"broken", cx.broken()},
         {"minimal", cx.minimal},
         {"origin", cx.origin},
         {"unrepresentable", cx.unrepresentable},
         {"embedding", cx.embedding_failures},
         {"replay", replay}};
  if (with_record(level)) detail::add_counterexample_record(j, cx);
  return j;
}

Json event_contradiction_json(const Counterexample& cx, const std::string& replay, JsonDetail level) {
  Json j{{"darts", cx.host.size()}, {"hooks", cx.hooks}, {"origin", cx.origin}, {"contradictions", cx.event_contradictions}, {"replay", replay}};
  if (with_record(level)) detail::add_counterexample_record(j, cx);
  return j;
}

Json fuzz_json(const FuzzReport& f, const std::string& replay, const std::string& events_replay, JsonDetail level) {
  Json refusals = Json::object();
  for (const auto& [why, n] : f.refusals) refusals[why] = n;
  Json j{{"class", name_of(f.verdict)},
         {"applications", f.applications},
         {"hosts", f.hosts},
         {"largest_host", f.largest_host},
         {"exhaustive_darts", f.exhaustive_darts},
         {"event_checks", f.event_checks},
         {"refusals", std::move(refusals)},
         {"seconds", f.seconds},
         {"out_of_time", f.out_of_time},
         {"reason", f.reason},
         {"checked", f.checked},
         {"outcome", outcome_text(f)}};
  j["counterexample"] = f.counterexample ? fuzz_counterexample_json(*f.counterexample, replay, level) : Json(nullptr);
  j["event_contradiction"] = f.event_contradiction ? event_contradiction_json(*f.event_contradiction, events_replay, level) : Json(nullptr);
  if (with_record(level)) {
    j["rule"] = f.rule;
    j["static_failures"] = f.static_failures;
  }
  return j;
}

Json confirmation_json(const RuleResult& r, JsonDetail level) {
  Json j{{"text", r.confirmation_text()}};
  if (r.host_search) {
    const auto& s = *r.host_search;
    j["search"] = "hosts of the model containing L";
    j["matched"] = s.matched;
    j["exhausted"] = s.exhausted;
    j["largest_host"] = s.largest_host;
    j["confirmed"] = s.host.has_value();
    if (s.host) {
      j["host"] = arcs_text(*s.host);
      j["result"] = arcs_text(*s.result);
    }
    if (with_record(level)) {
      j["hosts"] = s.hosts;
      j["derivations"] = s.derivations;
      j["host_graph"] = optional_json(s.host, detail::graph_json);
      j["result_graph"] = optional_json(s.result, detail::graph_json);
      j["violations"] = detail::violations_json(s.violations);
    }
  } else if (r.scheme_search) {
    j["search"] = "small, catalog and random maps of the model";
    j["confirmed"] = r.scheme_search->counterexample.has_value();
    j["fuzz"] = fuzz_json(*r.scheme_search, "", "", level);
  }
  return j;
}

// One constraint of the solver stage, its replay and (record) the map its
// counterexample replayed on.
Json constraint_proof_json(const proofs::ConstraintProof& c, const std::string& replay, const std::optional<Counterexample>* map, JsonDetail level) {
  Json j{{"constraint", c.constraint.name()},
         {"static", c.static_holds ? (*c.static_holds ? "holds" : "fails") : "none"},
         {"theorem", c.theorem ? answer_json(*c.theorem, level) : Json(nullptr)},
         {"model", answer_json(c.model, level)},
         {"agreement", proofs::name_of(c.agreement)},
         {"note", c.note},
         {"replay", replay}};
  if (with_record(level)) {
    j["kind"] = static_cast<int>(c.constraint.kind);
    j["i"] = c.constraint.i;
    j["j"] = c.constraint.j;
    j["map"] = map && *map ? [&] {
      Json cx = Json::object();
      detail::add_counterexample_record(cx, **map);
      return cx;
    }()
                           : Json(nullptr);
  }
  return j;
}

// The embeddings' answers (proofs/embedding_prover), one per embedding
// and reading.
Json embedding_answer_json(const proofs::EmbeddingAnswer& a, const std::string& replay, JsonDetail level) {
  Json j{{"condition", a.condition()},
         {"static", a.static_failures},
         {"reading", proofs::name_of(a.reading)},
         {"answer", proofs::name_of(a.status)},
         {"darts", a.darts},
         {"why", a.why},
         {"replayed", a.replayed},
         {"replay", replay},
         {"uninterpreted", a.uninterpreted},
         {"disagree", a.disagree},
         {"note", a.note}};
  if (with_record(level)) {
    j["embedding"] = a.embedding;
    j["functions"] = a.functions;
  }
  return j;
}

// The k-th entry of a list written one per constraint, answer or event.
const std::string& entry(const std::vector<std::string>& list, std::size_t k) {
  static const std::string none;
  return k < list.size() ? list[k] : none;
}

Json proof_json(const RuleResult& r, JsonDetail level) {
  const proofs::RuleProof& p = *r.proof;
  Json constraints = Json::array();
  for (std::size_t i = 0; i < p.constraints.size(); ++i)
    constraints.push_back(
        constraint_proof_json(p.constraints[i], entry(r.proof_replays, i), i < r.proof_maps.size() ? &r.proof_maps[i] : nullptr, level));
  Json embedding = Json::array();
  if (p.embedding)
    for (std::size_t i = 0; i < p.embedding->answers.size(); ++i)
      embedding.push_back(embedding_answer_json(p.embedding->answers[i], entry(r.embedding_replays, i), level));
  Json search = nullptr;
  if (p.embedding) {
    search = Json{{"hosts", p.embedding->hosts},
                  {"applications", p.embedding->applications},
                  {"queries", p.embedding->queries},
                  {"cached", p.embedding->cached}};
    if (with_record(level)) {
      search["out_of_scope"] = p.embedding->out_of_scope;
      search["interrupted"] = p.embedding->interrupted;
    }
  }
  Json j{{"scheme", p.scheme},
         {"embedding", std::move(embedding)},
         {"embedding_seconds", p.embedding ? p.embedding->seconds : 0.0},
         {"embedding_search", std::move(search)},
         {"out_of_scope", p.out_of_scope.empty() ? Json(nullptr) : Json(p.out_of_scope)},
         {"seconds", p.seconds},
         {"constraints", std::move(constraints)},
         {"agree", p.count(proofs::Agreement::agree)},
         {"disagree", p.count(proofs::Agreement::disagree)},
         {"unresolved", p.count(proofs::Agreement::unresolved)},
         {"not_compared", p.count(proofs::Agreement::not_compared)}};
  if (with_record(level)) {
    j["rule"] = p.rule;
    j["model"] = p.model;
    j["static_failures"] = p.static_failures;
    j["interrupted"] = p.interrupted;
  }
  return j;
}

// 004's potential events decided on hosts up to K (prove).
Json potential_events_json(const RuleResult& r, JsonDetail level) {
  const PotentialEvents& p = *r.potential_events;
  Json events = Json::array();
  for (std::size_t i = 0; i < p.events.size(); ++i) {
    const auto& pe = p.events[i];
    events.push_back(Json{{"orbit", pe.kind},
                          {"claim", pe.claim},
                          {"answer", pe.happens ? "witness" : "never"},
                          {"darts", pe.darts},
                          {"replay", entry(r.potential_event_replays, i)}});
  }
  Json j{{"events", std::move(events)}, {"hosts", p.hosts}, {"applications", p.applications}, {"not_decided", p.not_decided}, {"seconds", p.seconds}};
  if (with_record(level)) j["interrupted"] = p.interrupted;
  return j;
}

// A Jerboa rule's expressions: the Java, and the term it was read as or
// why it is opaque (docs/jerboa-expressions.md).
Json expressions_json(const std::vector<NodeExpression>& expressions) {
  Json out = Json::array();
  for (const auto& x : expressions) {
    Json j{{"node", x.node}, {"embedding", x.embedding}, {"source", x.code}, {"location", location_json(x.location)}, {"status", x.read() ? "read" : "opaque"}};
    if (x.read())
      j["term"] = x.term->str();
    else {
      j["reason"] = x.reason;
      j["reason_location"] = location_json(x.reason_location);
    }
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace

Json rule_result_json(const RuleResult& r, JsonDetail level) {
  const CatalogRule& e = *r.entry;
  Json conditions = Json::array();
  for (const auto& v : r.verdict.conditions) conditions.push_back(condition_json(v));
  Json embedding = Json::array();
  for (const auto& c : r.embedding) embedding.push_back(embedding_json(c));
  Json j{{"name", e.rule.name()},
         {"model", e.rule.model().name},
         {"location", location_json(e.location)},
         {"kind", e.jerboa        ? "jerboa-scheme"
                  : e.is_scheme() ? "scheme"
                                  : "dpo"},
         {"consistent", r.consistent()},
         {"failures", r.failures},
         {"verdict", r.verdict_text()},
         {"conditions", std::move(conditions)},
         {"embedding_checks", std::move(embedding)},
         {"embedding_expressions", expressions_json(e.expressions)},
         {"caveats", e.caveats},
         {"static_ms", r.static_ms}};
  j["recorded"] = Json{{"source", r.record_source_name()},
                       {"failures", e.expected_failures ? Json(*e.expected_failures) : Json(nullptr)},
                       {"text", r.recorded_text()}};
  j["matches_record"] = r.matches_record();
  j["mismatches"] = r.mismatches;
  j["unsound"] = r.unsound();
  j["confirmation"] = r.host_search || r.scheme_search ? confirmation_json(r, level) : Json(nullptr);
  j["fuzz"] = r.fuzz ? fuzz_json(*r.fuzz, r.fuzz_replay, r.events_replay, level) : Json(nullptr);
  j["proof"] = r.proof ? proof_json(r, level) : Json(nullptr);
  if (r.potential_events)
    j["potential_events"] = potential_events_json(r, level);
  else if (with_record(level))
    j["potential_events"] = nullptr;
  return j;
}

Json skipped_json(const std::vector<SkippedRule>& skipped) {
  Json out = Json::array();
  for (const auto& s : skipped) out.push_back(Json{{"name", s.name}, {"verdict", "not checked"}, {"why", s.why}, {"at", s.location.str()}});
  return out;
}

Json results_document(std::string_view command, const std::string& catalog_file, const Catalog& catalog, const std::vector<RuleResult>& results,
                      const std::vector<std::string>& baseline_mismatches) {
  Json doc = json_document(command);
  doc["catalog"] = catalog_file;
  Json rules = Json::array();
  for (const auto& r : results) rules.push_back(rule_result_json(r));
  doc["rules"] = std::move(rules);
  doc["skipped"] = skipped_json(catalog.skipped);
  doc["baseline_mismatches"] = baseline_mismatches;
  const auto counts = count_results(results);
  doc["counts"] = counts_json(counts);
  doc["mismatches"] = counts.mismatches + baseline_mismatches.size();
  return doc;
}

Json fuzz_summary_json(const FuzzRun& run, const std::vector<RuleResult>& results) {
  std::map<FuzzClass, std::size_t> classes;
  std::size_t applications = 0;
  for (const auto& r : results) ++classes[r.fuzz->verdict], applications += r.fuzz->applications;
  Json summary{{"catalog", run.catalog},
              {"seed", run.seed},
              {"seconds", run.seconds},
              {"rules", run.rules},
              {"finished", results.size()},
              {"consistent", classes[FuzzClass::consistent]},
              {"confirmed", classes[FuzzClass::confirmed]},
              {"unconfirmed", classes[FuzzClass::unconfirmed]},
              {"soundness_bugs", classes[FuzzClass::soundness_bug]},
              {"applications", applications},
              {"interrupted", run.interrupted},
              {"counts", counts_json(count_results(results))},
              {"baseline_mismatches", run.baseline_mismatches}};
  summary["wall_clock"] = run.wall_clock;
  if (run.shard_seconds) summary["shard_seconds"] = *run.shard_seconds;
  return summary;
}

Json prove_document(const ProveRun& run, const std::vector<RuleResult>& results) {
  Json doc = json_document("prove");
  doc["catalog"] = run.catalog;
  doc["max_darts"] = run.max_darts;
  doc["rlimit"] = run.rlimit;
  doc["seconds"] = run.seconds;
  Json rows = Json::array();
  std::size_t scoped = 0, counts[4] = {};
  for (const auto& r : results) {
    rows.push_back(rule_result_json(r));
    scoped += r.proof->out_of_scope.empty();
    for (auto a : {proofs::Agreement::agree, proofs::Agreement::disagree, proofs::Agreement::unresolved, proofs::Agreement::not_compared})
      counts[static_cast<int>(a)] += r.proof->count(a);
  }
  doc["rules"] = std::move(rows);
  doc["in_scope"] = scoped;
  doc["agree"] = counts[0];
  doc["disagree"] = counts[1];
  doc["unresolved"] = counts[2];
  doc["not_compared"] = counts[3];
  doc["counts"] = counts_json(count_results(results));
  doc["baseline_mismatches"] = run.baseline_mismatches;
  return doc;
}

Json counts_json(const ResultCounts& c) {
  return Json{{"rules", c.rules},           {"consistent", c.consistent}, {"failing", c.failing},
              {"mismatches", c.mismatches}, {"unsound", c.unsound},       {"events_contradicted", c.events_contradicted}};
}

}  // namespace dartcheck::reports
