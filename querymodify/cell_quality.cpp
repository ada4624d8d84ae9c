#include "querymodify/cell_quality.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "querymodify/orientation.hpp"

namespace dartcheck::querymodify {

namespace {

using Point = std::array<double, 3>;

// A corner v with edges towards a, b, c, in the order whose determinant is
// positive on a right-handed cell.
struct Corner {
  int v, a, b, c;
};
constexpr std::array<Corner, 6> prism_corners{{{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5}, {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}}};
constexpr std::array<Corner, 4> pyramid_corners{{{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}}};

double det(const Point& x, const Point& y, const Point& z) {
  return x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) + x[2] * (y[0] * z[1] - y[1] * z[0]);
}

Point minus(const Point& x, const Point& y) { return {x[0] - y[0], x[1] - y[1], x[2] - y[2]}; }
double length(const Point& x) { return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]); }

// The minimum over the corners of scale * det / lengths, signed by the
// cell's handedness (the sign of the corners' sum); 0 if it is positive in
// floating point but some corner's exact sign disagrees.
template <std::size_t N>
double quality(std::span<const Point> p, const std::array<Corner, N>& corners, double scale) {
  std::array<double, N> value{};
  double sum = 0;
  for (std::size_t k = 0; k < N; ++k) {
    const Corner& c = corners[k];
    const Point& v = p[static_cast<std::size_t>(c.v)];
    const Point e1 = minus(p[static_cast<std::size_t>(c.a)], v), e2 = minus(p[static_cast<std::size_t>(c.b)], v),
                e3 = minus(p[static_cast<std::size_t>(c.c)], v);
    const double len = length(e1) * length(e2) * length(e3);
    value[k] = len > 0 ? scale * det(e1, e2, e3) / len : 0;
    sum += value[k];
  }
  const int hand = sum >= 0 ? 1 : -1;
  double lo = 1e300;
  for (double x : value) lo = std::min(lo, hand * x);
  if (lo > 0)
    for (const Corner& c : corners) {
      auto at = [&](int i) { return p[static_cast<std::size_t>(i)]; };
      if (orientation_sign(at(c.a), at(c.b), at(c.c), at(c.v)) != hand) return 0.0;
    }
  return lo;
}

template <std::size_t N, std::size_t M>
bool left_handed(const std::array<std::uint32_t, N>& corners, const std::vector<Point>& points, const std::array<Corner, M>& table) {
  std::array<Point, N> p{};
  for (std::size_t k = 0; k < N; ++k) p[k] = points[corners[k]];
  double sum = 0;
  for (const Corner& c : table) {
    auto at = [&](int i) { return p[static_cast<std::size_t>(i)]; };
    sum += det(minus(at(c.a), at(c.v)), minus(at(c.b), at(c.v)), minus(at(c.c), at(c.v)));
  }
  return sum < 0;
}

}  // namespace

double prism_quality(const std::array<Point, 6>& corner) { return quality(std::span<const Point>(corner), prism_corners, 2 / std::sqrt(3.0)); }

double pyramid_quality(const std::array<Point, 5>& corner) { return quality(std::span<const Point>(corner), pyramid_corners, std::sqrt(2.0)); }

std::array<std::uint32_t, 6> right_handed_prism(const std::array<std::uint32_t, 6>& c, const std::vector<Point>& points) {
  if (!left_handed(c, points, prism_corners)) return c;
  return {c[0], c[2], c[1], c[3], c[5], c[4]};
}

std::array<std::uint32_t, 5> right_handed_pyramid(const std::array<std::uint32_t, 5>& c, const std::vector<Point>& points) {
  if (!left_handed(c, points, pyramid_corners)) return c;
  return {c[0], c[3], c[2], c[1], c[4]};
}

}  // namespace dartcheck::querymodify
