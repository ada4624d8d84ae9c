#include "generators/random_maps.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/error.hpp"
#include "core/orbit.hpp"

namespace dartcheck {
namespace {

// Darts of the G-map face `first`.. of k sides: side e is 2e (start) and
// 2e+1 (end); 0-links inside a side, 1-links between consecutive sides.
void add_gmap_face(Map& m, std::size_t k) {
  const Dart b = m.add_darts(2 * k);
  for (std::size_t e = 0; e < k; ++e) {
    m.sew(0, b + 2 * e, b + 2 * e + 1);
    m.sew(1, b + 2 * e + 1, b + 2 * ((e + 1) % k));
  }
}

void loop_all(Map& m, Dim i) {
  for (Dart d = 0; d < m.size(); ++d)
    if (m.link(i, d) == no_dart) m.sew(i, d, d);
}

// The darts of a <0,1>-orbit in walking order d, a0 d, a1 a0 d, ...
std::vector<Dart> face_walk(const Map& m, Dart d) {
  std::vector<Dart> w;
  Dart x = d;
  do {
    w.push_back(x);
    x = m.link(w.size() % 2 == 1 ? 0 : 1, x);
  } while (x != d);
  return w;
}

void sew_gmap(Map& m, const SewStep& s) {
  const Dim n = m.model().dimension();
  if (s.dim == 2 || n < 3) {
    // Free edges: one representative dart d < a0(d) with both darts 2-free.
    std::vector<Dart> free;
    for (Dart d = 0; d < m.size(); ++d) {
      const Dart e = m.link(0, d);
      if (d < e && m.link(2, d) == d && m.link(2, e) == e) free.push_back(d);
    }
    if (free.size() < 2) return;
    const Dart x = free[s.a % free.size()], y = free[s.b % free.size()];
    if (x == y) return;
    const Dart y0 = s.twist % 2 ? m.link(0, y) : y;
    m.sew(2, x, y0);
    m.sew(2, m.link(0, x), m.link(0, y0));
  } else {
    // 3-free faces: walks whose darts all carry 3-loops.
    std::vector<Dart> free;
    for_each_class(
        m.size(), all_darts(m.size()), [&](Dart d) { return face_walk(m, d); },
        [&](Dart d, const std::vector<Dart>& walk) {
          if (std::all_of(walk.begin(), walk.end(), [&](Dart x) { return m.link(3, x) == x; })) free.push_back(d);
        });
    if (free.size() < 2) return;
    const Dart x = free[s.a % free.size()], y = free[s.b % free.size()];
    if (x == y) return;
    const auto wx = face_walk(m, x), wy = face_walk(m, y);
    if (wx.size() != wy.size()) return;
    // Start y's walk at any of its darts with a matching parity of links:
    // an offset by an even step keeps 0-sides on 0-sides.
    const std::size_t k = wy.size();
    const std::size_t start = 2 * (s.twist % (k / 2));
    const bool reflect = (s.twist / (k / 2)) % 2;
    for (std::size_t t = 0; t < k; ++t) {
      // Reflection walks y's face backwards from a dart whose 0-link is
      // first: wy[start + 1] then wy[start], wy[start - 1], ...
      const std::size_t idx = reflect ? (start + 1 + k - t) % k : (start + t) % k;
      m.sew(3, wx[t], wy[idx]);
    }
  }
}

}  // namespace

Map build_random_map(const Model& model, const MapRecipe& recipe) {
  const Dim n = model.dimension();
  Map m(model);
  if (model.is_generalized()) {
    if (n < 1 || n > 3) throw ValueError("random G-maps are built for dimensions 1 to 3");
    for (auto k : recipe.face_sizes) add_gmap_face(m, k);
    if (n >= 2) loop_all(m, 2);
    if (n >= 3) loop_all(m, 3);
    if (n >= 2)
      for (const SewStep& s : recipe.sewings) sew_gmap(m, s);
    return m;
  }
  if (n < 2 || n > 3) throw ValueError("random O-maps are built for dimensions 2 and 3");
  const int copies = n == 3 ? 2 : 1;
  std::vector<std::pair<Dart, std::size_t>> faces;
  for (auto k : recipe.face_sizes)
    for (int c = 0; c < copies; ++c) {
      const Dart b = m.add_darts(k);
      for (Dart e = 0; e < k; ++e) m.sew(1, b + e, b + (e + 1) % k);
      faces.emplace_back(b, k);
    }
  if (n == 3)
    for (std::size_t f = 0; f < faces.size(); f += 2) {
      auto [b1, k] = faces[f];
      const Dart b2 = faces[f + 1].first;
      const std::size_t r = recipe.sewings.empty() ? 0 : recipe.sewings[(f / 2) % recipe.sewings.size()].twist % k;
      for (std::size_t i = 0; i < k; ++i) m.sew(3, b1 + static_cast<Dart>(i), b2 + static_cast<Dart>((r + k - i) % k));
    }
  for (const SewStep& s : recipe.sewings) {
    std::vector<Dart> free;
    for (Dart d = 0; d < m.size(); ++d)
      if (m.link(2, d) == no_dart) free.push_back(d);
    if (free.empty()) break;
    m.sew(2, free[s.a % free.size()], free[s.b % free.size()]);
  }
  loop_all(m, 2);
  return m;
}

void apply_corruption(Map& map, const LinkCorruption& c) {
  const std::size_t n = map.size();
  if (n == 0) return;
  const Dart d = static_cast<Dart>(c.dart % n);
  const Dim i = map.model().dims[c.dim % map.model().dims.size()];
  const Dart t = c.target % (n + 1) == n ? no_dart : static_cast<Dart>(c.target % (n + 1));
  if (c.resew) {
    const Dart e = static_cast<Dart>(c.target % n);
    const Dart sd = map.link(i, d), se = map.link(i, e);
    if (sd == no_dart || se == no_dart || d == e) return;
    if (map.model().is_oriented(i)) {
      map.set_link(i, d, se);
      map.set_link(i, e, sd);
    } else if (sd != e) {
      // d-sd and e-se become d-se and e-sd (loops stay loops of the other).
      const Dart pd = sd == d ? e : sd, pe = se == e ? d : se;
      map.sew(i, d, pe);
      map.sew(i, e, pd);
    }
    return;
  }
  if (c.inverse && map.model().is_oriented(i))
    map.set_inverse_link_raw(i, d, t);
  else
    map.set_link_raw(i, d, t);
}

bool has_random_generator(const Model& m) {
  for (int n = 1; n <= 3; ++n)
    if (m == Model::gmap(n) || (n >= 2 && m == Model::omap(n))) return true;
  return false;
}

MapRecipe draw_recipe(std::mt19937& rng, std::uint32_t faces, int top_dim) {
  auto pick = [&](std::uint32_t lo, std::uint32_t hi) { return std::uniform_int_distribution<std::uint32_t>(lo, hi)(rng); };
  MapRecipe recipe;
  for (std::uint32_t f = 0; f < faces; ++f) recipe.face_sizes.push_back(static_cast<std::uint8_t>(pick(1, 6)));
  const std::uint32_t sewings = pick(0, 2 * faces);
  const auto top = static_cast<std::uint32_t>(std::max(2, top_dim));
  for (std::uint32_t k = 0; k < sewings; ++k)
    recipe.sewings.push_back({static_cast<std::uint8_t>(pick(2, top)), pick(0, 999), pick(0, 999), pick(0, 999)});
  return recipe;
}

std::vector<MapRecipe> shrink_candidates(const MapRecipe& r) {
  std::vector<MapRecipe> out;
  const std::size_t faces = r.face_sizes.size(), sewings = r.sewings.size();
  auto keep = [&](std::size_t f, std::size_t s) {
    MapRecipe c;
    c.face_sizes.assign(r.face_sizes.begin(), r.face_sizes.begin() + static_cast<std::ptrdiff_t>(f));
    c.sewings.assign(r.sewings.begin(), r.sewings.begin() + static_cast<std::ptrdiff_t>(s));
    out.push_back(std::move(c));
  };
  // Large steps first: half the faces, then no sewings, then one element
  // at a time (each face, each sewing, each face one edge shorter).
  if (faces > 1) keep(faces / 2, sewings);
  if (sewings > 0) keep(faces, 0);
  for (std::size_t k = faces; k-- > 0;) {
    if (faces == 1) break;
    MapRecipe c = r;
    c.face_sizes.erase(c.face_sizes.begin() + static_cast<std::ptrdiff_t>(k));
    out.push_back(std::move(c));
  }
  for (std::size_t k = sewings; k-- > 0;) {
    MapRecipe c = r;
    c.sewings.erase(c.sewings.begin() + static_cast<std::ptrdiff_t>(k));
    out.push_back(std::move(c));
  }
  for (std::size_t k = 0; k < faces; ++k)
    if (r.face_sizes[k] > 1) {
      MapRecipe c = r;
      --c.face_sizes[k];
      out.push_back(std::move(c));
    }
  return out;
}

}  // namespace dartcheck
