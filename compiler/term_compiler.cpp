#include "compiler/term_compiler.hpp"

#include <cmath>
#include <map>
#include <numeric>

#include <fmt/args.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compiler/comatch_text.hpp"
#include "compiler/cpp_text.hpp"
#include "core/disjoint_sets.hpp"
#include "rewriting/term_facts.hpp"
#include "rewriting/term_functions.hpp"

namespace dartcheck::compiler {
namespace {

// Every function call of a term, depth first.
void for_each_call(const Term& t, const auto& f) {
  if (t.kind == Term::Kind::call) f(t);
  for (const Term& a : t.args) for_each_call(a, f);
}

// `x.pi` on node x for its own embedding pi (the interpreter's own_value):
// checked by a read, not an evaluation and a comparison.
bool own_value(const NodeTerm& t) {
  return t.term.kind == Term::Kind::access && t.term.name == t.embedding && t.term.args[0].kind == Term::Kind::variable &&
         t.term.args[0].name == t.node;
}

// A double as a C++ literal that reads back to the same bits.
std::string double_literal(double x) {
  if (std::isnan(x)) return "std::numeric_limits<double>::quiet_NaN()";
  if (std::isinf(x)) return x > 0 ? "std::numeric_limits<double>::infinity()" : "-std::numeric_limits<double>::infinity()";
  return fmt::format("{:a}", x);  // hexadecimal: exact
}

// Two more spaces before every line of generated code.
void indent(std::string& code) {
  for (std::size_t i = 0; i < code.size(); ++i)
    if (i == 0 || code[i - 1] == '\n') code.insert(i, "  ");
}

struct Grouping {
  bool grouped = true;
  std::vector<std::size_t> group_of;
  std::vector<std::vector<int>> words;  // per group: generators followed
};

}  // namespace

std::optional<std::string> terms_not_compilable(const Operation& op) {
  if (!op.terms) return std::nullopt;
  std::optional<std::string> why;
  auto check = [&](const NodeTerm& t) {
    for_each_call(t.term, [&](const Term& c) {
      if (!why && (!c.function || c.function->cpp.empty()))
        why = fmt::format("its term {} calls {}, a function with no C++ text (not one of the built-in algebra's)", t.term.str(), c.name);
    });
  };
  for (const NodeTerm& t : op.terms->left) check(t);
  for (const NodeTerm& t : op.terms->right) check(t);
  return why;
}

struct TermCode::Plan {
  const Operation& op;
  const SchemeFacts& facts;
  const RuleTerms& terms;
  TermFacts tf;  // the interpreter's own decisions (term_facts)
  const std::vector<const EmbeddingSignature*>& used = tf.used;
  const std::vector<NodeId>&left_node = tf.left_node, &right_node = tf.right_node, &stored_at = tf.stored_at;
  const std::vector<char>&closed = tf.closed, &left_closed = tf.left_closed;
  std::vector<std::string> embeddings;      // every embedding a term names: e0, e1, ...
  std::map<const Term*, std::size_t> site;  // collect -> CollectSite number (and bag)
  std::vector<const Term*> sites;
  std::map<const Term*, std::size_t> each_site;  // each -> EachSite number
  std::vector<const Term*> each_sites;
  std::vector<Grouping> right_groups;  // per used embedding
  std::vector<std::vector<NodeId>> kept_at;  // per used embedding and group: kept_groups

  Plan(const Operation& o, const SchemeFacts& f) : op(o), facts(f), terms(*o.terms), tf(term_facts(o.rule, *o.terms)) {
    for (const EmbeddingSignature* e : used) embedding(e->name);
    auto number = [&](const Term& t, const auto& self) -> void {
      if (t.kind == Term::Kind::access || t.kind == Term::Kind::collect) embedding(t.name);
      if (t.kind == Term::Kind::collect) {
        site[&t] = sites.size();
        sites.push_back(&t);
      }
      if (t.kind == Term::Kind::each) {
        each_site[&t] = each_sites.size();
        each_sites.push_back(&t);
      }
      for (const Term& a : t.args) self(a, self);
    };
    for (const NodeTerm& x : terms.left) number(x.term, number);
    for (const NodeTerm& x : terms.right) number(x.term, number);
    for (const EmbeddingSignature* sig : used) right_groups.push_back(grouping(op.rule.right(), op.words.right, sig->orbit));
    for (std::size_t u = 0; u < used.size(); ++u) kept_at.push_back(kept_groups(u));
  }

  // The groups of R for embedding u whose classes need no walk when G's
  // labels agree along the group's loops (the kept-label shortcut): per
  // group, the L node whose matched darts' stored value is each of the
  // group's terms, or no_node. Conditions, all known from the rule:
  //   - extended instantiation, R closes the orbit (a class is written per
  //     instance), the classes found by groups, the group has loop words;
  //   - every term of u in the group is kept from G, from one node of L
  //     (stored_at): then every instance of a copy p reads the same dart;
  //   - no node of L is deleted, so no dart of G is renumbered.
  // Why the result is the walk's, bit for bit: if at every copy p the
  // pool index i(p) of the kept node's matched dart is defined and equals
  // i(p.w) for each loop word w of the group, then i is constant on each
  // class (a class is connected by those shifts), and the class's source,
  // i at its first copy, is i(p) at each of its copies. The generated code
  // checks that at run time, in one pass without marks, and walks the
  // classes as before when it fails (G inconsistent, or equal values kept
  // as distinct pool entries, or a missing value, which the walk reports).
  std::vector<NodeId> kept_groups(std::size_t u) const {
    const Grouping& gr = right_groups[u];
    std::vector<NodeId> out(gr.words.size(), no_node);
    if (!extended() || !closed[u] || !gr.grouped || op.rule.deletes_nodes()) return out;
    for (std::size_t g = 0; g < out.size(); ++g)
      if (!gr.words[g].empty()) out[g] = kept_source(tf, terms, used[u]->name, [&](NodeId y) { return gr.group_of[y] == g; });
    return out;
  }

  std::size_t embedding(const std::string& name) {
    const auto it = std::find(embeddings.begin(), embeddings.end(), name);
    if (it != embeddings.end()) return static_cast<std::size_t>(it - embeddings.begin());
    embeddings.push_back(name);
    return embeddings.size() - 1;
  }
  std::size_t index_of(const std::string& name) const {
    return static_cast<std::size_t>(std::find(embeddings.begin(), embeddings.end(), name) - embeddings.begin());
  }
  bool extended() const { return terms.instantiation == Instantiation::extended; }

  // The dart variables of the each loops around a term being generated,
  // outermost first: (name, C++ variable).
  using Bound = std::vector<std::pair<std::string, std::string>>;

  // The dart of a Node term at pattern position p. A name is L's node
  // first, then an each's dart variable (the evaluator's order of names;
  // the checker refuses a dart variable that hides a node).
  std::string node(const Term& t, const Bound& bound = {}) const {
    if (t.kind == Term::Kind::variable) {
      if (const auto x = op.rule.left().find(t.name)) return fmt::format("match[{} * np + p]", *x);
      for (const auto& [name, var] : bound)
        if (name == t.name) return var;
      return fmt::format("(throw EvaluationError({}), no_dart)", cpp_literal(fmt::format("node variable '{}' is not bound", t.name)));
    }
    return fmt::format("neighbour(g, {}, {}, {})", t.dim, node(t.args[0], bound), cpp_literal(t.str()));
  }

  // The class a term of R is evaluated for in an everywhere function
  // (positions are darts): embedding u's group g, whose first position p
  // evaluates it.
  struct Along {
    std::size_t u, g;
  };

  // Whether group g of embedding u is joined by two single-letter
  // generators of non-oriented dimensions (a face, an edge or a vertex of
  // a G-map), whose shifts are involutions of the positions on a valid
  // host, so that alternating_classes can number its classes; their
  // indices into W's generators.
  std::optional<std::pair<int, int>> two_involutions(std::size_t u, std::size_t g) const {
    const Grouping& gr = right_groups[u];
    if (!gr.grouped || gr.words[g].size() != 2) return std::nullopt;
    for (int k : gr.words[g]) {
      const ConjWord& w = facts.gens[static_cast<std::size_t>(k)];
      if (w.size() != 1 || w.bar(0) || op.rule.model().is_oriented(w.dim(0))) return std::nullopt;
    }
    return std::pair{gr.words[g][0], gr.words[g][1]};
  }

  // A collect pi<o'>(x) whose orbit is the class it is evaluated for: x is
  // the hook (the match is the identity, so x is dart p) and <o'> is the
  // group's two letters, so the class of p is the <o'>-orbit of dart p.
  // The shift tables of o'[0] and o'[1], or nullopt.
  std::optional<std::pair<int, int>> collect_along(const Term& t, const Along* along) const {
    if (!along || t.args[0].kind != Term::Kind::variable || !op.rule.left().find(t.args[0].name) || t.orbit.size() != 2) return std::nullopt;
    const auto ab = two_involutions(along->u, along->g);
    if (!ab || kept_at[along->u][along->g] != no_node) return std::nullopt;  // the kept-label shortcut numbers no class
    const Dim da = facts.gens[static_cast<std::size_t>(ab->first)].dim(0), db = facts.gens[static_cast<std::size_t>(ab->second)].dim(0);
    if (t.orbit[0] == da && t.orbit[1] == db) return ab;
    if (t.orbit[0] == db && t.orbit[1] == da) return std::pair{ab->second, ab->first};
    return std::nullopt;
  }

  // Statements computing the value of t into a fresh variable; its name.
  // `seen` (the collects of the term so far, by text) lets a collect that
  // the term repeats, as count(x) beside center(x), reuse the first one's
  // bag instead of walking the orbit again. `bound`: the dart variables
  // of the each loops around t. A multiset (collect, each, list) is a
  // span or a vector of values, which the bag functions take as a span.
  std::string value(const Term& t, std::string& code, int& next, const Along* along = nullptr,
                    std::map<std::string, std::string>* seen = nullptr, const Bound& bound = {}) const {
    if (t.kind == Term::Kind::collect && seen)
      if (const auto it = seen->find(t.str()); it != seen->end()) return it->second;
    const std::string v = fmt::format("v{}", next++);
    if (t.kind == Term::Kind::collect && seen) (*seen)[t.str()] = v;
    auto out = std::back_inserter(code);
    switch (t.kind) {
      case Term::Kind::literal:
      case Term::Kind::parameter: {
        const Value& x = t.literal;
        if (x.type == ValueType::string)
          fmt::format_to(out, "    const Value {} = Value::text({});\n", v, cpp_literal(x.string()));
        else
          fmt::format_to(out, "    const Value {} = Value{{ValueType::{}, {{{}, {}, {}}}, {}}};  // {}\n", v, name_of(x.type), double_literal(x.x[0]),
                         double_literal(x.x[1]), double_literal(x.x[2]), x.i, comment_text(t.str()));
        return v;
      }
      case Term::Kind::access:
        fmt::format_to(out, "    const Value {} = read(e{}, {}, {}, {});\n", v, index_of(t.name), node(t.args[0], bound), cpp_literal(t.name),
                       cpp_literal(t.str()));
        return v;
      case Term::Kind::collect: {
        const std::size_t s = site.at(&t);
        if (const auto ab = collect_along(t, along)) {
          fmt::format_to(out,
                         "    const std::span<const Value> {0} = alternated{1}_{2}  // {3}: the class of p is this orbit\n"
                         "        ? tw.collect_class({4}, site{4}, g, e{5}, static_cast<std::uint32_t>(p), ws.shift[{6}].data(), ws.shift[{7}].data())\n"
                         "        : tw.collect({4}, site{4}, g, e{5}, {8});\n",
                         v, along->u, along->g, comment_text(t.str()), s, index_of(t.name), ab->first, ab->second, node(t.args[0], bound));
          return v;
        }
        fmt::format_to(out, "    const std::span<const Value> {} = tw.collect({}, site{}, g, e{}, {});  // {}\n", v, s, s, index_of(t.name),
                       node(t.args[0], bound), comment_text(t.str()));
        return v;
      }
      case Term::Kind::call: {
        fmt::dynamic_format_arg_store<fmt::format_context> args;
        for (const Term& a : t.args) args.push_back(value(a, code, next, along, seen, bound));
        fmt::format_to(out, "    const Value {} = {};  // {}\n", v, fmt::vformat(t.function->cpp, args), comment_text(t.str()));
        return v;
      }
      case Term::Kind::each: {
        // The evaluator's each_bag: the body once per dart of the orbit,
        // in its walk's order, then each_values. The body's code is a
        // block of its own: what it declares, its collects included, is
        // not seen after the loop.
        const std::size_t s = each_site.at(&t);
        const std::string orbit = fmt::format("orbit{}", v), x = fmt::format("x{}", v);
        fmt::format_to(out,
                       "    std::vector<Value> {0};  // {1}\n"
                       "    {{\n"
                       "    const std::vector<Dart> {2} = tw.each_orbit(g, {3}, each{4});\n"
                       "    {0}.reserve({2}.size());\n"
                       "    for ([[maybe_unused]] const Dart {5} : {2}) {{  // a body may not read its dart\n",
                       v, comment_text(t.str()), orbit, node(t.args[0], bound), s, x);
        Bound inner = bound;
        inner.emplace_back(t.name, x);
        std::map<std::string, std::string> body_seen = seen ? *seen : std::map<std::string, std::string>{};
        std::string body;
        const std::string b = value(t.args[1], body, next, along, &body_seen, inner);
        indent(body);
        code += body;
        fmt::format_to(out, "      {}.push_back({});\n    }}\n    tw.each_finish({}, {}, g, each{});\n    }}\n", v, b, v, orbit, s);
        return v;
      }
      case Term::Kind::list: {
        // The evaluator's list: values and multisets' elements, sorted.
        std::vector<std::string> parts;
        for (const Term& a : t.args) parts.push_back(value(a, code, next, along, seen, bound));
        fmt::format_to(out, "    std::vector<Value> {};  // {}\n", v, comment_text(t.str()));
        for (std::size_t k = 0; k < parts.size(); ++k) {
          if (t.args[k].sort.kind == Sort::multiset)
            fmt::format_to(out, "    {0}.insert({0}.end(), {1}.begin(), {1}.end());\n", v, parts[k]);
          else
            fmt::format_to(out, "    {}.push_back({});\n", v, parts[k]);
        }
        fmt::format_to(out, "    std::sort({0}.begin(), {0}.end(), [](const Value& a, const Value& b) {{ return value_less(a, b); }});\n", v);
        return v;
      }
      case Term::Kind::variable:
      case Term::Kind::neighbour:
        break;
    }
    fmt::format_to(out, "    const Value {} = (throw EvaluationError({}), Value{{}});\n", v,
                   cpp_literal(fmt::format("'{}' is a node, not a value", t.str())));
    return v;
  }

  // How the classes of R's instances for one orbit are found: by groups of
  // nodes joined by arcs of <o> with the empty word (their instances in one
  // pattern copy share a class), each group's classes a walk of P_v along
  // its nodes' loop words and their conjugates; or, when an arc of <o> with
  // a word joins two groups, by unions per instance.
  Grouping grouping(const TopoGraph& side, const std::vector<ConjWord>& words, const std::vector<Dim>& orbit) const {
    Grouping out;
    const std::size_t n = side.node_count();
    DisjointSets<std::size_t> group(n);
    auto in_orbit = [&](Dim i) { return std::find(orbit.begin(), orbit.end(), i) != orbit.end(); };
    for (ArcId e = 0; e < side.arc_count(); ++e)
      if (in_orbit(side.arc(e).label) && arc_word(words, e).empty()) group.attach(side.arc(e).source, side.arc(e).target);
    std::vector<std::size_t> number(n, n);
    for (NodeId x = 0; x < n; ++x) {
      const std::size_t r = group.find(x);
      if (number[r] == n) {
        number[r] = out.words.size();
        out.words.emplace_back();
      }
      out.group_of.push_back(number[r]);
    }
    const ConjugateRewriting rw(op.rule.model());
    for (ArcId e = 0; e < side.arc_count(); ++e) {
      const auto& a = side.arc(e);
      const ConjWord& w = arc_word(words, e);
      if (!in_orbit(a.label) || w.empty()) continue;
      const std::size_t g = out.group_of[a.source];
      if (g != out.group_of[a.target]) {
        out.grouped = false;
        return out;
      }
      for (const ConjWord& x : {w, rw.conjugate(w)}) {
        const int k = generator_index(facts.gens, x);
        if (k < 0 || static_cast<std::size_t>(k) >= facts.gens.size()) {
          out.grouped = false;
          return out;
        }
        if (std::find(out.words[g].begin(), out.words[g].end(), k) == out.words[g].end()) out.words[g].push_back(k);
      }
    }
    return out;
  }

  // The class of R's instance (p, y) for embedding u, as an expression.
  std::string class_of(std::size_t u, NodeId y) const {
    const Grouping& g = right_groups[u];
    return g.grouped ? fmt::format("cls[{} * np + p]", g.group_of[y]) : fmt::format("cls[{} * np + p]", y);
  }

  // R's classes for embedding u into `cls` and tw.class_count[u].
  void right_classes(Out out, std::size_t u, bool everywhere) const {
    const Grouping& gr = right_groups[u];
    const TopoGraph& R = op.rule.right();
    if (!gr.grouped) {
      classes(out, R, op.words.right, used[u]->orbit, "cls");
      fmt::format_to(out, "    tw.class_count[{}] = static_cast<std::uint32_t>({} * np);\n", u, R.node_count());
      return;
    }
    fmt::format_to(out, "    cls.assign({} * np, dartcheck::compiled::none);\n    std::uint32_t count = 0;\n", gr.words.size());
    for (std::size_t g = 0; g < gr.words.size(); ++g) {
      std::string members;
      for (NodeId y = 0; y < R.node_count(); ++y)
        if (gr.group_of[y] == g) members += (members.empty() ? "" : ", ") + comment_text(R.name(y));
      if (gr.words[g].empty()) {
        fmt::format_to(out, "    for (std::size_t p = 0; p < np; ++p) cls[{} * np + p] = count++;  // {{{}}}: a class per copy\n", g, members);
        continue;
      }
      const NodeId at = kept_at[u][g];
      if (at != no_node) {
        // The kept-label shortcut (kept_groups): cls holds G's pool index
        // of the kept node's dart at each copy instead of a class number.
        std::string agree;
        for (int k : gr.words[g])
          agree += fmt::format(" || slot_of(match[{} * np + ws.shift[{}][p]]) != v", at, k);
        fmt::format_to(out,
                       "    {{  // {{{0}}}: G's value of {1} at every copy when G's labels agree along the loops\n"
                       "      const auto slot_of = [e = e{2}](Dart d) {{ return d < e->slot.size() ? e->slot[d] : Embedding::none; }};\n"
                       "      kept{3}_{4} = true;\n"
                       "      for (std::size_t p = 0; p < np; ++p) {{\n"
                       "        const std::uint32_t v = slot_of(match[{5} * np + p]);\n"
                       "        if (v == Embedding::none{6}) {{  // the walk below decides\n"
                       "          kept{3}_{4} = false;\n"
                       "          std::fill(cls.begin() + {4} * np, cls.begin() + {4} * np + p, dartcheck::compiled::none);\n"
                       "          break;\n        }}\n"
                       "        cls[{4} * np + p] = v;\n"
                       "      }}\n"
                       "      ++(kept{3}_{4} ? tw.shortcuts : tw.shortcut_fallbacks);\n"
                       "    }}\n"
                       "    if (!kept{3}_{4})\n",
                       members, comment_text(op.rule.left().name(at)), index_of(used[u]->name), u, g, at, agree);
      }
      // Two involutions of the positions: the walk without a stack, the
      // stack walk kept for a host whose links are not involutions. In an
      // everywhere function its outcome is kept: the group's collects may
      // walk the class (collect_along).
      if (const auto ab = two_involutions(u, g); ab && everywhere && at == no_node)
        fmt::format_to(out,
                       "    const bool alternated{0}_{1} = dartcheck::compiled::alternating_classes(cls.data() + {1} * np, ws.shift[{2}].data(), "
                       "ws.shift[{3}].data(), np, count);\n    if (!alternated{0}_{1})\n",
                       u, g, ab->first, ab->second);
      else if (ab)
        fmt::format_to(out, "    if (!dartcheck::compiled::alternating_classes(cls.data() + {} * np, ws.shift[{}].data(), ws.shift[{}].data(), np, count))\n",
                       g, ab->first, ab->second);
      std::string follow;
      for (int k : gr.words[g])
        follow += fmt::format(
            "          if (const std::uint32_t r = ws.shift[{0}][q]; cls[{1} * np + r] == dartcheck::compiled::none) {{  // {2}\n"
            "            cls[{1} * np + r] = count;\n            tw.stack.push_back(r);\n          }}\n",
            k, g, facts.gens[static_cast<std::size_t>(k)].str());
      fmt::format_to(out,
                     "    for (std::uint32_t p0 = 0; p0 < np; ++p0) {{  // {{{}}}: copies joined along the loops\n"
                     "      if (cls[{} * np + p0] != dartcheck::compiled::none) continue;\n"
                     "      cls[{} * np + p0] = count;\n      tw.stack.assign(1, p0);\n"
                     "      while (!tw.stack.empty()) {{\n        const std::uint32_t q = tw.stack.back();\n        tw.stack.pop_back();\n{}"
                     "      }}\n      ++count;\n    }}\n",
                     members, g, g, follow);
    }
    fmt::format_to(out, "    tw.class_count[{}] = count;\n", u);
  }

  // Unions of one side's instances along its arcs in <o>.
  void classes(Out out, const TopoGraph& side, const std::vector<ConjWord>& words, const std::vector<Dim>& orbit, const std::string& table) const {
    fmt::format_to(out, "    TermWorkspace::reset({}, {} * np);\n", table, side.node_count());
    bool any = false;
    for (ArcId e = 0; e < side.arc_count(); ++e) {
      const auto& a = side.arc(e);
      if (std::find(orbit.begin(), orbit.end(), a.label) == orbit.end()) continue;
      if (!any) fmt::format_to(out, "    for (std::size_t p = 0; p < np; ++p) {{\n");
      any = true;
      const int k = generator_index(facts.gens, arc_word(words, e));
      fmt::format_to(
          out, "      TermWorkspace::unite({}, static_cast<std::uint32_t>({} * np + p), static_cast<std::uint32_t>({} * np + {}));  // {}\n", table,
          a.source, a.target, shifted(k, "p"), comment_text(fmt::format("{} -{}-> {}", side.name(a.source), a.label, side.name(a.target))));
    }
    if (any) fmt::format_to(out, "    }}\n");
    fmt::format_to(out, "    TermWorkspace::flatten({});\n", table);
  }

  std::string instance_name(const TopoGraph& side, NodeId x) const {
    return op.is_scheme() ? fmt::format("std::string({}) + \"@\" + std::to_string(ws.pattern[p])", cpp_literal(side.name(x)))
                          : fmt::format("std::string({})", cpp_literal(side.name(x)));
  }
};

TermCode::TermCode(const Operation& op, const SchemeFacts& facts) : plan_(std::make_unique<Plan>(op, facts)) {}
TermCode::~TermCode() = default;

void TermCode::lookups(Out out) const {
  const Plan& p = *plan_;
  fmt::format_to(out, "  Map& g = em.map;\n  TermWorkspace& tw = ws.terms;\n");
  for (std::size_t k = 0; k < p.embeddings.size(); ++k)
    fmt::format_to(out, "  Embedding* const e{} = em.find({});\n", k, cpp_literal(p.embeddings[k]));
  for (const EmbeddingSignature* e : p.used) {
    const std::string why = fmt::format("the rule labels {} <{}>, and the map has no embedding {}", e->name, fmt::join(e->orbit, ","), e->name);
    fmt::format_to(out, "  if (!e{}) return ws.refuse(Refusal::no_value, {});\n", p.index_of(e->name), cpp_literal(why));
  }
  for (std::size_t s = 0; s < p.sites.size(); ++s)
    fmt::format_to(out, "  static const CollectSite site{}({}, {{{}}});\n", s, cpp_literal(p.sites[s]->name), fmt::join(p.sites[s]->orbit, ", "));
  for (std::size_t s = 0; s < p.each_sites.size(); ++s) {
    const Term& t = *p.each_sites[s];
    fmt::format_to(out, "  static const EachSite each{}({{{}}}, {{{}}}, {}, {});\n", s, fmt::join(t.orbit, ", "), fmt::join(t.sub_orbit, ", "),
                   t.per_sub, cpp_literal(t.str()));
  }
  for (std::size_t u = 0; u < p.kept_at.size(); ++u)
    for (std::size_t g = 0; g < p.kept_at[u].size(); ++g)
      if (p.kept_at[u][g] != no_node) fmt::format_to(out, "  bool kept{}_{} = false;  // the kept-label shortcut taken\n", u, g);
}

// L's terms as the labels the match must carry (003 Def. 10).
void TermCode::left_labels(Out out) const {
  const Plan& p = *plan_;
  const TopoGraph& L = p.op.rule.left();
  for (std::size_t k = 0; k < p.terms.left.size(); ++k) {
    const NodeTerm& t = p.terms.left[k];
    const NodeId x = p.left_node[k];
    const std::size_t e = p.index_of(t.embedding);
    fmt::format_to(out, "  for (std::size_t p = 0; p < np; ++p) {{  // L: {} labeled {} = {}\n    const Dart d = match[{} * np + p];\n",
                   comment_text(t.node), comment_text(t.embedding), comment_text(t.term.str()), x);
    if (own_value(t)) {
      fmt::format_to(out, "    if (!e{0}->value(d)) (void)read(e{0}, d, {1}, {2});\n", e, cpp_literal(t.embedding), cpp_literal(t.term.str()));
    } else {
      std::string code;
      int next = 0;
      std::map<std::string, std::string> seen;
      const std::string v = p.value(t.term, code, next, nullptr, &seen);
      code += fmt::format(
          "    const Value* have = e{}->value(d);\n"
          "    if (!have || !(*have == {}))\n"
          "      return ws.refuse(Refusal::label_mismatch, \"node \" + {} + \" of L is labeled \" {} \" = \" + {}.str() + \", but dart \" + "
          "std::to_string(d) + \" has \" + (have ? have->str() : std::string(\"no value\")));\n",
          e, v, p.instance_name(L, x), cpp_literal(fmt::format("{} = {}", t.embedding, t.term.str())), v);
      out = std::copy(code.begin(), code.end(), out);
    }
    fmt::format_to(out, "  }}\n");
  }
}

// Lemma 3, where L's darts are not closed under the orbit.
void TermCode::overlap_checks(Out out) const {
  const Plan& p = *plan_;
  const TopoGraph& L = p.op.rule.left();
  if (p.extended())
    for (std::size_t u = 0; u < p.used.size(); ++u) {
      if (p.left_closed[u]) continue;
      const EmbeddingSignature& e = *p.used[u];
      fmt::format_to(out, "  {{  // 003 Lemma 3 for {} <{}>: L does not close the orbit\n", comment_text(e.name), fmt::join(e.orbit, ","));
      p.classes(out, L, p.op.words.left, e.orbit, "tw.left_class");
      fmt::format_to(out, "    static const std::vector<OrbitWord> gens = dims_generators({{{}}});\n    static const char* const names[] = {{",
                     fmt::join(e.orbit, ", "));
      for (NodeId x = 0; x < L.node_count(); ++x) fmt::format_to(out, "{}{}", x ? ", " : "", cpp_literal(L.name(x)));
      fmt::format_to(
          out,
          "}};\n    if (std::string why = overlap(tw, g, gens, std::span<const Dart>(match, {} * np), np, names, ws.pattern, {}); !why.empty())\n"
          "      return ws.refuse(Refusal::overlap, std::move(why));\n  }}\n",
          L.node_count(), cpp_literal(e.name));
    }
}

// The classes of R for the u-th embedding used and their sources: a
// value kept from G or one evaluation per class (003 Thm 4).
void TermCode::right_sources(Out out, std::size_t u, bool everywhere) const {
  const Plan& p = *plan_;
  const EmbeddingSignature& sig = *p.used[u];
  const std::size_t e = p.index_of(sig.name);
  fmt::format_to(out, "  {{  // {} <{}>\n", comment_text(sig.name), fmt::join(sig.orbit, ","));
  if (p.extended()) {
    fmt::format_to(out, "    std::vector<std::uint32_t>& cls = tw.class_of[{}];\n", u);
    p.right_classes(out, u, everywhere);
    fmt::format_to(out,
                   "    std::vector<Source>& src = tw.sources[{0}];\n    src.assign(tw.class_count[{0}], Source{{}});\n"
                   "    reserve_more(tw.evaluated, tw.class_count[{0}]);  // at most a value per class\n",
                   u);
  } else {
    fmt::format_to(out, "    std::vector<Source>& src = tw.sources[{}];\n    src.assign({} * np, Source{{}});\n", u, p.terms.right.size());
  }
  for (std::size_t k = 0; k < p.terms.right.size(); ++k) {
    const NodeTerm& t = p.terms.right[k];
    if (t.embedding != sig.name) continue;
    const NodeId y = p.right_node[k];
    if (p.extended() && p.right_groups[u].grouped && p.kept_at[u][p.right_groups[u].group_of[y]] != no_node)
      fmt::format_to(out, "    if (!kept{}_{})  // else its values are G's, in cls\n", u, p.right_groups[u].group_of[y]);
    fmt::format_to(out, "    for (std::size_t p = 0; p < np; ++p) {{  // R: {} labeled {} = {}\n      Source& here = src[{}];\n",
                   comment_text(t.node), comment_text(t.embedding), comment_text(t.term.str()),
                   p.extended() ? p.class_of(u, y) : fmt::format("{} * np + p", k));
    fmt::format_to(out, "      if (here.index != Embedding::none) continue;  // its class has one\n");
    if (const NodeId at = p.stored_at[k]; at != no_node) {
      fmt::format_to(out,
                     "      const Dart d = match[{} * np + p];  // kept from G: no evaluation\n"
                     "      if (d >= e{}->slot.size() || e{}->slot[d] == Embedding::none)\n"
                     "        throw EvaluationError(std::string({}) + \": dart \" + std::to_string(d) + \" has no \" {} \" value\");\n"
                     "      here = {{e{}->slot[d], true}};\n",
                     at, e, e, cpp_literal(t.term.str()), cpp_literal(t.embedding), e);
    } else {
      std::string code;
      int next = 0;
      const Plan::Along along{u, p.right_groups[u].grouped ? p.right_groups[u].group_of[y] : 0};
      std::map<std::string, std::string> seen;
      const std::string v = p.value(t.term, code, next, everywhere && p.extended() && p.right_groups[u].grouped ? &along : nullptr, &seen);
      indent(code);  // one more level
      out = std::copy(code.begin(), code.end(), out);
      fmt::format_to(out, "      here = {{static_cast<std::uint32_t>(tw.evaluated.size()), false}};\n      tw.evaluated.push_back({});\n", v);
    }
    fmt::format_to(out, "    }}\n");
  }
  fmt::format_to(out, "  }}\n");
}

void TermCode::before_rewrite(Out out, bool everywhere) const {
  const Plan& p = *plan_;
  const Rule& r = p.op.rule;
  fmt::format_to(out, "  // Terms (003 Def. 10): L's labels, then one source per class of R.\n  tw.prepare({}, {});\n", p.used.size(),
                 p.sites.size());
  fmt::format_to(out, "  {{\n  {}\n  try {{\n", match_declaration(r, everywhere));
  left_labels(out);
  fmt::format_to(out,
                 "  }} catch (const EvaluationError& x) {{\n    return ws.refuse(Refusal::no_value, std::string(\"a term of L has no value: \") + "
                 "x.what());\n  }}\n");
  overlap_checks(out);
  // Classes of R and their sources (one evaluation per class: Thm 4).
  fmt::format_to(out, "  try {{\n");
  for (std::size_t u = 0; u < p.used.size(); ++u) right_sources(out, u, everywhere);
  fmt::format_to(out,
                 "  }} catch (const EvaluationError& x) {{\n    return ws.refuse(Refusal::no_value, std::string(\"a term of R has no value: \") + "
                 "x.what());\n  }}\n  }}\n");
}

// Added darts start unlabeled.
void TermCode::unlabel_added(Out out, bool everywhere) const {
  const Plan& p = *plan_;
  const Rule& r = p.op.rule;
  const TopoGraph& R = r.right();
  const auto cm = [&](NodeId y) { return comatch_dart(r, y, "p", everywhere); };  // y's dart at position p
  std::vector<NodeId> added;
  for (NodeId y = 0; y < R.node_count(); ++y)
    if (r.to_left(y) == no_node) added.push_back(y);
  if (!added.empty() && !r.deletes_nodes()) {
    // The new darts are one range (comatch_dart): a slot table longer than
    // the map (darts removed before) may hold stale labels there.
    fmt::format_to(out,
                   "  for (Embedding& e : em.embeddings)  // added darts start unlabeled\n"
                   "    if (e.slot.size() > first_new)\n"
                   "      std::fill(e.slot.begin() + first_new, e.slot.begin() + std::min<std::size_t>(e.slot.size(), first_new + {} * np), "
                   "Embedding::none);\n",
                   added.size());
  } else if (!added.empty()) {
    fmt::format_to(out, "  for (Embedding& e : em.embeddings) {{  // added darts start unlabeled\n");
    for (NodeId y : added)
      fmt::format_to(out, "    for (std::size_t p = 0; p < np; ++p)\n      if (const Dart d = {}; d < e.slot.size()) e.slot[d] = Embedding::none;\n",
                     cm(y));
    fmt::format_to(out, "  }}\n");
  }
}

// The u-th embedding's values written on H: a closed class without a
// walk, an extended class along its orbit, a direct label on its dart.
void TermCode::write_values(Out out, std::size_t u, bool everywhere) const {
  const Plan& p = *plan_;
  const Rule& r = p.op.rule;
  const TopoGraph& R = r.right();
  const auto cm = [&](NodeId y) { return comatch_dart(r, y, "p", everywhere); };  // y's dart at position p
  const EmbeddingSignature& sig = *p.used[u];
  const std::size_t e = p.index_of(sig.name);
  fmt::format_to(out, "  {{  // {} <{}>\n    Embedding& e = *e{};\n    const std::vector<Source>& src = tw.sources[{}];\n", comment_text(sig.name),
                 fmt::join(sig.orbit, ","), e, u);
  if (p.extended() && p.closed[u]) {
    // Every node of R has one arc of each dimension of <o>: a class is a
    // whole orbit of H, written without a walk.
    fmt::format_to(out,
                   "    [[maybe_unused]] const std::vector<std::uint32_t>& cls = tw.class_of[{0}];  // unused when R is empty\n"
                   "    std::vector<std::uint32_t>& pool = tw.pool_of;\n"
                   "    pool.assign(tw.class_count[{0}], Embedding::none);\n"
                   "    reserve_more(e.pool, tw.class_count[{0}]);\n"
                   "    for (std::size_t c = 0; c < pool.size(); ++c)\n"
                   "      if (const Source f = src[c]; f.index != Embedding::none) pool[c] = f.stored ? f.index : e.store(tw.evaluated[f.index]);\n"
                   "    // R closes <{1}>: a class is a whole orbit of H. (em.follow made the slots as many as the darts.)\n",
                   u, fmt::join(sig.orbit, ","));
    for (NodeId y = 0; y < R.node_count(); ++y) {
      const std::size_t g = p.right_groups[u].grouped ? p.right_groups[u].group_of[y] : 0;
      const NodeId at = p.right_groups[u].grouped ? p.kept_at[u][g] : no_node;
      if (at != no_node && r.to_left(y) == at)
        // The shortcut stored, at each copy, the pool index of this very
        // dart (no dart is renumbered: kept_groups): nothing to write.
        fmt::format_to(out, "    if (!kept{}_{})  // else {} keeps its own value from G\n", u, g, comment_text(R.name(y)));
      else if (at != no_node)
        fmt::format_to(out,
                       "    if (kept{0}_{1})\n"
                       "      for (std::size_t p = 0; p < np; ++p) e.slot[{2}] = cls[{1} * np + p];  // {3}: G's value\n"
                       "    else\n",
                       u, g, cm(y), comment_text(R.name(y)));
      fmt::format_to(out,
                     "    for (std::size_t p = 0; p < np; ++p)  // {}\n"
                     "      if (const std::uint32_t v = pool[{}]; v != Embedding::none) e.slot[{}] = v;\n",
                     comment_text(R.name(y)), p.class_of(u, y), cm(y));
    }
  } else if (p.extended()) {
    fmt::format_to(
        out,
        "    const std::vector<std::uint32_t>& cls = tw.class_of[{}];\n    static const std::vector<OrbitWord> gens = dims_generators({{{}}});\n", u,
        fmt::join(sig.orbit, ", "));
    for (std::size_t k = 0; k < p.terms.right.size(); ++k) {
      if (p.terms.right[k].embedding != sig.name) continue;
      const NodeId y = p.right_node[k];
      fmt::format_to(out,
                     "    for (std::size_t p = 0; p < np; ++p)  // {}: its orbit of H\n      write_orbit(tw, g, e, gens, {}, "
                     "src[{}]);\n",
                     comment_text(p.terms.right[k].node), cm(y), p.class_of(u, y));
    }
    fmt::format_to(out, "    end_writes(tw);\n");
  } else {
    for (std::size_t k = 0; k < p.terms.right.size(); ++k) {
      if (p.terms.right[k].embedding != sig.name) continue;
      const NodeId y = p.right_node[k];
      fmt::format_to(out,
                     "    for (std::size_t p = 0; p < np; ++p) {{  // {}: its own dart (direct)\n"
                     "      const Source f = src[{} * np + p];\n      e.set_index({}, f.stored ? f.index : "
                     "e.store(tw.evaluated[f.index]));\n    }}\n",
                     comment_text(p.terms.right[k].node), k, cm(y));
    }
  }
  fmt::format_to(out, "  }}\n");
}

void TermCode::after_rewrite(Out out, bool everywhere) const {
  const Plan& p = *plan_;
  const Rule& r = p.op.rule;
  const auto cm = [&](NodeId y) { return comatch_dart(r, y, "p", everywhere); };  // y's dart at position p
  fmt::format_to(out, "  // Labels (003 Def. 12).\n  em.follow(ws.moved);\n  {{\n");
  unlabel_added(out, everywhere);
  for (std::size_t k = 0; k < p.terms.left.size(); ++k) {
    const NodeTerm& t = p.terms.left[k];
    const NodeId y = r.to_right(p.left_node[k]);
    if (y == no_node || p.terms.find('R', t.node, t.embedding)) continue;
    const std::size_t e = p.index_of(t.embedding);
    fmt::format_to(out,
                   "  {{  // {} keeps no {} label in R: it loses its value\n"
                   "    const std::vector<OrbitWord> gens = dims_generators(e{}->signature.orbit);\n"
                   "    for (std::size_t p = 0; p < np; ++p) unlabel(tw, g, *e{}, gens, {}, {});\n  }}\n",
                   comment_text(t.node), comment_text(t.embedding), e, e, cm(y), p.extended());
  }
  for (std::size_t u = 0; u < p.used.size(); ++u) write_values(out, u, everywhere);
  fmt::format_to(out, "  }}\n");
}

}  // namespace dartcheck::compiler
