// Subdivision topologies written at the polygon level, as independent
// oracles for the inference tests: each returns the after faces and, for
// each before dart it preserves, the after dart that κ sends it to. Darts
// are named as build_surface numbers them: face f's darts are 2 per side,
// dart first(f) + 2e at vertex f[e] towards f[e+1], first(f) + 2e + 1 at
// f[e+1] towards f[e].
#pragma once

#include <cstdint>
#include <map>
#include <tuple>
#include <stdexcept>
#include <utility>
#include <vector>

#include "generators/polygon_soup.hpp"

namespace dartcheck::inference::test {

/// A dart of a polygon soup: face, the vertex it sits at, the vertex it
/// looks towards along its side.
struct SoupDart {
  std::uint32_t face, at, to;
};

inline Dart soup_dart(const std::vector<Polygon>& faces, const SoupDart& s) {
  Dart first = 0;
  for (std::uint32_t f = 0; f < s.face; ++f) first += static_cast<Dart>(2 * faces[f].size());
  const auto& p = faces[s.face];
  const std::size_t k = p.size();
  for (std::size_t e = 0; e < k; ++e) {
    if (p[e] == s.at && p[(e + 1) % k] == s.to) return first + static_cast<Dart>(2 * e);
    if (p[(e + 1) % k] == s.at && p[e] == s.to) return first + static_cast<Dart>(2 * e + 1);
  }
  throw std::logic_error("no such dart in the soup");
}

struct Subdivided {
  std::vector<Polygon> faces;
  std::vector<std::pair<SoupDart, SoupDart>> kappa;  // before dart -> after dart
};

inline std::uint32_t vertex_count(const std::vector<Polygon>& faces) {
  std::uint32_t n = 0;
  for (const auto& f : faces)
    for (auto v : f) n = std::max(n, v + 1);
  return n;
}

/// One new vertex per edge, numbered after the old ones.
class Midpoints {
 public:
  explicit Midpoints(std::uint32_t next) : next_(next) {}
  std::uint32_t operator()(std::uint32_t a, std::uint32_t b) {
    const auto key = std::minmax(a, b);
    auto [it, fresh] = ids_.emplace(key, next_);
    if (fresh) ++next_;
    return it->second;
  }
  std::uint32_t next() { return next_++; }

 private:
  std::uint32_t next_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> ids_;
};

/// The old darts of corner v of face f (sides towards next and prev) stay
/// at v in the after face `sub`, looking at the new vertices `to_next` and
/// `to_prev` of those sides.
inline void keep_corner(Subdivided& s, std::uint32_t f, std::uint32_t v, std::uint32_t next, std::uint32_t prev, std::uint32_t sub,
                        std::uint32_t to_next, std::uint32_t to_prev) {
  s.kappa.push_back({{f, v, next}, {sub, v, to_next}});
  s.kappa.push_back({{f, v, prev}, {sub, v, to_prev}});
}

/// Quad subdivision (000 Sec. 4.4; Catmull-Clark's topology): a vertex per
/// edge and per face, the face split into one quad per corner. The old
/// darts stay at their corners, looking at the edge midpoints.
inline Subdivided quad_subdivision(const std::vector<Polygon>& faces) {
  Subdivided s;
  Midpoints mid(vertex_count(faces));
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    const auto& p = faces[f];
    const std::size_t k = p.size();
    const std::uint32_t center = mid.next();
    const auto base = static_cast<std::uint32_t>(s.faces.size());
    for (std::size_t i = 0; i < k; ++i) {
      const auto v = p[i], next = p[(i + 1) % k], prev = p[(i + k - 1) % k];
      s.faces.push_back({v, mid(v, next), center, mid(prev, v)});
      keep_corner(s, f, v, next, prev, base + static_cast<std::uint32_t>(i), mid(v, next), mid(prev, v));
    }
  }
  return s;
}

/// Loop's topology (000 Sec. 9.1.2; also Butterfly's): a vertex per edge,
/// each triangle split into four.
inline Subdivided loop_subdivision(const std::vector<Polygon>& faces) {
  Subdivided s;
  Midpoints mid(vertex_count(faces));
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    const auto& p = faces[f];
    if (p.size() != 3) throw std::logic_error("Loop subdivision takes triangles");
    const auto base = static_cast<std::uint32_t>(s.faces.size());
    for (std::size_t i = 0; i < 3; ++i) {
      const auto v = p[i], next = p[(i + 1) % 3], prev = p[(i + 2) % 3];
      s.faces.push_back({v, mid(v, next), mid(prev, v)});
      keep_corner(s, f, v, next, prev, base + static_cast<std::uint32_t>(i), mid(v, next), mid(prev, v));
    }
    s.faces.push_back({mid(p[0], p[1]), mid(p[1], p[2]), mid(p[2], p[0])});
  }
  return s;
}

/// Powell-Sabin 6-split (000 Sec. 9.1.3): a vertex per edge and per face,
/// the face centre joined to every corner and every midpoint.
inline Subdivided powell_sabin(const std::vector<Polygon>& faces) {
  Subdivided s;
  Midpoints mid(vertex_count(faces));
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    const auto& p = faces[f];
    const std::size_t k = p.size();
    const std::uint32_t center = mid.next();
    const auto base = static_cast<std::uint32_t>(s.faces.size());
    for (std::size_t i = 0; i < k; ++i) {
      const auto v = p[i], next = p[(i + 1) % k];
      s.faces.push_back({v, mid(v, next), center});
      s.faces.push_back({mid(v, next), next, center});
    }
    for (std::size_t i = 0; i < k; ++i) {
      const auto v = p[i], next = p[(i + 1) % k], prev = p[(i + k - 1) % k];
      s.kappa.push_back({{f, v, next}, {base + static_cast<std::uint32_t>(2 * i), v, mid(v, next)}});
      s.kappa.push_back({{f, v, prev}, {base + static_cast<std::uint32_t>(2 * ((i + k - 1) % k) + 1), v, mid(prev, v)}});
    }
  }
  return s;
}

/// Kobbelt's sqrt(3) (000 Sec. 9.1.4): a vertex per face joined to its
/// corners, then every old edge flipped: edge {a, b} between faces f1 and
/// f2 becomes the triangles (a, g1, g2) and (b, g2, g1). An old dart at a
/// on edge ab in face f stays at a in the triangle of edge ab, looking at
/// f's centre.
inline Subdivided sqrt3(const std::vector<Polygon>& faces) {
  Subdivided s;
  const std::uint32_t n = vertex_count(faces);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edge_faces;
  for (std::uint32_t f = 0; f < faces.size(); ++f)
    for (std::size_t i = 0; i < faces[f].size(); ++i) edge_faces[std::minmax(faces[f][i], faces[f][(i + 1) % faces[f].size()])].push_back(f);
  for (const auto& [edge, fs] : edge_faces) {
    if (fs.size() != 2) throw std::logic_error("sqrt3 takes closed surfaces");
    const auto [a, b] = edge;
    const std::uint32_t g1 = n + fs[0], g2 = n + fs[1];
    const auto base = static_cast<std::uint32_t>(s.faces.size());
    s.faces.push_back({a, g1, g2});
    s.faces.push_back({b, g2, g1});
    s.kappa.push_back({{fs[0], a, b}, {base, a, g1}});
    s.kappa.push_back({{fs[1], a, b}, {base, a, g2}});
    s.kappa.push_back({{fs[0], b, a}, {base + 1, b, g1}});
    s.kappa.push_back({{fs[1], b, a}, {base + 1, b, g2}});
  }
  return s;
}

/// Doo-Sabin (000 Sec. 9.1.5): a new vertex per face corner; each face
/// shrinks to the face of its corners (F-face), each edge becomes a quad
/// (E-face), each vertex a face of its corners (V-face). An old dart stays
/// in the F-face of its face, at its corner, looking at the next corner
/// along its side. Works on any closed surface.
inline Subdivided doo_sabin(const std::vector<Polygon>& faces) {
  Subdivided s;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> corner;  // (face, vertex) -> new vertex
  std::uint32_t next = 0;
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    Polygon shrunk;
    for (auto v : faces[f]) {
      corner[{f, v}] = next;
      shrunk.push_back(next++);
    }
    s.faces.push_back(shrunk);
    const std::size_t k = faces[f].size();
    for (std::size_t i = 0; i < k; ++i) {
      const auto v = faces[f][i], w = faces[f][(i + 1) % k], u = faces[f][(i + k - 1) % k];
      s.kappa.push_back({{f, v, w}, {f, corner[{f, v}], corner[{f, w}]}});  // the corner moves: not keep_corner
      s.kappa.push_back({{f, v, u}, {f, corner[{f, v}], corner[{f, u}]}});
    }
  }
  // The face with side a -> b, for each directed side.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> directed;
  for (std::uint32_t f = 0; f < faces.size(); ++f)
    for (std::size_t i = 0; i < faces[f].size(); ++i) directed[{faces[f][i], faces[f][(i + 1) % faces[f].size()]}] = f;
  // E-faces: edge {a, b} between f (a -> b) and g (b -> a).
  for (const auto& [ab, f] : directed) {
    const auto [a, b] = ab;
    if (a > b) continue;
    const auto g = directed.at({b, a});
    s.faces.push_back({corner[{f, a}], corner[{g, a}], corner[{g, b}], corner[{f, b}]});
  }
  // V-faces: the corners around each vertex v, turning from face f (side
  // u -> v) to the face across that side (side v -> u).
  std::map<std::uint32_t, bool> done;
  for (std::uint32_t f0 = 0; f0 < faces.size(); ++f0)
    for (const auto v : faces[f0]) {
      if (done[v]) continue;
      done[v] = true;
      Polygon around;
      std::uint32_t f = f0;
      do {
        around.push_back(corner[{f, v}]);
        const auto& p = faces[f];
        const std::size_t k = p.size();
        std::size_t i = 0;
        while (p[i] != v) ++i;
        f = directed.at({v, p[(i + k - 1) % k]});
      } while (f != f0);
      s.faces.push_back(around);
    }
  return s;
}

/// Applies `second` after `first`, composing their κ.
inline Subdivided iterate(const Subdivided& first, Subdivided (*second)(const std::vector<Polygon>&)) {
  Subdivided two = second(first.faces);
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, SoupDart> step;
  for (const auto& [b, a] : two.kappa) step[{b.face, b.at, b.to}] = a;
  Subdivided out;
  out.faces = two.faces;
  for (const auto& [b, a] : first.kappa)
    if (auto it = step.find({a.face, a.at, a.to}); it != step.end()) out.kappa.push_back({b, it->second});
  return out;
}

inline std::vector<Polygon> octahedron_faces() {
  // Vertices: 0 top, 5 bottom, 1..4 around.
  return {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {5, 2, 1}, {5, 3, 2}, {5, 4, 3}, {5, 1, 4}};
}

inline std::vector<Polygon> icosahedron_faces() {
  // 0 top, 1..5 upper ring, 6..10 lower ring, 11 bottom.
  std::vector<Polygon> f;
  for (std::uint32_t i = 0; i < 5; ++i) {
    const std::uint32_t u = 1 + i, un = 1 + (i + 1) % 5, l = 6 + i, ln = 6 + (i + 1) % 5;
    f.push_back({0, u, un});
    f.push_back({u, l, un});
    f.push_back({un, l, ln});
    f.push_back({11, ln, l});
  }
  return f;
}

}  // namespace dartcheck::inference::test
