#include "io/jerboa_modeler.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <pugixml.hpp>

#include "core/error.hpp"
#include "core/disjoint_sets.hpp"
#include "core/input_error.hpp"
#include "io/input_file.hpp"
#include "io/jerboa_expression.hpp"
#include "rewriting/jerboa_scheme.hpp"

namespace dartcheck {
namespace {

// Byte offsets of pugixml nodes, as file:line:column.
class Positions {
 public:
  Positions(std::string file, const std::string& text) : file_(std::move(file)) {
    starts_.push_back(0);
    for (std::size_t k = 0; k < text.size(); ++k)
      if (text[k] == '\n') starts_.push_back(k + 1);
  }
  SourceLocation at(std::ptrdiff_t offset) const {
    if (offset < 0) return {file_, 0, 0};
    const auto line = std::upper_bound(starts_.begin(), starts_.end(), static_cast<std::size_t>(offset)) - starts_.begin();
    return {file_, static_cast<int>(line), static_cast<int>(static_cast<std::size_t>(offset) - starts_[line - 1] + 1)};
  }
  SourceLocation at(const pugi::xml_node& n) const { return at(n.offset_debug()); }
  [[noreturn]] void fail(const pugi::xml_node& n, const std::string& message) const {
    const auto w = at(n);
    throw InputError(w.file, w.line, w.column, message);
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::vector<std::size_t> starts_;
};

std::string trimmed(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  return std::string(s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1));
}

// An integer attribute (or text) in [lo, hi]; InputError at `n` otherwise.
int integer(const Positions& p, const pugi::xml_node& n, std::string_view text, std::string_view what, int lo, int hi) {
  const std::string t = trimmed(text);
  int v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size()) p.fail(n, fmt::format("{}: expected an integer, got '{}'", what, t));
  if (v < lo || v > hi) p.fail(n, fmt::format("{} {} is out of range ({} to {})", what, v, lo, hi));
  return v;
}

// "0,-1,3" -> <0,_,3>; "" -> <>. Entries are dimensions 0..n or -1.
OrbitType orbit_label(const Positions& p, const pugi::xml_node& n, std::string_view text, int dimension) {
  OrbitType t;
  const std::string s = trimmed(text);
  if (s.empty()) return t;
  std::stringstream in(s);
  for (std::string entry; std::getline(in, entry, ',');) {
    const std::string e = trimmed(entry);
    int v = 0;
    const auto [end, ec] = std::from_chars(e.data(), e.data() + e.size(), v);
    if (e.empty() || ec != std::errc() || end != e.data() + e.size() || v < -1 || v > dimension)
      p.fail(n, fmt::format("orbit \"{}\": unknown entry '{}' (expected a dimension 0 to {}, or -1 for '_')", s, e, dimension));
    t.push_back(v < 0 ? std::nullopt : std::optional<Dim>(static_cast<Dim>(v)));
  }
  return t;
}

struct JmeNode {
  std::string name;
  OrbitType label;
  bool hook = false;
  pugi::xml_node xml;
};

// One side: its nodes (name, orbit label, kind) and its arcs, checked
// against the modeler's dimension; arcs are kept as (dim, a, b), b == a
// for a loop.
struct JmeSide {
  std::vector<JmeNode> nodes;
  std::vector<std::tuple<Dim, std::string, std::string>> arcs;
  const JmeNode* find(const std::string& name) const {
    for (const auto& n : nodes)
      if (n.name == name) return &n;
    return nullptr;
  }
};

JmeSide read_side(const Positions& p, const pugi::xml_node& side, int dimension) {
  JmeSide s;
  for (const auto& n : side.child("nodes").children("node")) {
    const std::string name = n.attribute("name").value();
    if (name.empty()) p.fail(n, "a node without a name");
    if (s.find(name)) p.fail(n, fmt::format("node '{}' is declared twice in <{}>", name, side.name()));
    const std::string kind = n.attribute("kind").value();
    if (!kind.empty() && kind != "HOOK" && kind != "SIMPLE")
      p.fail(n, fmt::format("node '{}': unknown kind '{}' (expected HOOK or SIMPLE)", name, kind));
    s.nodes.push_back({name, orbit_label(p, n, n.attribute("orbit").value(), dimension), kind == "HOOK", n});
  }
  for (const auto& a : side.child("arcs").children()) {
    const std::string tag = a.name();
    if (tag != "arc" && tag != "arcloop") continue;
    const Dim d = static_cast<Dim>(integer(p, a, a.attribute("dim").value(), "arc dimension", 0, dimension));
    const std::string x = tag == "arc" ? a.attribute("a").value() : a.attribute("node").value();
    const std::string y = tag == "arc" ? a.attribute("b").value() : x;
    for (const auto& end : {x, y})
      if (!s.find(end)) p.fail(a, fmt::format("<{}> names node '{}', which is not a node of <{}>", tag, end, side.name()));
    s.arcs.emplace_back(d, x, y);
  }
  return s;
}

// A side as a graph in the Jerboa translation: explicit arcs are
// non-oriented (ε,d)-pairs, loops single (ε,d)-loops; each node's orbit
// label adds its implicit loops.
TopoGraph build_side(const JmeSide& s, std::vector<ConjWord>& words, const OrbitType& parameter, const Model& model, std::vector<OrbitType>& labels) {
  TopoGraph g;
  for (const auto& n : s.nodes) {
    const NodeId v = g.add_node(n.name);
    add_implicit_arcs(g, words, v, parameter, n.label, model);
    labels.push_back(n.label);
  }
  for (const auto& [d, a, b] : s.arcs) {
    const NodeId x = *g.find(a), y = *g.find(b);
    g.add_arc(x, y, d);
    words.push_back(ConjWord{});
    if (x != y) {
      g.add_arc(y, x, d);
      words.push_back(ConjWord{});
    }
  }
  return g;
}

// Why a rule cannot be represented, or empty.
std::string unrepresentable(const pugi::xml_node& rule) {
  for (const char* side : {"left", "right"})
    for (const auto& n : rule.child(side).child("nodes").children("node")) {
      const std::string m = trimmed(n.attribute("multiplicity").value());
      if (!m.empty() && m != "{1}")
        return fmt::format("node '{}' of <{}> has multiplicity {}: dartcheck represents only {{1}} (one copy per match)", n.attribute("name").value(),
                           side, m);
    }
  return {};
}

// The file offset of position k of an element's text as pugixml decodes
// it (entities such as &lt; one character, CR LF one newline).
std::ptrdiff_t text_offset(const std::string& raw, const pugi::xml_node& e, std::size_t k) {
  const pugi::xml_node text = e.first_child();
  if (!text || text.offset_debug() < 0) return e.offset_debug();
  auto r = static_cast<std::size_t>(text.offset_debug());
  for (std::size_t d = 0; d < k && r < raw.size(); ++d) {
    if (raw[r] == '&') {
      const auto semi = raw.find(';', r);
      r = semi == std::string::npos ? r + 1 : semi + 1;
    } else {
      r += raw.compare(r, 2, "\r\n") == 0 ? 2 : 1;
    }
  }
  return static_cast<std::ptrdiff_t>(r);
}

// What every rule's expressions may read: the modeler's typed embeddings.
struct ModelerScope {
  std::vector<EmbeddingSignature> typed;  // embeddings whose Java class dartcheck reads
  std::vector<std::string> untyped;       // "norm (fr.Foo)": the others
};

// The rule's parameters (<paramsebd>): values from their text, Java's
// default when empty (said as a caveat), opaque when not read.
void read_parameters(const pugi::xml_node& rule, JerboaScope& scope, std::vector<std::string>& caveats) {
  for (const auto& e : rule.child("paramsebd").children("paramebd")) {
    const std::string name = e.attribute("name").value(), type = e.attribute("type").value(), text = trimmed(e.child_value());
    if (const auto v = jerboa_parameter_value(type, text)) {
      scope.parameters[name] = *v;
      if (text.empty())
        caveats.push_back(fmt::format("parameter {} ({}) has no value in the .jme: expressions read Java's default, {}", name, type, v->str()));
    } else {
      scope.opaque_parameters.push_back(name);
    }
  }
}

// R's pi-orbits through explicit arcs labeled in <o> (Jerboa's implicit
// arcs join copies of one node only), as a root per node.
std::vector<std::size_t> explicit_orbits(const JmeSide& side, const std::vector<Dim>& orbit) {
  DisjointSets<std::size_t> orbits(side.nodes.size());
  auto index = [&](const std::string& n) {
    for (std::size_t k = 0; k < side.nodes.size(); ++k)
      if (side.nodes[k].name == n) return k;
    return std::size_t{0};
  };
  for (const auto& [d, a, b] : side.arcs)
    if (std::find(orbit.begin(), orbit.end(), d) != orbit.end()) orbits.join(index(a), index(b));
  return orbits.representatives();
}

// A read rule's terms (003 Sec. 6.3, extended instantiation, as Jerboa
// applies a scheme): every node of L reads its orbit's value (x.pi); a node
// of R carries its expression's term; a preserved node without one keeps
// its value (x.pi) unless an expression of its R pi-orbit gives the
// orbit's new value (Jerboa propagates it, 003 Def. 12); an added node
// without one is unlabeled, and takes its orbit's value by propagation.
RuleTerms jerboa_terms(const JmeSide& left, const JmeSide& right, const std::vector<NodeExpression>& expressions, const JerboaScope& scope) {
  RuleTerms t;
  t.embeddings = scope.embeddings;
  t.parameters = scope.parameters;
  t.instantiation = Instantiation::extended;
  TermScope ts{scope.model, &scope.embeddings, scope.nodes, scope.parameters, nullptr};
  auto own = [&](const std::string& node, const std::string& pi) {
    Term x;
    x.kind = Term::Kind::variable;
    x.name = node;
    Term a;
    a.kind = Term::Kind::access;
    a.name = pi;
    a.args.push_back(std::move(x));
    check_term(a, ts);
    return a;
  };
  for (const auto& e : scope.embeddings) {
    // The nodes of one pi-orbit of L hold one value: each reads it at the
    // orbit's first node (as 003's Fig. 25a labels e and f with e.col).
    const auto left_orbit = explicit_orbits(left, e.orbit);
    auto value_of = [&](const std::string& n) {
      for (std::size_t k = 0; k < left.nodes.size(); ++k)
        if (left.nodes[k].name == n) return own(left.nodes[left_orbit[k]].name, e.name);
      return own(n, e.name);
    };
    for (const auto& n : left.nodes) t.left.push_back({n.name, e.name, value_of(n.name), {}, 0, 0});
    const auto orbit = explicit_orbits(right, e.orbit);
    std::vector<char> computed(right.nodes.size());
    for (std::size_t k = 0; k < right.nodes.size(); ++k)
      for (const auto& x : expressions)
        if (x.embedding == e.name && x.node == right.nodes[k].name) computed[orbit[k]] = 1;
    for (std::size_t k = 0; k < right.nodes.size(); ++k) {
      const std::string& n = right.nodes[k].name;
      const auto x = std::find_if(expressions.begin(), expressions.end(), [&](const NodeExpression& y) { return y.embedding == e.name && y.node == n; });
      if (x != expressions.end())
        t.right.push_back({n, e.name, *x->term, x->location.file, x->location.line, x->location.column});
      else if (left.find(n) && !computed[orbit[k]])
        t.right.push_back({n, e.name, value_of(n), {}, 0, 0});
    }
  }
  return t;
}

std::vector<std::string> caveats_of(const pugi::xml_node& rule) {
  std::vector<std::string> out;
  if (!trimmed(rule.child_value("precondition")).empty())
    out.push_back("precondition ignored (Java code, not evaluated): the verdicts hold for every match, and a precondition can only exclude matches");
  for (const char* code : {"preprocess", "midprocess", "postprocess"})
    if (!trimmed(rule.child_value(code)).empty())
      out.push_back(fmt::format("<{}> code ignored (Java code, not evaluated): it may change the map outside the rule", code));
  return out;
}

// The rule's hooks: in the order of <paramstopo>, then any other HOOK node
// of L; a HOOK on the right side, or a <paramtopo> naming no HOOK of L,
// fails the file.
std::vector<std::string> rule_hooks(const Positions& p, const pugi::xml_node& r, const JmeSide& left, const JmeSide& right) {
  std::vector<std::string> hooks;
  for (const auto& t : r.child("paramstopo").children("paramtopo")) {
    const std::string h = t.attribute("name").value();
    const JmeNode* n = left.find(h);
    if (!n) p.fail(t, fmt::format("<paramtopo> names '{}', which is not a node of <left>", h));
    if (!n->hook) p.fail(t, fmt::format("<paramtopo> names '{}', which is not a HOOK node", h));
    hooks.push_back(h);
  }
  for (const auto& n : left.nodes)
    if (n.hook && std::find(hooks.begin(), hooks.end(), n.name) == hooks.end()) hooks.push_back(n.name);
  for (const auto& n : right.nodes)
    if (n.hook) p.fail(n.xml, fmt::format("node '{}' of <right> is a HOOK: hooks belong to the left side", n.name));
  return hooks;
}

// One <expr> of a right node: its Java, and the term it reads as or why it
// is opaque (docs/jerboa-expressions.md); Java that is not Java fails the
// file at its position.
NodeExpression read_expression(const Positions& p, const std::string& raw, const ModelerScope& ms, const JerboaScope& scope, const std::string& rule,
                               const JmeNode& n, const pugi::xml_node& e, const EmbeddingDecl& decl) {
  const std::string ebd = e.attribute("ebd").value();
  const std::string code = e.child_value();
  const auto first = code.find_first_not_of(" \t\r\n");
  const std::size_t lead = first == std::string::npos ? 0 : first;
  NodeExpression x{n.name, ebd, trimmed(code), p.at(e), std::nullopt, {}, {}};
  const auto sig = std::find_if(ms.typed.begin(), ms.typed.end(), [&](const EmbeddingSignature& t) { return t.name == ebd; });
  if (sig == ms.typed.end()) {
    x.reason = fmt::format("the embedding {} has the Java class {}, whose values dartcheck does not read", ebd, decl.type);
    x.reason_location = x.location;
    return x;
  }
  try {
    ReadExpression read = read_jerboa_expression(x.code, scope, sig->type);
    x.term = std::move(read.term);
    x.reason = std::move(read.reason);
    x.reason_location = p.at(text_offset(raw, e, lead + read.offset));
  } catch (const JerboaCodeError& err) {
    const auto w = p.at(text_offset(raw, e, lead + err.offset()));
    throw InputError(w.file, w.line, w.column, fmt::format("rule '{}', node '{}', expression for {}: {}", rule, n.name, ebd, err.what()));
  }
  return x;
}

// Every <expr> of the rule's nodes: the right side's read, the left
// side's a caveat (Jerboa reads embeddings on the left).
void read_expressions(const Catalog& c, const Positions& p, const std::string& raw, const ModelerScope& ms, const JerboaScope& scope,
                      const JmeSide& left, const JmeSide& right, CatalogRule& cr) {
  for (const auto* side : {&left, &right})
    for (const auto& n : side->nodes)
      for (const auto& e : n.xml.children("expr")) {
        const std::string ebd = e.attribute("ebd").value();
        const auto decl = std::find_if(c.embeddings.begin(), c.embeddings.end(), [&](const EmbeddingDecl& d) { return d.name == ebd; });
        if (decl == c.embeddings.end())
          p.fail(e, fmt::format("node '{}': <expr ebd=\"{}\">, but the modeler declares no embedding '{}'", n.name, ebd, ebd));
        if (side == &left)
          cr.caveats.push_back(
              fmt::format("expression for {} on node '{}' of the left side ignored (Jerboa reads embeddings on the left)", ebd, n.name));
        else
          cr.expressions.push_back(read_expression(p, raw, ms, scope, cr.rule.name(), n, e, *decl));
      }
}

// Every node labeled '_' in every position (<_>, <_,_>...): the orbits
// hold no link, each node is one dart, and the rule is the plain DPO rule
// on darts of orbit type <> (real modelers write single-dart rules so).
void clear_removed_labels(JmeSide& left, JmeSide& right) {
  const auto all_removed = [](const JmeSide& s) {
    return std::all_of(s.nodes.begin(), s.nodes.end(),
                       [](const JmeNode& n) { return std::all_of(n.label.begin(), n.label.end(), [](const auto& x) { return !x.has_value(); }); });
  };
  if (all_removed(left) && all_removed(right))
    for (auto* side : {&left, &right})
      for (auto& n : side->nodes) n.label.clear();
}

// Why the parameter orbit type (the first hook's label) cannot be read,
// or "": a '_' in it, or a node with another number of positions.
std::string parameter_problem(const OrbitType& parameter, const std::vector<std::string>& hooks, const JmeSide& left, const JmeSide& right) {
  if (std::find(parameter.begin(), parameter.end(), std::nullopt) != parameter.end())
    return fmt::format("the hook '{}' is labeled {}, with '_': a hook's label is the parameter orbit type", hooks.front(), orbit_type_str(parameter));
  for (const auto* side : {&left, &right})
    for (const auto& n : side->nodes)
      if (n.label.size() != parameter.size())
        return fmt::format("node '{}' is labeled {} ({} positions) but the parameter orbit type {} has {}", n.name, orbit_type_str(n.label),
                           n.label.size(), orbit_type_str(parameter), parameter.size());
  return "";
}

void read_rule(Catalog& c, const Positions& p, const std::string& raw, const ModelerScope& ms, const pugi::xml_node& r, const Model& model,
               int dimension) {
  const std::string name = r.attribute("name").value();
  if (name.empty()) p.fail(r, "a rule without a name");
  if (c.find_rule(name) || std::any_of(c.skipped.begin(), c.skipped.end(), [&](const SkippedRule& s) { return s.name == name; }))
    p.fail(r, fmt::format("rule '{}' is declared twice", name));
  const SourceLocation at = p.at(r);
  // Structural errors (orbits, arcs, dimensions) fail the file; what
  // dartcheck cannot represent skips the rule.
  JmeSide left = read_side(p, r.child("left"), dimension), right = read_side(p, r.child("right"), dimension);
  clear_removed_labels(left, right);
  auto skip = [&](std::string why) { c.skipped.push_back({name, std::move(why), at}); };
  if (auto why = unrepresentable(r); !why.empty()) return skip(why);

  const std::vector<std::string> hooks = rule_hooks(p, r, left, right);
  if (hooks.empty() && !left.nodes.empty()) return skip("the left side has nodes but no hook: Jerboa needs one hook per connected component of L");

  // The parameter orbit type is the first hook's label (000 Sec. 4.3.2).
  const OrbitType parameter = hooks.empty() ? OrbitType{} : left.find(hooks.front())->label;
  if (auto why = parameter_problem(parameter, hooks, left, right); !why.empty()) return skip(why);
  std::vector<std::string> caveats = caveats_of(r);
  for (std::size_t k = 1; k < hooks.size(); ++k)
    if (left.find(hooks[k])->label != parameter)
      caveats.push_back(fmt::format("hook '{}' is labeled {}, not the parameter {}: read relative to the first hook's orbit type", hooks[k],
                                    orbit_type_str(left.find(hooks[k])->label), orbit_type_str(parameter)));

  ArcWords words;
  JerboaLabels labels{parameter, {}, {}};
  TopoGraph lg = build_side(left, words.left, parameter, model, labels.left);
  TopoGraph rg = build_side(right, words.right, parameter, model, labels.right);
  std::optional<Rule> rule;
  try {
    if (parameter.empty())  // orbit type <>: one dart per node, a plain DPO rule
      rule.emplace(name, model, std::move(lg), std::move(rg), hooks);
    else
      rule.emplace(name, model, std::move(lg), std::move(rg), hooks, words.left, words.right);
  } catch (const ValueError& e) {
    return skip(e.what());
  }
  if (parameter.empty())
    words = ArcWords{};
  else
    words.scheme = true;
  CatalogRule cr{{std::move(*rule),
                  words,
                  parameter.empty() ? std::nullopt : std::optional<JerboaLabels>(std::move(labels)),
                  {},
                  std::move(caveats),
                  std::nullopt},
                 trimmed(r.child_value("comment")),
                 {},
                 at,
                 std::nullopt,
                 {},
                 std::nullopt,
                 {}};
  JerboaScope scope{&cr.rule.model(), ms.typed, {}, {}, {}};
  for (const auto& n : left.nodes) scope.nodes.push_back(n.name);
  read_parameters(r, scope, cr.caveats);
  read_expressions(c, p, raw, ms, scope, left, right, cr);
  // A rule whose every expression is read, on a modeler whose every
  // embedding is typed, is checked, applied and compiled with its terms.
  const bool all_read = std::all_of(cr.expressions.begin(), cr.expressions.end(), [](const NodeExpression& x) { return x.read(); });
  if (all_read && ms.untyped.empty() && !ms.typed.empty()) cr.terms = jerboa_terms(left, right, cr.expressions, scope);
  c.rules.push_back(std::move(cr));
}

}  // namespace

Catalog read_jme(const std::string& file) {
  const std::string text = read_input(file);
  refuse_nul_bytes(file, text, "a .jme file");
  const Positions p(file, text);
  pugi::xml_document doc;
  const auto parsed = doc.load_buffer(text.data(), text.size());
  if (!parsed) {
    const auto w = p.at(parsed.offset);
    throw InputError(file, w.line, w.column, fmt::format("malformed XML: {}", parsed.description()));
  }
  const auto root = doc.child("jerboamodelereditor");
  if (!root) throw InputError(file, 1, 1, "not a Jerboa modeler file: the root element must be <jerboamodelereditor>");
  const auto modeler = root.child("modeler");
  if (!modeler) p.fail(root, "<jerboamodelereditor> has no <modeler>");
  const int dimension = integer(p, modeler, modeler.attribute("dimension").value(), "modeler dimension", 0, max_dimension);
  const Model model = Model::gmap(dimension);

  Catalog c;
  c.file = file;
  c.modeler = modeler.attribute("name").value();
  for (const auto& e : modeler.child("embeddings").children("embedding")) {
    EmbeddingDecl d{e.attribute("name").value(), e.attribute("type").value(), {}, p.at(e)};
    if (d.name.empty()) p.fail(e, "an embedding without a name");
    for (const auto& k : orbit_label(p, e, e.attribute("orbit").value(), dimension)) {
      if (!k) p.fail(e, fmt::format("embedding '{}': an embedding's orbit type cannot contain -1", d.name));
      d.orbit.push_back(*k);
    }
    c.embeddings.push_back(std::move(d));
  }
  ModelerScope ms;
  for (const auto& d : c.embeddings) {
    if (const auto t = jerboa_value_type(d.type))
      ms.typed.push_back({d.name, *t, d.orbit});
    else
      ms.untyped.push_back(fmt::format("{} ({})", d.name, d.type));
  }
  if (ms.untyped.empty()) c.signatures = ms.typed;  // the rules' terms use them
  for (const auto& r : modeler.child("rules").children()) {
    const std::string tag = r.name();
    if (tag == "rule") {
      read_rule(c, p, text, ms, r, model, dimension);
    } else if (tag == "script") {
      c.skipped.push_back({r.attribute("name").value(), "a script (Java code calling rules), not a rule: not checked", p.at(r)});
    } else {
      c.skipped.push_back({r.attribute("name").value(), fmt::format("<{}> is not a rule dartcheck reads", tag), p.at(r)});
    }
  }
  return c;
}

}  // namespace dartcheck
