#include "events/event_log.hpp"

#include <algorithm>
#include <numeric>
#include <map>
#include <set>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "core/orbit.hpp"
#include "core/dart_index.hpp"
#include "core/disjoint_sets.hpp"

namespace dartcheck::events {
namespace {

// A set of orbits in compressed form: orbit a has the darts
// darts[start[a] .. start[a+1]) and the representative rep[a].
struct Orbits {
  std::vector<Dart> rep;
  std::vector<std::size_t> start{0};
  std::vector<Dart> darts;
  std::size_t size() const { return rep.size(); }
  std::span<const Dart> of(std::size_t a) const { return {darts.data() + start[a], start[a + 1] - start[a]}; }
  void add(std::span<const Dart> members) {
    rep.push_back(*std::min_element(members.begin(), members.end()));
    darts.insert(darts.end(), members.begin(), members.end());
    start.push_back(darts.size());
  }
};

// Splits, by G orbit (`pairs`, the (G orbit, H orbit) pairs of the
// correspondence, are sorted by G orbit): a G orbit whose darts go to two
// H orbits or more.
void add_splits(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs, const Orbits& go, const Orbits& ho,
                std::vector<LoggedEvent>& out) {
  for (std::size_t i = 0; i < pairs.size();) {
    std::size_t j = i;
    while (j < pairs.size() && pairs[j].first == pairs[i].first) ++j;
    if (j - i >= 2) {
      LoggedEvent e{Event::split, {go.rep[pairs[i].first]}, {}};
      for (std::size_t q = i; q < j; ++q) e.after.push_back(ho.rep[pairs[q].second]);
      std::sort(e.after.begin(), e.after.end());
      out.push_back(std::move(e));
    }
    i = j;
  }
}

// Whether every generator of the orbit kind links the images of `darts` in
// H as it links them in G (a non-modification, 004 Def. 3.4.2).
template <class Darts, class ToH>
bool links_kept(const Map& g, const Map& h, const OrbitKind& kind, const Darts& darts, ToH to_h) {
  for (Dart d : darts) {
    const Dart e = to_h(d);
    for (const OrbitWord& w : kind.generators) {
      const Dart dg = follow(g, d, w), dh = follow(h, e, w);
      if ((dg == no_dart) != (dh == no_dart) || (dg != no_dart && to_h(dg) != dh)) return false;
    }
  }
  return true;
}

// The events between G's orbits and H's orbits (004 Def. 3.1.1-3.4.2 on
// transformations). to_h / to_g: the correspondence; h_orbit / g_orbit:
// the orbit index of a dart of the other side's images.
template <class ToH, class ToG, class HOrbit, class GOrbit, class Matched>
std::vector<LoggedEvent> derive(const Map& g, const Map& h, const OrbitKind& kind, const Orbits& go, const Orbits& ho, ToH to_h, ToG to_g,
                                HOrbit h_orbit, GOrbit g_orbit, Matched matched, bool skip_unmatched_unchanged) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::vector<char> deleted(go.size(), 0), created(ho.size(), 0);
  for (std::size_t a = 0; a < go.size(); ++a)
    for (Dart d : go.of(a)) {
      const Dart e = to_h(d);
      if (e == no_dart)
        deleted[a] = 1;
      else
        pairs.emplace_back(static_cast<std::uint32_t>(a), h_orbit(e));
    }
  for (std::size_t b = 0; b < ho.size(); ++b)
    for (Dart e : ho.of(b))
      if (to_g(e) == no_dart) {
        created[b] = 1;
      } else {
        // An H orbit whose preserved darts come from a G orbit outside `go`
        // is caught by the pair count below; g_orbit asserts membership.
        (void)g_orbit(to_g(e));
      }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<std::uint32_t> nb(go.size(), 0), na(ho.size(), 0), only_b(go.size(), 0);
  for (auto [a, b] : pairs) {
    ++nb[a];
    ++na[b];
    only_b[a] = b;
  }
  std::vector<LoggedEvent> out;
  add_splits(pairs, go, ho, out);
  // Merges, by H orbit.
  std::vector<std::vector<Dart>> before(ho.size());
  for (auto [a, b] : pairs)
    if (na[b] >= 2) before[b].push_back(go.rep[a]);
  for (std::size_t b = 0; b < ho.size(); ++b) {
    if (na[b] >= 2) {
      std::sort(before[b].begin(), before[b].end());
      out.push_back({Event::merge, std::move(before[b]), {ho.rep[b]}});
    }
    if (na[b] == 0) out.push_back({Event::creation, {}, {ho.rep[b]}});
  }
  for (std::size_t a = 0; a < go.size(); ++a) {
    if (nb[a] == 0) {
      out.push_back({Event::deletion, {go.rep[a]}, {}});
      continue;
    }
    if (nb[a] != 1 || na[only_b[a]] != 1) continue;
    const std::uint32_t b = only_b[a];
    const bool same = !deleted[a] && !created[b] && go.of(a).size() == ho.of(b).size() && links_kept(g, h, kind, go.of(a), to_h);
    if (same && skip_unmatched_unchanged) {
      const auto darts = go.of(a);
      if (std::none_of(darts.begin(), darts.end(), matched)) continue;
    }
    out.push_back({same ? Event::non_modification : Event::modification, {go.rep[a]}, {ho.rep[b]}});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Every orbit of the map, in order of smallest dart, and each dart's orbit.
Orbits all_orbits(const Map& m, const OrbitKind& kind, std::vector<std::uint32_t>& orbit_of) {
  Orbits o;
  orbit_of.assign(m.size(), static_cast<std::uint32_t>(-1));
  OrbitWalker walker(m);
  for (Dart d = 0; d < m.size(); ++d) {
    if (orbit_of[d] != static_cast<std::uint32_t>(-1)) continue;
    const auto& darts = walker.orbit(d, kind.generators);
    for (Dart e : darts) orbit_of[e] = static_cast<std::uint32_t>(o.size());
    o.add(darts);
  }
  return o;
}

// The orbits of one side's instance: complete rule orbits by union-find on
// (node, position) pairs, incomplete ones by traversal from their darts.
void side_instance(const Map& m, const EventRule& r, const EventSide& side, const SideOrbits& so, const OrbitKind& kind,
                   const std::vector<std::vector<Dart>>& darts, const std::optional<PatternGraphs>& pattern, Orbits& out, DartIndex& orbit_of) {
  const std::size_t np = darts.empty() ? 0 : darts[0].size();
  std::vector<int> step_of(r.parameter.size(), -1);
  if (pattern)
    for (std::size_t k = 0; k < r.parameter.size(); ++k) step_of[k] = pattern->generator(r.position_words[k]);
  std::unique_ptr<OrbitWalker> walker;
  std::vector<std::uint32_t> parent;
  std::vector<Dart> members;
  for (const RuleOrbit& x : so.orbits) {
    if (!x.complete) {
      if (!walker) walker = std::make_unique<OrbitWalker>(m);
      for (NodeId v : x.nodes)
        for (Dart d : darts[v]) {
          if (orbit_of.get(d) != DartIndex::none) continue;
          const auto& orbit = walker->orbit(d, kind.generators);
          for (Dart e : orbit) orbit_of.set(e, static_cast<std::uint32_t>(out.size()));
          out.add(orbit);
        }
      continue;
    }
    // Local index of (node, p): position of the node in x.nodes times np + p.
    const std::size_t nx = x.nodes.size();
    make_singletons(parent, nx * np);
    auto local = [&](NodeId v) { return static_cast<std::size_t>(std::lower_bound(x.nodes.begin(), x.nodes.end(), v) - x.nodes.begin()); };
    auto unite = [&](std::size_t i, std::size_t j) { attach_set(parent, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)); };
    for (ArcId e : side.explicit_arcs) {
      const auto& a = side.graph->arc(e);
      if (a.source == a.target || !has_dim(kind.dims(), a.label) || so.orbit_of[a.source] != so.orbit_of[x.nodes[0]]) continue;
      const std::size_t s = local(a.source), t = local(a.target);
      for (std::size_t p = 0; p < np; ++p) unite(s * np + p, t * np + p);
    }
    // Orbit-word generators (O-map DPO rules) join the nodes of x: one position.
    if (!kind.single_letters())
      for (std::size_t i = 1; i < nx; ++i) unite(0, i * np);
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t k = 0; k < r.parameter.size(); ++k)
        if (in_kind(kind, side.labels[x.nodes[i]][k]))
          for (std::size_t p = 0; p < np; ++p) unite(i * np + p, i * np + pattern->step(p, step_of[k]));
    // Components, in order of their first (node, position): count, then
    // place (a counting sort on the roots, no per-component allocation).
    std::vector<std::uint32_t> slot(nx * np, DartIndex::none);
    std::vector<std::uint32_t> sizes, order;
    for (std::size_t i = 0; i < nx * np; ++i) {
      auto& c = slot[find_representative(parent, static_cast<std::uint32_t>(i))];
      if (c == DartIndex::none) {
        c = static_cast<std::uint32_t>(sizes.size());
        sizes.push_back(0);
      }
      ++sizes[c];
      order.push_back(c);
    }
    std::vector<std::size_t> begin(sizes.size() + 1, 0);
    for (std::size_t c = 0; c < sizes.size(); ++c) begin[c + 1] = begin[c] + sizes[c];
    members.assign(nx * np, 0);
    std::vector<std::size_t> at(begin.begin(), begin.end() - 1);
    for (std::size_t i = 0; i < nx * np; ++i) members[at[order[i]]++] = darts[x.nodes[i / np]][i % np];
    for (std::size_t c = 0; c < sizes.size(); ++c) {
      const std::span<const Dart> comp(members.data() + begin[c], sizes[c]);
      for (Dart e : comp) orbit_of.set(e, static_cast<std::uint32_t>(out.size()));
      out.add(comp);
    }
  }
}

}  // namespace

EventLog dynamic_log(const Map& g, const Map& h, const Rule& rule, const Application& t, const OrbitKind& kind) {
  const Renumbering c = t.renumbering(rule, h.size());
  std::vector<Dart> g2h(g.size()), h2g(h.size());
  for (Dart d = 0; d < g.size(); ++d) g2h[d] = c.to_h(d);
  for (Dart d = 0; d < h.size(); ++d) h2g[d] = c.to_g(d);
  std::vector<char> matched(g.size(), 0);
  for (const auto& darts : t.match)
    for (Dart d : darts) matched[d] = 1;
  std::vector<std::uint32_t> g_of, h_of;
  const Orbits go = all_orbits(g, kind, g_of), ho = all_orbits(h, kind, h_of);
  return {kind, derive(
                    g, h, kind, go, ho, [&](Dart d) { return g2h[d]; }, [&](Dart d) { return h2g[d]; }, [&](Dart d) { return h_of[d]; },
                    [&](Dart d) { return g_of[d]; }, [&](Dart d) { return matched[d] != 0; }, true)};
}

EventLog instantiated_log(const Map& g, const Map& h, const EventRule& r, const KindEvents& k, const Application& t) {
  const Renumbering c = t.renumbering(*r.rule, h.size());
  Orbits go, ho;
  std::size_t matched = 0, comatched = 0;
  for (const auto& d : t.match) matched += d.size();
  for (const auto& d : t.comatch) comatched += d.size();
  DartIndex is_matched(matched, g.size());
  for (const auto& darts : t.match)
    for (Dart d : darts) is_matched.set(d, 1);
  DartIndex g_of(matched, g.size()), h_of(comatched, h.size());
  side_instance(g, r, r.left, k.left, k.kind, t.match, t.pattern, go, g_of);
  side_instance(h, r, r.right, k.right, k.kind, t.comatch, t.pattern, ho, h_of);
  auto lookup = [](const DartIndex& m, Dart d) {
    const std::uint32_t v = m.get(d);
    // A preserved dart outside every instantiated orbit would contradict
    // 004 Sec. 2.2 (the rewrite changes only matched darts' links).
    if (v == DartIndex::none) throw InternalError(fmt::format("dart {} is outside the instantiated orbits", d));
    return v;
  };
  return {k.kind,
          derive(
              g, h, k.kind, go, ho, [&](Dart d) { return c.to_h(d); }, [&](Dart d) { return c.to_g(d); }, [&](Dart d) { return lookup(h_of, d); },
              [&](Dart d) { return lookup(g_of, d); }, [&](Dart d) { return is_matched.get(d) != DartIndex::none; }, true)};
}

std::string event_line(const OrbitKind& kind, const LoggedEvent& e) {
  const std::string o = kind.str();
  auto names = [&](char side, const std::vector<Dart>& ds) {
    std::vector<std::string> n;
    for (Dart d : ds) n.push_back(fmt::format("{}{}({})", side, o, d));
    return n.size() == 1 ? n[0] : fmt::format("{{{}}}", fmt::join(n, ", "));
  };
  switch (e.event) {
    case Event::creation:
      return fmt::format("creation {}", names('H', e.after));
    case Event::deletion:
      return fmt::format("deletion {}", names('G', e.before));
    default:
      return fmt::format("{} {} -> {}", name_of(e.event), names('G', e.before), names('H', e.after));
  }
}

std::vector<Dart> orbit_representatives(const Map& m, const OrbitKind& kind) {
  const OrbitPartition orbits = partition_orbits(m, kind.generators);
  std::vector<Dart> rep(m.size());
  for (Dart d = 0; d < m.size(); ++d) rep[d] = orbits.first[orbits.of[d]];
  return rep;
}

std::vector<std::vector<std::string>> event_rule_orbits(const EventRule& r, const KindEvents& k, const Map& g, const Map& h, const Application& t,
                                                        const EventLog& log) {
  const std::vector<Dart> grep = orbit_representatives(g, k.kind), hrep = orbit_representatives(h, k.kind);
  std::map<Dart, std::set<int>> left, right;  // orbit representative -> rule orbits
  for (NodeId v = 0; v < t.match.size(); ++v)
    for (Dart d : t.match[v]) left[grep[d]].insert(k.left.orbit_of[v]);
  for (NodeId w = 0; w < t.comatch.size(); ++w)
    for (Dart d : t.comatch[w]) right[hrep[d]].insert(k.right.orbit_of[w]);
  std::vector<std::vector<std::string>> out;
  for (const LoggedEvent& e : log.events) {
    std::set<int> orbits;
    const bool creation = e.event == Event::creation;
    for (Dart rep : creation ? e.after : e.before)
      if (const auto& index = creation ? right : left; index.count(rep)) orbits.insert(index.at(rep).begin(), index.at(rep).end());
    std::vector<std::string> names;
    for (int o : orbits) names.push_back(rule_orbit_name(r, k, !creation, o));
    out.push_back(std::move(names));
  }
  return out;
}

}  // namespace dartcheck::events
