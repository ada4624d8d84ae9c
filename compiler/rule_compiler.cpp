#include "compiler/rule_compiler.hpp"

#include "compiler/cpp_identifiers.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>

#include <fmt/format.h>

#include "compiler/comatch_text.hpp"
#include "compiler/cpp_text.hpp"
#include "compiler/term_compiler.hpp"
#include "rewriting/pattern_graphs.hpp"

namespace dartcheck::compiler {
namespace {

// The statements of `follow` for one generator: its letters as links.
std::string follow_case(const ConjWord& w) {
  std::string out;
  for (std::size_t k = 0; k < w.size(); ++k) {
    const std::string link = fmt::format("g.{}({}, d)", w.bar(k) ? "inverse_link" : "link", w.dim(k));
    if (k + 1 == w.size())
      out += fmt::format("return {};", link);
    else
      out += fmt::format("d = {}; if (d == no_dart) return d; ", link);
  }
  return out;
}

std::string arc_text(const TopoGraph& g, ArcId e, const std::vector<ConjWord>& words) {
  const auto& a = g.arc(e);
  const ConjWord& w = arc_word(words, e);
  const std::string label = w.empty() ? fmt::format("{}", a.label) : fmt::format("({},{})", w.str(), a.label);
  return fmt::format("{} -{}-> {}", cpp_literal(g.name(a.source)), label, cpp_literal(g.name(a.target)));
}

std::string side_text(const TopoGraph& g, const std::vector<ConjWord>& words) {
  std::string out = "nodes";
  for (NodeId v = 0; v < g.node_count(); ++v) fmt::format_to(std::back_inserter(out), " {}", cpp_literal(g.name(v)));
  out += g.arc_count() == 0 ? "; no arcs" : "; arcs";
  for (ArcId e = 0; e < g.arc_count(); ++e) fmt::format_to(std::back_inserter(out), "{}{}", e == 0 ? " " : ", ", arc_text(g, e, words));
  return out;
}

// The rule-only facts are the interpreter's own (scheme_facts), so the
// generated refusals are the ones SchemeRewriter checks.
using RuleFacts = SchemeFacts;

using Out = std::back_insert_iterator<std::string>;

// Injectivity and connectedness of the instantiated L (check_match), with
// L's node names for its sentences.
void emit_check_match(Out out, const TopoGraph& L) {
  fmt::format_to(out, "  static const char* const left_names[] = {{");
  for (NodeId x = 0; x < L.node_count(); ++x) fmt::format_to(out, "{}{}", x == 0 ? "" : ", ", cpp_literal(L.name(x)));
  fmt::format_to(out, "}};\n  if (const Refusal r = check_match(ws, {}, left_names); r != Refusal::none) return r;\n", L.node_count());
}

// The match: (p, hook) is the hook dart, propagated along the instantiated
// arcs of L, one switch case per node with its arcs spelt out.
void emit_propagation(Out out, const Operation& op, const RuleFacts& f) {
  const Rule& core = op.rule;
  const TopoGraph& L = core.left();
  const ConjugateRewriting rw(core.model());
  if (L.node_count() == 0) return;  // a rule that creates: nothing to match
  fmt::format_to(out, "  ws.work.clear();\n");
  for (std::size_t h = 0; h < core.hooks().size(); ++h)
    fmt::format_to(out, "  ws.match[{0} * np] = hooks[{1}];  // hook {2}\n  ws.work.emplace_back(0, {0});\n", core.hooks()[h], h,
                   cpp_literal(L.name(core.hooks()[h])));
  if (L.arc_count() > 0) {
    fmt::format_to(out,
                   "  for (std::size_t k = 0; k < ws.work.size(); ++k) {{\n    const auto [p, x] = ws.work[k];\n"
                   "    const Dart here = ws.match[x * np + p];\n    switch (x) {{\n");
    for (NodeId x = 0; x < L.node_count(); ++x) {
      std::vector<ArcId> incident;
      std::merge(L.out_arcs(x).begin(), L.out_arcs(x).end(), L.in_arcs(x).begin(), L.in_arcs(x).end(), std::back_inserter(incident));
      incident.erase(std::unique(incident.begin(), incident.end()), incident.end());
      fmt::format_to(out, "      case {}: {{  // {}\n", x, cpp_literal(L.name(x)));
      for (ArcId e : incident) {
        const auto& a = L.arc(e);
        const bool forward = a.source == x;
        const ConjWord& word = arc_word(op.words.left, e);
        const int k = generator_index(f.gens, forward ? word : rw.conjugate(word));
        const NodeId other = forward ? a.target : a.source;
        fmt::format_to(
            out,
            "        {{  // {} {}\n"
            "          const Dart there = g.{}({}, here);\n"
            "          if (there == no_dart)\n"
            "            return ws.refuse(Refusal::no_match, \"arc \" {} \" of L at pattern dart \" + std::to_string(ws.pattern[p]) + "
            "\": dart \" + std::to_string(here) + \" has no {}-arc\");\n"
            "          const std::uint32_t q = {};\n"
            "          if (!propagate(ws, q, {}, there))\n"
            "            return ws.refuse(Refusal::no_match, \"node (\" + std::to_string(ws.pattern[q]) + \", \" {} \") of the instantiated L "
            "would be both dart \" + std::to_string(ws.match[{} * np + q]) + \" and dart \" + std::to_string(there));\n"
            "        }}\n",
            forward ? "out along" : "in along", arc_text(L, e, op.words.left), forward ? "link" : "inverse_link", a.label,
            cpp_literal(fmt::format("{} -{}-> {}", L.name(a.source), a.label, L.name(a.target))), a.label, shifted(k, "p"), other,
            cpp_literal(L.name(other)), other);
      }
      fmt::format_to(out, "        break;\n      }}\n");
    }
    fmt::format_to(out, "      default:\n        break;\n    }}\n  }}\n");
  }
  emit_check_match(out, L);
}

// A DPO rule's match, as rewriting/match.cpp builds it: from the hooks,
// each node taken from the queue must sit on a combinatorial part of the
// host, and L's arcs in their order fix the nodes not yet matched. The
// order depends on L alone, so it is unrolled here; then every arc must
// land on its arc and the nodes on distinct darts.
void emit_dpo_match(Out out, const Operation& op) {
  const Rule& core = op.rule;
  const TopoGraph& L = core.left();
  fmt::format_to(out, "  ws.prepare_dpo(g.size(), {});\n  [[maybe_unused]] const std::size_t np = 1;\n", L.node_count());
  if (L.node_count() == 0) return;
  std::vector<bool> set(L.node_count(), false);
  std::vector<NodeId> queue;
  for (std::size_t h = 0; h < core.hooks().size(); ++h) {
    fmt::format_to(out, "  ws.match[{}] = hooks[{}];  // hook {}\n", core.hooks()[h], h, cpp_literal(L.name(core.hooks()[h])));
    set[core.hooks()[h]] = true;
    queue.push_back(core.hooks()[h]);
  }
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const NodeId v = queue[q];
    fmt::format_to(
        out,
        "  if (std::string why = combinatorial_violation(g, ws.match[{0}]); !why.empty())\n"
        "    return ws.refuse(Refusal::not_combinatorial, why + \" (matched to node \" {1} \"); DPO application needs a combinatorial host\");\n",
        v, cpp_literal(L.name(v)));
    for (ArcId e = 0; e < L.arc_count(); ++e) {
      const auto& a = L.arc(e);
      NodeId other = no_node;
      bool forward = true;
      if (a.source == v && !set[a.target]) {
        other = a.target;
      } else if (a.target == v && !set[a.source]) {
        other = a.source;
        forward = false;
      } else {
        continue;
      }
      fmt::format_to(out,
                     "  ws.match[{0}] = g.{1}({2}, ws.match[{3}]);  // {4}\n"
                     "  if (ws.match[{0}] == no_dart)\n"
                     "    return ws.refuse(Refusal::no_match, \"L has \" {5} \" but dart \" + std::to_string(ws.match[{3}]) + \" has no {2}-arc that "
                     "way\");\n",
                     other, forward ? "link" : "inverse_link", a.label, v, arc_text(L, e, {}),
                     cpp_literal(fmt::format("{} -{}-> {}", L.name(a.source), a.label, L.name(a.target))));
      set[other] = true;
      queue.push_back(other);
    }
  }
  for (ArcId e = 0; e < L.arc_count(); ++e) {
    const auto& a = L.arc(e);
    fmt::format_to(out,
                   "  if (g.link({0}, ws.match[{1}]) != ws.match[{2}])\n"
                   "    return ws.refuse(Refusal::no_match, \"L has \" {3} \" but the {0}-arc of dart \" + std::to_string(ws.match[{1}]) + \" goes "
                   "elsewhere\");\n",
                   a.label, a.source, a.target, cpp_literal(fmt::format("{} -{}-> {}", L.name(a.source), a.label, L.name(a.target))));
  }
  emit_check_match(out, L);
}

// The refusals that do not depend on the match's darts beyond a link:
// dangling (002 Sec. 2.2) and representability. Returns false when one
// refuses every match (the rest of the function would be unreachable).
bool emit_conditions(Out out, const Operation& op, const RuleFacts& f) {
  const Rule& core = op.rule;
  const TopoGraph &L = core.left(), &R = core.right();
  if (!f.two_arcs_in_l.empty()) {
    fmt::format_to(out, "  return ws.refuse(Refusal::not_injective, {});\n", cpp_literal(f.two_arcs_in_l));
    return false;
  }
  for (const auto& c : f.dangling) {
    std::string test;
    if (!c.out) test = fmt::format("g.link({}, d) != no_dart", c.i);
    if (!c.in) test += fmt::format("{}g.inverse_link({}, d) != no_dart", test.empty() ? "" : " || ", c.i);
    fmt::format_to(out,
                   "  for (std::size_t p = 0; p < np; ++p)  // deleted {} carries no {}-arc outside L\n"
                   "    if (const Dart d = ws.match[{} * np + p]; {})\n"
                   "      return ws.refuse(Refusal::dangling, \"deleted dart \" + std::to_string(d) + \" (node \" {} \") keeps a {}-arc outside the "
                   "match\");\n",
                   cpp_literal(L.name(c.x)), c.i, c.x, test, cpp_literal(L.name(c.x)), c.i);
  }
  for (const auto& a : f.added) {
    const auto& arc = R.arc(a.arc);
    if (!a.always.empty() || (a.x != no_node && !a.freed && a.kept)) {
      const std::string why = !a.always.empty()
                                  ? a.always
                                  : fmt::format("R adds a {}-arc out of {} whose dart keeps its {}-arc", arc.label, R.name(arc.source), arc.label);
      fmt::format_to(out, "  return ws.refuse(Refusal::not_representable, {});\n", cpp_literal(why));
      return false;
    }
    if (a.x == no_node || a.freed) continue;
    fmt::format_to(
        out,
        "  for (std::size_t p = 0; p < np; ++p)  // R adds {}: its source's {}-arc must be free\n"
        "    if (const Dart d = ws.match[{} * np + p]; g.link({}, d) != no_dart)\n"
        "      return ws.refuse(Refusal::not_representable, \"R adds a {}-arc out of \" {} \" whose dart \" + std::to_string(d) + \" keeps "
        "its {}-arc\");\n",
        arc_text(R, a.arc, op.words.right), arc.label, a.x, arc.label, arc.label, cpp_literal(R.name(arc.source)), arc.label);
  }
  return true;
}

// The rewrite (002 Def. 4, Sec. 6.3): delete the instances of L \ K, place
// R's nodes (preserved ones on their darts, added ones in the deleted
// darts, then new ones), add the instances of R \ K, fill the holes. One
// loop over the pattern per step, every rule node and arc in its body, and
// the tables read through pointers taken once (links and tables are both
// 32-bit, so the compiler could not keep them in registers across writes).
// The order of the writes within a step does not matter: a representable
// rule writes each (dart, dimension) slot once.
void emit_rewrite(Out out, const Operation& op, const RuleFacts& f, bool everywhere) {
  const Rule& core = op.rule;
  const TopoGraph &L = core.left(), &R = core.right();
  const std::vector<ConjWord>& gens = f.gens;
  std::size_t deleted = 0, added = 0;
  for (NodeId x = 0; x < L.node_count(); ++x) deleted += core.to_right(x) == no_node;
  for (NodeId y = 0; y < R.node_count(); ++y) added += core.to_left(y) == no_node;
  fmt::format_to(out, "  {}\n", match_declaration(core, everywhere));
  std::vector<bool> used(gens.size(), false);
  for (ArcId e = 0; e < R.arc_count(); ++e)
    if (!core.preserved_right_arc(e))
      if (const int k = generator_index(gens, arc_word(op.words.right, e)); k >= 0) used[static_cast<std::size_t>(k)] = true;
  for (std::size_t k = 0; k < gens.size(); ++k)
    if (used[k]) fmt::format_to(out, "  const std::uint32_t* const shift{0} = ws.shift[{0}].data();  // p·{1}\n", k, gens[k].str());
  bool any = false;
  for (ArcId e = 0; e < L.arc_count(); ++e) {
    if (core.preserved_left_arc(e)) continue;
    if (!any) fmt::format_to(out, "  for (std::size_t p = 0; p < np; ++p) {{  // deletes L \\ K\n");
    any = true;
    fmt::format_to(out, "    g.remove_link({}, match[{} * np + p]);  // {}\n", L.arc(e).label, L.arc(e).source, arc_text(L, e, op.words.left));
  }
  if (any) fmt::format_to(out, "  }}\n");
  if (deleted > 0) {
    fmt::format_to(out, "  ws.holes.clear();\n");
    for (NodeId x = 0; x < L.node_count(); ++x)
      if (core.to_right(x) == no_node)
        fmt::format_to(out, "  ws.holes.insert(ws.holes.end(), match + {0} * np, match + {1} * np);  // {2} is deleted\n", x, x + 1,
                       cpp_literal(L.name(x)));
    // A DPO rule reuses the smallest deleted darts first (apply_rule).
    if (!op.is_scheme()) fmt::format_to(out, "  std::sort(ws.holes.begin(), ws.holes.end());\n");
  }
  if (deleted > 0)
    fmt::format_to(out, "  ws.comatch.resize({} * np);\n  [[maybe_unused]] Dart* const comatch = ws.comatch.data();\n", R.node_count());
  else
    fmt::format_to(out, "  // The comatch is arithmetic (no node of L is deleted): preserved nodes on their matched darts, added ones on new darts.\n");
  if (added > 0) {
    if (deleted > 0)
      fmt::format_to(out,
                     "  const std::size_t reused = std::min(ws.holes.size(), {0} * np);\n"
                     "  const Dart first_new = {0} * np > reused ? g.add_darts({0} * np - reused) : no_dart;\n"
                     "  std::size_t next_hole = 0, next_new = 0;\n",
                     added);
    else
      fmt::format_to(out, "  const Dart first_new = g.add_darts({} * np);\n", added);
  }
  // Added nodes: new darts in R's node order, position by position (as
  // the interpreter numbers them), after the deleted darts are reused.
  // Without deleted darts that is comatch_dart's arithmetic.
  if (deleted > 0)
    for (NodeId y = 0; y < R.node_count(); ++y) {
      if (const NodeId x = core.to_left(y); x != no_node)
        fmt::format_to(out, "  std::copy_n(match + {} * np, np, comatch + {} * np);  // {} is preserved\n", x, y, cpp_literal(R.name(y)));
      else
        fmt::format_to(out,
                       "  for (std::size_t p = 0; p < np; ++p)  // {} is added\n"
                       "    comatch[{} * np + p] = next_hole < reused ? ws.holes[next_hole++] : static_cast<Dart>(first_new + next_new++);\n",
                       cpp_literal(R.name(y)), y);
    }
  any = false;
  for (ArcId e = 0; e < R.arc_count(); ++e) {
    if (core.preserved_right_arc(e)) continue;
    if (!any) fmt::format_to(out, "  for (std::size_t p = 0; p < np; ++p) {{  // adds R \\ K\n");
    any = true;
    const auto& a = R.arc(e);
    const int k = generator_index(gens, arc_word(op.words.right, e));
    fmt::format_to(out, "    g.set_link({}, {}, {});  // {}\n", a.label, comatch_dart(core, a.source, "p", everywhere),
                   comatch_dart(core, a.target, k < 0 ? std::string("p") : fmt::format("shift{}[p]", k), everywhere), arc_text(R, e, op.words.right));
  }
  if (any) fmt::format_to(out, "  }}\n");
  if (deleted > 0) fmt::format_to(out, "  fill_holes(g, ws, {});\n", added > 0 ? "reused" : "0");
}

// Whether a scheme can also be applied at every component at once with
// positions as darts (compiled/whole_map_patterns): one hook, L the hook
// with a loop per letter of W, and a single-letter generator for every
// dimension of the model, so that P_v is the hook's connected component.
bool everywhere_applies(const Operation& op, const RuleFacts& f) {
  if (!op.is_scheme() || op.rule.hooks().size() != 1 || !f.identity_match) return false;
  for (const Dim i : op.rule.model().dims)
    if (std::none_of(f.gens.begin(), f.gens.end(), [i](const ConjWord& w) { return w.size() == 1 && w.dim(0) == i; })) return false;
  return true;
}

// One function: at the hook darts, or (`everywhere`) at every component.
void emit_function(Out out, const Operation& op, const RuleFacts& f, const std::optional<TermCode>& terms, const std::string& function,
                   bool everywhere) {
  const Rule& core = op.rule;
  const char* const map_parameter = terms ? "EmbeddedMap& em" : "Map& g";
  if (everywhere) {
    fmt::format_to(out,
                   "// {} at every connected component at once (Jerboa's application to the whole\n"
                   "// map): W's letters name every dimension, so P_v is a component and the P of\n"
                   "// all components is the map itself, position p being dart p. The result is\n"
                   "// isomorphic to applying {} at one hook per component, with the new\n"
                   "// darts numbered in dart order; refused, with the map unchanged, when any\n"
                   "// component would refuse.\n",
                   function, function);
    fmt::format_to(out, "inline Refusal {}_everywhere({}, Workspace& ws) {{\n", function, map_parameter);
  } else {
    fmt::format_to(out, "inline Refusal {}({}, std::span<const Dart> hooks, Workspace& ws) {{\n", function, map_parameter);
  }
  if (terms) terms->lookups(out);
  if (!everywhere)
    fmt::format_to(out,
                   "  if (hooks.size() != {})\n"
                   "    return ws.refuse(Refusal::bad_hooks, \"the rule needs {} hook dart{}, one per component of L\");\n"
                   "  for (const Dart h : hooks)\n"
                   "    if (h >= g.size()) return ws.refuse(Refusal::bad_hooks, \"hook dart \" + std::to_string(h) + \" is not below \" + "
                   "std::to_string(g.size()));\n",
                   core.hooks().size(), core.hooks().size(), core.hooks().size() == 1 ? "" : "s");
  if (!op.is_scheme()) {
    fmt::format_to(
        out, "  if (g.model().name != {})\n    return ws.refuse(Refusal::bad_hooks, \"the rule is for \" {} \", the map is a \" + g.model().name);\n",
        cpp_literal(core.model().name), cpp_literal(core.model().name));
    emit_dpo_match(out, op);
    // The interpreter checks a DPO rule's terms on the match, then applies
    // the rule (dangling, representability).
    if (terms) terms->before_rewrite(out, false);
  } else {
    // P_v (002 Def. 20).
    if (everywhere)
      fmt::format_to(out,
                     "  // P (002 Def. 20 at every component): position p is dart p, shift k the\n"
                     "  // dart along W's k-th generator.\n  static const char* const generator_names[] = {{");
    else
      fmt::format_to(out,
                     "  // P_v (002 Def. 20): the darts reached from the hook along W's generators.\n"
                     "  static const char* const generator_names[] = {{");
    for (std::size_t k = 0; k < f.gens.size(); ++k) fmt::format_to(out, "{}{}", k == 0 ? "" : ", ", cpp_literal(f.gens[k].str()));
    fmt::format_to(out, "}};\n  const auto follow = [&g](std::size_t k, Dart d) -> Dart {{\n    switch (k) {{\n");
    for (std::size_t k = 0; k < f.gens.size(); ++k) fmt::format_to(out, "      case {}: {}\n", k, follow_case(f.gens[k]));
    fmt::format_to(out, "      default: return no_dart;\n    }}\n  }};\n");
    if (everywhere)
      fmt::format_to(out, "  if (const Refusal r = whole_map_patterns<{}>(g, ws, follow, generator_names); r != Refusal::none) return r;\n",
                     f.gens.size());
    else
      fmt::format_to(out, "  if (const Refusal r = walk_patterns<{}>(g, hooks, ws, follow, generator_names); r != Refusal::none) return r;\n",
                     f.gens.size());
    fmt::format_to(out, "  [[maybe_unused]] const std::size_t np = ws.np;\n");
    if (everywhere) {
      fmt::format_to(out, "  // L is the hook with a loop per letter of W: whole_map_patterns set the match, product node (p, hook) being dart p.\n");
    } else if (f.identity_match && core.left().node_count() == 1) {
      fmt::format_to(out,
                     "  // L is the hook with a loop per letter of W: product node (p, hook) is the p-th dart of P_v.\n"
                     "  ws.match.assign(ws.pattern.begin(), ws.pattern.end());\n");
    } else {
      fmt::format_to(out, "  ws.match.assign({} * np, no_dart);\n", core.left().node_count());
      if (f.identity_match)
        fmt::format_to(out,
                       "  // L is the hook with a loop per letter of W: product node (p, hook) is the p-th dart of P_v.\n"
                       "  std::copy(ws.pattern.begin(), ws.pattern.end(), ws.match.begin());\n");
      else
        emit_propagation(out, op, f);
    }
  }
  if (emit_conditions(out, op, f)) {
    // A scheme's match includes its conditions (match_scheme), then terms.
    if (terms && op.is_scheme()) terms->before_rewrite(out, everywhere);
    emit_rewrite(out, op, f, everywhere);
    if (terms) terms->after_rewrite(out, everywhere);
    fmt::format_to(out, "  return Refusal::none;\n");
  }
  fmt::format_to(out, "}}\n");
}

}  // namespace

std::optional<std::string> not_compilable(const Operation& op) { return terms_not_compilable(op); }

std::string function_name(std::string_view rule_name, const std::set<std::string, std::less<>>& declared,
                          const std::set<std::string, std::less<>>& used, std::string* why) {
  std::string base;
  for (const char c : rule_name) base += (std::isalnum(static_cast<unsigned char>(c)) && static_cast<unsigned char>(c) < 0x80) ? c : '_';
  // "a--b" and "rule__Foo" would keep a reserved "__", "a-" would give a__everywhere.
  const auto single_underscores = [](std::string& name) {
    for (std::size_t at; (at = name.find("__")) != std::string::npos;) name.erase(at, 1);
    while (name.size() > 1 && name.back() == '_') name.pop_back();
  };
  single_underscores(base);
  std::string reason;
  if (base.empty() || std::isdigit(static_cast<unsigned char>(base[0]))) {
    base = "rule_" + base;
  } else if (const auto conflict = identifier_conflict(base, used)) {
    reason = fmt::format("'{}' is {}", base, *conflict);
    base = "rule_" + base;
  }
  single_underscores(base);
  const auto usable = [&](const std::string& name) {
    return !declared.contains(name) && !declared.contains(name + "_everywhere") && !identifier_conflict(name, used) &&
           !identifier_conflict(name + "_everywhere", used);
  };
  std::string name = base;
  for (int k = 2; !usable(name); ++k) name = fmt::format("{}_{}", base, k);
  if (name != base && reason.empty()) reason = fmt::format("'{}' or '{}_everywhere' is declared already or used by the header", base, base);
  if (why) *why = reason;
  return name;
}

std::optional<std::string> namespace_conflict(std::string_view ns) {
  if (!namespace_name(ns)) return "is not a C++ namespace name (identifiers joined by ::)";
  for (std::size_t start = 0; start <= ns.size();) {
    const std::size_t end = std::min(ns.find("::", start), ns.size());
    const std::string_view segment = ns.substr(start, end - start);
    if (const auto conflict = identifier_conflict(segment, {})) return fmt::format("'{}' is {}", segment, *conflict);
    if (start == 0 && (segment == "std" || segment == "dartcheck"))
      return fmt::format("'{}' is the namespace of {} (the generated code may not declare names there)", segment,
                         segment == "std" ? "the standard library" : "dartcheck's runtime");
    start = end + 2;
  }
  return std::nullopt;
}

bool has_everywhere(const Operation& op) { return everywhere_applies(op, scheme_facts(op.rule, op.words)); }

std::string compile_operation(const CompileUnit& unit, const std::string& function) {
  const Operation& op = *unit.operation;
  const Rule& core = op.rule;
  const RuleFacts f = scheme_facts(op.rule, op.words);
  std::string code;
  Out out(code);
  fmt::format_to(out, "// {} ({}), {}: a {}.\n// L: {}\n// R: {}\n", cpp_literal(core.name()), comment_text(core.model().name),
                 comment_text(unit.origin), op.is_scheme() ? "rule scheme (002 Sec. 6)" : "DPO rule (002 Def. 2)",
                 side_text(core.left(), op.words.left), side_text(core.right(), op.words.right));
  if (!unit.embedding_failures.empty())
    fmt::format_to(out,
                   "// Compiled with failing embedding conditions: {} (its topology holds).\n// 003 Thm 4 does not apply: this function gives the "
                   "interpreter's values; an orbit given two\n// values is counted in ws.terms.conflicts, a new dart that no term labels gets "
                   "no value.\n",
                   comment_text(unit.embedding_failures));
  if (!op.expressions.empty()) {
    // The reader gives terms only when every expression is read and every
    // embedding typed (io/jerboa_modeler.cpp).
    if (op.terms)
      fmt::format_to(out, "// Its {} Jerboa embedding expression(s) are read as the terms below (docs/jerboa-expressions.md).\n",
                     op.expressions.size());
    else
      fmt::format_to(out,
                     "// Its {} Jerboa embedding expression(s) are not all read (an opaque one, or an untyped embedding):\n// the "
                     "interpreter and this function apply the topology only.\n",
                     op.expressions.size());
  }
  if (!f.gens.empty()) {
    fmt::format_to(out, "// W's generators (with conjugates):");
    for (std::size_t k = 0; k < f.gens.size(); ++k) fmt::format_to(out, " w{} = {}", k, f.gens[k].str());
    fmt::format_to(out, "\n");
  }
  std::optional<TermCode> terms;
  if (op.terms) {
    terms.emplace(op, f);
    fmt::format_to(out, "// Terms ({} instantiation, 003 Sec. 6.3):\n", op.terms->instantiation == Instantiation::extended ? "extended" : "direct");
    for (const char side : {'L', 'R'})
      for (const NodeTerm& t : side == 'L' ? op.terms->left : op.terms->right)
        fmt::format_to(out, "//   {} {}: {} = {}\n", side, comment_text(t.node), comment_text(t.embedding), comment_text(t.term.str()));
  }
  emit_function(out, op, f, terms, function, false);
  if (everywhere_applies(op, f)) emit_function(out, op, f, terms, function, true);
  return code;
}

CompiledHeader compile_header(const std::vector<CompileUnit>& units, std::string_view ns, std::string_view source) {
  std::string code;
  Out out(code);
  fmt::format_to(out,
                 "// Generated by `dartcheck compile` from {}; regenerate rather than edit.\n"
                 "// Each function applies one rule or rule scheme that dartcheck's static checker\n"
                 "// calls consistent{}, exactly as dartcheck's interpreter applies it (docs/compile.md).\n"
                 "#pragma once\n\n#include <algorithm>\n#include <array>\n#include <cstddef>\n#include <cstdint>\n#include <limits>\n#include "
                 "<span>\n#include <string>\n#include <vector>\n\n"
                 "#include \"rewriting/compiled_runtime.hpp\"\n\nnamespace {} {{\n\n"
                 "using dartcheck::Dart;\nusing dartcheck::Map;\nusing dartcheck::no_dart;\nusing dartcheck::Refusal;\n"
                 "using dartcheck::compiled::check_match;\nusing dartcheck::combinatorial_violation;\nusing dartcheck::compiled::fill_holes;\nusing "
                 "dartcheck::compiled::propagate;\n"
                 "using dartcheck::compiled::walk_patterns;\nusing dartcheck::compiled::whole_map_patterns;\nusing dartcheck::compiled::Workspace;\n"
                 "// Terms (rewriting/compiled_terms.hpp).\n"
                 "using dartcheck::dims_generators;\nusing dartcheck::EmbeddedMap;\nusing dartcheck::Embedding;\nusing dartcheck::EvaluationError;\n"
                 "using dartcheck::Value;\nusing dartcheck::ValueType;\nusing dartcheck::OrbitWord;\nusing dartcheck::compiled::CollectSite;\n"
                 "using dartcheck::compiled::EachSite;\nusing dartcheck::value_less;\n"
                 "using dartcheck::compiled::end_writes;\nusing dartcheck::compiled::neighbour;\nusing dartcheck::compiled::overlap;\n"
                 "using dartcheck::compiled::read;\nusing dartcheck::compiled::reserve_more;\nusing dartcheck::compiled::Source;\nusing dartcheck::compiled::TermWorkspace;\n"
                 "using dartcheck::compiled::unlabel;\nusing dartcheck::compiled::write_orbit;\n\n",
                 comment_text(source),
                 std::any_of(units.begin(), units.end(), [](const CompileUnit& u) { return !u.embedding_failures.empty(); })
                     ? "\n// (or, where its comment says so, whose topological conditions hold and an embedding\n// condition fails)"
                     : "",
                 ns);
  // Each function is written under a stand-in name (\x01k\x01, no identifier),
  // so that the names are chosen knowing every identifier the code uses.
  std::vector<std::string> names;
  for (std::size_t k = 0; k < units.size(); ++k) {
    names.push_back(fmt::format("\x01{}\x01", k));
    code += compile_operation(units[k], names.back()) + "\n";
  }
  // Two tables: topological rules apply to a Map, rules with terms to an
  // EmbeddedMap.
  std::size_t topological = 0;
  for (const CompileUnit& u : units) topological += !u.operation->terms;
  fmt::format_to(
      out,
      "/// A compiled operation: the rule's name, its function at hook darts, and\n"
      "/// its function at every connected component (nullptr unless the rule is\n"
      "/// a scheme whose P_v is the hook's component).\n"
      "struct CompiledOperation {{\n  const char* name;\n  Refusal (*apply)(Map&, std::span<const Dart>, Workspace&);\n"
      "  Refusal (*everywhere)(Map&, Workspace&);\n}};\n"
      "/// A compiled operation with embedding terms.\n"
      "struct CompiledEmbeddedOperation {{\n  const char* name;\n  Refusal (*apply)(EmbeddedMap&, std::span<const Dart>, Workspace&);\n"
      "  Refusal (*everywhere)(EmbeddedMap&, Workspace&);\n}};\n\n");
  for (const bool embedded : {false, true}) {
    fmt::format_to(out, "inline constexpr std::array<{}, {}> {}{{{{\n", embedded ? "CompiledEmbeddedOperation" : "CompiledOperation",
                   embedded ? units.size() - topological : topological, embedded ? "embedded_operations" : "operations");
    for (std::size_t k = 0; k < units.size(); ++k)
      if (units[k].operation->terms.has_value() == embedded)
        fmt::format_to(out, "    {{{}, &{}, {}}},\n", cpp_literal(units[k].operation->rule.name()), names[k],
                       has_everywhere(*units[k].operation) ? fmt::format("&{}_everywhere", names[k]) : std::string("nullptr"));
    fmt::format_to(out, "}}}};\n");
  }
  fmt::format_to(out, "\n}}  // namespace {}\n", ns);

  CompiledHeader header;
  const auto used = code_identifiers(code);
  std::set<std::string, std::less<>> declared;
  for (std::size_t k = 0; k < units.size(); ++k) {
    const std::string& rule = units[k].operation->rule.name();
    std::string why;
    const std::string name = function_name(rule, declared, used, &why);
    declared.insert(name);
    declared.insert(name + "_everywhere");
    if (!why.empty()) header.renamed.push_back(fmt::format("rule '{}' is compiled as {}: {}", rule, name, why));
    for (std::size_t at = 0; (at = code.find(names[k], at)) != std::string::npos; at += name.size()) code.replace(at, names[k].size(), name);
  }
  header.code = std::move(code);
  return header;
}

}  // namespace dartcheck::compiler
