#include "core/embedded_application.hpp"

#include <numeric>
#include <unordered_map>

#include <fmt/format.h>

#include "core/orbit.hpp"
#include "core/term_eval.hpp"

namespace dartcheck {

namespace {

template <class T>
Outcome<T> refuse(Refusal r, std::string why) {
  return {std::nullopt, r, std::move(why)};
}

// The instantiated L: node (p, x) matched to dart[x][p]. A DPO rule is a
// scheme with one pattern position.
struct Instances {
  std::size_t np = 1;
  std::vector<std::vector<Dart>> dart;
  const PatternGraphs* pattern = nullptr;  // schemes only

  std::vector<Dart> column(std::size_t p) const {
    std::vector<Dart> c;
    for (const auto& d : dart) c.push_back(d[p]);
    return c;
  }
  std::string name(const TopoGraph& side, NodeId x, std::size_t p) const {
    return pattern ? fmt::format("{}@{}", side.name(x), pattern->darts[0][p]) : side.name(x);
  }
  std::uint32_t step(std::size_t p, const ConjWord& w) const { return pattern ? pattern->step(p, w) : static_cast<std::uint32_t>(p); }
};

struct UnionFind {
  std::vector<std::size_t> up;
  explicit UnionFind(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0); }
  std::size_t find(std::size_t x) {
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) { up[find(a)] = find(b); }
};

bool in_orbit(const std::vector<Dim>& orbit, Dim d) { return std::find(orbit.begin(), orbit.end(), d) != orbit.end(); }

// Lemma 3: instances of L in different pi-orbits of the instantiated L
// must match darts in different pi-orbits of G.
std::string overlap(const Rule& rule, const ArcWords& words, const Instances& in, const EmbeddingSignature& e, const Map& g) {
  const TopoGraph& L = rule.left();
  const std::size_t np = in.np;
  UnionFind uf(L.node_count() * np);
  for (ArcId a = 0; a < L.arc_count(); ++a) {
    const auto& arc = L.arc(a);
    if (!in_orbit(e.orbit, arc.label)) continue;
    for (std::size_t p = 0; p < np; ++p) uf.unite(arc.source * np + p, arc.target * np + in.step(p, arc_word(words.left, a)));
  }
  // The pi-orbit of each matched dart in G, named by its smallest dart.
  OrbitWalker walker(g);
  const auto gens = dims_generators(e.orbit);
  std::unordered_map<Dart, Dart> rep;
  std::unordered_map<Dart, std::size_t> owner;  // G orbit -> an instance in it
  for (NodeId x = 0; x < L.node_count(); ++x)
    for (std::size_t p = 0; p < np; ++p) {
      const Dart d = in.dart[x][p];
      if (!rep.contains(d)) {
        const auto& orbit = walker.orbit(d, gens);
        const Dart least = *std::min_element(orbit.begin(), orbit.end());
        for (Dart y : orbit) rep[y] = least;
      }
      const std::size_t k = x * np + p;
      const auto [it, fresh] = owner.emplace(rep[d], k);
      if (!fresh && uf.find(it->second) != uf.find(k)) {
        const std::size_t o = it->second;
        return fmt::format("nodes {} and {} are in different {}-orbits <{}> of L, but their darts {} and {} share one {}-orbit of the map (003 Lemma 3, "
                           "non-overlap): the extended rule would give that orbit the labels of both",
                           in.name(L, static_cast<NodeId>(o / np), o % np), in.name(L, x, p), e.name, fmt::join(e.orbit, ","),
                           in.dart[o / np][o % np], d, e.name);
      }
    }
  return {};
}

}  // namespace

Outcome<EmbeddedDerivation> apply_embedded(const Rule& rule, const ArcWords& words, const RuleTerms& terms, EmbeddedMap& g,
                                           std::span<const Dart> hook_darts, bool record) {
  const TopoGraph &L = rule.left(), &R = rule.right();
  // 1. The match (nothing is written yet).
  Instances in;
  std::optional<SchemeMatch> scheme_match;
  if (words.scheme) {
    auto m = match_scheme(rule, words, g.map, hook_darts);
    if (!m.ok()) return refuse<EmbeddedDerivation>(m.refusal, std::move(m.why));
    scheme_match = std::move(*m.value);
    in.np = scheme_match->pattern.darts[0].size();
    in.dart = scheme_match->node;
    in.pattern = &scheme_match->pattern;
  } else {
    auto m = match_from_hooks(rule, g.map, hook_darts);
    if (!m.ok()) return refuse<EmbeddedDerivation>(m.refusal, std::move(m.why));
    for (Dart d : m.value->node) in.dart.push_back({d});
  }
  const std::size_t np = in.np;

  // 2. Evaluation (Def. 10) on G, and the labeled match of L.
  TermEvaluator ev(g);
  const std::vector<std::string>& names = L.names();
  std::vector<std::vector<Dart>> columns;
  for (std::size_t p = 0; p < np; ++p) columns.push_back(in.column(p));
  try {
    for (const NodeTerm& t : terms.left) {
      const NodeId x = *L.find(t.node);
      const Embedding* e = g.find(t.embedding);
      for (std::size_t p = 0; p < np; ++p) {
        const Value want = ev.value(t.term, names, columns[p]);
        const Value* have = e ? e->value(in.dart[x][p]) : nullptr;
        if (!have || !(*have == want))
          return refuse<EmbeddedDerivation>(Refusal::label_mismatch,
                                            fmt::format("node {} of L is labeled {} = {} = {}, but dart {} has {}", in.name(L, x, p), t.embedding, t.term.str(),
                                                        want.str(), in.dart[x][p], have ? have->str() : "no value"));
      }
    }
  } catch (const EvaluationError& e) {
    return refuse<EmbeddedDerivation>(Refusal::no_value, fmt::format("a term of L has no value: {}", e.what()));
  }
  if (terms.instantiation == Instantiation::extended)
    for (const EmbeddingSignature* e : terms.used())
      if (auto why = overlap(rule, words, in, *e, g.map); !why.empty()) return refuse<EmbeddedDerivation>(Refusal::overlap, std::move(why));

  // The values of R's labeled instances, in terms.right order.
  std::vector<std::vector<Value>> values(terms.right.size());
  try {
    for (std::size_t k = 0; k < terms.right.size(); ++k)
      for (std::size_t p = 0; p < np; ++p) values[k].push_back(ev.value(terms.right[k].term, names, columns[p]));
  } catch (const EvaluationError& e) {
    return refuse<EmbeddedDerivation>(Refusal::no_value, fmt::format("a term of R has no value: {}", e.what()));
  }

  // 3. The topological rewrite.
  EmbeddedDerivation out;
  std::vector<std::vector<Dart>> comatch(R.node_count());
  if (words.scheme) {
    SchemeDerivation d = rewrite_scheme(rule, words, g.map, *scheme_match);
    out.matched = d.matched_darts;
    out.added = d.added_darts;
    out.moved = std::move(d.moved);
    comatch = std::move(d.comatch);
  } else {
    auto d = apply_rule(rule, g.map, hook_darts);
    if (!d.ok()) return refuse<EmbeddedDerivation>(d.refusal, std::move(d.why));
    out.matched = L.node_count();
    for (NodeId y = 0; y < R.node_count(); ++y) {
      comatch[y] = {d.value->comatch[y]};
      out.added += rule.to_left(y) == no_node;
    }
    out.moved = std::move(d.value->moved);
  }
  g.follow(out.moved);
  // Added darts may reuse deleted darts' slots: they start unlabeled.
  for (NodeId y = 0; y < R.node_count(); ++y)
    if (rule.to_left(y) == no_node)
      for (Dart d : comatch[y])
        for (Embedding& e : g.embeddings) e.set_index(d, Embedding::none);

  // 4. Labels. A preserved node labeled in L and not in R loses its value
  //    (unless a label of R reaches it); R's labels are written next.
  const bool extended = terms.instantiation == Instantiation::extended;
  OrbitWalker walker(g.map);
  for (const NodeTerm& t : terms.left) {
    const NodeId y = rule.to_right(*L.find(t.node));
    if (y == no_node || terms.find('R', t.node, t.embedding)) continue;
    Embedding* e = g.find(t.embedding);
    for (Dart d : comatch[y]) {
      if (!extended) {
        e->set_index(d, Embedding::none);
        continue;
      }
      for (Dart x : walker.orbit(d, dims_generators(e->signature.orbit))) e->set_index(x, Embedding::none);
    }
  }
  for (const EmbeddingSignature* sig : terms.used()) {
    Embedding* e = g.find(sig->name);
    const auto gens = dims_generators(sig->orbit);
    std::unordered_map<Dart, std::pair<std::uint32_t, std::string>> given;  // dart -> (value, instance) this application
    for (std::size_t k = 0; k < terms.right.size(); ++k) {
      const NodeTerm& t = terms.right[k];
      if (t.embedding != sig->name) continue;
      const NodeId y = *R.find(t.node);
      for (std::size_t p = 0; p < np; ++p) {
        const Dart d = comatch[y][p];
        const std::uint32_t idx = e->store(values[k][p]);
        if (record) out.written.push_back({sig->name, in.name(R, y, p), d, values[k][p]});
        if (!extended) {
          e->set_index(d, idx);
          continue;
        }
        if (const auto it = given.find(d); it != given.end()) {
          if (e->pool[it->second.first] == values[k][p]) continue;  // the orbit already has this value
          out.conflicts.push_back(fmt::format("the {}-orbit of dart {} gets {} from {} and {} from {}: the extended rule breaks (A), so the propagation "
                                              "of 003 Def. 12 does not exist",
                                              sig->name, d, e->pool[it->second.first].str(), it->second.second, values[k][p].str(), in.name(R, y, p)));
          e->set_index(d, idx);  // H shows both values
          continue;
        }
        const std::string who = in.name(R, y, p);
        for (Dart x : walker.orbit(d, gens)) {
          e->set_index(x, idx);
          given.emplace(x, std::make_pair(idx, who));
        }
      }
    }
  }
  return {std::move(out), Refusal::none, {}};
}

}  // namespace dartcheck
