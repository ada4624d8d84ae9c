#include "checkers/map_validity.hpp"

#include <array>
#include <system_error>
#include <thread>

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

namespace {

// The slot layout of a model's records: which slots hold each dimension's
// link and recorded predecessor, and the exchangeable pairs.
struct Layout {
  std::size_t nd = 0, np = 0, stride = 0;
  bool loop_free = false;
  std::array<DimSlots, max_dimension + 1> dims{};
  std::array<Pair, (max_dimension + 1) * (max_dimension + 1)> pairs{};
};

Layout layout_of(const Map& map) {
  const Model& model = map.model();
  Layout l;
  l.stride = map.stride();
  l.loop_free = model.loop_free;
  for (Dim i : model.dims) l.dims[l.nd++] = {i, map.succ_slot(i), map.pred_slot(i), model.is_oriented(i), has_dim(model.partial, i)};
  for (auto [i, j] : model.exchangeable) l.pairs[l.np++] = {map.succ_slot(i), map.succ_slot(j), map.pred_slot(i), map.pred_slot(j), i, j};
  return l;
}

bool same_layout(const Layout& a, const Layout& b) {
  if (a.nd != b.nd || a.np != b.np || a.stride != b.stride || a.loop_free != b.loop_free) return false;
  for (std::size_t x = 0; x < a.nd; ++x) {
    const DimSlots &p = a.dims[x], &q = b.dims[x];
    if (p.i != q.i || p.s != q.s || p.p != q.p || p.oriented != q.oriented || p.partial != q.partial) return false;
  }
  for (std::size_t y = 0; y < a.np; ++y) {
    const Pair &p = a.pairs[y], &q = b.pairs[y];
    if (p.si != q.si || p.sj != q.sj || p.pi != q.pi || p.pj != q.pj || p.i != q.i || p.j != q.j) return false;
  }
  return true;
}

// The fast pass. When the layout is a compile-time constant (the preset
// models), loops unroll and every offset is a constant. Returns false as
// soon as some dart breaks I, O or the loop ban; cycle failures go to `out`.
// Checks the darts lo..hi-1; the records they read may be anywhere.
template <class GetLayout>
bool fast_pass(const Dart* base, Dart lo, Dart hi, GetLayout layout, std::vector<Violation>& out) {
  const Layout& L = layout();
  const std::size_t stride = L.stride;
  // Each dart reads the records of its neighbours, which are anywhere in
  // memory when darts are shuffled: request them a few darts ahead so the
  // cache misses overlap.
  constexpr Dart ahead = 16;
  bool broken = false;
  for (Dart d = lo; d < hi; ++d) {
    if (d + ahead < hi) {
      // The records read below: those of the link targets, and of the
      // recorded predecessors where a partial dimension needs them.
      const Dart* f = base + (d + ahead) * stride;
      for (std::size_t x = 0; x < L.nd; ++x) {
        if (f[L.dims[x].s] != no_dart) __builtin_prefetch(base + f[L.dims[x].s] * stride);
        if (L.dims[x].oriented && L.dims[x].partial && f[L.dims[x].p] != no_dart) __builtin_prefetch(base + f[L.dims[x].p] * stride);
      }
    }
    const Dart* r = base + d * stride;
    for (std::size_t x = 0; x < L.nd; ++x) {
      const DimSlots& k = L.dims[x];
      const Dart s = r[k.s];
      if (k.oriented && !k.partial) {
        // pred(succ(d)) = d for every d makes succ injective, hence a
        // bijection of the finite dart set, and pred its inverse: the
        // converse check succ(pred(d)) = d would read one more random record.
        broken |= s == no_dart || base[s * stride + k.p] != d;
      } else if (k.oriented) {
        const Dart p = r[k.p];
        const bool ok_s = s == no_dart || base[s * stride + k.p] == d;
        const bool ok_p = p == no_dart || base[p * stride + k.s] == d;
        broken |= !(ok_s && ok_p);
      } else {
        broken |= s == no_dart ? !k.partial : base[s * stride + k.s] != d;
      }
      if (L.loop_free) broken |= s == d;
    }
    for (std::size_t y = 0; y < L.np; ++y) {
      const Pair& q = L.pairs[y];
      // Both sides of the identity need every intermediate dart.
      const Dart a = r[q.si], b = r[q.pj];
      if (a == no_dart || b == no_dart || base[a * stride + q.sj] != base[b * stride + q.pi] || base[a * stride + q.sj] == no_dart)
        out.push_back({Constraint::cycle, q.i, q.j, d});
    }
    if (broken) return false;
  }
  return true;
}

// Layouts of the preset models, as Map lays them out: links in dimension
// order, then the predecessors of oriented dimensions.
constexpr Layout preset(int n, bool generalized) {
  Layout l;
  const Dim lo = generalized ? 0 : 1;
  for (Dim i = lo; i <= n; ++i) l.dims[l.nd++] = {i, i - lo, i - lo, !generalized && i == 1, false};
  l.stride = l.nd + (generalized ? 0 : 1);
  if (!generalized) l.dims[0].p = static_cast<int>(l.nd);
  for (Dim i = lo; i <= n; ++i)
    for (Dim j = i + 2; j <= n; ++j) l.pairs[l.np++] = {l.dims[i - lo].s, l.dims[j - lo].s, l.dims[i - lo].p, l.dims[j - lo].p, i, j};
  return l;
}
constexpr Layout gmap2 = preset(2, true), gmap3 = preset(3, true), omap2 = preset(2, false), omap3 = preset(3, false);

// The fast pass over `threads` consecutive dart ranges, one thread each:
// darts are independent, and on a map larger than the caches each thread
// keeps its own cache misses in flight. Cycle failures are concatenated
// in range order, so the report is the one-thread report.
template <class GetLayout>
bool split_pass(const Dart* base, Dart n, unsigned threads, GetLayout layout, std::vector<Violation>& out) {
  if (threads <= 1) return fast_pass(base, 0, n, layout, out);
  std::vector<std::vector<Violation>> found(threads);
  std::vector<char> ok(threads, 0);
  auto range = [&](unsigned t) { return static_cast<Dart>(static_cast<std::uint64_t>(n) * t / threads); };
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < threads; ++t) {
      auto part = [&, t] { ok[t] = fast_pass(base, range(t), range(t + 1), layout, found[t]); };
      try {
        pool.emplace_back(part);
      } catch (const std::system_error&) {
        part();  // no thread to be had: this one checks the range
      }
    }
    ok[0] = fast_pass(base, 0, range(1), layout, found[0]);
  }
  for (unsigned t = 0; t < threads; ++t) {
    if (!ok[t]) return false;
    out.insert(out.end(), found[t].begin(), found[t].end());
  }
  return true;
}

}  // namespace

unsigned validity_threads(std::size_t darts) {
  if (darts < parallel_validity_darts) return 1;
  return std::clamp(std::thread::hardware_concurrency(), 1U, 8U);
}

ValidityReport check_map(const Map& map, unsigned threads) {
  ValidityReport report = make_report(map);
  const Dart* base = map.raw().data();
  const Dart n = static_cast<Dart>(map.size());
  if (threads == 0) threads = validity_threads(n);
  threads = std::clamp<unsigned>(threads, 1, std::max<Dart>(n, 1));
  const Layout mine = layout_of(map);
  bool ok;
  if (same_layout(mine, gmap2))
    ok = split_pass(
        base, n, threads, []() -> const Layout& { return gmap2; }, report.violations);
  else if (same_layout(mine, omap2))
    ok = split_pass(
        base, n, threads, []() -> const Layout& { return omap2; }, report.violations);
  else if (same_layout(mine, gmap3))
    ok = split_pass(
        base, n, threads, []() -> const Layout& { return gmap3; }, report.violations);
  else if (same_layout(mine, omap3))
    ok = split_pass(
        base, n, threads, []() -> const Layout& { return omap3; }, report.violations);
  else
    ok = split_pass(
        base, n, threads, [&mine]() -> const Layout& { return mine; }, report.violations);
  return ok ? report : check_map_exact(map);
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

  std::sort(report.violations.begin(), report.violations.end(), [](const Violation& a, const Violation& b) {
    return std::tie(a.element, a.constraint, a.i, a.j) < std::tie(b.element, b.constraint, b.i, b.j);
  });
  report.violations.erase(std::unique(report.violations.begin(), report.violations.end()), report.violations.end());
  return report;
}

}  // namespace dartcheck
