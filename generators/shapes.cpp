#include "generators/shapes.hpp"

#include "core/limits.hpp"

#include <charconv>
#include <fmt/format.h>

namespace dartcheck {

std::vector<Polygon> polygon_faces(int k) {
  Polygon f;
  for (int i = 0; i < k; ++i) f.push_back(static_cast<std::uint32_t>(i));
  return {f};
}

std::vector<Polygon> grid_faces(int rows, int cols) {
  auto id = [&](int r, int c) { return static_cast<std::uint32_t>(r * (cols + 1) + c); };
  std::vector<Polygon> faces;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) faces.push_back({id(r, c), id(r, c + 1), id(r + 1, c + 1), id(r + 1, c)});
  return faces;
}

// Vertices 0-3 are the bottom square (counter-clockwise seen from above),
// 4-7 the top one; faces are listed counter-clockwise seen from outside.
std::vector<Polygon> cube_faces(std::uint32_t b) {
  return {{b + 0, b + 3, b + 2, b + 1}, {b + 4, b + 5, b + 6, b + 7}, {b + 0, b + 1, b + 5, b + 4},
          {b + 1, b + 2, b + 6, b + 5}, {b + 2, b + 3, b + 7, b + 6}, {b + 3, b + 0, b + 4, b + 7}};
}

std::vector<Polygon> tetrahedron_faces() { return {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}; }

std::vector<Polygon> prism_faces(int k) {
  const auto n = static_cast<std::uint32_t>(k);
  Polygon bottom, top;
  for (std::uint32_t i = 0; i < n; ++i) {
    bottom.push_back((n - i) % n);
    top.push_back(n + i);
  }
  std::vector<Polygon> faces{bottom, top};
  for (std::uint32_t i = 0; i < n; ++i) faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
  return faces;
}

std::string_view shape_usage() { return "polygon:K (K>=3), grid:RxC, cube, tetrahedron, prism:K (K>=3), stacked-cubes"; }

ShapeSpec parse_shape(std::string_view text) {
  ShapeSpec s;
  auto colon = text.find(':');
  s.kind = std::string(text.substr(0, colon));
  if (colon == std::string_view::npos) return s;
  std::string_view rest = text.substr(colon + 1);
  while (!rest.empty()) {
    int v = 0;
    auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), v);
    if (ec != std::errc{}) throw BuildError(fmt::format("shape '{}': expected a number at '{}'", text, rest));
    s.params.push_back(v);
    rest.remove_prefix(static_cast<std::size_t>(end - rest.data()));
    if (!rest.empty()) {
      if (rest.front() != 'x' && rest.front() != ',') throw BuildError(fmt::format("shape '{}': expected 'x' or ',' at '{}'", text, rest));
      rest.remove_prefix(1);
    }
  }
  return s;
}

Map build_shape(const Model& model, const ShapeSpec& spec) {
  auto need = [&](std::size_t count, int min) {
    if (spec.params.size() != count)
      throw BuildError(fmt::format("shape '{}' takes {} parameter(s), got {} (shapes: {})", spec.kind, count, spec.params.size(), shape_usage()));
    for (int p : spec.params)
      if (p < min) throw BuildError(fmt::format("shape '{}': parameter {} is below {}", spec.kind, p, min));
  };
  // The darts a shape will have, bounded before anything is allocated: a
  // face side is at most two darts (G-maps: exactly two; O-maps: one, and
  // one more on the boundary's outer face), so 2 x sides. A grid:100000x100000
  // is refused here, not by the allocator.
  auto bound = [&](long double sides) {
    const long double darts = 2 * sides;
    if (darts > static_cast<long double>(limits().darts))
      throw BuildError(fmt::format("shape '{}' would have up to {:.0f} darts, over the limit of {} (raise it with --limit-darts)", spec.kind,
                                   static_cast<double>(darts), limits().darts));
  };
  if (spec.kind == "polygon" && spec.params.size() == 1) bound(spec.params[0]);
  if (spec.kind == "grid" && spec.params.size() == 2) bound(4.0L * spec.params[0] * spec.params[1]);
  if (spec.kind == "prism" && spec.params.size() == 1) bound(6.0L * spec.params[0]);
  const bool solid = model.dimension() >= 3;
  auto closed = [&](std::vector<Polygon> faces) { return solid ? build_volumes(model, {faces}) : build_surface(model, faces); };
  if (spec.kind == "polygon") {
    need(1, 3);
    return build_surface(model, polygon_faces(spec.params[0]));
  }
  if (spec.kind == "grid") {
    need(2, 1);
    return build_surface(model, grid_faces(spec.params[0], spec.params[1]));
  }
  if (spec.kind == "cube") {
    need(0, 0);
    return closed(cube_faces());
  }
  if (spec.kind == "tetrahedron") {
    need(0, 0);
    return closed(tetrahedron_faces());
  }
  if (spec.kind == "prism") {
    need(1, 3);
    return closed(prism_faces(spec.params[0]));
  }
  if (spec.kind == "stacked-cubes") {
    need(0, 0);
    if (!solid) throw BuildError(fmt::format("stacked-cubes is a 3-dimensional shape; {} has dimension {}", model.name, model.dimension()));
    return build_volumes(model, {cube_faces(0), cube_faces(4)});
  }
  throw BuildError(fmt::format("unknown shape '{}' (shapes: {})", spec.kind, shape_usage()));
}

}  // namespace dartcheck
