#include "proofs/rule_prover.hpp"

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include <fmt/format.h>

#include "core/error.hpp"
#include "checkers/graph_constraints.hpp"
#include "rewriting/graph_derivation.hpp"
#include "rewriting/scheme_instantiation.hpp"
#include "proofs/detail/dpo_encoding.hpp"
#include "proofs/detail/scheme_encoding.hpp"
#include "proofs/detail/solver_watch.hpp"

namespace dartcheck::proofs {

std::string_view name_of(Status s) {
  switch (s) {
    case Status::counterexample:
      return "counterexample";
    case Status::none:
      return "none";
    case Status::unknown:
      return "unknown";
    case Status::vacuous:
      return "vacuous";
  }
  return "";
}

std::string_view name_of(Agreement a) {
  switch (a) {
    case Agreement::agree:
      return "agree";
    case Agreement::disagree:
      return "DISAGREE";
    case Agreement::unresolved:
      return "unresolved";
    case Agreement::not_compared:
      return "not compared";
  }
  return "";
}

std::size_t RuleProof::embedding_disagreements() const {
  std::size_t n = 0;
  if (embedding)
    for (const auto& a : embedding->answers) n += a.disagree;
  return n;
}

std::size_t RuleProof::count(Agreement a) const {
  std::size_t n = 0;
  for (const auto& c : constraints) n += c.agreement == a;
  return n;
}

TopoGraph host_graph(const Rule& rule, const HostClass& cls, const SymbolicHost& h) {
  const TopoGraph& L = rule.left();
  TopoGraph g;
  for (std::size_t x = 0; x < h.size; ++x) g.add_node(x < L.node_count() ? L.name(static_cast<NodeId>(x)) : fmt::format("d{}", x));
  for (Dim d : rule.model().dims) {
    if (const auto* l = h.find(d)) {
      for (std::size_t x = 0; x < h.size; ++x)
        if ((*l)[x] != no_dart) g.add_arc(static_cast<NodeId>(x), (*l)[x], d);
      continue;
    }
    std::vector<bool> has_out(h.size, false), has_in(h.size, false);
    for (const auto& a : L.arcs())
      if (a.label == d) {
        g.add_arc(a.source, a.target, d);
        has_out[a.source] = has_in[a.target] = true;
      }
    if (!cls.others_combinatorial) continue;
    // Complete L's partial injection to a permutation: free sources to free
    // targets in order (the premise of Theorems 2-3 makes any completion a
    // host of the class; the constraint checked only reads encoded labels).
    std::vector<NodeId> sources, targets;
    for (NodeId x = 0; x < h.size; ++x) {
      if (!has_out[x]) sources.push_back(x);
      if (!has_in[x]) targets.push_back(x);
    }
    for (std::size_t k = 0; k < sources.size() && k < targets.size(); ++k) g.add_arc(sources[k], targets[k], d);
  }
  return g;
}

Map host_map(const Model& model, const SymbolicHost& h) {
  Map m(model, h.size);
  for (const auto& [d, l] : h.links)
    for (Dart x = 0; x < h.size; ++x)
      if (l[x] != no_dart) m.set_link(d, x, l[x]);
  return m;
}

namespace {

using Clock = std::chrono::steady_clock;

bool graph_breaks(const TopoGraph& g, const HConstraint& c, bool partial) {
  for (NodeId v = 0; v < g.node_count(); ++v) {
    switch (c.kind) {
      case RuleCondition::incident_arcs: {
        std::vector<Violation> out;
        check_incidence(g, v, c.i, partial, out);
        if (!out.empty()) return true;
        break;
      }
      case RuleCondition::non_orientation:
        if (!non_oriented_at(g, v, c.i)) return true;
        break;
      case RuleCondition::cycle:
        if (!cycle_at(g, v, c.i, c.j)) return true;
        break;
      default:
        break;
    }
  }
  if (c.kind == RuleCondition::no_loop)
    for (const auto& a : g.arcs())
      if (a.label == c.i && a.source == a.target) return true;
  return false;
}

// Why g is not a host of the class, or empty.
std::string outside_class(const TopoGraph& g, const HostClass& cls, const Model& m) {
  for (Dim d : m.dims) {
    if (!has_dim(cls.symbolic, d) && !cls.others_combinatorial) continue;
    const bool partial = has_dim(cls.partial, d);
    for (NodeId v = 0; v < g.node_count(); ++v) {
      std::vector<Violation> out;
      check_incidence(g, v, d, partial, out);
      if (!out.empty()) return fmt::format("I({}) fails at {}", d, g.name(v));
      if (has_dim(cls.involutive, d) && !non_oriented_at(g, v, d)) return fmt::format("O({}) fails at {}", d, g.name(v));
    }
  }
  for (auto [i, j] : cls.cycles)
    for (NodeId v = 0; v < g.node_count(); ++v)
      if (!cycle_at(g, v, i, j)) return fmt::format("C({},{}) fails at {}", i, j, g.name(v));
  if (cls.loop_free)
    for (const auto& a : g.arcs())
      if (a.source == a.target) return fmt::format("loop at {}", g.name(a.source));
  return {};
}

// The match of L in the solver's host that sends L's node v to nodes[v],
// with an unused host arc for every arc of L; nullopt if there is none.
std::optional<GraphMatch> match_at(const TopoGraph& L, const TopoGraph& host, std::vector<NodeId> nodes) {
  GraphMatch m{std::move(nodes), {}};
  std::vector<bool> used(host.arc_count(), false);
  for (const auto& e : L.arcs()) {
    ArcId found = static_cast<ArcId>(-1);
    for (ArcId f = 0; f < host.arc_count() && found == static_cast<ArcId>(-1); ++f) {
      const auto& x = host.arc(f);
      if (!used[f] && x.source == m.node[e.source] && x.target == m.node[e.target] && x.label == e.label) found = f;
    }
    if (found == static_cast<ArcId>(-1)) return std::nullopt;
    used[found] = true;
    m.arc.push_back(found);
  }
  return m;
}

// Derives H from a[.host_graph] by `rule` at `nodes` with the library's own
// DPO derivation, and records whether H breaks c.
void derive_and_check(const Rule& rule, std::vector<NodeId> nodes, const HostClass& cls, const HConstraint& c, ClassAnswer& a) {
  const auto m = match_at(rule.left(), a.host_graph, std::move(nodes));
  if (!m) {
    a.replay_failure = "the solver's match is not a match of L in its host";
    return;
  }
  if (!satisfies_dangling(rule, a.host_graph, *m)) {
    a.replay_failure = "the match breaks the dangling condition in the solver's host";
    return;
  }
  a.result_graph = derive(rule, a.host_graph, *m);
  a.replayed = graph_breaks(a.result_graph, c, has_dim(cls.partial, c.i) || (c.j >= 0 && has_dim(cls.partial, c.j)));
  if (!a.replayed) a.replay_failure = fmt::format("the library's derivation on the solver's host satisfies {}", c.name());
}

// Replays a solver host through the library: in the class, the identity
// match satisfies the dangling condition, and derive() breaks c.
void replay(const Rule& rule, const HostClass& cls, const HConstraint& c, ClassAnswer& a) {
  a.host_graph = host_graph(rule, cls, *a.host);
  if (auto why = outside_class(a.host_graph, cls, rule.model()); !why.empty()) {
    a.replay_failure = "the solver's host is not in the class: " + why;
    return;
  }
  std::vector<NodeId> identity(rule.left().node_count());
  for (NodeId v = 0; v < identity.size(); ++v) identity[v] = v;
  derive_and_check(rule, std::move(identity), cls, c, a);
}

// A scheme's replay: the pattern graph of dart 0 in the solver's map, the
// instantiated rule ι(S, P_v) built as a DPO rule, and derive() on it.
void replay_scheme(const Operation& entry, const HostClass& cls, const HConstraint& c, ClassAnswer& a) {
  const Model& model = entry.rule.model();
  const Map host = host_map(model, *a.host);
  a.host_graph = to_graph(host);
  if (auto why = outside_class(a.host_graph, cls, model); !why.empty()) {
    a.replay_failure = "the solver's host is not in the class: " + why;
    return;
  }
  const Dart hook = 0;
  const auto pattern = pattern_graphs(model, entry.words, host, std::span(&hook, 1));
  if (!pattern.ok()) {
    a.replay_failure = "no pattern graph at dart 0 of the solver's map: " + pattern.why;
    return;
  }
  try {
    const Rule inst = instantiate(entry.rule, entry.words, *pattern.value);
    // ι(L, P_v) has one node per pattern dart (L is the hook alone).
    std::vector<NodeId> nodes(pattern.value->darts.front().begin(), pattern.value->darts.front().end());
    derive_and_check(inst, std::move(nodes), cls, c, a);
  } catch (const ValueError& e) {
    a.replay_failure = fmt::format("the instantiated rule is not a rule: {}", e.what());
  }
}

// The queries of one host class, sharing one incremental solver.
// A scheme that application always refuses (apply_scheme's static
// refusals): two arcs of L, or two added arcs of R, out of one node with
// one dimension.
std::string scheme_never_applies(const Rule& core) {
  for (const auto* side : {&core.left(), &core.right()}) {
    const bool left = side == &core.left();
    for (ArcId e = 0; e < side->arc_count(); ++e)
      for (ArcId f = e + 1; f < side->arc_count(); ++f) {
        const auto &a = side->arc(e), &b = side->arc(f);
        if (a.source != b.source || a.label != b.label) continue;
        if (left || (!core.preserved_right_arc(e) && !core.preserved_right_arc(f)))
          return fmt::format("{} has two {}-arcs out of {}: application always refuses", left ? "L" : "R \\ K", a.label, side->name(a.source));
      }
  }
  return {};
}

class ClassRun {
 public:
  ClassRun(z3::context& ctx, const Operation& entry, HostClass cls, const ProveOptions& o)
      : ctx_(ctx), entry_(entry), rule_(entry.rule), cls_(std::move(cls)), o_(o) {
    const auto start = Clock::now();
    setup(rule_, o);
    setup_seconds_ = std::chrono::duration<double>(Clock::now() - start).count();
  }

  ClassAnswer ask(const HConstraint& c) {
    const auto start = Clock::now();
    ClassAnswer a;
    a.class_name = cls_.name;
    a.darts = darts_;
    a.bound = bound();
    if (!blocked_.empty()) {
      a.status = Status::vacuous;
      a.why = blocked_;
    } else if (!unknown_.empty()) {
      a.status = Status::unknown;
      a.why = unknown_;
    } else {
      switch (enc_->breaks(c, &a.core)) {
        case Answer::sat:
          a.status = Status::counterexample;
          a.minimal = o_.minimize && enc_->minimize();
          a.host = enc_->host();
          a.darts = a.host->size;
          if (entry_.is_scheme())
            replay_scheme(entry_, cls_, c, a);
          else
            replay(rule_, cls_, c, a);
          break;
        case Answer::unsat:
          a.status = Status::none;
          break;
        case Answer::unknown:
          a.status = Status::unknown;
          a.why = "rlimit reached";
          break;
      }
    }
    // The first answer carries the encoding's cost too.
    a.seconds = std::chrono::duration<double>(Clock::now() - start).count() + setup_seconds_;
    setup_seconds_ = 0;
    return a;
  }

 private:
  void setup(const Rule& rule, const ProveOptions& o) {
    darts_ = o.max_darts;
    if (entry_.is_scheme()) {
      darts_ = std::min(o.max_darts, o.scheme_darts);
      blocked_ = scheme_never_applies(rule);
      if (blocked_.empty()) enc_ = std::make_unique<SchemeEncoding>(ctx_, rule, entry_.words, cls_, darts_, o.rlimit, o.timeout_ms);
      decide_derivable();
      return;
    }
    blocked_ = unmatchable_outside(rule, cls_);
    if (blocked_.empty() && rule.left().node_count() > o.max_darts)
      unknown_ = fmt::format("L has {} nodes, more than --max-darts {}", rule.left().node_count(), o.max_darts);
    if (!blocked_.empty() || !unknown_.empty()) return;
    // Past a small-model bound, larger hosts add nothing: encode up to it.
    darts_ = bound() ? std::min(o.max_darts, bound()) : o.max_darts;
    enc_ = std::make_unique<DpoEncoding>(ctx_, rule, cls_, darts_, o.rlimit, o.timeout_ms, o.fault);
    decide_derivable();
  }

  void decide_derivable() {
    if (!enc_) return;
    derivable_ = enc_->derivable();
    if (derivable_ == Answer::unsat)
      blocked_ = fmt::format("no host of up to {} darts admits a match with a derivation", darts_);
    else if (derivable_ == Answer::unknown)
      unknown_ = "the solver ran out of resources deciding whether a derivation exists";
  }

  // The small-model bounds of docs/prove.md: Theorem 1's violations do not
  // depend on the host beyond L; Theorem 2's live in L and its O-partners.
  std::size_t bound() const {
    const std::size_t nl = rule_.left().node_count();
    return cls_.theorem == 1 ? nl : cls_.theorem == 2 ? 2 * nl : 0;
  }

  z3::context& ctx_;
  const Operation& entry_;
  const Rule& rule_;
  HostClass cls_;
  const ProveOptions& o_;
  std::size_t darts_ = 0;
  double setup_seconds_ = 0;
  std::string blocked_, unknown_;
  std::unique_ptr<HostEncoding> enc_;
  Answer derivable_ = Answer::unknown;
};

void judge(ConstraintProof& p, bool combinatorial_rule, bool consistent) {
  const HConstraint& c = p.constraint;
  const bool holds = p.static_holds.value_or(true);
  auto bad_replay = [](const ClassAnswer& a) { return a.status == Status::counterexample && !a.replayed; };
  if (bad_replay(p.model) || (p.theorem && bad_replay(*p.theorem))) {
    p.agreement = Agreement::disagree;
    p.note = "a solver counterexample does not replay: " + (bad_replay(p.model) ? p.model : *p.theorem).replay_failure;
    return;
  }
  // Maps of the model are hosts of every theorem's class, so a static
  // condition that holds (with the theorem's premise) forbids a map
  // counterexample; so does a consistent rule.
  const bool premise = c.kind == RuleCondition::incident_arcs || combinatorial_rule;
  if (p.model.status == Status::counterexample && (consistent || (holds && (premise || c.kind == RuleCondition::no_loop)))) {
    p.agreement = Agreement::disagree;
    p.note = fmt::format("static {} holds, yet a valid map on {} darts yields an H that breaks it", c.name(), p.model.darts);
    return;
  }
  if (!p.theorem) {
    p.agreement = (p.model.status == Status::counterexample) != holds ? Agreement::agree : Agreement::not_compared;
    if (p.agreement == Agreement::not_compared)
      p.note = p.model.status == Status::unknown ? "unknown" : "static fails, no counterexample among maps up to the bound";
    return;
  }
  const ClassAnswer& t = *p.theorem;
  const int n = c.kind == RuleCondition::incident_arcs ? 1 : c.kind == RuleCondition::non_orientation ? 2 : 3;
  if (n > 1 && !combinatorial_rule) {
    p.agreement = Agreement::not_compared;
    p.note = fmt::format("Theorem {} assumes a D-combinatorial rule", n);
  } else if (t.status == Status::vacuous) {
    p.agreement = Agreement::not_compared;
    p.note = fmt::format("Theorem {} is vacuous here: {}", n, t.why);
  } else if (t.status == Status::unknown) {
    p.agreement = Agreement::not_compared;
    p.note = "the solver answered unknown: " + t.why;
  } else if (t.status == Status::counterexample) {
    p.agreement = holds ? Agreement::disagree : Agreement::agree;
    if (holds) p.note = fmt::format("static {} holds but a host of Theorem {}'s class breaks it: the theorem's (=>) fails", c.name(), n);
  } else if (holds) {
    p.agreement = Agreement::agree;
  } else if (t.proved_for_all()) {
    p.agreement = Agreement::disagree;
    p.note = fmt::format("static {} fails but no host of Theorem {}'s class breaks it (small-model bound {} darts): the theorem's (<=) fails",
                         c.name(), n, t.bound);
  } else {
    p.agreement = Agreement::unresolved;
    p.note = fmt::format("static {} fails; no counterexample up to {} darts", c.name(), t.darts);
  }
  if (p.agreement == Agreement::agree && !holds && p.model.status != Status::counterexample)
    p.note = fmt::format("a host of Theorem {}'s class breaks it, none of the {} up to {} darts does", n, p.model.class_name, p.model.darts);
}

// Schemes are asked about maps of the model only. Theorems 4-6 give the
// (=>) direction on them: a scheme whose condition holds (with the
// theorem's premise: Theorem 5 a (W,D)-combinatorial scheme, Theorem 6
// also O_S(N)) yields no H that breaks the constraint, so a map
// counterexample then contradicts the static checker. The (<=) of
// Theorems 4-5 quantifies over W-pattern graphs, and the P_v of a map
// obeys L's loops and the model's relations, so a failed condition with
// no map counterexample is not a contradiction; Theorem 6 is sufficient
// only.
void judge_scheme(ConstraintProof& p, const RuleVerdict& v) {
  const HConstraint& c = p.constraint;
  const bool holds = p.static_holds.value_or(true);
  const ClassAnswer& m = p.model;
  if (m.status == Status::counterexample && !m.replayed) {
    p.agreement = Agreement::disagree;
    p.note = "a solver counterexample does not replay: " + m.replay_failure;
    return;
  }
  const int theorem = c.kind == RuleCondition::incident_arcs ? 4 : c.kind == RuleCondition::non_orientation ? 5 : 6;
  bool premise = c.kind == RuleCondition::incident_arcs || c.kind == RuleCondition::no_loop || combinatorial(v);
  if (c.kind == RuleCondition::cycle)
    for (const auto& cond : v.conditions) premise = premise && (cond.condition != RuleCondition::non_orientation || cond.holds);
  if (m.status == Status::counterexample) {
    if (v.consistent() || (holds && premise)) {
      p.agreement = Agreement::disagree;
      p.note = fmt::format("static {} holds, yet a valid map on {} darts yields an H that breaks it{}", c.name(), m.darts,
                           c.kind == RuleCondition::no_loop ? "" : fmt::format(": Theorem {}'s (=>) fails", theorem));
    } else {
      p.agreement = Agreement::agree;
      if (holds) p.note = fmt::format("static {} holds, but Theorem {}'s premise does not", c.name(), theorem);
    }
    return;
  }
  if (m.status == Status::unknown || m.status == Status::vacuous) {
    p.agreement = Agreement::not_compared;
    p.note = (m.status == Status::unknown ? "the solver answered unknown: " : "the scheme never applies: ") + m.why;
    return;
  }
  if (holds) {
    p.agreement = Agreement::agree;
    return;
  }
  p.agreement = Agreement::not_compared;
  if (!premise) {
    p.note = fmt::format("Theorem {} assumes a (W,D)-combinatorial scheme{}", theorem, theorem == 6 ? " satisfying O_S(N)" : "");
    return;
  }
  p.note = c.kind == RuleCondition::cycle
               ? fmt::format("static {} fails, no map up to {} darts breaks it: Theorem 6 is sufficient, not necessary", c.name(), m.darts)
               : fmt::format(
                     "static {} fails, no map up to {} darts breaks it: Theorem {}'s (<=) ranges over W-pattern graphs, not over "
                     "the P_v of maps where L matches",
                     c.name(), m.darts, theorem);
}

}  // namespace

RuleProof prove_rule(const Operation& entry, const ProveOptions& o) {
  const auto start = Clock::now();
  const Rule& rule = entry.rule;
  RuleProof p;
  p.rule = rule.name();
  p.model = rule.model().name;
  p.scheme = entry.is_scheme();
  if (p.scheme) p.out_of_scope = scheme_out_of_scope(rule);
  // Embeddings first: their hosts are enumerated, so a scheme outside the
  // topological encoding's scope is still answered.
  if (o.embeddings && entry.terms) {
    EmbeddingProveOptions eo;
    eo.max_darts = embedding_host_darts(rule, o.embedding_darts);
    eo.rlimit = o.rlimit;
    eo.stop = o.stop;
    p.embedding = prove_embeddings(entry, eo);
    if (p.embedding->interrupted) {  // Ctrl-C: the topological queries are not started
      p.interrupted = true;
      p.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      return p;
    }
  }
  if (!p.out_of_scope.empty()) {
    p.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return p;
  }
  const RuleVerdict verdict = check_rule(rule, entry.words);
  for (const auto& c : verdict.conditions)
    if (!c.holds) p.static_failures.push_back(c.name());
  const bool comb = combinatorial(verdict);
  z3::context ctx;
  const SolverWatch watch(ctx, o.stop);
  ClassRun maps(ctx, entry, model_class(rule.model()), o);
  for (const HConstraint& c : model_constraints(rule.model())) {
    if (watch.fired()) break;  // the rule's remaining constraints are not asked
    ConstraintProof cp;
    cp.constraint = c;
    if (const auto* sc = static_condition(verdict, c)) cp.static_holds = sc->holds;
    cp.model = maps.ask(c);
    if (!p.scheme)
      if (auto cls = theorem_class(c)) cp.theorem = ClassRun(ctx, entry, *cls, o).ask(c);
    // An interrupted query ends "unknown" like one out of resources: say which.
    if (watch.fired())
      for (ClassAnswer* a : {&cp.model, cp.theorem ? &*cp.theorem : nullptr})
        if (a && a->status == Status::unknown) a->why = "interrupted (SIGINT or SIGTERM)";
    if (p.scheme)
      judge_scheme(cp, verdict);
    else
      judge(cp, comb, verdict.consistent());
    p.constraints.push_back(std::move(cp));
  }
  p.interrupted = watch.fired();
  p.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return p;
}

std::string solver_version() {
  unsigned major = 0, minor = 0, build = 0, revision = 0;
  Z3_get_version(&major, &minor, &build, &revision);
  return fmt::format("{}.{}.{}", major, minor, build);
}

}  // namespace dartcheck::proofs
