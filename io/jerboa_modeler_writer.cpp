#include "io/jerboa_modeler_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <pugixml.hpp>
#include <stdexcept>

#include "core/error.hpp"
#include "core/input_error.hpp"

namespace dartcheck {
namespace {

std::string positional(const OrbitType& t) {
  std::string s;
  for (std::size_t k = 0; k < t.size(); ++k) s += fmt::format("{}{}", k ? "," : "", t[k] ? *t[k] : -1);
  return s;
}

// Throws ValueError for an explicit arc without its reverse.
// Where the editor draws node `k` of a side: rows of six, so a preserved
// node (the same index on both sides for inferred rules) sits at the same
// place in L and R.
std::pair<int, int> position(std::size_t k) { return {100 + 150 * static_cast<int>(k % 6), 120 + 120 * static_cast<int>(k / 6)}; }

void text_child(pugi::xml_node parent, const char* tag) { parent.append_child(tag).append_child(pugi::node_pcdata); }

void write_side(pugi::xml_node parent, const char* tag, const TopoGraph& g, const std::vector<ConjWord>& words, const std::vector<OrbitType>& labels,
                const std::vector<NodeId>& hooks) {
  auto side = parent.append_child(tag);
  auto nodes = side.append_child("nodes");
  nodes.append_attribute("count") = g.node_count();
  for (NodeId v = 0; v < g.node_count(); ++v) {
    auto n = nodes.append_child("node");
    n.append_attribute("name") = g.name(v).c_str();
    const auto [x, y] = position(v);
    n.append_attribute("x") = x;
    n.append_attribute("y") = y;
    n.append_attribute("orbit") = positional(labels[v]).c_str();
    const bool hook = std::find(hooks.begin(), hooks.end(), v) != hooks.end();
    n.append_attribute("kind") = hook ? "HOOK" : "SIMPLE";
    n.append_attribute("multiplicity") = "{1}";
    n.append_attribute("color") = "255;255;255;0";
  }
  auto arcs = side.append_child("arcs");
  std::size_t count = 0;
  std::vector<bool> done(g.arc_count(), false);
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    if (done[e] || !arc_word(words, e).empty()) continue;  // implicit arcs are in the labels
    done[e] = true;
    const auto& a = g.arc(e);
    if (a.source == a.target) {
      auto x = arcs.append_child("arcloop");
      x.append_attribute("dim") = a.label;
      x.append_attribute("node") = g.name(a.source).c_str();
      x.append_attribute("angle") = 1.5707963267948966 * a.label;  // one side of the node per dimension
      ++count;
      continue;
    }
    bool paired = false;
    for (ArcId f = e + 1; f < g.arc_count() && !paired; ++f) {
      const auto& b = g.arc(f);
      if (!done[f] && b.label == a.label && b.source == a.target && b.target == a.source && arc_word(words, f).empty()) done[f] = paired = true;
    }
    if (!paired)
      throw ValueError(fmt::format("the arc {} -{}-> {} of <{}> has no reverse: Jerboa's arcs are non-oriented", g.name(a.source), a.label,
                                   g.name(a.target), tag));
    auto x = arcs.append_child("arc");
    x.append_attribute("dim") = a.label;
    x.append_attribute("a") = g.name(a.source).c_str();
    x.append_attribute("b") = g.name(a.target).c_str();
    x.append_attribute("size") = 0;
    ++count;
  }
  arcs.prepend_attribute("count") = count;
}

}  // namespace

std::optional<std::string> xml_name_problem(std::string_view name) {
  for (std::size_t k = 0; k < name.size();) {
    const auto c = static_cast<unsigned char>(name[k]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') return fmt::format("a control character (\\x{:02x})", c);
    if (c < 0x80) {
      ++k;
      continue;
    }
    // The length of a UTF-8 sequence and its code point, overlongs and surrogates refused.
    const int length = c >= 0xf0 && c < 0xf5 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
    if (length == 0 || k + static_cast<std::size_t>(length) > name.size()) return std::string("invalid UTF-8");
    std::uint32_t cp = c & (0xffU >> (length + 1));
    for (int j = 1; j < length; ++j) {
      const auto b = static_cast<unsigned char>(name[k + static_cast<std::size_t>(j)]);
      if ((b & 0xc0) != 0x80) return std::string("invalid UTF-8");
      cp = (cp << 6) | (b & 0x3fU);
    }
    if ((length == 3 && cp < 0x800) || (length == 4 && (cp < 0x10000 || cp > 0x10ffff)) || (cp >= 0xd800 && cp <= 0xdfff))
      return std::string("invalid UTF-8");
    if (cp == 0xfffe || cp == 0xffff) return fmt::format("the non-character U+{:04X}", cp);
    k += static_cast<std::size_t>(length);
  }
  return std::nullopt;
}

void write_jme(std::ostream& out, const std::string& modeler, int dimension, const std::vector<const Operation*>& rules) {
  const auto check_name = [](std::string_view what, const std::string& name) {
    if (const auto problem = xml_name_problem(name))
      throw ValueError(fmt::format("{} '{}' cannot be written in a .jme (XML 1.0): it holds {}", what, printable(name), *problem));
  };
  check_name("modeler name", modeler);
  for (const Operation* op : rules) {
    check_name("rule name", op->rule.name());
    for (const TopoGraph* side : {&op->rule.left(), &op->rule.right()})
      for (std::size_t v = 0; v < side->node_count(); ++v) check_name("node name", side->name(static_cast<NodeId>(v)));
  }
  // The elements and attributes Jerboa's editor writes (compare
  // ../shared/jerboa-samples/JerboaRebuilt2.jme), so the file opens there
  // as a modeler, not only in dartcheck's reader.
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  decl.append_attribute("standalone") = "yes";
  auto root = doc.append_child("jerboamodelereditor");
  root.append_attribute("version") = 1;
  auto m = root.append_child("modeler");
  m.append_attribute("name") = modeler.c_str();
  m.append_attribute("module") = "";
  m.append_attribute("dimension") = dimension;
  m.append_attribute("destDir") = ".";
  m.append_attribute("projectDir") = ".";
  text_child(m, "comment");
  text_child(m, "header");
  m.append_child("generationType").append_child(pugi::node_pcdata).set_value("java");
  m.append_child("embeddings").append_attribute("count") = 0;  // inferred rules are topological
  auto list = m.append_child("rules");
  list.append_attribute("count") = rules.size();
  for (const Operation* op : rules) {
    if (!op->jerboa) throw ValueError(fmt::format("rule {} has no Jerboa labels: it cannot be written as a .jme rule", op->rule.name()));
    auto r = list.append_child("rule");
    r.append_attribute("name") = op->rule.name().c_str();
    for (const char* a : {"module", "category"}) r.append_attribute(a) = "";
    r.append_attribute("shape") = "CIRCLE";
    r.append_attribute("magnetic") = "false";
    r.append_attribute("showgrid") = "false";
    r.append_attribute("gridsize") = "MEDIUM";
    for (const char* t : {"header", "precondition", "comment"}) text_child(r, t);
    write_side(r, "left", op->rule.left(), op->words.left, op->jerboa->left, op->rule.hooks());
    write_side(r, "right", op->rule.right(), op->words.right, op->jerboa->right, {});
    for (const char* t : {"preprocess", "postprocess", "midprocess"}) text_child(r, t);
    r.append_child("paramsebd");
    auto params = r.append_child("paramstopo");
    for (std::size_t k = 0; k < op->rule.hooks().size(); ++k) {
      auto p = params.append_child("paramtopo");
      p.append_attribute("name") = op->rule.left().name(op->rule.hooks()[k]).c_str();
      p.append_attribute("order") = k;
    }
  }
  m.append_child("inferrules").append_attribute("count") = 0;
  doc.save(out, "    ", pugi::format_default, pugi::encoding_utf8);
}

}  // namespace dartcheck
