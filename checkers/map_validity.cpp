#include "checkers/map_validity.hpp"

#include <array>
#include "core/orbit.hpp"

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

  // The i-arcs of the map are (d, link(d)). For an oriented dimension the
  // recorded predecessors must name the sources of those arcs.
  std::vector<std::uint32_t> out(n), in(n);
  std::vector<Dart> source(n);
  for (Dim i : model.dims) {
    std::fill(out.begin(), out.end(), 0);
    std::fill(in.begin(), in.end(), 0);
    for (Dart d = 0; d < n; ++d)
      if (Dart e = map.link(i, d); e != no_dart) {
        ++out[d];
        ++in[e];
        source[e] = d;
      }
    const bool partial = has_dim(model.partial, i);
    for (Dart d = 0; d < n; ++d) {
      if (out[d] > 1 || (out[d] == 0 && !partial)) report.violations.push_back({Constraint::incident_out, i, -1, d, out[d]});
      if (in[d] > 1 || (in[d] == 0 && !partial)) report.violations.push_back({Constraint::incident_in, i, -1, d, in[d]});
      if (model.is_oriented(i) && in[d] <= 1) {
        const Dart recorded = map.inverse_link(i, d), actual = in[d] ? source[d] : no_dart;
        if (recorded != actual)
          report.violations.push_back({Constraint::predecessor, i, actual == no_dart ? -1 : static_cast<Dim>(actual), d, recorded});
      }
      if (model.loop_free && map.link(i, d) == d) report.violations.push_back({Constraint::loop, i, -1, d});
    }
    if (!model.is_oriented(i)) {
      // x -> y has a reverse iff link(y) == x; a missing reverse breaks O(i)
      // at both ends.
      for (Dart x = 0; x < n; ++x)
        if (Dart y = map.link(i, x); y != no_dart && map.link(i, y) != x) {
          report.violations.push_back({Constraint::non_orientation, i, -1, x});
          report.violations.push_back({Constraint::non_orientation, i, -1, y});
        }
    }
  }

  // C(i,j) at v: the ijij-path from v (unique: one arc per label) ends at v.
  for (auto [i, j] : model.exchangeable)
    for (Dart v = 0; v < n; ++v)
      if (follow(map, v, std::array<Dim, 4>{i, j, i, j}) != v) report.violations.push_back({Constraint::cycle, i, j, v});

  std::sort(report.violations.begin(), report.violations.end(),
            [](const Violation& a, const Violation& b) { return std::tie(a.element, a.constraint, a.i, a.j) < std::tie(b.element, b.constraint, b.i, b.j); });
  report.violations.erase(std::unique(report.violations.begin(), report.violations.end()), report.violations.end());
  return report;
}

}  // namespace dartcheck
