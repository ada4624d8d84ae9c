#include "rewriting/instantiated_classes.hpp"

#include <algorithm>
#include <numeric>

#include "core/disjoint_sets.hpp"

namespace dartcheck {
namespace {

constexpr std::uint32_t none = 0xffffffffU;

// 32-bit entries: a side instantiated on a large hook orbit has |nodes| x
// |P_v| instances, and halving the table halves its page faults. The
// entries live in the caller's scratch memory.
struct UnionFind {
  std::vector<std::uint32_t>& up;
  UnionFind(std::vector<std::uint32_t>& memory, std::size_t n) : up(memory) { make_singletons(up, n); }
  std::uint32_t find(std::size_t x) { return find_representative(up, static_cast<std::uint32_t>(x)); }
  void unite(std::size_t a, std::size_t b) { attach_set(up, static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)); }
};

bool in_orbit(const std::vector<Dim>& orbit, Dim d) { return std::find(orbit.begin(), orbit.end(), d) != orbit.end(); }

std::size_t copies(const PatternGraphs* pattern) { return pattern ? pattern->darts[0].size() : 1; }
int generator(const PatternGraphs* pattern, const ConjWord& w) { return pattern ? pattern->generator(w) : -1; }
std::uint32_t step(const PatternGraphs* pattern, std::size_t p, int w) { return pattern ? pattern->step(p, w) : static_cast<std::uint32_t>(p); }

// out[p] = the dense number of uf's root of first + p, numbers given in
// order of first appearance from `count` on (number: per root, none first).
void renumber(UnionFind& uf, std::size_t first, std::size_t np, std::vector<std::uint32_t>& number, std::uint32_t& count,
              std::vector<std::uint32_t>& out) {
  out.resize(np);
  for (std::size_t p = 0; p < np; ++p) {
    std::uint32_t& id = number[uf.find(first + p)];
    if (id == none) id = count++;
    out[p] = id;
  }
}

// out[p] = the class of p under the steps p -> p·w (w in `words`),
// numbered from `count` on in order of first appearance, by a depth-first
// walk: no union-find, one read per step. When every step is a
// permutation of P_v (a valid host) the positions reached forward from p
// are its whole orbit. Each step is checked when its source is popped; one
// into an earlier class (a step that is not injective, possible on an
// invalid host) returns false, and the caller takes the symmetric closure.
bool label_orbits(const PatternGraphs* pattern, std::size_t np, const std::vector<int>& words, std::vector<std::uint32_t>& stack,
                  std::uint32_t& count, std::vector<std::uint32_t>& out) {
  out.assign(np, none);
  stack.clear();
  for (std::size_t p = 0; p < np; ++p) {
    if (out[p] != none) continue;
    const std::uint32_t c = count++;
    out[p] = c;
    stack.push_back(static_cast<std::uint32_t>(p));
    while (!stack.empty()) {
      const std::uint32_t q = stack.back();
      stack.pop_back();
      for (int w : words) {
        const std::uint32_t r = step(pattern, q, w);
        if (out[r] == none) {
          out[r] = c;
          stack.push_back(r);
        } else if (out[r] != c) {
          return false;
        }
      }
    }
  }
  return true;
}

}  // namespace

void instantiated_classes_by_instance(const TopoGraph& side, const std::vector<ConjWord>& words, const PatternGraphs* pattern,
                                      const std::vector<Dim>& orbit, InstantiatedClasses& out) {
  const std::size_t n = side.node_count(), np = copies(pattern);
  UnionFind uf(out.scratch.up, n * np);
  for (ArcId a = 0; a < side.arc_count(); ++a) {
    const auto& arc = side.arc(a);
    if (!in_orbit(orbit, arc.label)) continue;
    const int w = generator(pattern, arc_word(words, a));
    for (std::size_t p = 0; p < np; ++p) uf.unite(arc.source * np + p, arc.target * np + step(pattern, p, w));
  }
  // Each node its own group; one numbering for all (a class may span nodes).
  std::vector<std::uint32_t>& number = out.scratch.number;
  number.assign(n * np, none);
  out.count = 0;
  out.by_pattern = false;
  out.group_of.resize(n);
  out.id.resize(n);
  for (NodeId x = 0; x < n; ++x) {
    out.group_of[x] = x;
    renumber(uf, x * np, np, number, out.count, out.id[x]);
  }
}

// Arcs in <o> with the empty word join nodes within each pattern copy:
// they group the side's nodes. When every other arc in <o> (word w:
// (x, p) ~ (y, p·w)) joins two nodes of one group, the class of (y, p) is
// y's group times the orbit of p under the words of that group's arcs:
// the group gives (x, p) ~ (x', p) for x, x' in it, with it each such arc
// gives (z, p) ~ (z', p·w) for any z, z' of the group, and no arc leaves
// the group. So one walk over the pattern per group (label_orbits)
// replaces a union-find over |side| x |P_v| instances. A Jerboa scheme's
// implicit arcs are loops (one node) and its explicit arcs have the empty
// word: always this case.
// An arc with a word between two groups (a general (W, D) scheme) falls
// back to the definition.
void instantiated_classes(const TopoGraph& side, const std::vector<ConjWord>& words, const PatternGraphs* pattern, const std::vector<Dim>& orbit,
                          InstantiatedClasses& out, const GroupNumbering* numbering) {
  const std::size_t n = side.node_count(), np = copies(pattern);
  // The node groups use the scratch tables first; the pattern's walks
  // reuse them once group_of is known.
  UnionFind nodes(out.scratch.up, n);
  std::vector<std::pair<ArcId, int>>& shifted = out.scratch.shifted;
  shifted.clear();
  for (ArcId a = 0; a < side.arc_count(); ++a) {
    const auto& arc = side.arc(a);
    if (!in_orbit(orbit, arc.label)) continue;
    const int w = generator(pattern, arc_word(words, a));
    if (w < 0)
      nodes.unite(arc.source, arc.target);
    else
      shifted.emplace_back(a, w);
  }
  std::size_t groups = 0;
  out.group_of.resize(n);
  {
    std::vector<std::uint32_t>& number = out.scratch.number;
    number.assign(n, none);
    for (NodeId x = 0; x < n; ++x) {
      std::uint32_t& k = number[nodes.find(x)];
      if (k == none) k = static_cast<std::uint32_t>(groups++);
      out.group_of[x] = k;
    }
  }
  std::vector<std::vector<int>>& group_words = out.scratch.group_words;
  group_words.resize(groups);
  for (auto& w : group_words) w.clear();
  for (auto [a, w] : shifted) {
    const std::uint32_t k = out.group_of[side.arc(a).source];
    if (k != out.group_of[side.arc(a).target]) return instantiated_classes_by_instance(side, words, pattern, orbit, out);
    if (std::find(group_words[k].begin(), group_words[k].end(), w) == group_words[k].end()) group_words[k].push_back(w);
  }
  out.count = 0;
  out.by_pattern = true;
  out.id.resize(groups);
  for (std::size_t k = 0; k < groups; ++k) {
    const std::uint32_t first = out.count;
    if (numbering && (*numbering)(static_cast<std::uint32_t>(k), out.group_of, group_words[k], out.id[k], out.count)) continue;
    if (!label_orbits(pattern, np, group_words[k], out.scratch.up, out.count, out.id[k])) {
      out.count = first;
      UnionFind uf(out.scratch.up, np);
      for (int w : group_words[k])
        for (std::size_t p = 0; p < np; ++p) uf.unite(p, step(pattern, p, w));
      out.scratch.number.assign(np, none);
      renumber(uf, 0, np, out.scratch.number, out.count, out.id[k]);
    }
  }
}

}  // namespace dartcheck
