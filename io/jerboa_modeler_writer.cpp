#include "io/jerboa_modeler_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <ostream>
#include <pugixml.hpp>
#include <stdexcept>

namespace dartcheck {
namespace {

std::string positional(const OrbitType& t) {
  std::string s;
  for (std::size_t k = 0; k < t.size(); ++k) s += fmt::format("{}{}", k ? "," : "", t[k] ? *t[k] : -1);
  return s;
}

// Throws std::invalid_argument for an explicit arc without its reverse.
void write_side(pugi::xml_node parent, const char* tag, const TopoGraph& g, const std::vector<ConjWord>& words, const std::vector<OrbitType>& labels,
                const std::vector<NodeId>& hooks) {
  auto side = parent.append_child(tag);
  auto nodes = side.append_child("nodes");
  for (NodeId v = 0; v < g.node_count(); ++v) {
    auto n = nodes.append_child("node");
    n.append_attribute("name") = g.name(v).c_str();
    n.append_attribute("orbit") = positional(labels[v]).c_str();
    const bool hook = std::find(hooks.begin(), hooks.end(), v) != hooks.end();
    n.append_attribute("kind") = hook ? "HOOK" : "SIMPLE";
  }
  auto arcs = side.append_child("arcs");
  std::vector<bool> done(g.arc_count(), false);
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    if (done[e] || !arc_word(words, e).empty()) continue;  // implicit arcs are in the labels
    done[e] = true;
    const auto& a = g.arc(e);
    if (a.source == a.target) {
      auto x = arcs.append_child("arcloop");
      x.append_attribute("dim") = a.label;
      x.append_attribute("node") = g.name(a.source).c_str();
      continue;
    }
    bool paired = false;
    for (ArcId f = e + 1; f < g.arc_count() && !paired; ++f) {
      const auto& b = g.arc(f);
      if (!done[f] && b.label == a.label && b.source == a.target && b.target == a.source && arc_word(words, f).empty()) done[f] = paired = true;
    }
    if (!paired)
      throw std::invalid_argument(fmt::format("the arc {} -{}-> {} of <{}> has no reverse: Jerboa's arcs are non-oriented", g.name(a.source), a.label,
                                              g.name(a.target), tag));
    auto x = arcs.append_child("arc");
    x.append_attribute("dim") = a.label;
    x.append_attribute("a") = g.name(a.source).c_str();
    x.append_attribute("b") = g.name(a.target).c_str();
  }
}

}  // namespace

void write_jme(std::ostream& out, const std::string& modeler, int dimension, const std::vector<const Operation*>& rules) {
  pugi::xml_document doc;
  auto root = doc.append_child("jerboamodelereditor");
  auto m = root.append_child("modeler");
  m.append_attribute("name") = modeler.c_str();
  m.append_attribute("dimension") = dimension;
  auto list = m.append_child("rules");
  for (const Operation* op : rules) {
    if (!op->jerboa) throw std::invalid_argument(fmt::format("rule {} has no Jerboa labels: it cannot be written as a .jme rule", op->rule.name()));
    auto r = list.append_child("rule");
    r.append_attribute("name") = op->rule.name().c_str();
    write_side(r, "left", op->rule.left(), op->words.left, op->jerboa->left, op->rule.hooks());
    write_side(r, "right", op->rule.right(), op->words.right, op->jerboa->right, {});
  }
  doc.save(out, "  ");
}

}  // namespace dartcheck
