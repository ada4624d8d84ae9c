#include "campaign/detail/result_record.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dartcheck::campaign {

using analysis::Counterexample;
using analysis::FuzzReport;
using analysis::RuleResult;
using reports::Json;

namespace {

// ---- Writing -------------------------------------------------------------

Json model_json(const Model& m) {
  Json pairs = Json::array();
  for (const auto& [i, j] : m.exchangeable) pairs.push_back(Json::array({i, j}));
  return Json{{"name", m.name},        {"dims", m.dims},       {"non_oriented", m.non_oriented},
              {"exchangeable", pairs}, {"partial", m.partial}, {"loop_free", m.loop_free}};
}

// Every link and, for an oriented dimension, every predecessor record as
// stored: a counterexample's H may hold records that disagree.
Json map_json(const Map& m) {
  Json dims = Json::array();
  for (Dim i : m.model().dims) {
    std::vector<Dart> links(m.size()), preds;
    for (Dart d = 0; d < m.size(); ++d) links[d] = m.link(i, d);
    Json dim{{"dim", i}, {"links", links}};
    if (m.model().is_oriented(i)) {
      for (Dart d = 0; d < m.size(); ++d) preds.push_back(m.inverse_link(i, d));
      dim["predecessors"] = preds;
    }
    dims.push_back(std::move(dim));
  }
  return Json{{"model", model_json(m.model())}, {"darts", m.size()}, {"dims", std::move(dims)}};
}

Json graph_json(const TopoGraph& g) {
  Json arcs = Json::array();
  for (const auto& a : g.arcs()) arcs.push_back(Json::array({a.source, a.target, a.label}));
  return Json{{"nodes", g.names()}, {"arcs", std::move(arcs)}};
}

Json violations_json(const std::vector<Violation>& vs) {
  Json out = Json::array();
  for (const auto& v : vs)
    out.push_back(Json{{"constraint", static_cast<int>(v.constraint)}, {"i", v.i}, {"j", v.j}, {"element", v.element}, {"count", v.count}});
  return out;
}

template <class T, class F>
Json optional_json(const std::optional<T>& v, F&& f) {
  return v ? f(*v) : Json(nullptr);
}

Json counterexample_json(const Counterexample& cx) {
  Json match = Json::array();
  for (const auto& [node, dart] : cx.match) match.push_back(Json::array({node, dart}));
  Json comatch = Json::array();
  for (const auto& [node, dart] : cx.comatch) comatch.push_back(Json::array({node, dart}));
  return Json{{"host", map_json(cx.host)},
              {"hooks", cx.hooks},
              {"match", std::move(match)},
              {"result", optional_json(cx.result, map_json)},
              {"violations", violations_json(cx.violations)},
              {"unrepresentable", cx.unrepresentable},
              {"origin", cx.origin},
              {"minimal", cx.minimal},
              {"embedding_failures", cx.embedding_failures},
              {"broken_embeddings", cx.broken_embeddings},
              {"orbit_values", cx.orbit_values},
              {"event_contradictions", cx.event_contradictions},
              {"comatch", std::move(comatch)}};
}

Json fuzz_record(const FuzzReport& f) {
  Json refusals = Json::object();
  for (const auto& [why, n] : f.refusals) refusals[why] = n;
  return Json{{"rule", f.rule},
              {"static_failures", f.static_failures},
              {"verdict", static_cast<int>(f.verdict)},
              {"reason", f.reason},
              {"checked", f.checked},
              {"applications", f.applications},
              {"hosts", f.hosts},
              {"largest_host", f.largest_host},
              {"exhaustive_darts", f.exhaustive_darts},
              {"refusals", std::move(refusals)},
              {"event_checks", f.event_checks},
              {"out_of_time", f.out_of_time},
              {"seconds", f.seconds},
              {"counterexample", optional_json(f.counterexample, counterexample_json)},
              {"event_contradiction", optional_json(f.event_contradiction, counterexample_json)}};
}

Json host_search_record(const HostSearch& s) {
  return Json{{"matched", s.matched},
              {"exhausted", s.exhausted},
              {"hosts", s.hosts},
              {"derivations", s.derivations},
              {"largest_host", s.largest_host},
              {"host", optional_json(s.host, graph_json)},
              {"result", optional_json(s.result, graph_json)},
              {"violations", violations_json(s.violations)}};
}

Json symbolic_host_json(const proofs::SymbolicHost& h) {
  Json links = Json::array();
  for (const auto& [dim, darts] : h.links) links.push_back(Json{{"dim", dim}, {"links", darts}});
  return Json{{"size", h.size}, {"links", std::move(links)}};
}

Json answer_record(const proofs::ClassAnswer& a) {
  return Json{{"class_name", a.class_name},
              {"status", static_cast<int>(a.status)},
              {"darts", a.darts},
              {"minimal", a.minimal},
              {"bound", a.bound},
              {"core", a.core},
              {"why", a.why},
              {"host", optional_json(a.host, symbolic_host_json)},
              {"host_graph", graph_json(a.host_graph)},
              {"result_graph", graph_json(a.result_graph)},
              {"replayed", a.replayed},
              {"replay_failure", a.replay_failure},
              {"seconds", a.seconds}};
}

// The solver's embedding answers, without their hosts (the files are
// written before the record; the renderers read the rest).
Json embedding_record(const proofs::EmbeddingProof& e) {
  Json answers = Json::array();
  for (const auto& a : e.answers)
    answers.push_back(Json{{"embedding", a.embedding},
                           {"static_failures", a.static_failures},
                           {"reading", static_cast<int>(a.reading)},
                           {"status", static_cast<int>(a.status)},
                           {"darts", a.darts},
                           {"why", a.why},
                           {"uninterpreted", a.uninterpreted},
                           {"functions", a.functions},
                           {"replayed", a.replayed},
                           {"replay", a.replay},
                           {"disagree", a.disagree},
                           {"note", a.note}});
  return Json{{"answers", std::move(answers)}, {"hosts", e.hosts},         {"applications", e.applications}, {"queries", e.queries},
              {"cached", e.cached},            {"out_of_scope", e.out_of_scope}, {"interrupted", e.interrupted}, {"seconds", e.seconds}};
}

Json potential_events_record(const analysis::PotentialEvents& p) {
  Json events = Json::array();
  for (const auto& e : p.events) events.push_back(Json{{"kind", e.kind}, {"claim", e.claim}, {"happens", e.happens}, {"darts", e.darts}});
  return Json{{"events", std::move(events)},       {"hosts", p.hosts},   {"applications", p.applications},
              {"not_decided", p.not_decided}, {"interrupted", p.interrupted}, {"seconds", p.seconds}};
}

Json proof_record(const proofs::RuleProof& p) {
  Json constraints = Json::array();
  for (const auto& c : p.constraints)
    constraints.push_back(Json{{"kind", static_cast<int>(c.constraint.kind)},
                               {"i", c.constraint.i},
                               {"j", c.constraint.j},
                               {"static_holds", c.static_holds ? Json(*c.static_holds) : Json(nullptr)},
                               {"theorem", optional_json(c.theorem, answer_record)},
                               {"model", answer_record(c.model)},
                               {"agreement", static_cast<int>(c.agreement)},
                               {"note", c.note}});
  return Json{{"rule", p.rule},
              {"model", p.model},
              {"scheme", p.scheme},
              {"out_of_scope", p.out_of_scope},
              {"static_failures", p.static_failures},
              {"constraints", std::move(constraints)},
              {"interrupted", p.interrupted},
              {"embedding", optional_json(p.embedding, embedding_record)},
              {"seconds", p.seconds}};
}

// ---- Reading -------------------------------------------------------------

// A position in the record: every read names its path when the value is
// not what a shard writes, so a damaged file says where.
struct In {
  const Json& j;
  std::string path;

  [[noreturn]] void fail(std::string_view what) const { throw RecordError(fmt::format("{}: expected {}", path, what)); }
  In operator[](std::string_view key_text) const {
    if (!j.is_object()) fail("an object");
    const std::string key(key_text);
    const auto it = j.find(key);
    if (it == j.end()) throw RecordError(fmt::format("{}: no key \"{}\"", path, key));
    return {*it, path + "." + key};
  }
  In operator[](std::size_t k) const { return {j[k], fmt::format("{}[{}]", path, k)}; }
  bool null() const { return j.is_null(); }
  std::size_t size() const {
    if (!j.is_array()) fail("an array");
    return j.size();
  }
  std::string str() const {
    if (!j.is_string()) fail("a string");
    return j.get<std::string>();
  }
  bool boolean() const {
    if (!j.is_boolean()) fail("true or false");
    return j.get<bool>();
  }
  std::uint64_t count(std::uint64_t below = UINT64_MAX) const {
    if (!j.is_number_unsigned() || j.get<std::uint64_t>() >= below)
      fail(below == UINT64_MAX ? std::string("a count") : fmt::format("an integer from 0 to {}", below - 1));
    return j.get<std::uint64_t>();
  }
  int integer(int low, int high) const {
    if (!j.is_number_integer() || j.get<std::int64_t>() < low || j.get<std::int64_t>() > high)
      fail(fmt::format("an integer from {} to {}", low, high));
    return static_cast<int>(j.get<std::int64_t>());
  }
  double real() const {
    if (!j.is_number()) fail("a number");
    return j.get<double>();
  }
  std::vector<std::string> strings() const {
    std::vector<std::string> out;
    for (std::size_t k = 0; k < size(); ++k) out.push_back((*this)[k].str());
    return out;
  }
  template <class F>
  auto optional(F&& f) const -> std::optional<decltype(f(*this))> {
    if (null()) return std::nullopt;
    return f(*this);
  }
};

Dart dart_below(const In& in, std::size_t darts) {
  if (in.j.is_number_unsigned() && in.j.get<std::uint64_t>() == no_dart) return no_dart;
  return static_cast<Dart>(in.count(darts));
}

Model read_model(const In& in) {
  Model m;
  m.name = in["name"].str();
  const In dims = in["dims"];
  for (std::size_t k = 0; k < dims.size(); ++k) {
    const Dim i = dims[k].integer(0, max_dimension);
    if (!m.dims.empty() && i <= m.dims.back()) dims[k].fail("dimensions in ascending order");
    m.dims.push_back(i);
  }
  if (m.dims.empty()) dims.fail("at least one dimension");
  m.non_oriented = static_cast<DimSet>(in["non_oriented"].count(DimSet{1} << (max_dimension + 1)));
  m.partial = static_cast<DimSet>(in["partial"].count(DimSet{1} << (max_dimension + 1)));
  const In pairs = in["exchangeable"];
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (pairs[k].size() != 2) pairs[k].fail("a pair of dimensions");
    m.exchangeable.emplace_back(pairs[k][0].integer(0, max_dimension), pairs[k][1].integer(0, max_dimension));
  }
  m.loop_free = in["loop_free"].boolean();
  return m;
}

Map read_map(const In& in) {
  Map m(read_model(in["model"]), in["darts"].count(1U << 31));
  const In dims = in["dims"];
  for (std::size_t k = 0; k < dims.size(); ++k) {
    const Dim i = dims[k]["dim"].integer(0, max_dimension);
    if (!m.model().contains(i)) dims[k]["dim"].fail("a dimension of the model");
    const In links = dims[k]["links"];
    if (links.size() != m.size()) links.fail(fmt::format("{} links", m.size()));
    for (Dart d = 0; d < m.size(); ++d) m.set_link_raw(i, d, dart_below(links[d], m.size()));
    if (!m.model().is_oriented(i)) continue;
    const In preds = dims[k]["predecessors"];
    if (preds.size() != m.size()) preds.fail(fmt::format("{} predecessors", m.size()));
    for (Dart d = 0; d < m.size(); ++d) m.set_inverse_link_raw(i, d, dart_below(preds[d], m.size()));
  }
  return m;
}

TopoGraph read_graph(const In& in) {
  TopoGraph g;
  const In nodes = in["nodes"];
  for (std::size_t k = 0; k < nodes.size(); ++k) g.add_node(nodes[k].str());
  const In arcs = in["arcs"];
  for (std::size_t k = 0; k < arcs.size(); ++k) {
    if (arcs[k].size() != 3) arcs[k].fail("[source, target, label]");
    g.add_arc(static_cast<NodeId>(arcs[k][0].count(g.node_count())), static_cast<NodeId>(arcs[k][1].count(g.node_count())),
              arcs[k][2].integer(-1, max_dimension));
  }
  return g;
}

std::vector<Violation> read_violations(const In& in) {
  std::vector<Violation> out;
  for (std::size_t k = 0; k < in.size(); ++k) {
    const In v = in[k];
    out.push_back(Violation{static_cast<Constraint>(v["constraint"].integer(0, static_cast<int>(Constraint::predecessor))),
                            v["i"].integer(-1, max_dimension), v["j"].integer(-1, max_dimension),
                            static_cast<std::uint32_t>(v["element"].count(std::uint64_t{no_element} + 1)),
                            static_cast<std::uint32_t>(v["count"].count(std::uint64_t{UINT32_MAX} + 1))});
  }
  return out;
}

Counterexample read_counterexample(const In& in) {
  Counterexample cx{read_map(in["host"]), {}, {}, std::nullopt, {}, {}, {}, false, {}, {}, {}, {}, {}};
  const In hooks = in["hooks"];
  for (std::size_t k = 0; k < hooks.size(); ++k) cx.hooks.push_back(static_cast<Dart>(hooks[k].count(cx.host.size())));
  const In match = in["match"];
  for (std::size_t k = 0; k < match.size(); ++k) {
    if (match[k].size() != 2) match[k].fail("[node, dart]");
    cx.match.emplace_back(match[k][0].str(), static_cast<Dart>(match[k][1].count(cx.host.size())));
  }
  cx.result = in["result"].optional(read_map);
  cx.violations = read_violations(in["violations"]);
  cx.unrepresentable = in["unrepresentable"].str();
  cx.origin = in["origin"].str();
  cx.minimal = in["minimal"].boolean();
  cx.embedding_failures = in["embedding_failures"].strings();
  cx.broken_embeddings = in["broken_embeddings"].strings();
  cx.orbit_values = in["orbit_values"].strings();
  cx.event_contradictions = in["event_contradictions"].strings();
  const In comatch = in["comatch"];
  const std::size_t h_size = cx.result ? cx.result->size() : 0;
  for (std::size_t k = 0; k < comatch.size(); ++k) {
    if (comatch[k].size() != 2) comatch[k].fail("[node, dart]");
    cx.comatch.emplace_back(comatch[k][0].str(), static_cast<Dart>(comatch[k][1].count(h_size)));
  }
  return cx;
}

FuzzReport read_fuzz(const In& in) {
  FuzzReport f;
  f.rule = in["rule"].str();
  f.static_failures = in["static_failures"].strings();
  f.verdict = static_cast<analysis::FuzzClass>(in["verdict"].integer(0, static_cast<int>(analysis::FuzzClass::soundness_bug)));
  f.reason = in["reason"].str();
  f.checked = in["checked"].str();
  f.applications = in["applications"].count();
  f.hosts = in["hosts"].count();
  f.largest_host = in["largest_host"].count();
  f.exhaustive_darts = in["exhaustive_darts"].count();
  const In refusals = in["refusals"];
  if (!refusals.j.is_object()) refusals.fail("an object");
  for (const auto& [why, n] : refusals.j.items()) f.refusals[why] = In{n, refusals.path + "." + why}.count();
  f.event_checks = in["event_checks"].count();
  f.out_of_time = in["out_of_time"].boolean();
  f.seconds = in["seconds"].real();
  f.counterexample = in["counterexample"].optional(read_counterexample);
  f.event_contradiction = in["event_contradiction"].optional(read_counterexample);
  return f;
}

HostSearch read_host_search(const In& in) {
  HostSearch s;
  s.matched = in["matched"].boolean();
  s.exhausted = in["exhausted"].boolean();
  s.hosts = in["hosts"].count();
  s.derivations = in["derivations"].count();
  s.largest_host = in["largest_host"].count();
  s.host = in["host"].optional(read_graph);
  s.result = in["result"].optional(read_graph);
  s.violations = read_violations(in["violations"]);
  return s;
}

proofs::SymbolicHost read_symbolic_host(const In& in) {
  proofs::SymbolicHost h;
  h.size = in["size"].count(1U << 16);
  const In links = in["links"];
  for (std::size_t k = 0; k < links.size(); ++k) {
    std::vector<Dart> darts;
    const In ds = links[k]["links"];
    for (std::size_t d = 0; d < ds.size(); ++d) darts.push_back(dart_below(ds[d], h.size));
    h.links.emplace_back(links[k]["dim"].integer(0, max_dimension), std::move(darts));
  }
  return h;
}

proofs::ClassAnswer read_answer(const In& in) {
  proofs::ClassAnswer a;
  a.class_name = in["class_name"].str();
  a.status = static_cast<proofs::Status>(in["status"].integer(0, static_cast<int>(proofs::Status::vacuous)));
  a.darts = in["darts"].count();
  a.minimal = in["minimal"].boolean();
  a.bound = in["bound"].count();
  a.core = in["core"].strings();
  a.why = in["why"].str();
  a.host = in["host"].optional(read_symbolic_host);
  a.host_graph = read_graph(in["host_graph"]);
  a.result_graph = read_graph(in["result_graph"]);
  a.replayed = in["replayed"].boolean();
  a.replay_failure = in["replay_failure"].str();
  a.seconds = in["seconds"].real();
  return a;
}

proofs::EmbeddingProof read_embedding(const In& in) {
  proofs::EmbeddingProof e;
  const In as = in["answers"];
  for (std::size_t k = 0; k < as.size(); ++k) {
    const In a = as[k];
    proofs::EmbeddingAnswer x;
    x.embedding = a["embedding"].str();
    x.static_failures = a["static_failures"].strings();
    x.reading = static_cast<proofs::Reading>(a["reading"].integer(0, static_cast<int>(proofs::Reading::arithmetic)));
    x.status = static_cast<proofs::EmbeddingAnswer::Status>(a["status"].integer(0, static_cast<int>(proofs::EmbeddingAnswer::Status::unknown)));
    x.darts = a["darts"].count();
    x.why = a["why"].str();
    x.uninterpreted = a["uninterpreted"].strings();
    x.functions = a["functions"].strings();
    x.replayed = a["replayed"].boolean();
    x.replay = a["replay"].str();
    x.disagree = a["disagree"].boolean();
    x.note = a["note"].str();
    e.answers.push_back(std::move(x));
  }
  e.hosts = in["hosts"].count();
  e.applications = in["applications"].count();
  e.queries = in["queries"].count();
  e.cached = in["cached"].count();
  e.out_of_scope = in["out_of_scope"].str();
  e.interrupted = in["interrupted"].boolean();
  e.seconds = in["seconds"].real();
  return e;
}

analysis::PotentialEvents read_potential_events(const In& in) {
  analysis::PotentialEvents p;
  const In es = in["events"];
  for (std::size_t k = 0; k < es.size(); ++k)
    p.events.push_back({es[k]["kind"].str(), es[k]["claim"].str(), es[k]["happens"].boolean(), es[k]["darts"].count(), std::nullopt, {}});
  p.hosts = in["hosts"].count();
  p.applications = in["applications"].count();
  p.not_decided = in["not_decided"].str();
  p.interrupted = in["interrupted"].boolean();
  p.seconds = in["seconds"].real();
  return p;
}

proofs::RuleProof read_proof(const In& in) {
  proofs::RuleProof p;
  p.rule = in["rule"].str();
  p.model = in["model"].str();
  p.scheme = in["scheme"].boolean();
  p.out_of_scope = in["out_of_scope"].str();
  p.static_failures = in["static_failures"].strings();
  const In cs = in["constraints"];
  for (std::size_t k = 0; k < cs.size(); ++k) {
    const In c = cs[k];
    proofs::ConstraintProof cp;
    cp.constraint = {static_cast<RuleCondition>(c["kind"].integer(0, static_cast<int>(RuleCondition::no_loop))), c["i"].integer(-1, max_dimension),
                     c["j"].integer(-1, max_dimension)};
    if (!c["static_holds"].null()) cp.static_holds = c["static_holds"].boolean();
    cp.theorem = c["theorem"].optional(read_answer);
    cp.model = read_answer(c["model"]);
    cp.agreement = static_cast<proofs::Agreement>(c["agreement"].integer(0, static_cast<int>(proofs::Agreement::not_compared)));
    cp.note = c["note"].str();
    p.constraints.push_back(std::move(cp));
  }
  p.interrupted = in["interrupted"].boolean();
  p.embedding = in["embedding"].optional(read_embedding);
  p.seconds = in["seconds"].real();
  return p;
}

}  // namespace

Json result_record(const RuleResult& r) {
  Json maps = Json::array();
  for (const auto& m : r.proof_maps) maps.push_back(optional_json(m, counterexample_json));
  return Json{{"failures", r.failures},
              {"static_ms", r.static_ms},
              {"host_search", optional_json(r.host_search, host_search_record)},
              {"scheme_search", optional_json(r.scheme_search, fuzz_record)},
              {"fuzz", optional_json(r.fuzz, fuzz_record)},
              {"fuzz_replay", r.fuzz_replay},
              {"events_replay", r.events_replay},
              {"proof", optional_json(r.proof, proof_record)},
              {"proof_replays", r.proof_replays},
              {"proof_maps", std::move(maps)},
              {"embedding_replays", r.embedding_replays},
              {"potential_events", optional_json(r.potential_events, potential_events_record)},
              {"potential_event_replays", r.potential_event_replays}};
}

void restore_record(RuleResult& r, const Json& record) {
  const In in{record, "record"};
  const auto failures = in["failures"].strings();
  if (failures != r.failures)
    throw RecordError(fmt::format("record.failures: the shard found [{}] for rule '{}', the catalog now gives [{}] (did the catalog change?)",
                                  fmt::join(failures, ", "), r.name(), fmt::join(r.failures, ", ")));
  r.static_ms = in["static_ms"].real();
  r.host_search = in["host_search"].optional(read_host_search);
  r.scheme_search = in["scheme_search"].optional(read_fuzz);
  r.fuzz = in["fuzz"].optional(read_fuzz);
  r.fuzz_replay = in["fuzz_replay"].str();
  r.events_replay = in["events_replay"].str();
  r.proof = in["proof"].optional(read_proof);
  r.proof_replays = in["proof_replays"].strings();
  r.proof_maps.clear();
  const In maps = in["proof_maps"];
  for (std::size_t k = 0; k < maps.size(); ++k) r.proof_maps.push_back(maps[k].optional(read_counterexample));
  r.embedding_replays = in["embedding_replays"].strings();
  r.potential_events = in["potential_events"].optional(read_potential_events);
  r.potential_event_replays = in["potential_event_replays"].strings();
  analysis::compare_with_record(r);
}

}  // namespace dartcheck::campaign
