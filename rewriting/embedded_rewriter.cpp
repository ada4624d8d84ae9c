#include "rewriting/detail/embedded_rewriter.hpp"

#include <fmt/format.h>

#include "core/dart_table.hpp"
#include "core/orbit.hpp"
#include "rewriting/instantiated_classes.hpp"
#include "rewriting/term_eval.hpp"

namespace dartcheck {
namespace {

// The instantiated L: node (p, x) matched to dart[x][p]. A DPO rule is a
// scheme with one pattern position.
struct Instances {
  std::size_t np = 1;
  const std::vector<std::vector<Dart>>* dart = nullptr;  // the Application's match (not copied)
  const PatternGraphs* pattern = nullptr;                // schemes only

  explicit Instances(const Application& a)
      : np(a.pattern ? a.pattern->darts[0].size() : 1), dart(&a.match), pattern(a.pattern ? &*a.pattern : nullptr) {}

  Dart at(NodeId x, std::size_t p) const { return (*dart)[x][p]; }
  std::string name(const TopoGraph& side, NodeId x, std::size_t p) const {
    return pattern ? fmt::format("{}@{}", side.name(x), pattern->darts[0][p]) : side.name(x);
  }
  int generator(const ConjWord& w) const { return pattern ? pattern->generator(w) : -1; }
  std::uint32_t step(std::size_t p, int generator) const { return pattern ? pattern->step(p, generator) : static_cast<std::uint32_t>(p); }
};

// `x.pi` on node x for its own pi label: its value is the matched dart's.
bool own_value(const NodeTerm& t) {
  return t.term.kind == Term::Kind::access && t.term.name == t.embedding && t.term.args[0].kind == Term::Kind::variable &&
         t.term.args[0].name == t.node;
}

// Where the value of a labeled instance of R is: a stored value of G (a
// label kept from L, index into its pool) or an evaluated one (index into
// the application's evaluated values).
struct Source {
  std::uint32_t index = Embedding::none;
  bool stored = false;
};

// A refusal found by one phase of an application.
struct Refused {
  Refusal refusal;
  std::string why;
};

// The first labeled instance written to an orbit of H: its pool index,
// its source, and the instance (term k, pattern copy p).
struct Writer {
  std::uint32_t value;
  Source from;
  std::size_t k, p;
};

}  // namespace

struct EmbeddedRewriter::Context {
  Applier& topology;  // the match and the rewrite
  const Rule& rule;
  const ArcWords& words;
  const RuleTerms& terms;
  EmbeddedMap& g;
  Evaluation evaluation;
  TermFacts facts;  // what the rule and its terms decide alone
  const std::vector<NodeId>&left_node = facts.left_node, &right_node = facts.right_node, &stored_at = facts.stored_at;
  const std::vector<const EmbeddingSignature*>& used = facts.used;
  const std::vector<char>&closed = facts.closed, &left_closed = facts.left_closed;
  TermEvaluator ev;
  // The terms of L and R compiled for ev, once per application (the map
  // may have gained embeddings between applications).
  std::vector<CompiledTerm> left_code, right_code;
  OrbitWalker walker;
  // classes[u]: the classes of used[u] in the instantiated R, when one
  // evaluation per class or a write per class needs them (kept for the
  // next application's tables).
  std::vector<InstantiatedClasses> classes;
  InstantiatedClasses left_classes;               // of Lemma 3's check
  std::vector<std::vector<OrbitWord>> used_gens;  // generators of used[u]'s orbit
  // Per-application tables, kept for their memory: a loop of small
  // applications allocates nothing once they have grown.
  std::vector<Dart> flat;
  std::vector<Value> evaluated;
  std::vector<Source> source;
  std::vector<std::vector<Source>> class_source;
  std::vector<char> has_classes, per_class;
  std::vector<std::uint32_t> pooled, writer_of;
  std::vector<Writer> writers;
  DartTable orbit_of, given;  // each left empty between applications
  bool kept_shortcut = true;  // EvaluationOptions::kept_label_shortcut
  Applier::ShortcutCounts shortcuts;

  Context(Applier& a, const Operation& op, const RuleTerms& t, EmbeddedMap& map, const EvaluationOptions& o)
      : topology(a),
        rule(op.rule),
        words(op.words),
        terms(t),
        g(map),
        evaluation(o.evaluation),
        facts(term_facts(op.rule, t)),
        ev(map),
        walker(map.map),
        kept_shortcut(o.kept_label_shortcut) {
    classes.resize(used.size());
    class_source.resize(used.size());
    for (const EmbeddingSignature* sig : used) used_gens.push_back(dims_generators(sig->orbit));
  }

  Outcome<EmbeddedApplication> apply(std::span<const Dart> hook_darts, bool record);
  // The phases of apply.
  bool extended() const { return terms.instantiation == Instantiation::extended; }
  std::span<const Dart> binding(const Instances& in, std::size_t p) const;
  std::optional<Refused> label_match(const Instances& in);
  std::optional<Refused> right_sources(const Instances& in);
  void clear_labels(const std::vector<std::vector<Dart>>& comatch);
  void write_classes(std::size_t u, const Instances& in, const std::vector<std::vector<Dart>>& comatch, bool record, EmbeddedApplication& out);
  void write_instances(std::size_t u, const Instances& in, const std::vector<std::vector<Dart>>& comatch, bool record, EmbeddedApplication& out);
  std::string overlap(const Instances& in, std::size_t u);
  bool kept_classes(const Instances& in, std::size_t u, std::uint32_t group, const std::vector<std::uint32_t>& group_of,
                    const std::vector<int>& steps, std::vector<std::uint32_t>& id, std::uint32_t& count);
};

// The kept-label shortcut (EvaluationOptions::kept_label_shortcut) for
// group `group` of R's nodes and embedding used[u]: one class per pattern
// copy when the check holds, else false (the group is walked).
bool EmbeddedRewriter::Context::kept_classes(const Instances& in, std::size_t u, std::uint32_t group, const std::vector<std::uint32_t>& group_of,
                                             const std::vector<int>& steps, std::vector<std::uint32_t>& id, std::uint32_t& count) {
  if (steps.empty()) return false;
  const NodeId at = kept_source(facts, terms, used[u]->name, [&](NodeId y) { return group_of[y] == group; });
  const Embedding* e = g.find(used[u]->name);
  if (at == no_node || !e) return false;
  const auto slot_of = [e](Dart d) { return d < e->slot.size() ? e->slot[d] : Embedding::none; };
  for (std::size_t p = 0; p < in.np; ++p) {
    const std::uint32_t v = slot_of(in.at(at, p));
    bool agree = v != Embedding::none;
    for (std::size_t s = 0; agree && s < steps.size(); ++s) agree = slot_of(in.at(at, in.step(p, steps[s]))) == v;
    if (!agree) {
      ++shortcuts.refused;
      return false;
    }
  }
  id.resize(in.np);
  for (std::size_t p = 0; p < in.np; ++p) id[p] = count + static_cast<std::uint32_t>(p);
  count += static_cast<std::uint32_t>(in.np);
  ++shortcuts.taken;
  return true;
}

// Lemma 3: instances of L in different pi-orbits of the instantiated L
// must match darts in different pi-orbits of G. The matched darts are
// marked with their instance (x * np + p: the match is injective); each
// pi-orbit of G that holds one is walked once, from the first met, and
// every matched dart found in it must be in that instance's class. Only
// the matched darts are written, not the orbits walked.
std::string EmbeddedRewriter::Context::overlap(const Instances& in, std::size_t u) {
  constexpr std::uint32_t covered = DartTable::none - 1;  // in an orbit walked
  const EmbeddingSignature& e = *used[u];
  const TopoGraph& L = rule.left();
  const std::size_t np = in.np;
  instantiated_classes(L, words.left, in.pattern, e.orbit, left_classes);
  const DartTable::ClearOnExit emptied{orbit_of};
  for (NodeId x = 0; x < L.node_count(); ++x)
    for (std::size_t p = 0; p < np; ++p) orbit_of.set(in.at(x, p), static_cast<std::uint32_t>(x * np + p));
  const std::vector<OrbitWord>& gens = used_gens[u];
  for (NodeId x = 0; x < L.node_count(); ++x)
    for (std::size_t p = 0; p < np; ++p) {
      const Dart d = in.at(x, p);
      if (orbit_of.get(d) == covered) continue;
      const std::uint32_t cls = left_classes.of(x, p);
      for (Dart y : walker.orbit(d, gens)) {
        const std::uint32_t i = orbit_of.get(y);
        if (i == DartTable::none || i == covered) continue;  // covered: links that are not permutations (an invalid host)
        const auto z = static_cast<NodeId>(i / np);
        if (left_classes.of(z, i % np) != cls)
          return fmt::format(
              "nodes {} and {} are in different {}-orbits <{}> of L, but their darts {} and {} share one {}-orbit of the map (003 Lemma 3, "
              "non-overlap): the extended rule would give that orbit the labels of both",
              in.name(L, x, p), in.name(L, z, i % np), e.name, fmt::join(e.orbit, ","), d, y, e.name);
        orbit_of.set(y, covered);
      }
    }
  return {};
}

Outcome<EmbeddedApplication> EmbeddedRewriter::Context::apply(std::span<const Dart> hook_darts, bool record) {
  // Every embedding the rule labels is written, so the map must have it.
  for (const EmbeddingSignature* e : used)
    if (!g.find(e->name))
      return refuse<EmbeddedApplication>(
          Refusal::no_value, fmt::format("the rule labels {} <{}>, and the map has no embedding {}", e->name, fmt::join(e->orbit, ","), e->name));
  // 1. The match (nothing is written yet). Every return hands the
  //    application's tables back to the Applier, for the next one, but the
  //    one that gives them to the caller.
  struct Held {
    Applier& topology;
    std::optional<Application> a;
    ~Held() {
      if (a) topology.recycle(std::move(*a));
    }
  } held{topology, {}};
  {
    auto m = topology.match(g.map, hook_darts);
    if (!m.ok()) return refuse<EmbeddedApplication>(m.refusal, std::move(m.why));
    held.a = std::move(*m.value);
  }
  Instances in(*held.a);
  // 2. Evaluation (Def. 10) on G: the labeled match of L, Lemma 3, and
  //    the value of each labeled instance of R.
  if (auto r = label_match(in)) return refuse<EmbeddedApplication>(r->refusal, std::move(r->why));
  if (auto r = right_sources(in)) return refuse<EmbeddedApplication>(r->refusal, std::move(r->why));
  // 3. The topological rewrite (a DPO rule may still refuse: dangling,
  //    not-representable).
  {
    auto d = topology.rewrite(g.map, std::move(*held.a));
    held.a.reset();
    if (!d.ok()) return refuse<EmbeddedApplication>(d.refusal, std::move(d.why));
    held.a = std::move(*d.value);
  }
  in = Instances(*held.a);
  const std::vector<std::vector<Dart>>& comatch = held.a->comatch;
  const TopoGraph& R = rule.right();
  EmbeddedApplication out;
  out.matched = in.np * rule.left().node_count();
  for (NodeId y = 0; y < R.node_count(); ++y)
    if (rule.to_left(y) == no_node) out.added += comatch[y].size();
  g.follow(held.a->moved);
  // 4. Labels: those R drops, then R's.
  clear_labels(comatch);
  // pooled[i]: where evaluated[i] went once moved into its pool.
  pooled.assign(evaluated.size(), Embedding::none);
  for (std::size_t u = 0; u < used.size(); ++u) {
    if (extended() && closed[u] && per_class[u])
      write_classes(u, in, comatch, record, out);
    else
      write_instances(u, in, comatch, record, out);
  }
  out.topology.g_size = held.a->g_size;
  if (record) {
    out.topology = std::move(*held.a);
    held.a.reset();
  } else {
    out.topology.moved = held.a->moved;  // a copy: the tables go back to the Applier
  }
  return {std::move(out), Refusal::none, {}};
}

std::span<const Dart> EmbeddedRewriter::Context::binding(const Instances& in, std::size_t p) const {
  const std::size_t nl = rule.left().node_count();
  return nl == 1 ? std::span<const Dart>(&(*in.dart)[0][p], 1) : std::span<const Dart>(flat.data() + p * nl, nl);
}

// The labeled match of L: each term of L, compiled for this map, evaluated
// at its node's darts must equal their value; then Lemma 3 for each
// embedding L does not close.
std::optional<Refused> EmbeddedRewriter::Context::label_match(const Instances& in) {
  const TopoGraph& L = rule.left();
  const std::size_t np = in.np, nl = L.node_count();
  ev.memorise(true);
  ev.forget();
  const std::vector<std::string>& names = L.names();
  left_code.resize(terms.left.size());
  right_code.resize(terms.right.size());
  for (std::size_t k = 0; k < terms.left.size(); ++k) ev.compile(terms.left[k].term, names, left_code[k]);
  for (std::size_t k = 0; k < terms.right.size(); ++k) ev.compile(terms.right[k].term, names, right_code[k]);
  // binding(p): the darts of L's nodes in pattern copy p. With one node in
  // L (a Jerboa hook), the p-th entry of the match's own column: no table.
  if (nl > 1) {
    flat.resize(np * nl);
    for (NodeId x = 0; x < nl; ++x)
      for (std::size_t p = 0; p < np; ++p) flat[p * nl + x] = in.at(x, p);
  }
  try {
    for (std::size_t k = 0; k < terms.left.size(); ++k) {
      const NodeTerm& t = terms.left[k];
      const NodeId x = left_node[k];
      const Embedding* e = g.find(t.embedding);
      const bool trivial = own_value(t);
      for (std::size_t p = 0; p < np; ++p) {
        const Value* have = e ? e->value(in.at(x, p)) : nullptr;
        if (trivial && have) continue;
        const Value want = ev.value(left_code[k], binding(in, p));
        if (!have || !(*have == want))
          return Refused{Refusal::label_mismatch, fmt::format("node {} of L is labeled {} = {} = {}, but dart {} has {}", in.name(L, x, p),
                                                              t.embedding, t.term.str(), want.str(), in.at(x, p), have ? have->str() : "no value")};
      }
    }
  } catch (const EvaluationError& e) {
    return Refused{Refusal::no_value, fmt::format("a term of L has no value: {}", e.what())};
  }
  if (extended())
    for (std::size_t u = 0; u < used.size(); ++u)
      if (!left_closed[u])
        if (auto why = overlap(in, u); !why.empty()) return Refused{Refusal::overlap, std::move(why)};
  return std::nullopt;
}

std::optional<Refused> EmbeddedRewriter::Context::right_sources(const Instances& in) {
  const TopoGraph& R = rule.right();
  const std::size_t np = in.np;
  // The source of each labeled instance of R. With one evaluation per
  // class, every instance of a class takes its class's source
  // (class_source[u][c]: no per-instance table); otherwise each instance
  // has its own (source[k * np + p]).
  evaluated.clear();
  source.clear();
  has_classes.assign(used.size(), 0);
  per_class.assign(used.size(), 0);
  for (std::size_t u = 0; u < used.size(); ++u) {
    if (extended() && (evaluation == Evaluation::one_per_orbit || closed[u])) {
      if (kept_shortcut && evaluation == Evaluation::one_per_orbit && closed[u] && !rule.deletes_nodes()) {
        const GroupNumbering kept = [&](std::uint32_t group, const std::vector<std::uint32_t>& group_of, const std::vector<int>& steps,
                                        std::vector<std::uint32_t>& id,
                                        std::uint32_t& count) { return kept_classes(in, u, group, group_of, steps, id, count); };
        instantiated_classes(R, words.right, in.pattern, used[u]->orbit, classes[u], &kept);
      } else {
        instantiated_classes(R, words.right, in.pattern, used[u]->orbit, classes[u]);
      }
      has_classes[u] = true;
    }
    per_class[u] = has_classes[u] && evaluation == Evaluation::one_per_orbit;
    if (per_class[u])
      class_source[u].assign(classes[u].count, Source{});
    else if (source.empty())
      source.assign(terms.right.size() * np, Source{});
  }
  try {
    for (std::size_t u = 0; u < used.size(); ++u) {
      const EmbeddingSignature* sig = used[u];
      const Embedding* e = g.find(sig->name);
      const InstantiatedClasses& cls = classes[u];
      // One evaluation per class: a collect is not met twice from one
      // class, so it is not memorised.
      ev.memorise(!per_class[u]);
      for (std::size_t k = 0; k < terms.right.size(); ++k) {
        const NodeTerm& t = terms.right[k];
        if (t.embedding != sig->name) continue;
        for (std::size_t p = 0; p < np; ++p) {
          Source& here = per_class[u] ? class_source[u][cls.of(right_node[k], p)] : source[k * np + p];
          if (here.index != Embedding::none) continue;  // its class has one
          if (const NodeId at = stored_at[k]; at != no_node) {
            const Dart d = in.at(at, p);
            if (d >= e->slot.size() || e->slot[d] == Embedding::none)
              throw EvaluationError(fmt::format("{}: dart {} has no {} value", t.term.str(), d, t.embedding));
            here = {e->slot[d], true};
          } else {
            here = {static_cast<std::uint32_t>(evaluated.size()), false};
            evaluated.push_back(ev.value(right_code[k], binding(in, p)));
          }
        }
      }
    }
  } catch (const EvaluationError& e) {
    return Refused{Refusal::no_value, fmt::format("a term of R has no value: {}", e.what())};
  }
  return std::nullopt;
}

// Added darts may reuse deleted darts' slots: they start unlabeled (a dart
// beyond an embedding's table has no value yet).
void EmbeddedRewriter::Context::clear_labels(const std::vector<std::vector<Dart>>& comatch) {
  const TopoGraph& R = rule.right();
  for (NodeId y = 0; y < R.node_count(); ++y)
    if (rule.to_left(y) == no_node)
      for (Embedding& e : g.embeddings)
        for (Dart d : comatch[y])
          if (d < e.slot.size()) e.slot[d] = Embedding::none;
  // A preserved node labeled in L and not in R loses its value (unless a
  // label of R reaches it); R's labels are written next.
  for (std::size_t k = 0; k < terms.left.size(); ++k) {
    const NodeTerm& t = terms.left[k];
    const NodeId y = rule.to_right(left_node[k]);
    if (y == no_node || terms.find('R', t.node, t.embedding)) continue;
    Embedding* e = g.find(t.embedding);
    const auto gens = dims_generators(e->signature.orbit);
    for (Dart d : comatch[y]) {
      if (!extended()) {
        e->set_index(d, Embedding::none);
        continue;
      }
      for (Dart x : walker.orbit(d, gens)) e->set_index(x, Embedding::none);
    }
  }
}

// Every instance of a class took the class's source, so no two disagree:
// each labeled class's value is pooled once, and each instance of the
// class (a whole orbit of H) takes it.
void EmbeddedRewriter::Context::write_classes(std::size_t u, const Instances& in, const std::vector<std::vector<Dart>>& comatch, bool record,
                                              EmbeddedApplication& out) {
  const TopoGraph& R = rule.right();
  const std::size_t np = in.np;
  const EmbeddingSignature* sig = used[u];
  Embedding* e = g.find(sig->name);
  const InstantiatedClasses& cls = classes[u];
  writer_of.assign(cls.count, DartTable::none);
  const std::vector<Source>& of_class = class_source[u];
  auto value = [&](Source f) -> const Value& { return f.stored ? e->pool[f.index] : evaluated[f.index]; };
  if (record)
    for (std::size_t k = 0; k < terms.right.size(); ++k)
      if (terms.right[k].embedding == sig->name)
        for (std::size_t p = 0; p < np; ++p) {
          const NodeId y = right_node[k];
          out.written.push_back({sig->name, in.name(R, y, p), comatch[y][p], value(of_class[cls.of(y, p)])});
        }
  std::vector<std::uint32_t>& pool_index = writer_of;
  for (std::uint32_t c = 0; c < cls.count; ++c)
    if (const Source f = of_class[c]; f.index != Embedding::none) pool_index[c] = f.stored ? f.index : e->store(evaluated[f.index]);
  for (NodeId y = 0; y < R.node_count(); ++y)
    for (std::size_t p = 0; p < np; ++p)
      if (const std::uint32_t v = pool_index[cls.of(y, p)]; v != DartTable::none) e->set_index(comatch[y][p], v);
}

// The writer of each orbit of H this application labels is its first
// labeled instance. A closed embedding finds it by class (writer_of, per
// class), another by dart (given[d], set by walking the orbit from the
// writer). Two values for one orbit are a conflict (003 Def. 13).
void EmbeddedRewriter::Context::write_instances(std::size_t u, const Instances& in, const std::vector<std::vector<Dart>>& comatch, bool record,
                                                EmbeddedApplication& out) {
  const TopoGraph& R = rule.right();
  const std::size_t np = in.np;
  const EmbeddingSignature* sig = used[u];
  Embedding* e = g.find(sig->name);
  const std::vector<OrbitWord>& gens = used_gens[u];
  writers.clear();
  const InstantiatedClasses& cls = classes[u];
  const bool by_class = extended() && closed[u];
  writer_of.assign(by_class ? cls.count : 0, DartTable::none);
  std::vector<std::pair<Dart, std::uint32_t>> second_values;  // darts of a conflict
  const DartTable::ClearOnExit emptied{given};
  for (std::size_t k = 0; k < terms.right.size(); ++k) {
    const NodeTerm& t = terms.right[k];
    if (t.embedding != sig->name) continue;
    const NodeId y = right_node[k];
    for (std::size_t p = 0; p < np; ++p) {
      const Dart d = comatch[y][p];
      const Source from = per_class[u] ? class_source[u][cls.of(y, p)] : source[k * np + p];
      Value& v = from.stored ? e->pool[from.index] : pooled[from.index] != Embedding::none ? e->pool[pooled[from.index]] : evaluated[from.index];
      if (record) out.written.push_back({sig->name, in.name(R, y, p), d, v});
      auto stored = [&] { return from.stored ? from.index : e->store(v); };
      if (!extended()) {
        e->set_index(d, stored());
        continue;
      }
      if (const std::uint32_t w = by_class ? writer_of[cls.of(y, p)] : given.get(d); w != DartTable::none) {
        const Writer& first = writers[w];
        // The orbit already has this value: the same source (one per
        // orbit), the same stored value, or an equal evaluated one.
        if ((from.index == first.from.index && from.stored == first.from.stored) || (from.stored && first.value == from.index) ||
            e->pool[first.value] == v)
          continue;
        out.conflicts.push_back(
            fmt::format("the {}-orbit of dart {} gets {} from {} and {} from {}: the extended rule breaks (A), so the propagation "
                        "of 003 Def. 12 does not exist",
                        sig->name, d, e->pool[first.value].str(), in.name(R, right_node[first.k], first.p), v.str(), in.name(R, y, p)));
        if (by_class)
          second_values.emplace_back(d, stored());  // H shows both values
        else
          e->set_index(d, stored());
        continue;
      }
      // An evaluated value is written once as its orbit's first value:
      // moved into the pool (it is compared through the pool afterwards).
      std::uint32_t idx = from.index;
      if (!from.stored) idx = pooled[from.index] != Embedding::none ? pooled[from.index] : (pooled[from.index] = e->store(std::move(v)));
      const auto w = static_cast<std::uint32_t>(writers.size());
      writers.push_back({idx, from, k, p});
      if (by_class) {
        writer_of[cls.of(y, p)] = w;
        continue;
      }
      for (Dart x : walker.orbit(d, gens)) {
        e->set_index(x, idx);
        given.set(x, w);
      }
    }
  }
  // A written class is a whole orbit of H: each of its instances, labeled
  // or not, takes the class's value.
  if (by_class) {
    for (NodeId y = 0; y < R.node_count(); ++y)
      for (std::size_t p = 0; p < np; ++p)
        if (const std::uint32_t w = writer_of[cls.of(y, p)]; w != DartTable::none) e->set_index(comatch[y][p], writers[w].value);
    for (auto [d, idx] : second_values) e->set_index(d, idx);
  }
}

NodeId kept_source(const TermFacts& facts, const RuleTerms& terms, const std::string& embedding, const std::function<bool(NodeId)>& in_group) {
  NodeId at = no_node;
  for (std::size_t k = 0; k < terms.right.size(); ++k) {
    if (terms.right[k].embedding != embedding || !in_group(facts.right_node[k])) continue;
    if (facts.stored_at[k] == no_node || (at != no_node && facts.stored_at[k] != at)) return no_node;
    at = facts.stored_at[k];
  }
  return at;
}

TermFacts term_facts(const Rule& r, const RuleTerms& t) {
  TermFacts f;
  for (const NodeTerm& x : t.left) f.left_node.push_back(*r.left().find(x.node));
  for (const NodeTerm& x : t.right) {
    f.right_node.push_back(*r.right().find(x.node));
    const NodeId l = r.to_left(f.right_node.back());
    const Term* before = l == no_node ? nullptr : t.find('L', r.left().name(l), x.embedding);
    NodeId at = before && before->same(x.term) ? l : no_node;
    if (at == no_node && x.term.kind == Term::Kind::access && x.term.name == x.embedding && x.term.args[0].kind == Term::Kind::variable)
      if (const auto v = r.left().find(x.term.args[0].name)) at = *v;
    f.stored_at.push_back(at);
  }
  f.used = t.used();
  const TopoGraph &L = r.left(), &R = r.right();
  for (const EmbeddingSignature* sig : f.used) {
    bool all = true;
    for (NodeId y = 0; all && y < R.node_count(); ++y)
      for (Dim i : sig->orbit) all = all && R.out_arcs(y, i).size() == 1;
    f.closed.push_back(all);
    bool left = true;
    for (NodeId x = 0; left && x < L.node_count(); ++x)
      for (Dim i : sig->orbit) left = left && !L.out_arcs(x, i).empty();
    f.left_closed.push_back(left);
  }
  return f;
}

EmbeddedRewriter::EmbeddedRewriter(Applier& topology, const Operation& op, const RuleTerms& terms, EmbeddedMap& g, const EvaluationOptions& options)
    : c_(std::make_unique<Context>(topology, op, terms, g, options)) {}

EmbeddedRewriter::~EmbeddedRewriter() = default;

Outcome<EmbeddedApplication> EmbeddedRewriter::apply(std::span<const Dart> hook_darts, bool record) { return c_->apply(hook_darts, record); }

Applier::ShortcutCounts EmbeddedRewriter::kept_label_shortcuts() const { return c_->shortcuts; }

}  // namespace dartcheck
