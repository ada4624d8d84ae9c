#include "reports/rule_dot.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "core/terminal.hpp"
#include "reports/dot_text.hpp"
#include "reports/render.hpp"

namespace dartcheck::reports {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

// The steps (source, label, target) of a witness arc or path as the
// checker writes it: "a -1-> b", "c -(1,2)-> c -0-> d" (a path may write
// an ε-word label as the bare dimension).
struct Step {
  std::string source, label, target;
};
std::vector<Step> steps(const std::string& text) {
  std::vector<Step> out;
  std::size_t at = text.find(" -");
  std::string from = text.substr(0, at);
  while (at != std::string::npos) {
    const std::size_t arrow = text.find("-> ", at + 2);
    if (arrow == std::string::npos) break;
    const std::string label = text.substr(at + 2, arrow - at - 2);
    const std::size_t next = text.find(" -", arrow + 3);
    const std::string to = text.substr(arrow + 3, next == std::string::npos ? std::string::npos : next - arrow - 3);
    out.push_back({from, label, to});
    from = to;
    at = next;
  }
  return out;
}

// One side of the rule, as a cluster.
// A node's label: its name, its orbit type (Jerboa-style schemes) and its
// terms. Plain text without terms, an HTML-like label with them.
std::string node_label(const std::string& name, const std::string& type, const TermLines& terms, bool left, bool lit) {
  std::vector<const NodeTerm*> lines;
  if (terms.terms)
    for (const NodeTerm& t : left ? terms.terms->left : terms.terms->right)
      if (t.node == name) lines.push_back(&t);
  if (lines.empty()) return fmt::format("label={}", quote(type.empty() ? name : name + "\n" + type));
  std::string html = html_text(name);
  if (!type.empty()) html += fmt::format("<br/><font point-size=\"9\">{}</font>", html_text(type));
  for (const NodeTerm* t : lines) {
    const bool hot = lit && contains(terms.failing, t->embedding);
    html += fmt::format("<br/><font point-size=\"9\" color=\"{}\">{}{}: {}{}</font>", hot ? highlight_line : term_color, hot ? "<b>" : "",
                        html_text(t->embedding), html_text(t->term.str()), hot ? "</b>" : "");
  }
  return fmt::format("label=<{}>, shape=box", html);
}

// What happens to an element, as its line style; the colour is left to
// the dimension (arcs) so that one visual channel means one thing.
std::string_view change_style(bool kept, bool left) { return kept ? "solid" : left ? "dashed" : "bold"; }

// Where a side's nodes go: by the union layout's node name (unquoted:
// prefix + "L:" + name for L's nodes and R's preserved ones, prefix + "R:"
// + name for R's added nodes), in inches; R's shifted right by dx.
struct SidePins {
  std::map<std::string, std::array<double, 2>> at;
  double dx = 0;
  // Each side's extent in x in the union's coordinates (lo[0], hi[0] for
  // L; [1] for R), and the union's in y; nodes' sizes included.
  std::array<double, 2> lo{0, 0}, hi{0, 0};
  double bottom = 0, top = 0;
};

// One side of a rule in DOT: its nodes and arcs, those a witness names
// lit.
class SideDrawing {
 public:
  SideDrawing(const Rule& rule, const ArcWords& words, bool left, const std::vector<RuleWitness>& witnesses, const std::string& prefix,
              const JerboaLabels* labels, const TermLines& terms, const SidePins* pins, bool merged)
      : rule_(rule),
        words_(words),
        left_(left),
        g_(left ? rule.left() : rule.right()),
        ws_(left ? words.left : words.right),
        rw_(rule.model()),
        side_(left ? "L" : "R"),
        prefix_(prefix),
        labels_(labels),
        terms_(terms),
        pins_(pins),
        merged_(merged),
        dx_(left || !pins ? 0 : pins->dx) {
    for (const auto& w : witnesses)
      if (w.side == side_[0]) {
        lit_nodes_.insert(lit_nodes_.end(), w.nodes.begin(), w.nodes.end());
        for (const auto& text : w.arcs)
          for (auto& s : steps(text)) {
            lit_nodes_.push_back(s.source);
            lit_nodes_.push_back(s.target);
            lit_arcs_.push_back(std::move(s));
          }
      }
  }

  std::string text() const {
    std::string out = opening();
    for (NodeId v = 0; v < g_.node_count(); ++v) out += node(v);
    out += arcs();
    return merged_ || pins_ ? out : out + "    }\n";
  }

 private:
  bool lit_arc(ArcId e) const {
    const auto& a = g_.arc(e);
    const std::string full = label_text(a.label, arc_word(ws_, e), words_.scheme), bare = std::to_string(a.label);
    return std::any_of(lit_arcs_.begin(), lit_arcs_.end(), [&](const Step& s) {
      return s.source == g_.name(a.source) && s.target == g_.name(a.target) && (s.label == full || (arc_word(ws_, e).empty() && s.label == bare));
    });
  }
  // A node's name in the union layout, and in the picture.
  std::string union_name(NodeId v) const {
    const NodeId in_left = left_ ? v : rule_.to_left(v);
    return in_left != no_node ? prefix_ + "L:" + rule_.left().name(in_left) : prefix_ + "R:" + g_.name(v);
  }
  std::string key(NodeId v) const { return quote(merged_ ? union_name(v) : prefix_ + side_ + ":" + g_.name(v)); }

  // The frame is a node pinned under the side's nodes, not a cluster:
  // neato orders clusters by address (its SVG changes from run to run)
  // and draws them just around their nodes, the label over them. Room for
  // the label and for loops (with their labels, about 0.4 inch past their
  // node); both frames have the union's height.
  std::string opening() const {
    if (pins_) {
      constexpr double loop_room = 0.4, label_room = 0.5;
      const double x0 = pins_->lo[!left_] - loop_room + dx_, x1 = pins_->hi[!left_] + loop_room + dx_;
      const double y0 = pins_->bottom - loop_room, y1 = pins_->top + loop_room + label_room;
      return fmt::format(
          "    {} [shape=box, color=\"#bdbdbd\", fontsize=14, label={}, labelloc=t, fixedsize=true, width={:.4f}, height={:.4f}, "
          "pos=\"{:.4f},{:.4f}!\"];\n",
          quote(prefix_ + side_ + ":#frame"), quote(side_), x1 - x0, y1 - y0, (x0 + x1) / 2, (y0 + y1) / 2);
    }
    if (!merged_) return fmt::format("    subgraph {} {{\n      label={}; color=\"#bdbdbd\";\n", quote("cluster_" + prefix_ + side_), quote(side_));
    return "";
  }

  std::string node(NodeId v) const {
    const bool kept = left_ ? rule_.to_right(v) != no_node : rule_.to_left(v) != no_node;
    if (merged_ && !left_ && kept) return "";  // declared with L's nodes
    const NodeId in_left = left_ ? v : rule_.to_left(v);
    const bool hook = in_left != no_node && std::find(rule_.hooks().begin(), rule_.hooks().end(), in_left) != rule_.hooks().end();
    const bool lit = contains(lit_nodes_, g_.name(v));
    const auto* types = labels_ ? (left_ ? &labels_->left : &labels_->right) : nullptr;
    const std::string type = types && v < types->size() ? orbit_type_str((*types)[v]) : "";
    const std::string label = node_label(g_.name(v), type, terms_, left_, lit);
    const bool boxed = label.find("shape=box") != std::string::npos;
    std::string style(change_style(kept, left_));
    if (boxed) style = "rounded," + style;
    if (lit) style += ",filled";
    std::string pin;
    if (pins_)
      if (const auto at = pins_->at.find(union_name(v)); at != pins_->at.end())
        pin = fmt::format(", pos=\"{:.4f},{:.4f}!\"", at->second[0] + dx_, at->second[1]);
    return fmt::format("      {} [{}, style=\"{}\"{}{}{}];\n", key(v), label, style, hook ? ", peripheries=2" : "",
                       lit ? fmt::format(", fillcolor=\"{}\", witness=\"true\"", highlight_fill) : "", pin);
  }

  // The arcs; a non-oriented arc and its reverse (conjugate word, same
  // change) as one undirected edge.
  std::string arcs() const {
    std::string out;
    std::vector<bool> drawn(g_.arc_count(), false);
    std::vector<std::size_t> loops(g_.node_count(), 0);  // drawn so far per node: each takes the next side
    for (ArcId e = 0; e < g_.arc_count(); ++e) {
      if (drawn[e]) continue;
      drawn[e] = true;
      const auto& a = g_.arc(e);
      const bool kept = left_ ? rule_.preserved_left_arc(e) : rule_.preserved_right_arc(e);
      const ConjWord& w = arc_word(ws_, e);
      bool pair = false;
      ArcId partner = e;
      if (!rule_.model().is_oriented(a.label)) {
        if (a.source == a.target && rw_.conjugate(w) == w) pair = true;
        for (ArcId f = e + 1; f < g_.arc_count() && !pair; ++f) {
          const auto& b = g_.arc(f);
          const bool f_kept = left_ ? rule_.preserved_left_arc(f) : rule_.preserved_right_arc(f);
          if (!drawn[f] && b.label == a.label && b.source == a.target && b.target == a.source && f_kept == kept &&
              arc_word(ws_, f) == rw_.conjugate(w))
            drawn[f] = pair = true, partner = f;
        }
      }
      const auto color = dimension_color(a.label);
      const bool lit = lit_arc(e) || lit_arc(partner);
      // A Jerboa node's orbit type already says what its implicit loops say.
      if (labels_ && a.source == a.target && !w.empty() && !lit) continue;
      const std::string port = a.source == a.target ? fmt::format(":{}", loop_port(loops[a.source]++, true)) : "";
      out += fmt::format("      {}{} -> {}{} [label={}, color=\"{}\", fontcolor=\"{}\", style={}{}{}];\n", key(a.source), port, key(a.target), port,
                         quote(labels_ && w.empty() ? std::to_string(a.label) : label_text(a.label, w, words_.scheme)),
                         lit ? fmt::format("{}:{}:{}", color, highlight_line, color) : std::string(color), color, change_style(kept, left_),
                         pair ? ", dir=none" : "", lit ? ", witness=\"true\"" : "");
    }
    return out;
  }

  const Rule& rule_;
  const ArcWords& words_;
  bool left_;
  const TopoGraph& g_;
  const std::vector<ConjWord>& ws_;
  const ConjugateRewriting rw_;
  std::string side_;
  const std::string& prefix_;
  const JerboaLabels* labels_;
  const TermLines& terms_;
  const SidePins* pins_;
  bool merged_;
  double dx_;
  std::vector<std::string> lit_nodes_;
  std::vector<Step> lit_arcs_;
};

// One side as a cluster, or (`merged`, for the union layout) as bare
// statements with R's preserved nodes named as in L and not declared again.
std::string side_cluster(const Rule& rule, const ArcWords& words, bool left, const std::vector<RuleWitness>& witnesses, const std::string& prefix,
                         const JerboaLabels* labels, const TermLines& terms, const SidePins* pins, bool merged = false) {
  return SideDrawing(rule, words, left, witnesses, prefix, labels, terms, pins, merged).text();
}

// The node attributes of the union layout: those of rule_dot's picture.
constexpr std::string_view node_defaults =
    "  node [shape=circle, fontname=\"Helvetica\", fontsize=11, width=0.35]; edge [fontname=\"Helvetica\", fontsize=10];\n";

// L and R laid out as one graph (L's nodes, R's added nodes, both sides'
// arcs) by dot, so that a preserved node has one place, which both sides
// use: R is L's layout shifted right, with R's added nodes where the union
// put them.
SidePins rule_pins(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses, const std::string& prefix,
                   const JerboaLabels* labels, const TermLines& terms) {
  const std::string merged = "digraph union {\n  rankdir=LR;\n" + std::string(node_defaults) +
                             side_cluster(rule, words, true, witnesses, prefix, labels, terms, nullptr, true) +
                             side_cluster(rule, words, false, witnesses, prefix, labels, terms, nullptr, true) + "}\n";
  SidePins pins;
  std::map<std::string, std::array<double, 2>> half;  // each node's half width and height
  for (const NodePosition& p : node_positions(merged, "dot")) {
    pins.at[p.name] = {p.at[0] / 72, p.at[1] / 72};
    half[p.name] = {p.width / 2, p.height / 2};
  }
  std::array<bool, 2> seen{false, false};
  bool any = false;
  auto extend = [&](int s, const std::string& name) {
    const auto at = pins.at.find(name);
    if (at == pins.at.end()) return;
    const auto [x, y] = at->second;
    const auto [w, h] = half[name];
    pins.lo[s] = seen[s] ? std::min(pins.lo[s], x - w) : x - w;
    pins.hi[s] = seen[s] ? std::max(pins.hi[s], x + w) : x + w;
    pins.bottom = any ? std::min(pins.bottom, y - h) : y - h;
    pins.top = any ? std::max(pins.top, y + h) : y + h;
    seen[s] = any = true;
  };
  for (NodeId v = 0; v < rule.left().node_count(); ++v) {
    extend(0, prefix + "L:" + rule.left().name(v));
    if (rule.to_right(v) != no_node) extend(1, prefix + "L:" + rule.left().name(v));
  }
  for (NodeId v = 0; v < rule.right().node_count(); ++v)
    if (rule.to_left(v) == no_node) extend(1, prefix + "R:" + rule.right().name(v));
  // An empty side (L of a creation) is a frame of its own, no node wide.
  for (int s : {0, 1})
    if (!seen[s]) pins.lo[s] = pins.hi[s] = seen[1 - s] ? pins.lo[1 - s] : 0;
  pins.dx = pins.hi[0] - pins.lo[1] + 1.2;  // R's left edge past L's right one: the frames' margins and a gap
  return pins;
}

}  // namespace

std::vector<RuleWitness> failed_witnesses(const RuleVerdict& v) {
  std::vector<RuleWitness> out;
  for (const auto& c : v.conditions)
    if (!c.holds) out.insert(out.end(), c.witnesses.begin(), c.witnesses.end());
  return out;
}

std::string rule_cluster(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses, const std::string& prefix,
                         const JerboaLabels* labels, const TermLines& terms, bool titled, bool pinned) {
  // At the graph's top level (the callers put the sides there): the pins
  // need neato (dot cannot keep them: it ranks each side on its own), and
  // neato draws no cluster nested in another, so the sides are not
  // wrapped; the rule's name, when asked for, is the picture's label.
  // Straight edges: Graphviz 2.43's spline router in neato corrupts its
  // heap on some rules (makeMultiSpline, seen on the seed catalog).
  std::string out = pinned ? "  layout=neato; splines=false;\n" : "";
  // Preserved nodes at the same place on both sides: every node pinned
  // from one layout of L and R together.
  const std::optional<SidePins> pins = pinned ? std::optional(rule_pins(rule, words, witnesses, prefix, labels, terms)) : std::nullopt;
  if (titled) out += fmt::format("  label={};\n", quote(rule.name()));
  out += side_cluster(rule, words, true, witnesses, prefix, labels, terms, pins ? &*pins : nullptr);
  out += side_cluster(rule, words, false, witnesses, prefix, labels, terms, pins ? &*pins : nullptr);
  return out;
}

std::string failure_caption(const std::string& head, const std::vector<RuleWitness>& witnesses) {
  if (witnesses.empty()) return head;
  return fmt::format("{}: {}{}", head, witnesses.front().text, witnesses.size() > 1 ? fmt::format(" (and {} more)", witnesses.size() - 1) : "");
}

std::vector<std::string> caption_lines(const std::string& caption, std::size_t width) { return wrap_words(caption, width); }

std::vector<std::string> failure_captions(const RuleVerdict& v) {
  std::vector<std::string> out;
  for (const auto& c : v.conditions)
    if (!c.holds) out.push_back(failure_caption("fails " + c.name(), c.witnesses));
  return out;
}

std::string rule_legend(const Model& model, bool witnesses, const TermLines& terms, bool maps) {
  // One cell per clause: Graphviz spaces the pieces of a line by its own
  // font metrics, which a browser's font does not match, so pieces of
  // different colours in one cell can touch.
  std::string clauses = "<td>lines: solid preserved, dashed deleted, bold added;</td><td>double border: hook</td>";
  if (witnesses) clauses += fmt::format(R"(<td><font color="{}">amber: witness in the rule</font></td>)", highlight_line);
  // A counterexample's fills on a row of their own: one row would be
  // wider than the three panels.
  const std::string fills =
      maps ? fmt::format(R"(<tr><td><table border="0" cellspacing="4" cellpadding="0"><tr><td><font color="{}">blue: the match in G</font></td>)"
                         R"(<td><font color="{}">red: darts of H breaking a constraint</font></td></tr></table></td></tr>)",
                         match_line, broken_line)
           : "";
  if (terms.terms) {
    clauses += "<td>embedding: term</td>";
    if (!terms.failing.empty()) clauses += fmt::format(R"(<td><font color="{}"><b>bold: failing</b></font></td>)", highlight_line);
  }
  return fmt::format(R"(<table border="0" cellspacing="2"><tr><td><table border="0" cellspacing="4" cellpadding="0"><tr>{}</tr></table></td></tr>)"
                     R"({}<tr><td>{}</td></tr></table>)",
                     clauses, fills, dimension_legend(model));
}

std::string rule_dot(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses, const JerboaLabels* labels,
                     const TermLines& terms, const std::vector<std::string>& captions, bool pinned) {
  std::string caption = fmt::format("<tr><td><b>{}</b></td></tr>", html_text(rule.name()));
  for (const auto& text : captions)
    for (const auto& line : caption_lines(text)) caption += fmt::format(R"(<tr><td><font color="{}">{}</font></td></tr>)", deleted_color, html_text(line));
  return fmt::format(
      "digraph {} {{\n  rankdir=LR; newrank=true; fontname=\"Helvetica\"; labelloc=t;\n"
      "  label=<<table border=\"0\" cellspacing=\"1\">{}<tr><td>{}</td></tr></table>>;\n"
      "{}{}}}\n",
      quote(rule.name()), caption, rule_legend(rule.model(), !witnesses.empty(), terms), node_defaults,
      rule_cluster(rule, words, witnesses, "", labels, terms, false, pinned));
}

}  // namespace dartcheck::reports
