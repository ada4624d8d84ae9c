#include "io/catalog_writer.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "io/map_io.hpp"

namespace dartcheck {
namespace {

// The side's arcs in catalog notation: a non-oriented pair (or a loop) as
// "a -d- b", anything else as "a -d-> b". A Jerboa side lists its explicit
// arcs only: the orbit types on its nodes stand for the implicit loops.
std::vector<std::string> arcs_of(const TopoGraph& g, const std::vector<ConjWord>& words, bool jerboa, const Model& model) {
  std::vector<std::string> out;
  std::vector<bool> done(g.arc_count(), false);
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    if (done[e] || (jerboa && !arc_word(words, e).empty())) continue;
    done[e] = true;
    const auto& a = g.arc(e);
    bool pair = a.source == a.target && !model.is_oriented(a.label);
    for (ArcId f = e + 1; f < g.arc_count() && !pair && !model.is_oriented(a.label); ++f) {
      const auto& b = g.arc(f);
      if (!done[f] && b.label == a.label && b.source == a.target && b.target == a.source && arc_word(words, f) == arc_word(words, e))
        done[f] = pair = true;
    }
    out.push_back(fmt::format("{} -{}{} {}", g.name(a.source), a.label, pair ? "-" : "->", g.name(a.target)));
  }
  return out;
}

void side(YAML::Emitter& y, const TopoGraph& g, const std::vector<ConjWord>& words, const std::vector<OrbitType>* labels, const Model& model) {
  y << YAML::BeginMap << YAML::Key << "nodes";
  if (labels) {
    y << YAML::Flow << YAML::BeginMap;
    for (NodeId v = 0; v < g.node_count(); ++v) y << YAML::Key << g.name(v) << YAML::Value << YAML::DoubleQuoted << orbit_type_str((*labels)[v]);
    y << YAML::EndMap;
  } else {
    y << YAML::Flow << YAML::BeginSeq;
    for (NodeId v = 0; v < g.node_count(); ++v) y << g.name(v);
    y << YAML::EndSeq;
  }
  const auto arcs = arcs_of(g, words, labels != nullptr, model);
  if (!arcs.empty()) {
    y << YAML::Key << "arcs" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const auto& a : arcs) y << YAML::DoubleQuoted << a;
    y << YAML::EndSeq;
  }
  y << YAML::EndMap;
}

}  // namespace

namespace {

// A value as a closed term the term parser reads back to the same value.
std::string value_term(const Value& v) {
  switch (v.type) {
    case ValueType::real: {
      std::string x = fmt::format("{}", v.x[0]);
      if (x.find_first_of(".eEn") == std::string::npos) x += ".0";  // a real, not an integer
      return x;
    }
    case ValueType::point2:
    case ValueType::vector2:
      return fmt::format("{}({}, {})", name_of(v.type), value_term(Value::real(v.x[0])), value_term(Value::real(v.x[1])));
    case ValueType::point3:
    case ValueType::vector3:
    case ValueType::color:
      return fmt::format("{}({}, {}, {})", name_of(v.type), value_term(Value::real(v.x[0])), value_term(Value::real(v.x[1])),
                         value_term(Value::real(v.x[2])));
    default:
      return v.str();
  }
}

// The terms of a Jerboa rule whose expressions were read (labels, its
// parameters, extended instantiation), so that the export checks as the
// .jme does; its expressions' Java stays beside them.
void write_terms(YAML::Emitter& y, const RuleTerms& t) {
  y << YAML::Key << "labels" << YAML::Value << YAML::BeginMap;
  for (const char side : {'L', 'R'}) {
    const auto& labels = side == 'L' ? t.left : t.right;
    if (labels.empty()) continue;
    y << YAML::Key << (side == 'L' ? "left" : "right") << YAML::Value << YAML::BeginMap;
    std::vector<std::string> nodes;
    for (const auto& x : labels)
      if (std::find(nodes.begin(), nodes.end(), x.node) == nodes.end()) nodes.push_back(x.node);
    for (const auto& n : nodes) {
      y << YAML::Key << n << YAML::Value << YAML::Flow << YAML::BeginMap;
      for (const auto& x : labels)
        if (x.node == n) y << YAML::Key << x.embedding << YAML::Value << YAML::DoubleQuoted << x.term.str();
      y << YAML::EndMap;
    }
    y << YAML::EndMap;
  }
  y << YAML::EndMap;
  if (!t.parameters.empty()) {
    y << YAML::Key << "parameters" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& [name, v] : t.parameters) y << YAML::Key << name << YAML::Value << YAML::DoubleQuoted << value_term(v);
    y << YAML::EndMap;
  }
  y << YAML::Key << "instantiation" << YAML::Value << (t.instantiation == Instantiation::extended ? "extended" : "direct");
}

// Models that are not presets are declared, so the catalog reads back.
void write_custom_models(YAML::Emitter& y, const Catalog& c) {
  std::vector<const Model*> models, custom;
  for (const auto& r : c.rules) models.push_back(&r.rule.model());
  for (const auto& m : c.maps)
    if (m.map) models.push_back(&m.map->model());
  for (const Model* model : models) {
    const Model& m = *model;
    const auto preset = Model::by_name(m.name);
    if ((!preset || !(*preset == m)) && std::none_of(custom.begin(), custom.end(), [&](const Model* x) { return x->name == m.name; }))
      custom.push_back(&m);
  }
  if (custom.empty()) return;
  y << YAML::Key << "models" << YAML::Value << YAML::BeginMap;
  for (const Model* m : custom) {
    const auto dims_of = [&](DimSet s) {
      std::vector<Dim> out;
      for (Dim i : m->dims)
        if (has_dim(s, i)) out.push_back(i);
      return out;
    };
    y << YAML::Key << m->name << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "dims" << YAML::Value << m->dims << YAML::Key
      << "non_oriented" << YAML::Value << dims_of(m->non_oriented) << YAML::Key << "exchangeable" << YAML::Value << YAML::BeginSeq;
    for (const auto& [i, j] : m->exchangeable) y << YAML::Flow << YAML::BeginSeq << i << j << YAML::EndSeq;
    y << YAML::EndSeq;
    if (m->partial) y << YAML::Key << "partial" << YAML::Value << dims_of(m->partial);
    if (m->loop_free) y << YAML::Key << "loop_free" << YAML::Value << true;
    y << YAML::EndMap;
  }
  y << YAML::EndMap;
}

// The maps given by their links (shapes and mesh files are not written).
void write_maps(YAML::Emitter& y, const Catalog& c) {
  if (std::none_of(c.maps.begin(), c.maps.end(), [](const MapSource& m) { return m.map.has_value(); })) return;
  y << YAML::Key << "maps" << YAML::Value << YAML::BeginMap;
  for (const auto& m : c.maps)
    if (m.map) {
      // A map file names a custom model in full; in a catalog the
      // `models` section above declares it, and maps name it.
      YAML::Node node = YAML::Load(map_to_yaml(*m.map));
      node["model"] = m.map->model().name;
      y << YAML::Key << m.name << YAML::Value << node;
    }
  y << YAML::EndMap;
}

void write_embeddings_and_skipped(YAML::Emitter& y, const Catalog& c) {
  if (!c.embeddings.empty()) {
    y << YAML::Key << "embeddings" << YAML::Value << YAML::BeginSeq;
    for (const auto& e : c.embeddings)
      y << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << e.name << YAML::Key << "type" << YAML::Value << e.type << YAML::Key
        << "orbit" << YAML::Value << YAML::DoubleQuoted << fmt::format("<{}>", fmt::join(e.orbit, ",")) << YAML::EndMap;
    y << YAML::EndSeq;
  }
  if (!c.skipped.empty()) {
    y << YAML::Key << "skipped" << YAML::Value << YAML::BeginSeq;
    for (const auto& s : c.skipped)
      y << YAML::BeginMap << YAML::Key << "name" << YAML::Value << s.name << YAML::Key << "why" << YAML::Value << s.why << YAML::EndMap;
    y << YAML::EndSeq;
  }
}

// A Jerboa rule's expressions, grouped by node in the order the nodes
// first carry one.
void write_expressions(YAML::Emitter& y, const std::vector<NodeExpression>& expressions) {
  y << YAML::Key << "expressions" << YAML::Value << YAML::BeginMap;
  std::vector<std::string> nodes;
  for (const auto& x : expressions)
    if (std::find(nodes.begin(), nodes.end(), x.node) == nodes.end()) nodes.push_back(x.node);
  for (const auto& n : nodes) {
    y << YAML::Key << n << YAML::Value << YAML::BeginMap;
    for (const auto& x : expressions)
      if (x.node == n) y << YAML::Key << x.embedding << YAML::Value << YAML::DoubleQuoted << x.code;
    y << YAML::EndMap;
  }
  y << YAML::EndMap;
}

void write_examples(YAML::Emitter& y, const std::vector<Example>& examples) {
  y << YAML::Key << "examples" << YAML::Value << YAML::BeginSeq;
  for (const auto& e : examples) {
    y << YAML::Flow << YAML::BeginMap << YAML::Key << "map" << YAML::Value << e.map << YAML::Key << "hooks" << YAML::Value << YAML::Flow
      << YAML::BeginSeq;
    for (Dart h : e.hooks) y << h;
    y << YAML::EndSeq << YAML::Key << "expect" << YAML::Value << e.expect;
    if (e.cells) {
      y << YAML::Key << "cells" << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (auto x : *e.cells) y << x;
      y << YAML::EndSeq;
    }
    if (!e.isomorphic_to.empty()) y << YAML::Key << "isomorphic-to" << YAML::Value << e.isomorphic_to;
    y << YAML::EndMap;
  }
  y << YAML::EndSeq;
}

void write_rule(YAML::Emitter& y, const CatalogRule& r) {
  const Rule& rule = r.rule;
  y << YAML::BeginMap << YAML::Key << "name" << YAML::Value << rule.name() << YAML::Key << "model" << YAML::Value << rule.model().name;
  if (!r.note.empty()) y << YAML::Key << "note" << YAML::Value << r.note;
  if (r.expected_failures) {
    y << YAML::Key << "verdict" << YAML::Value;
    if (r.expected_failures->empty()) {
      y << "consistent";
    } else {
      y << YAML::Flow << YAML::BeginSeq;
      for (const auto& f : *r.expected_failures) y << YAML::DoubleQuoted << f;
      y << YAML::EndSeq;
    }
  }
  if (!rule.hooks().empty()) {
    y << YAML::Key << "hooks" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (NodeId h : rule.hooks()) y << rule.left().name(h);
    y << YAML::EndSeq;
  }
  y << YAML::Key << "left" << YAML::Value;
  side(y, rule.left(), r.words.left, r.jerboa ? &r.jerboa->left : nullptr, rule.model());
  y << YAML::Key << "right" << YAML::Value;
  side(y, rule.right(), r.words.right, r.jerboa ? &r.jerboa->right : nullptr, rule.model());
  if (!r.expressions.empty()) write_expressions(y, r.expressions);
  if (r.terms && !r.expressions.empty()) write_terms(y, *r.terms);
  if (!r.examples.empty()) write_examples(y, r.examples);
  if (!r.caveats.empty()) {
    y << YAML::Key << "caveats" << YAML::Value << YAML::BeginSeq;
    for (const auto& x : r.caveats) y << x;
    y << YAML::EndSeq;
  }
  y << YAML::EndMap;
}

}  // namespace

std::string catalog_yaml(const Catalog& c, const std::string& description) {
  YAML::Emitter y;
  y << YAML::BeginMap;
  if (!c.modeler.empty()) y << YAML::Key << "modeler" << YAML::Value << c.modeler;
  y << YAML::Key << "description" << YAML::Value << (description.empty() ? fmt::format("converted by dartcheck from {}", c.file) : description);
  write_custom_models(y, c);
  write_maps(y, c);
  write_embeddings_and_skipped(y, c);
  y << YAML::Key << "rules" << YAML::Value << YAML::BeginSeq;
  for (const auto& r : c.rules) write_rule(y, r);
  y << YAML::EndSeq << YAML::EndMap;
  return std::string(y.c_str()) + "\n";
}

}  // namespace dartcheck
