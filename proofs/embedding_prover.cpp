#include "proofs/embedding_prover.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <set>
#include <unordered_map>

#include <fmt/format.h>

#include "checkers/embedding_conditions.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/host_search.hpp"
#include "checkers/rule_conditions.hpp"
#include "core/orbit.hpp"
#include "rewriting/application.hpp"
#include "rewriting/instantiated_classes.hpp"
#include "proofs/detail/solver_watch.hpp"
#include "proofs/symbolic_terms.hpp"
#include "proofs/detail/value_encoding.hpp"

namespace dartcheck::proofs {

std::string_view name_of(Reading r) { return r == Reading::uninterpreted ? "uninterpreted" : "arithmetic"; }

std::string_view name_of(EmbeddingAnswer::Status s) {
  switch (s) {
    case EmbeddingAnswer::Status::counterexample:
      return "counterexample";
    case EmbeddingAnswer::Status::none:
      return "none";
    case EmbeddingAnswer::Status::unknown:
      return "unknown";
  }
  return "";
}

namespace {

using Clock = std::chrono::steady_clock;

// One embedding's question on one derivation: H's orbits that hold two
// different expressions (one must differ for a break), and whether a dart
// of H has no value at all (a break whatever the values).
struct OrbitQuestion {
  std::vector<std::vector<std::uint32_t>> orbits;  // distinct expressions, two or more
  std::vector<Dart> at;                            // a dart of H in each
  Dart valueless = no_dart;
};

// The derivation's facts for every embedding: L's labels as equalities
// (the labeled match), and per embedding the orbits of H with their
// expressions, by 003 Def. 12-13 (extended) or Def. 1 (direct).
struct Derived {
  SymPool pool;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> equal;
  std::vector<OrbitQuestion> questions;  // per embedding of terms.embeddings
  Map h;
  explicit Derived(Map g) : h(std::move(g)) {}
};

// Lemma 3 (non-overlap), as application checks it: instances of L in
// different classes of the instantiated L must lie in different pi-orbits
// of G.
bool overlaps(const Operation& op, const Application& app, const SymbolicEvaluator& ev, const EmbeddingSignature& e) {
  const TopoGraph& L = op.rule.left();
  InstantiatedClasses cls;
  instantiated_classes(L, op.words.left, app.pattern ? &*app.pattern : nullptr, e.orbit, cls);
  std::map<std::uint32_t, std::uint32_t> class_of_orbit;
  for (NodeId x = 0; x < L.node_count(); ++x)
    for (std::size_t p = 0; p < app.match[x].size(); ++p) {
      const auto [it, fresh] = class_of_orbit.try_emplace(ev.orbit_of(e.name, app.match[x][p]), cls.of(x, p));
      if (!fresh && it->second != cls.of(x, p)) return true;
    }
  return false;
}

// H's orbits of embedding e and what each dart of them holds.
OrbitQuestion question(const Operation& op, const Application& app, const Map& h, SymbolicEvaluator& ev,
                       const std::vector<std::pair<Dart, std::uint32_t>>& writes, const EmbeddingSignature& e) {
  const RuleTerms& terms = *op.terms;
  const Rule& rule = op.rule;
  const bool extended = terms.instantiation == Instantiation::extended;
  const auto gens = dims_generators(e.orbit);
  const OrbitPartition part = partition_orbits(h, gens);
  const Renumbering ren = app.renumbering(rule, h.size());
  // Darts that lose their value: instances of a preserved node labeled in
  // L and not in R (their whole orbit, extended).
  std::vector<bool> cleared(h.size(), false);
  for (const NodeTerm& t : terms.left) {
    if (t.embedding != e.name) continue;
    const NodeId y = rule.to_right(*rule.left().find(t.node));
    if (y == no_node || terms.find('R', rule.right().name(y), e.name)) continue;
    for (Dart d : app.comatch[y]) {
      if (!extended) {
        cleared[d] = true;
        continue;
      }
      for (Dart x = 0; x < h.size(); ++x)
        if (part.of[x] == part.of[d]) cleared[x] = true;
    }
  }
  std::vector<std::vector<std::uint32_t>> written(extended ? part.size() : h.size());
  for (const auto& [d, v] : writes) written[extended ? part.of[d] : d].push_back(v);
  OrbitQuestion q;
  std::vector<std::vector<std::uint32_t>> held(part.size());
  for (Dart d = 0; d < h.size(); ++d) {
    const std::uint32_t o = part.of[d];
    const auto& w = written[extended ? o : d];
    if (!w.empty()) {
      held[o].insert(held[o].end(), w.begin(), w.end());
      continue;
    }
    const Dart from = ren.to_g(d);
    if (cleared[d] || from == no_dart) {
      if (q.valueless == no_dart) q.valueless = d;
      continue;
    }
    held[o].push_back(ev.value_at(e.name, from));
  }
  for (std::uint32_t o = 0; o < part.size(); ++o) {
    auto& v = held[o];
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    if (v.size() < 2) continue;
    q.orbits.push_back(std::move(v));
    q.at.push_back(part.first[o]);
  }
  return q;
}

// The facts of one application, or nothing where the library refuses it
// whatever the values (no match, a missing neighbour, Lemma 3).
std::optional<Derived> derive(const Operation& op, Applier& applier, const Map& g, std::span<const Dart> hooks, std::string& not_encoded,
                              bool fault) {
  Derived out(g);
  auto app = applier.apply(out.h, hooks);
  if (!app.ok()) return std::nullopt;
  const RuleTerms& terms = *op.terms;
  const TopoGraph& L = op.rule.left();
  SymbolicEvaluator ev(g, terms.embeddings, out.pool);
  const std::size_t np = app.value->match.empty() ? 1 : app.value->match[0].size();
  std::vector<std::vector<std::pair<Dart, std::uint32_t>>> writes(terms.embeddings.size());
  try {
    for (std::size_t p = 0; p < np; ++p) {
      std::vector<Dart> darts;
      for (NodeId x = 0; x < L.node_count(); ++x) darts.push_back(app.value->match[x][p]);
      for (const NodeTerm& t : terms.left) {
        const std::uint32_t have = ev.value_at(t.embedding, darts[*L.find(t.node)]);
        const std::uint32_t want = ev.value(t.term, L.names(), darts);
        if (have != want) out.equal.emplace_back(have, want);
      }
      for (const NodeTerm& t : terms.right)
        for (std::size_t k = 0; k < terms.embeddings.size(); ++k)
          if (terms.embeddings[k].name == t.embedding)
            writes[k].emplace_back(
                app.value->comatch[*op.rule.right().find(t.node)][p],
                fault ? out.pool.unknown(t.embedding, terms.embeddings[k].type, 1'000'000 + static_cast<std::uint32_t>(writes[k].size()), no_dart)
                      : ev.value(t.term, L.names(), darts));
    }
  } catch (const NoValue&) {
    return std::nullopt;
  } catch (const NotEncoded& e) {
    not_encoded = e.what();
    return std::nullopt;
  }
  if (terms.instantiation == Instantiation::extended)
    for (const EmbeddingSignature* e : terms.used())
      if (overlaps(op, *app.value, ev, *e)) return std::nullopt;
  for (std::size_t k = 0; k < terms.embeddings.size(); ++k)
    out.questions.push_back(question(op, *app.value, out.h, ev, writes[k], terms.embeddings[k]));
  return out;
}

// The query's text: two hosts with one text ask one question.
std::string query_key(Reading r, const Derived& d, const OrbitQuestion& q) {
  std::string key(name_of(r));
  for (const Unknown& u : d.pool.unknowns()) key += fmt::format(" {}", u.embedding);
  for (const auto& [a, b] : d.equal) key += fmt::format("|{}={}", d.pool.str(a), d.pool.str(b));
  for (const auto& v : q.orbits) {
    key += "|{";
    for (std::uint32_t x : v) key += d.pool.str(x) + ";";
  }
  if (q.valueless != no_dart) key += "|none";
  return key;
}

// The host of a counterexample with the model's values on every orbit
// the query read (other orbits get the type's zero, which nothing reads).
EmbeddedMap valued_host(const Operation& op, const Map& g, const Derived& d, ValueEncoding& enc, const z3::model* m) {
  EmbeddedMap host(g);
  for (const EmbeddingSignature& e : op.terms->embeddings) {
    const std::size_t k = host.add_embedding(e);
    if (!m) continue;
    const OrbitPartition part = partition_orbits(g, dims_generators(e.orbit));
    for (Dart first : part.first) {
      Value zero;
      zero.type = e.type;
      if (e.type == ValueType::string) zero = Value::text("");
      host.label_orbit(k, first, zero);
    }
    for (std::uint32_t u = 0; u < d.pool.unknowns().size(); ++u)
      if (const Unknown& x = d.pool.unknowns()[u]; x.embedding == e.name && x.dart < g.size()) host.label_orbit(k, x.dart, enc.decode(*m, u));
  }
  return host;
}

// The functions an embedding's terms call (for "every interpretation of ...").
std::vector<std::string> functions_of(const RuleTerms& terms, const std::string& embedding) {
  std::set<std::string> names;
  std::function<void(const Term&)> walk = [&](const Term& t) {
    if (t.kind == Term::Kind::call && !t.implicit) names.insert(t.name);
    for (const Term& a : t.args) walk(a);
  };
  for (const auto* side : {&terms.left, &terms.right})
    for (const NodeTerm& t : *side)
      if (t.embedding == embedding) walk(t.term);
  return std::vector<std::string>(names.begin(), names.end());
}

// One embedding in one reading, while the hosts are searched.
struct Search {
  EmbeddingAnswer answer;
  std::size_t embedding = 0;
  bool settled = false;
  std::string unknown;  // why the answer cannot be none
};

// Every embedding in both readings, with the static conditions it fails.
std::vector<Search> searches_of(const Operation& op) {
  const RuleTerms& terms = *op.terms;
  const auto verdicts = check_term_conditions(op.rule, op.words, terms);
  std::vector<Search> out;
  for (std::size_t k = 0; k < terms.embeddings.size(); ++k)
    for (Reading r : {Reading::uninterpreted, Reading::arithmetic}) {
      Search s;
      s.embedding = k;
      s.answer.embedding = terms.embeddings[k].name;
      s.answer.reading = r;
      s.answer.functions = functions_of(terms, s.answer.embedding);
      for (const auto& v : verdicts)
        if (v.embedding == s.answer.embedding && v.required && !v.holds) s.answer.static_failures.push_back(v.name());
      out.push_back(std::move(s));
    }
  return out;
}

// The search over rooted hosts: per application, every unsettled
// embedding and reading asked of Z3 (queries with one text asked once).
class HostQueries {
 public:
  HostQueries(const Operation& op, const EmbeddingProveOptions& o, EmbeddingProof& out)
      : op_(op), o_(o), out_(out), searches_(searches_of(op)), watch_(ctx_, o.stop), params_(ctx_), applier_(op) {
    params_.set("rlimit", o.rlimit);
    params_.set("ctrl_c", false);
  }

  bool all_settled() const {
    return std::all_of(searches_.begin(), searches_.end(), [](const Search& s) { return s.settled; });
  }
  bool stopped() const { return watch_.fired() || (o_.stop && o_.stop()); }

  // One application: every unsettled embedding and reading asked.
  void ask(const Map& g, std::span<const Dart> hooks) {
    auto d = derive(op_, applier_, g, hooks, not_encoded_, o_.fault == EmbeddingProveOptions::Fault::fresh_writes);
    if (o_.fault == EmbeddingProveOptions::Fault::no_breaks) return;
    if (!d) return;
    ++out_.applications;
    for (Search& s : searches_) {
      if (s.settled) continue;
      const OrbitQuestion& q = d->questions[s.embedding];
      if (q.orbits.empty() && q.valueless == no_dart) continue;  // consistent whatever the values
      try {  // a Z3 error (a literal it cannot read, memory) makes this answer unknown, not a crash
        ask(s, g, hooks, *d, q);
      } catch (const z3::exception& e) {
        s.unknown = fmt::format("Z3: {}", e.msg());
      }
    }
  }

  // The answers once the search ended: settled ones as found, the others
  // none or unknown (and why), on hosts up to `largest` darts.
  void finish(std::size_t largest, bool budget_hit) {
    out_.interrupted = stopped();
    for (Search& s : searches_) {
      EmbeddingAnswer& a = s.answer;
      if (a.reading == Reading::arithmetic) a.uninterpreted.assign(uninterpreted_.begin(), uninterpreted_.end());
      if (s.settled) {
        out_.answers.push_back(std::move(a));
        continue;
      }
      a.darts = largest;
      if (out_.interrupted)
        s.unknown = "interrupted (SIGINT or SIGTERM)";
      else if (budget_hit && largest < (op_.is_scheme() ? 1 : op_.rule.left().node_count()))
        s.unknown = fmt::format("the host budget of {} maps was reached at {} darts", o_.host_budget, largest + 1);
      else if (!not_encoded_.empty())
        s.unknown = fmt::format("a term outside the encoding: {}", not_encoded_);
      a.status = s.unknown.empty() ? EmbeddingAnswer::Status::none : EmbeddingAnswer::Status::unknown;
      a.why = s.unknown;
      if (a.status == EmbeddingAnswer::Status::none && budget_hit)
        a.why = fmt::format("searched up to {} darts: the host budget of {} maps was reached at {}", largest, o_.host_budget, largest + 1);
      out_.answers.push_back(std::move(a));
    }
  }

 private:
  // One embedding and reading on one application: is there a valuation
  // of the unknowns, equal on L's labels, under which an orbit of H gets
  // two values (or a dart none)?
  void ask(Search& s, const Map& g, std::span<const Dart> hooks, const Derived& d, const OrbitQuestion& q) {
    const std::string key = query_key(s.answer.reading, d, q);
    if (const auto it = cache_.find(key); it != cache_.end() && it->second != z3::sat) {
      ++out_.cached;
      return;
    }
    ValueEncoding enc(ctx_, d.pool, s.answer.reading);
    z3::solver solver(ctx_);
    solver.set(params_);
    for (const auto& [a, b] : d.equal) solver.add(enc.equal(a, b));
    z3::expr_vector breaks(ctx_);
    if (q.valueless != no_dart) breaks.push_back(ctx_.bool_val(true));
    for (const auto& v : q.orbits)
      for (std::size_t k = 1; k < v.size(); ++k) breaks.push_back(!enc.equal(v[0], v[k]));
    solver.add(z3::mk_or(breaks));
    for (const auto& p : enc.premises()) solver.add(p);
    ++out_.queries;
    const auto asked = Clock::now();
    const z3::check_result r = solver.check();
    out_.z3_seconds += std::chrono::duration<double>(Clock::now() - asked).count();
    cache_[key] = r;
    for (const auto& f : enc.uninterpreted()) uninterpreted_.insert(f);
    if (r == z3::unknown) {
      s.unknown =
          stopped() ? "interrupted (SIGINT or SIGTERM)" : fmt::format("Z3's rlimit of {} per query reached on a {}-dart host", o_.rlimit, g.size());
      return;
    }
    if (r == z3::sat) settle(s, g, hooks, d, q, enc, solver);
  }

  // A counterexample: its host with values (doubles preferred exact),
  // what breaks in the solver's model, and the library's own replay.
  void settle(Search& s, const Map& g, std::span<const Dart> hooks, const Derived& d, const OrbitQuestion& q, ValueEncoding& enc,
              z3::solver& solver) {
    EmbeddingAnswer& a = s.answer;
    s.settled = true;
    a.status = EmbeddingAnswer::Status::counterexample;
    a.darts = g.size();
    a.hooks.assign(hooks.begin(), hooks.end());
    if (a.reading == Reading::arithmetic) {
      solver.push();
      for (const auto& c : enc.small_integers(16)) solver.add(c);
      const bool small = solver.check() == z3::sat;
      if (!small) solver.pop();
      if (small || solver.check() == z3::sat) {
        const z3::model m = solver.get_model();
        a.host = valued_host(op_, g, d, enc, &m);
      }
    } else {
      a.host = valued_host(op_, g, d, enc, nullptr);
    }
    const z3::model m = solver.get_model();
    if (q.valueless != no_dart) {
      a.why = fmt::format("dart {} of H has no {} value", q.valueless, a.embedding);
    } else {
      for (std::size_t k = 0; k < q.orbits.size() && a.why.empty(); ++k)
        for (std::size_t j = 1; j < q.orbits[k].size() && a.why.empty(); ++j)
          if (m.eval(!enc.equal(q.orbits[k][0], q.orbits[k][j]), true).is_true())
            a.why = fmt::format("the {}-orbit of dart {} of H gets {} and {}", a.embedding, q.at[k], d.pool.str(q.orbits[k][0]),
                                d.pool.str(q.orbits[k][j]));
    }
    if (a.reading == Reading::arithmetic && a.host) replay(s);
  }

  // The library's own application must break the same embedding.
  void replay(Search& s) {
    EmbeddingAnswer& a = s.answer;
    EmbeddedMap replay = *a.host;
    const auto r = Applier(op_).apply(replay, a.hooks, true);
    if (!r.ok()) {
      a.replay = fmt::format("refused: {}", r.why);
      return;
    }
    const auto c = check_embedding(replay.map, *replay.find(a.embedding), true);
    a.replayed = !c.consistent();
    a.replay = a.replayed ? c.conflicts.front().describe(a.embedding, op_.terms->embeddings[s.embedding].orbit)
                          : fmt::format("the library's application leaves {} consistent", a.embedding);
  }

  const Operation& op_;
  const EmbeddingProveOptions& o_;
  EmbeddingProof& out_;
  std::vector<Search> searches_;
  z3::context ctx_;
  SolverWatch watch_;
  z3::params params_;
  std::unordered_map<std::string, z3::check_result> cache_;
  std::set<std::string> uninterpreted_;
  Applier applier_;
  std::string not_encoded_;
};

// Theorems 2 and 4 speak of rules whose topological conditions hold too:
// a break they forbid, or a counterexample the library does not replay,
// is a disagreement; a none where a static condition fails, a false alarm.
void judge(const Operation& op, EmbeddingProof& out) {
  const bool topology = check_rule(op.rule, op.words).consistent();
  for (EmbeddingAnswer& a : out.answers) {
    const bool holds = a.static_failures.empty() && topology;
    if (a.status == EmbeddingAnswer::Status::counterexample && holds) {
      a.disagree = true;
      a.note = fmt::format("the static conditions of {} hold, and Theorems 2 and 4 forbid a break in any algebra", a.embedding);
    } else if (a.status == EmbeddingAnswer::Status::counterexample && a.reading == Reading::arithmetic && !a.replayed) {
      a.disagree = true;
      a.note = fmt::format("the solver's counterexample does not replay: {}", a.replay);
    } else if (a.status == EmbeddingAnswer::Status::none && out.applications == 0) {
      a.note = fmt::format("no host up to {} darts admits an application (every match is refused whatever the values): nothing was decided", a.darts);
    } else if (a.status == EmbeddingAnswer::Status::none && !holds) {
      a.note = fmt::format("{} fails syntactically; no host up to {} darts breaks {}{}: a false alarm up to {} darts",
                           fmt::join(a.static_failures, ", "), a.darts, a.embedding,
                           a.reading == Reading::uninterpreted ? " for any interpretation of the operations" : " in real arithmetic", a.darts);
    }
  }
}

}  // namespace

EmbeddingProof prove_embeddings(const Operation& op, const EmbeddingProveOptions& o) {
  EmbeddingProof out;
  const auto start = Clock::now();
  if (!op.terms) {
    out.out_of_scope = "no embedding terms";
    return out;
  }
  HostQueries queries(op, o, out);
  const RootedHosts searched = for_each_rooted_host(
      op, o.max_darts,
      [&](const Map& g, std::span<const Dart> hooks) {
        queries.ask(g, hooks);
        return !queries.all_settled() && !queries.stopped();
      },
      o.host_budget);
  out.hosts = searched.hosts;
  queries.finish(searched.complete, searched.budget_hit);
  judge(op, out);
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return out;
}

}  // namespace dartcheck::proofs
