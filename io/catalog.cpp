#include "io/catalog.hpp"
#include "core/error.hpp"
#include "io/detail/yaml_readers.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/limits.hpp"
#include "io/jerboa_expression.hpp"
#include "io/jerboa_modeler.hpp"
#include "rewriting/jerboa_scheme.hpp"
#include "io/map_io.hpp"
#include "io/rule_terms_reader.hpp"
#include "io/detail/yaml_util.hpp"

namespace dartcheck {

const MapSource* Catalog::find_map(const std::string& name) const {
  for (const auto& m : maps)
    if (m.name == name) return &m;
  return nullptr;
}

const CatalogRule* Catalog::find_rule(const std::string& name) const {
  for (const auto& r : rules)
    if (r.rule.name() == name) return &r;
  return nullptr;
}

namespace {

SourceLocation where(const std::string& file, const YAML::Node& n) { return {file, n.Mark().line + 1, n.Mark().column + 1}; }

// "x -i- y", "x -i-> y" or "x <-i- y": three whitespace-separated words.
struct ArcText {
  std::string source, target;
  int label = 0;
  bool oriented = false, backwards = false;
  std::optional<std::string> word;  // scheme label "(w,d)"
};

std::optional<ArcText> parse_arc(const std::string& text) {
  std::istringstream in(text);
  ArcText a;
  std::string word, extra;
  if (!(in >> a.source >> word >> a.target) || (in >> extra)) return std::nullopt;
  std::string_view link = word;
  bool forwards = false;
  if (link.starts_with("<-")) {
    a.backwards = true;
    link.remove_prefix(2);
  } else if (link.starts_with("-")) {
    link.remove_prefix(1);
  } else {
    return std::nullopt;
  }
  if (link.ends_with("->")) {
    forwards = true;
    link.remove_suffix(2);
  } else if (link.ends_with("-")) {
    link.remove_suffix(1);
  } else {
    return std::nullopt;
  }
  if (a.backwards && forwards) return std::nullopt;
  // A scheme label (w,d): the word and the dimension.
  if (link.size() >= 5 && link.front() == '(' && link.back() == ')') {
    const auto comma = link.rfind(',');
    if (comma == std::string_view::npos) return std::nullopt;
    a.word = std::string(link.substr(1, comma - 1));
    link = link.substr(comma + 1, link.size() - comma - 2);
  }
  if (link.empty() || link.size() > 3) return std::nullopt;
  for (char c : link) {
    if (c < '0' || c > '9') return std::nullopt;
    a.label = a.label * 10 + (c - '0');
  }
  a.oriented = a.backwards || forwards;
  return a;
}

}  // namespace

Model read_model(const std::string& file, const YAML::Node& node, const std::vector<Model>& custom) {
  const std::string name = yaml::as_string(file, node, "model");
  for (const auto& m : custom)
    if (m.name == name) return m;
  if (auto m = Model::by_name(name)) return *m;
  fail_at(file, node, fmt::format("unknown model '{}' (expected {}, or a model declared under 'models')", name, Model::known_names()));
}

TopoGraph read_side(const std::string& file, const YAML::Node& side, const char* which, const Model* model, std::vector<ConjWord>* words,
                    bool* has_words, const OrbitType* jerboa, std::vector<OrbitType>* orbit_types) {
  yaml::expect_map(file, side, which);
  yaml::allow_keys(file, side, {"nodes", "arcs"});
  TopoGraph g;
  const auto nodes = yaml::require(file, side, "nodes");
  if (nodes.size() > limits().rule_nodes)
    fail_at(file, nodes, over_limit(fmt::format("{}.nodes", which).c_str(), nodes.size(), limits().rule_nodes, "--limit-rule-nodes"));
  if (jerboa) {
    // Jerboa notation: nodes map to generalized orbit types (000 Sec. 4.3).
    if (!model || !words) fail_at(file, nodes, "Jerboa node labels are allowed only in a rule");
    yaml::expect_map(file, nodes, fmt::format("{}.nodes (Jerboa notation: name: \"<0,_,2>\")", which));
    for (const auto& kv : nodes) {
      const auto name = yaml::as_string(file, kv.first, "node name");
      if (g.find(name)) fail_at(file, kv.first, fmt::format("{} declares node '{}' twice", which, name));
      const NodeId v = g.add_node(name);
      try {
        const OrbitType t = parse_orbit_type(yaml::as_string(file, kv.second, "orbit type"));
        add_implicit_arcs(g, *words, v, *jerboa, t, *model);
        if (orbit_types) orbit_types->push_back(t);
      } catch (const ValueError& e) {
        fail_at(file, kv.second, fmt::format("node '{}': {}", name, e.what()));
      }
    }
    if (has_words) *has_words = true;
  } else {
    yaml::expect_sequence(file, nodes, fmt::format("{}.nodes", which));
    for (const auto& n : nodes) {
      const auto name = yaml::as_string(file, n, "node name");
      if (g.find(name)) fail_at(file, n, fmt::format("{} declares node '{}' twice", which, name));
      g.add_node(name);
    }
  }
  if (const auto arcs = side["arcs"]) {
    yaml::expect_sequence(file, arcs, fmt::format("{}.arcs", which));
    for (const auto& a : arcs) {
      const auto text = yaml::as_string(file, a, "arc");
      const auto arc = parse_arc(text);
      if (!arc)
        fail_at(file, a,
                fmt::format("arc '{}': expected 'x -i- y' (non-oriented pair), 'x -i-> y' or 'x <-i- y' (one oriented arc), "
                            "with i a dimension or a scheme label (w,i)",
                            text));
      auto node = [&](const std::string& name) {
        auto v = g.find(name);
        if (!v) fail_at(file, a, fmt::format("arc '{}': node '{}' is not declared in {}.nodes", text, name, which));
        return *v;
      };
      NodeId x = node(arc->source), y = node(arc->target);
      if (arc->label > max_dimension) fail_at(file, a, fmt::format("arc '{}': dimension {} is above {}", text, arc->label, max_dimension));
      if (arc->backwards) std::swap(x, y);
      ConjWord w;
      if (arc->word && jerboa)
        fail_at(file, a, fmt::format("arc '{}': a Jerboa scheme's explicit arcs are plain dimensions; relabelings go in the node labels", text));
      if (arc->word) {
        if (!model || !words) fail_at(file, a, fmt::format("arc '{}': a scheme label (w,i) is not allowed here", text));
        try {
          w = parse_conj_word(*arc->word, *model);
        } catch (const ValueError& e) {
          fail_at(file, a, fmt::format("arc '{}': {}", text, e.what()));
        }
        if (has_words) *has_words = true;
      }
      g.add_arc(x, y, arc->label);
      if (words) words->push_back(w);
      if (!arc->oriented && x != y) {
        // The reverse of (w, i) is (conj(w), i) (002 Def. 24).
        g.add_arc(y, x, arc->label);
        if (words) words->push_back(model ? ConjugateRewriting(*model).conjugate(w) : w);
      }
    }
  }
  return g;
}

namespace {

Example read_example(const std::string& file, const YAML::Node& n) {
  yaml::expect_map(file, n, "example");
  yaml::allow_keys(file, n, {"map", "hooks", "expect", "cells", "isomorphic-to"});
  Example e;
  e.location = where(file, n);
  e.map = yaml::as_string(file, yaml::require(file, n, "map"), "map");
  const auto hooks = yaml::require(file, n, "hooks");
  yaml::expect_sequence(file, hooks, "hooks");
  for (const auto& h : hooks) e.hooks.push_back(static_cast<Dart>(yaml::as_int(file, h, "hook dart", 0, (1LL << 31))));
  const auto expect = yaml::require(file, n, "expect");
  e.expect = yaml::as_string(file, expect, "expect");
  static const std::vector<std::string> allowed{
      "valid", "invalid", "no-match", "not-injective", "dangling", "not-representable", "not-combinatorial", "bad-hooks", "disconnected-instance"};
  if (std::find(allowed.begin(), allowed.end(), e.expect) == allowed.end())
    fail_at(file, expect, fmt::format("expect: '{}' is not one of {}", e.expect, fmt::join(allowed, ", ")));
  if (const auto cells = n["cells"]) {
    yaml::expect_sequence(file, cells, "cells");
    std::vector<std::size_t> c;
    for (const auto& x : cells) c.push_back(static_cast<std::size_t>(yaml::as_int(file, x, "cell count", 0, 1LL << 40)));
    e.cells = c;
  }
  if (const auto iso = n["isomorphic-to"]) e.isomorphic_to = yaml::as_string(file, iso, "isomorphic-to");
  return e;
}

}  // namespace

namespace {

// A side of a variant: the base side's nodes (or the variant's `nodes:
// {left|right: ...}`) and arcs, minus `remove: {side: [...]}`, plus `add:
// {side: [...]}`. Arcs are matched by their exact text; the kept YAML nodes
// keep their positions for error messages.
YAML::Node edit_side(const std::string& file, const YAML::Node& base, const YAML::Node& variant, const char* which) {
  yaml::expect_map(file, base, which);
  YAML::Node side(YAML::NodeType::Map);
  const auto nodes = variant["nodes"];
  if (nodes) {
    yaml::expect_map(file, nodes, "nodes");
    yaml::allow_keys(file, nodes, {"left", "right"});
  }
  side["nodes"] = nodes && nodes[which] ? nodes[which] : base["nodes"];
  // YAML::Node's assignment writes through to the shared node, so arcs are
  // dropped by flag, never by moving handles around (vector::erase would
  // overwrite the base rule's own arcs).
  std::vector<YAML::Node> arcs;
  std::vector<bool> dropped;
  if (const auto a = base["arcs"]) {
    yaml::expect_sequence(file, a, fmt::format("{}.arcs", which));
    for (const auto& x : a) arcs.push_back(x);
  }
  dropped.assign(arcs.size(), false);
  auto part = [&](const char* key) {
    const auto edit = variant[key];
    if (!edit) return YAML::Node(YAML::NodeType::Sequence);
    yaml::expect_map(file, edit, key);
    yaml::allow_keys(file, edit, {"left", "right"});
    if (!edit[which]) return YAML::Node(YAML::NodeType::Sequence);
    yaml::expect_sequence(file, edit[which], fmt::format("{}.{}", key, which));
    return edit[which];
  };
  for (const auto& r : part("remove")) {
    const auto text = yaml::as_string(file, r, "arc");
    std::size_t k = 0;
    while (k < arcs.size() && (dropped[k] || !arcs[k].IsScalar() || arcs[k].Scalar() != text)) ++k;
    if (k == arcs.size()) fail_at(file, r, fmt::format("remove: the base rule's {} side has no arc '{}'", which, text));
    dropped[k] = true;
  }
  YAML::Node seq(YAML::NodeType::Sequence);
  for (std::size_t k = 0; k < arcs.size(); ++k)
    if (!dropped[k]) seq.push_back(arcs[k]);
  for (const auto& a : part("add")) seq.push_back(a);
  side["arcs"] = seq;
  return side;
}

// The parameter orbit type of a Jerboa scheme (its L nodes map to orbit
// types): the label of its first hook, which must have no '_' (000 Sec.
// 4.3.2). nullopt for a rule in the (W,D) notation.
std::optional<OrbitType> jerboa_parameter(const std::string& file, const YAML::Node& left, const YAML::Node& rule) {
  const auto nodes = left["nodes"];
  if (!nodes || !nodes.IsMap()) return std::nullopt;
  const auto hooks = rule["hooks"];
  if (!hooks || !hooks.IsSequence() || hooks.size() == 0)
    fail_at(file, rule, "a Jerboa scheme (nodes labeled by orbit types) needs a hook: its label is the parameter orbit type");
  const auto hook = yaml::as_string(file, hooks[0], "hook");
  const auto label = nodes[hook];
  if (!label) fail_at(file, hooks[0], fmt::format("hook '{}' is not a node of left", hook));
  OrbitType t;
  try {
    t = parse_orbit_type(yaml::as_string(file, label, "orbit type"));
  } catch (const ValueError& e) {
    fail_at(file, label, e.what());
  }
  if (std::find(t.begin(), t.end(), std::nullopt) != t.end())
    fail_at(file, label, fmt::format("the hook's label {} is the parameter orbit type and cannot contain '_'", orbit_type_str(t)));
  return t;
}

// Builds one rule (a catalog entry or a variant `v` of the entry `n`) and
// appends it; `v` holds the name, note and verdict, `n` the hooks.
void add_rule(Catalog& c, const std::string& file, const YAML::Node& v, const std::string& name, const Model& model, const YAML::Node& left_node,
              const YAML::Node& right_node, const YAML::Node& n, const RuleTerms* base_terms = nullptr) {
  if (c.find_rule(name)) fail_at(file, v["name"] ? v["name"] : v, fmt::format("rule '{}' is declared twice", name));
  const auto parameter = jerboa_parameter(file, left_node, n);
  const OrbitType* jerboa = parameter ? &*parameter : nullptr;
  if (!jerboa && right_node["nodes"] && right_node["nodes"].IsMap())
    fail_at(file, right_node["nodes"], "right uses Jerboa node labels but left does not");
  ArcWords words;
  std::optional<JerboaLabels> labels;
  if (jerboa) labels.emplace().parameter = *jerboa;
  TopoGraph left = read_side(file, left_node, "left", &model, &words.left, &words.scheme, jerboa, labels ? &labels->left : nullptr);
  TopoGraph right = read_side(file, right_node, "right", &model, &words.right, &words.scheme, jerboa, labels ? &labels->right : nullptr);
  if (!words.scheme) words = ArcWords{};
  std::vector<std::string> hooks;
  const auto hn = n["hooks"];
  if (hn) {
    yaml::expect_sequence(file, hn, "hooks");
    for (const auto& h : hn) hooks.push_back(yaml::as_string(file, h, "hook"));
  }
  std::optional<Rule> rule;
  try {
    rule.emplace(name, model, std::move(left), std::move(right), std::move(hooks), words.left, words.right);
  } catch (const ValueError& e) {
    fail_at(file, hn ? hn : v, fmt::format("rule '{}': {}", name, e.what()));
  }
  CatalogRule cr{{std::move(*rule), words, std::move(labels), {}, {}, std::nullopt},
                 v["note"] ? yaml::as_string(file, v["note"], "note") : "",
                 {},
                 where(file, v),
                 {},
                 {},
                 std::nullopt,
                 {}};
  if (v["labels"] || v["parameters"] || v["instantiation"] || v["embeddings"] || base_terms) {
    if (c.signatures.size() != c.embeddings.size())
      fail_at(file, v["labels"] ? v["labels"] : v, "labels need typed embeddings: declare each under 'embeddings' with a type (point2, color, ...)");
    cr.terms = read_rule_terms(file, v, cr.rule, c.signatures, base_terms);
  }
  if (const auto ex = n["expressions"]) {
    // {node of R: {embedding: code}}
    yaml::expect_map(file, ex, "expressions");
    for (const auto& kv : ex) {
      const auto node = yaml::as_string(file, kv.first, "node name");
      if (!cr.rule.right().find(node)) fail_at(file, kv.first, fmt::format("expressions: '{}' is not a node of right", node));
      yaml::expect_map(file, kv.second, "expressions of a node");
      for (const auto& e : kv.second) {
        const auto ebd = yaml::as_string(file, e.first, "embedding name");
        if (std::none_of(c.embeddings.begin(), c.embeddings.end(), [&](const EmbeddingDecl& d) { return d.name == ebd; }))
          fail_at(file, e.first, fmt::format("expressions: no embedding named '{}' under 'embeddings'", ebd));
        // The code of a modeler's export: read when the rule's labels carry
        // its term (the export writes both), opaque otherwise.
        NodeExpression x{node, ebd, yaml::as_string(file, e.second, "expression"), where(file, e.second), std::nullopt, {}, where(file, e.second)};
        if (const Term* t = cr.terms ? cr.terms->find('R', node, ebd) : nullptr)
          x.term = *t;
        else
          x.reason = "kept as code in a YAML catalog without its term (labels): dartcheck reads Jerboa's Java from a .jme";
        cr.expressions.push_back(std::move(x));
      }
    }
  }
  if (const auto cv = n["caveats"]) {
    yaml::expect_sequence(file, cv, "caveats");
    for (const auto& x : cv) cr.caveats.push_back(yaml::as_string(file, x, "caveat"));
  }
  if (const auto vn = v["verdict"]) {
    // "consistent", or the list of the conditions that must fail.
    cr.verdict_location = where(file, vn);
    if (vn.IsScalar() && vn.Scalar() == "consistent") {
      cr.expected_failures.emplace();
    } else {
      if (!vn.IsSequence()) fail_at(file, vn, "verdict: expected 'consistent' or a list of failing conditions such as [\"C(0,2)\"]");
      cr.expected_failures.emplace();
      for (const auto& f : vn) cr.expected_failures->push_back(yaml::as_string(file, f, "failing condition"));
    }
  }
  c.rules.push_back(std::move(cr));
}

}  // namespace

static Catalog read_yaml_catalog(const std::string& file);

Catalog read_catalog(const std::string& file) {
  if (file.ends_with(".jme")) return read_jme(file);
  try {
    return read_yaml_catalog(file);
  } catch (const YAML::Exception& e) {
    // A shape the reader did not foresee: still an error at its position.
    throw yaml_input_error(file, e);
  }
}

// The catalog's embeddings: [{name, type, orbit: "<1,2,3>"}].
static void read_embedding_decls(const std::string& file, const YAML::Node& ebds, Catalog& c) {
  yaml::expect_sequence(file, ebds, "embeddings");
  for (const auto& e : ebds) {
    yaml::expect_map(file, e, "embedding");
    yaml::allow_keys(file, e, {"name", "type", "orbit"});
    EmbeddingDecl d{yaml::as_string(file, yaml::require(file, e, "name"), "embedding name"),
                    e["type"] ? yaml::as_string(file, e["type"], "embedding type") : "",
                    {},
                    where(file, e)};
    const auto orbit = yaml::require(file, e, "orbit");
    try {
      for (const auto& k : parse_orbit_type(yaml::as_string(file, orbit, "orbit type"))) {
        if (!k) throw ValueError("an embedding's orbit type cannot contain '_'");
        d.orbit.push_back(*k);
      }
    } catch (const ValueError& x) {
      fail_at(file, orbit, fmt::format("embedding '{}': {}", d.name, x.what()));
    }
    // A Jerboa class (a modeler's export) has the reading the .jme gives it.
    if (const auto t = jerboa_value_type(d.type) ? jerboa_value_type(d.type) : type_by_name(d.type)) c.signatures.push_back({d.name, *t, d.orbit});
    c.embeddings.push_back(std::move(d));
  }
}

// Rules an import could not represent: [{name, why}].
static void read_skipped(const std::string& file, const YAML::Node& sk, Catalog& c) {
  yaml::expect_sequence(file, sk, "skipped");
  for (const auto& x : sk) {
    yaml::expect_map(file, x, "skipped rule");
    c.skipped.push_back(
        {yaml::as_string(file, yaml::require(file, x, "name"), "name"), yaml::as_string(file, yaml::require(file, x, "why"), "why"), where(file, x)});
  }
}

namespace {

// The maps and rules of a catalog, each read on its own: an error in one is
// kept and the next is read, up to `max_errors` (the rest of the file then
// unread).
class EntryReader {
 public:
  EntryReader(const std::string& file, const YAML::Node& root, Catalog& c) : file_(file), c_(c) {
    if (const auto models = root["models"]) {
      yaml::expect_map(file, models, "models");
      for (const auto& kv : models) custom_.push_back(yaml::custom_model(file, kv.first.Scalar(), kv.second));
    }
    if (root["model"]) default_model_ = read_model(file, root["model"], custom_);
  }

  template <class Entry, class Read>
  void each(const Entry& entry, const Read& read) {
    if (errors_.size() >= max_errors) return;
    try {
      read(entry);
    } catch (const InputError& e) {
      errors_.push_back(e);
    } catch (const YAML::Exception& e) {
      errors_.push_back(yaml_input_error(file_, e));
    }
  }

  void map(const YAML::Node& name, const YAML::Node& n) {
    failed_maps_.insert(name.Scalar());
    yaml::expect_map(file_, n, "map");
    yaml::allow_keys(file_, n, {"model", "darts", "links", "pred", "shape", "file"});
    MapSource m{name.Scalar(), model_of(n), std::nullopt, {}, {}, where(file_, name)};
    if (c_.find_map(m.name)) fail_at(file_, name, fmt::format("map '{}' is declared twice", m.name));
    const int forms = (n["darts"] ? 1 : 0) + (n["shape"] ? 1 : 0) + (n["file"] ? 1 : 0);
    if (forms != 1) fail_at(file_, n, "a map needs exactly one of 'darts' + 'links', 'shape', 'file'");
    if (n["shape"]) m.shape = yaml::as_string(file_, n["shape"], "shape");
    if (n["file"]) {
      m.mesh = yaml::as_string(file_, n["file"], "file");
      if (!m.mesh.empty() && m.mesh.front() != '/') {
        const auto slash = file_.rfind('/');
        if (slash != std::string::npos) m.mesh = file_.substr(0, slash + 1) + m.mesh;
      }
    }
    if (n["darts"]) m.map = read_map_links(file_, n, m.model);
    failed_maps_.erase(m.name);
    c_.maps.push_back(std::move(m));
  }

  void rule(const YAML::Node& n) {
    yaml::expect_map(file_, n, "rule");
    yaml::allow_keys(file_, n,
                     {"name", "model", "note", "hooks", "left", "right", "examples", "verdict", "variants", "expressions", "caveats", "labels",
                      "parameters", "instantiation", "embeddings"});
    const auto name = yaml::as_string(file_, yaml::require(file_, n, "name"), "name");
    const Model model = model_of(n);
    const auto left = yaml::require(file_, n, "left"), right = yaml::require(file_, n, "right");
    yaml::expect_map(file_, left, "left");
    yaml::expect_map(file_, right, "right");
    add_rule(c_, file_, n, name, model, left, right, n);
    if (const auto ex = n["examples"]) examples(name, ex);
    if (const auto vs = n["variants"]) {
      // Broken (or alternative) variants: the base rule with arcs removed
      // or added, each with its own verdict.
      yaml::expect_sequence(file_, vs, "variants");
      for (const auto& v : vs) {
        yaml::expect_map(file_, v, "variant");
        yaml::allow_keys(file_, v, {"name", "note", "verdict", "remove", "add", "nodes", "labels", "parameters", "instantiation", "embeddings"});
        const auto vname = name + "/" + yaml::as_string(file_, yaml::require(file_, v, "name"), "variant name");
        const auto* base_rule = c_.find_rule(name);
        const std::optional<RuleTerms> base_terms = base_rule->terms;
        add_rule(c_, file_, v, vname, model, edit_side(file_, left, v, "left"), edit_side(file_, right, v, "right"), n,
                 base_terms ? &*base_terms : nullptr);
      }
    }
  }

  // One error as itself, several as InputErrors.
  void throw_errors() {
    if (errors_.size() == 1) throw errors_.front();
    if (!errors_.empty()) {
      const bool stopped = errors_.size() >= max_errors;
      throw InputErrors(std::move(errors_), stopped);
    }
  }

 private:
  static constexpr std::size_t max_errors = 20;

  Model model_of(const YAML::Node& n) const {
    if (n["model"]) return read_model(file_, n["model"], custom_);
    if (!default_model_) fail_at(file_, n, "missing key 'model' (and the catalog sets no default model)");
    return *default_model_;
  }

  // The examples of the rule just added, each naming a map of the catalog.
  void examples(const std::string& name, const YAML::Node& ex) {
    auto& base = c_.rules.back();
    yaml::expect_sequence(file_, ex, "examples");
    for (const auto& e : ex) {
      base.examples.push_back(read_example(file_, e));
      if (!c_.find_map(base.examples.back().map) && !failed_maps_.count(base.examples.back().map))
        fail_at(file_, e["map"], fmt::format("example of rule '{}': no map named '{}' under 'maps'", name, base.examples.back().map));
      if (const auto& iso = base.examples.back().isomorphic_to; !iso.empty() && !c_.find_map(iso))
        fail_at(file_, e["isomorphic-to"], fmt::format("example of rule '{}': isomorphic-to names '{}', which is not under 'maps'", name, iso));
    }
  }

  const std::string& file_;
  Catalog& c_;
  std::vector<Model> custom_;
  std::optional<Model> default_model_;
  std::vector<InputError> errors_;
  std::set<std::string> failed_maps_;  // their examples' "no map named" would only repeat the error
};

}  // namespace

static Catalog read_yaml_catalog(const std::string& file) {
  const YAML::Node root = load_yaml_file(file);
  Catalog c;
  c.file = file;
  if (!root.IsMap()) throw InputError(file, 1, 1, "a catalog is a mapping with keys models, maps, rules");
  yaml::allow_keys(file, root, {"models", "maps", "rules", "model", "description", "modeler", "embeddings", "skipped"});
  if (root["modeler"]) c.modeler = yaml::as_string(file, root["modeler"], "modeler");
  if (const auto ebds = root["embeddings"]) read_embedding_decls(file, ebds, c);
  if (const auto sk = root["skipped"]) read_skipped(file, sk, c);
  EntryReader entries(file, root, c);
  if (const auto maps = root["maps"]) {
    yaml::expect_map(file, maps, "maps");
    for (const auto& kv : maps) entries.each(kv, [&](const auto& e) { entries.map(e.first, e.second); });
  }
  if (const auto rules = root["rules"]) {
    yaml::expect_sequence(file, rules, "rules");
    for (const auto& n : rules) entries.each(n, [&](const YAML::Node& e) { entries.rule(e); });
  }
  entries.throw_errors();
  return c;
}

}  // namespace dartcheck
