#include "campaign/detail/result_record.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/formatting.hpp"

namespace dartcheck::campaign {

using analysis::Counterexample;
using analysis::FuzzReport;
using analysis::RuleResult;
using reports::Json;

namespace {

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
  bool has(std::string_view key) const { return j.is_object() && j.contains(std::string(key)); }
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
  /// An enum written by its name (name_of), one of E's values 0..last.
  template <class E>
  E named(E last) const {
    if (const auto e = dartcheck::named(str(), last)) return *e;
    std::vector<std::string> names;
    for (int k = 0; k <= static_cast<int>(last); ++k) names.push_back(fmt::format("\"{}\"", name_of(static_cast<E>(k))));
    fail(fmt::format("one of {}", fmt::join(names, ", ")));
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

// A fuzz stage (or a scheme's confirmation) and the replay commands of
// its counterexample and event contradiction.
FuzzReport read_fuzz(const In& in, std::string* replay = nullptr, std::string* events_replay = nullptr) {
  FuzzReport f;
  f.rule = in["rule"].str();
  f.static_failures = in["static_failures"].strings();
  f.verdict = in["class"].named(analysis::FuzzClass::soundness_bug);
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
  if (replay) *replay = f.counterexample ? in["counterexample"]["replay"].str() : std::string();
  if (events_replay) *events_replay = f.event_contradiction ? in["event_contradiction"]["replay"].str() : std::string();
  return f;
}

HostSearch read_host_search(const In& in) {
  HostSearch s;
  s.matched = in["matched"].boolean();
  s.exhausted = in["exhausted"].boolean();
  s.hosts = in["hosts"].count();
  s.derivations = in["derivations"].count();
  s.largest_host = in["largest_host"].count();
  s.host = in["host_graph"].optional(read_graph);
  s.result = in["result_graph"].optional(read_graph);
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
  a.class_name = in["class"].str();
  a.status = in["status"].named(proofs::Status::vacuous);
  a.darts = in["darts"].count();
  a.minimal = in["minimal"].boolean();
  a.bound = in["bound"].count();
  a.core = in["core"].strings();
  a.why = in["why"].str();
  a.host = in["symbolic_host"].optional(read_symbolic_host);
  a.host_graph = read_graph(in["host_graph"]);
  a.result_graph = read_graph(in["result_graph"]);
  a.replayed = in["replayed"].boolean();
  a.replay_failure = in["replay_failure"].str();
  a.seconds = in["seconds"].real();
  return a;
}

// The embeddings' answers of a proof (none when its embedding_search is
// null) and their replay commands.
std::optional<proofs::EmbeddingProof> read_embedding(const In& proof, std::vector<std::string>& replays) {
  replays.clear();
  const In search = proof["embedding_search"];
  if (search.null()) return std::nullopt;
  proofs::EmbeddingProof e;
  const In as = proof["embedding"];
  for (std::size_t k = 0; k < as.size(); ++k) {
    const In a = as[k];
    proofs::EmbeddingAnswer x;
    x.embedding = a["embedding"].str();
    x.static_failures = a["static"].strings();
    x.reading = a["reading"].named(proofs::Reading::arithmetic);
    x.status = a["answer"].named(proofs::EmbeddingAnswer::Status::unknown);
    x.darts = a["darts"].count();
    x.why = a["why"].str();
    x.uninterpreted = a["uninterpreted"].strings();
    x.functions = a["functions"].strings();
    x.replayed = a["replayed"].boolean();
    x.disagree = a["disagree"].boolean();
    x.note = a["note"].str();
    replays.push_back(a["replay"].str());
    e.answers.push_back(std::move(x));
  }
  e.hosts = search["hosts"].count();
  e.applications = search["applications"].count();
  e.queries = search["queries"].count();
  e.cached = search["cached"].count();
  e.out_of_scope = search["out_of_scope"].str();
  e.interrupted = search["interrupted"].boolean();
  e.seconds = proof["embedding_seconds"].real();
  return e;
}

std::optional<bool> read_static(const In& in) {
  const std::string s = in.str();
  if (s == "none") return std::nullopt;
  if (s != "holds" && s != "fails") in.fail("\"holds\", \"fails\" or \"none\"");
  return s == "holds";
}

proofs::ConstraintProof read_constraint(const In& c) {
  proofs::ConstraintProof cp;
  cp.constraint = {static_cast<RuleCondition>(c["kind"].integer(0, static_cast<int>(RuleCondition::no_loop))), c["i"].integer(-1, max_dimension),
                   c["j"].integer(-1, max_dimension)};
  cp.static_holds = read_static(c["static"]);
  cp.theorem = c["theorem"].optional(read_answer);
  cp.model = read_answer(c["model"]);
  cp.agreement = c["agreement"].named(proofs::Agreement::not_compared);
  cp.note = c["note"].str();
  return cp;
}

// The solver stage into `r`: the proof, per constraint its replay and
// replayed map, per embedding answer its replay.
void read_proof(RuleResult& r, const In& in) {
  proofs::RuleProof p;
  p.rule = in["rule"].str();
  p.model = in["model"].str();
  p.scheme = in["scheme"].boolean();
  p.out_of_scope = in["out_of_scope"].null() ? std::string() : in["out_of_scope"].str();
  p.static_failures = in["static_failures"].strings();
  r.proof_replays.clear();
  r.proof_maps.clear();
  const In cs = in["constraints"];
  for (std::size_t k = 0; k < cs.size(); ++k) {
    p.constraints.push_back(read_constraint(cs[k]));
    r.proof_replays.push_back(cs[k]["replay"].str());
    r.proof_maps.push_back(cs[k]["map"].optional(read_counterexample));
  }
  p.interrupted = in["interrupted"].boolean();
  p.embedding = read_embedding(in, r.embedding_replays);
  p.seconds = in["seconds"].real();
  r.proof = std::move(p);
}

// 004's potential events into `r`, with their replay commands.
void read_potential_events(RuleResult& r, const In& in) {
  analysis::PotentialEvents p;
  r.potential_event_replays.clear();
  const In es = in["events"];
  for (std::size_t k = 0; k < es.size(); ++k) {
    const In answer = es[k]["answer"];
    if (answer.str() != "witness" && answer.str() != "never") answer.fail("\"witness\" or \"never\"");
    p.events.push_back({es[k]["orbit"].str(), es[k]["claim"].str(), answer.str() == "witness", es[k]["darts"].count(), std::nullopt, {}});
    r.potential_event_replays.push_back(es[k]["replay"].str());
  }
  p.hosts = in["hosts"].count();
  p.applications = in["applications"].count();
  p.not_decided = in["not_decided"].str();
  p.interrupted = in["interrupted"].boolean();
  p.seconds = in["seconds"].real();
  r.potential_events = std::move(p);
}

}  // namespace

void restore_record(RuleResult& r, const Json& record) {
  const In in{record, "record"};
  const auto failures = in["failures"].strings();
  if (failures != r.failures)
    throw RecordError(fmt::format("record.failures: the shard found [{}] for rule '{}', the catalog now gives [{}] (did the catalog change?)",
                                  fmt::join(failures, ", "), r.name(), fmt::join(r.failures, ", ")));
  r.static_ms = in["static_ms"].real();
  r.host_search.reset();
  r.scheme_search.reset();
  if (const In c = in["confirmation"]; !c.null()) {
    if (c.has("fuzz"))
      r.scheme_search = read_fuzz(c["fuzz"]);
    else
      r.host_search = read_host_search(c);
  }
  r.fuzz = in["fuzz"].optional([&](const In& f) { return read_fuzz(f, &r.fuzz_replay, &r.events_replay); });
  if (!r.fuzz) r.fuzz_replay.clear(), r.events_replay.clear();
  r.proof.reset();
  r.proof_replays.clear();
  r.proof_maps.clear();
  r.embedding_replays.clear();
  if (const In p = in["proof"]; !p.null()) read_proof(r, p);
  r.potential_events.reset();
  r.potential_event_replays.clear();
  if (const In p = in["potential_events"]; !p.null()) read_potential_events(r, p);
  analysis::compare_with_record(r);
}

}  // namespace dartcheck::campaign
