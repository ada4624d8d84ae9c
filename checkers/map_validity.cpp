#include "checkers/map_validity.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

namespace dartcheck {
namespace {

struct Pair {
  int si, sj;  // successor slots of i and j
  int pi, pj;  // inverse slots of i and j
  Dim i, j;
};

struct DimSlots {
  Dim i;
  int s, p;
  bool oriented, partial;
};

ValidityReport make_report(const Map& map) {
  ValidityReport r;
  r.model = map.model().name;
  r.elements = map.size();
  return r;
}

}  // namespace

ValidityReport check_map(const Map& map) {
  const Model& model = map.model();
  const std::size_t stride = map.stride();
  const Dart* base = map.raw().data();
  const Dart n = static_cast<Dart>(map.size());

  std::vector<DimSlots> dims;
  for (Dim i : model.dims)
    dims.push_back({i, map.succ_slot(i), map.pred_slot(i), model.is_oriented(i), has_dim(model.partial, i)});
  std::vector<Pair> pairs;
  for (auto [i, j] : model.exchangeable) pairs.push_back({map.succ_slot(i), map.succ_slot(j), map.pred_slot(i), map.pred_slot(j), i, j});

  ValidityReport report = make_report(map);
  bool broken = false;  // some dart breaks I, O or the loop ban
  for (Dart d = 0; d < n && !broken; ++d) {
    const Dart* r = base + d * stride;
    for (const DimSlots& k : dims) {
      const Dart s = r[k.s];
      if (k.oriented) {
        const Dart p = r[k.p];
        const bool ok_s = s == no_dart ? k.partial : base[s * stride + k.p] == d;
        const bool ok_p = p == no_dart ? k.partial : base[p * stride + k.s] == d;
        broken |= !(ok_s && ok_p);
      } else {
        broken |= s == no_dart ? !k.partial : base[s * stride + k.s] != d;
      }
      broken |= model.loop_free && s == d;
    }
    for (const Pair& q : pairs) {
      // Both sides of the identity need every intermediate dart.
      const Dart a = r[q.si], b = r[q.pj];
      if (a == no_dart || b == no_dart) {
        report.violations.push_back({Constraint::cycle, q.i, q.j, d});
        continue;
      }
      const Dart lhs = base[a * stride + q.sj], rhs = base[b * stride + q.pi];
      if (lhs != rhs || lhs == no_dart) report.violations.push_back({Constraint::cycle, q.i, q.j, d});
    }
  }
  if (broken) return check_map_exact(map);
  return report;
}

ValidityReport check_map_exact(const Map& map) {
  const Model& model = map.model();
  const Dart n = static_cast<Dart>(map.size());
  ValidityReport report = make_report(map);

  // The i-arcs of the map: (d, link(d)) plus, for an oriented dimension,
  // (inverse(e), e) when the successor array does not record it. `extra`
  // holds the latter, sorted by source.
  struct Arcs {
    std::vector<std::pair<Dart, Dart>> extra;
    std::vector<std::uint32_t> out, in;
  };
  std::vector<Arcs> arcs(max_dimension + 1);
  auto successors = [&](Dim i, Dart x, auto&& f) {
    if (Dart y = map.link(i, x); y != no_dart) f(y);
    const auto& ex = arcs[i].extra;
    for (auto it = std::lower_bound(ex.begin(), ex.end(), std::pair<Dart, Dart>{x, 0}); it != ex.end() && it->first == x; ++it)
      f(it->second);
  };

  for (Dim i : model.dims) {
    Arcs& a = arcs[i];
    a.out.assign(n, 0);
    a.in.assign(n, 0);
    for (Dart d = 0; d < n; ++d)
      if (Dart e = map.link(i, d); e != no_dart) {
        ++a.out[d];
        ++a.in[e];
      }
    if (model.is_oriented(i)) {
      for (Dart e = 0; e < n; ++e)
        if (Dart p = map.inverse_link(i, e); p != no_dart && map.link(i, p) != e) {
          a.extra.emplace_back(p, e);
          ++a.out[p];
          ++a.in[e];
        }
      std::sort(a.extra.begin(), a.extra.end());
    }
    const bool partial = has_dim(model.partial, i);
    for (Dart d = 0; d < n; ++d) {
      if (a.out[d] > 1 || (a.out[d] == 0 && !partial)) report.violations.push_back({Constraint::incident_out, i, -1, d, a.out[d]});
      if (a.in[d] > 1 || (a.in[d] == 0 && !partial)) report.violations.push_back({Constraint::incident_in, i, -1, d, a.in[d]});
    }
    if (!model.is_oriented(i)) {
      // Non-oriented dimensions have no extra arcs: x -> y has a reverse iff
      // link(y) == x, and a missing reverse breaks O(i) at both ends.
      for (Dart x = 0; x < n; ++x)
        if (Dart y = map.link(i, x); y != no_dart && map.link(i, y) != x) {
          report.violations.push_back({Constraint::non_orientation, i, -1, x});
          report.violations.push_back({Constraint::non_orientation, i, -1, y});
        }
    }
    if (model.loop_free)
      for (Dart x = 0; x < n; ++x) {
        bool loop = false;
        successors(i, x, [&](Dart y) { loop |= y == x; });
        if (loop) report.violations.push_back({Constraint::loop, i, -1, x});
      }
  }

  // C(i,j) at v: some ijij-path from v ends at v (paths may branch where
  // I fails, so follow every arc).
  std::vector<Dart> frontier, next;
  for (auto [i, j] : model.exchangeable)
    for (Dart v = 0; v < n; ++v) {
      frontier.assign(1, v);
      for (Dim letter : {i, j, i, j}) {
        next.clear();
        for (Dart x : frontier) successors(letter, x, [&](Dart y) { next.push_back(y); });
        std::sort(next.begin(), next.end());
        next.erase(std::unique(next.begin(), next.end()), next.end());
        std::swap(frontier, next);
      }
      if (!std::binary_search(frontier.begin(), frontier.end(), v)) report.violations.push_back({Constraint::cycle, i, j, v});
    }

  std::sort(report.violations.begin(), report.violations.end(),
            [](const Violation& a, const Violation& b) { return std::tie(a.element, a.constraint, a.i, a.j) < std::tie(b.element, b.constraint, b.i, b.j); });
  report.violations.erase(std::unique(report.violations.begin(), report.violations.end()), report.violations.end());
  return report;
}

}  // namespace dartcheck
