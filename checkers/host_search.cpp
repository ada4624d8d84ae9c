#include "checkers/host_search.hpp"

#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "checkers/graph_constraints.hpp"
#include "rewriting/graph_derivation.hpp"

namespace dartcheck {
namespace {

struct Search {
  const Rule* rule;  // null: only visit the maps
  const Model& model;
  const std::function<bool(const Violation&)>& relevant;
  std::size_t budget;
  std::size_t n = 0;                       // host size
  std::vector<std::vector<NodeId>> sigma;  // per dimension index
  std::vector<std::vector<bool>> used;     // targets taken, per dimension index
  HostSearch out;
  bool stop = false;
  std::function<bool(const std::vector<std::vector<NodeId>>&)> visit;

  // Partial checks as soon as the permutations they read are complete.
  bool consistent_so_far(std::size_t k) const {
    const Dim d = model.dims[k];
    for (NodeId v = 0; v < n; ++v) {
      if (!model.is_oriented(d) && sigma[k][sigma[k][v]] != v) return false;
      if (model.loop_free && sigma[k][v] == v) return false;
    }
    for (auto [i, j] : model.exchangeable) {
      const std::size_t a = index(i), b = index(j);
      if (std::max(a, b) != k) continue;
      for (NodeId v = 0; v < n; ++v)
        if (sigma[b][sigma[a][sigma[b][sigma[a][v]]]] != v) return false;
    }
    return true;
  }
  std::size_t index(Dim d) const { return static_cast<std::size_t>(std::find(model.dims.begin(), model.dims.end(), d) - model.dims.begin()); }

  void host_ready() {
    if (++out.hosts > budget) {
      out.exhausted = false;
      stop = true;
      return;
    }
    if (visit) {
      stop = !visit(sigma);
      return;
    }
    const TopoGraph& L = rule->left();
    TopoGraph G;
    for (NodeId v = 0; v < n; ++v) G.add_node(v < L.node_count() ? L.name(v) : fmt::format("x{}", v));
    for (std::size_t k = 0; k < model.dims.size(); ++k)
      for (NodeId v = 0; v < n; ++v) G.add_arc(v, sigma[k][v], model.dims[k]);  // arc k*n + v
    GraphMatch m{std::vector<NodeId>(L.node_count()), std::vector<ArcId>(L.arc_count())};
    std::iota(m.node.begin(), m.node.end(), 0);
    for (ArcId e = 0; e < L.arc_count(); ++e) m.arc[e] = static_cast<ArcId>(index(L.arc(e).label) * n + L.arc(e).source);
    if (!satisfies_dangling(*rule, G, m)) return;
    out.matched = true;
    ++out.derivations;
    TopoGraph H = derive(*rule, G, m);
    auto report = check_graph(H, model);
    std::vector<Violation> bad;
    for (const auto& v : report.violations)
      if (!relevant || relevant(v)) bad.push_back(v);
    if (!bad.empty()) {
      out.host = std::move(G);
      out.result = std::move(H);
      out.violations = std::move(bad);
      stop = true;
    }
  }

  void assign(std::size_t k, NodeId v) {
    if (stop) return;
    if (k == model.dims.size()) return host_ready();
    if (v == n) {
      if (consistent_so_far(k)) assign(k + 1, 0);
      return;
    }
    if (sigma[k][v] != no_node) return assign(k, v + 1);
    const bool involution = !model.is_oriented(model.dims[k]);
    auto place = [&](NodeId w, bool pair) {
      used[k][w] = true;
      sigma[k][v] = w;
      if (pair) {
        sigma[k][w] = v;
        used[k][v] = true;
      }
      assign(k, v + 1);
      if (pair) {
        sigma[k][w] = no_node;
        used[k][v] = false;
      }
      sigma[k][v] = no_node;
      used[k][w] = false;
    };
    if (involution && used[k][v]) {
      // Some u already goes to v: an involution sends v back to u.
      for (NodeId u = 0; u < n; ++u)
        if (sigma[k][u] == v && !used[k][u] && !(model.loop_free && u == v)) place(u, false);
      return;
    }
    for (NodeId w = 0; w < n && !stop; ++w) {
      if (used[k][w] || (model.loop_free && w == v)) continue;
      if (involution && w != v && sigma[k][w] != no_node) continue;
      place(w, involution && w != v);
    }
  }
};

}  // namespace

namespace {

// L's arcs fix entries of the permutations (the identity match); false on a
// clash, when no host of the class contains an injective image of L.
bool fix_arcs(Search& s, const TopoGraph& L) {
  for (const auto& a : L.arcs()) {
    if (!s.model.contains(a.label)) return false;
    const std::size_t k = s.index(a.label);
    if (s.sigma[k][a.source] != no_node || s.used[k][a.target]) return false;
    s.sigma[k][a.source] = a.target;
    s.used[k][a.target] = true;
  }
  return true;
}

void reset(Search& s, std::size_t n) {
  s.n = n;
  s.sigma.assign(s.model.dims.size(), std::vector<NodeId>(n, no_node));
  s.used.assign(s.model.dims.size(), std::vector<bool>(n, false));
}

}  // namespace

HostSearch search_hosts(const Rule& rule, const Model& host_model, std::size_t extra, const std::function<bool(const Violation&)>& relevant,
                        std::size_t budget) {
  Search s{&rule, host_model, relevant, budget, 0, {}, {}, {}, false, {}};
  const TopoGraph& L = rule.left();
  const std::size_t nl = L.node_count();
  for (std::size_t n = nl; n <= nl + extra && !s.stop; ++n) {
    reset(s, n);
    s.out.largest_host = n;
    if (!fix_arcs(s, L)) break;
    s.assign(0, 0);
  }
  return std::move(s.out);
}

std::size_t for_each_small_map(const Model& model, std::size_t n, const std::function<bool(const std::vector<std::vector<NodeId>>&)>& visit,
                               std::size_t budget, const TopoGraph* containing) {
  static const std::function<bool(const Violation&)> all;
  Search s{nullptr, model, all, budget, n, {}, {}, {}, false, visit};
  reset(s, n);
  if (containing && (containing->node_count() > n || !fix_arcs(s, *containing))) return 0;
  s.assign(0, 0);
  return std::min(s.out.hosts, budget);
}

namespace {

// Every dart reached from `roots` along the links of the model, both ways.
bool connected(const Map& g, std::span<const Dart> roots) {
  std::vector<bool> seen(g.size(), false);
  std::vector<Dart> stack;
  for (Dart r : roots)
    if (!seen[r]) {
      seen[r] = true;
      stack.push_back(r);
    }
  std::size_t count = stack.size();
  while (!stack.empty()) {
    const Dart d = stack.back();
    stack.pop_back();
    for (Dim i : g.model().dims)
      for (Dart x : {g.link(i, d), g.inverse_link(i, d)})
        if (x != no_dart && !seen[x]) {
          seen[x] = true;
          ++count;
          stack.push_back(x);
        }
  }
  return count == g.size();
}

}  // namespace

RootedHosts for_each_rooted_host(const Operation& op, std::size_t max_darts, const std::function<bool(const Map&, std::span<const Dart>)>& visit,
                                 std::size_t budget) {
  RootedHosts out;
  const Rule& rule = op.rule;
  const Model& model = rule.model();
  const TopoGraph& L = rule.left();
  const bool scheme = op.is_scheme();
  const std::size_t first = scheme ? 1 : L.node_count(), hooks = rule.hooks().size();
  bool stopped = false;
  out.complete = std::min(first - 1, max_darts);  // no smaller host can hold L
  for (std::size_t n = first; n <= max_darts && !stopped; ++n) {
    const std::size_t left = budget - std::min(budget, out.hosts);
    const std::size_t visited = for_each_small_map(
        model, n,
        [&](const std::vector<std::vector<NodeId>>& sigma) {
          Map g(model, n);
          for (std::size_t k = 0; k < model.dims.size(); ++k)
            for (Dart d = 0; d < n; ++d) g.set_link(model.dims[k], d, sigma[k][d]);
          ++out.hosts;
          if (!scheme) {
            std::vector<Dart> roots(L.node_count());
            std::iota(roots.begin(), roots.end(), Dart{0});
            if (!connected(g, roots)) return true;
            std::vector<Dart> hk(rule.hooks().begin(), rule.hooks().end());
            return !(stopped = !visit(g, hk));
          }
          // The first hook at dart 0, the others anywhere.
          std::vector<Dart> hk(hooks, 0);
          while (true) {
            if (connected(g, hk) && !visit(g, hk)) {
              stopped = true;
              return false;
            }
            std::size_t i = 1;
            while (i < hooks && ++hk[i] == n) hk[i++] = 0;
            if (i >= hooks) return true;
          }
        },
        left, scheme ? nullptr : &L);
    if (visited >= left) {
      out.budget_hit = true;
      break;
    }
    if (!stopped) out.complete = n;
  }
  return out;
}

}  // namespace dartcheck
