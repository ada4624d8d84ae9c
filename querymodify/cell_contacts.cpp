#include "querymodify/cell_contacts.hpp"

#include <algorithm>
#include <bit>

#include "querymodify/hex_subdivisions.hpp"

namespace dartcheck::querymodify {

namespace {

// The corners of `a` at vertices of `b`, as a mask.
unsigned shared_corners(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) {
  unsigned mask = 0;
  for (std::size_t c = 0; c < a.size(); ++c)
    if (std::find(b.begin(), b.end(), a[c]) != b.end()) mask |= 1u << c;
  return mask;
}

bool is_edge(const CellShape& s, unsigned mask) {
  for (const auto& f : s.faces)
    for (std::size_t k = 0; k < f.size(); ++k)
      if (mask == ((1u << f[k]) | (1u << f[(k + 1) % f.size()]))) return true;
  return false;
}

bool is_face(const CellShape& s, unsigned mask) {
  return std::any_of(s.faces.begin(), s.faces.end(), [&](const auto& f) {
    unsigned m = 0;
    for (int c : f) m |= 1u << c;
    return m == mask;
  });
}

}  // namespace

const CellShape& hex_shape() {
  static const CellShape s = [] {
    CellShape h;
    h.name = "hexahedron";
    h.corners = 8;
    for (const auto& f : hex_faces()) h.faces.push_back({f[0], f[1], f[2], f[3]});
    // The 48 symmetries of the cube, as the recombination reads hexes.
    for (const auto& p : cube_symmetries()) h.symmetries.push_back({p.begin(), p.end()});
    return h;
  }();
  return s;
}

bool conforming_contact(std::span<const std::uint32_t> a, const CellShape& as, std::span<const std::uint32_t> b, const CellShape& bs) {
  const unsigned in_a = shared_corners(a, b), in_b = shared_corners(b, a);
  switch (std::popcount(in_a)) {
    case 0:
    case 1:
      return true;
    case 2:
      return is_edge(as, in_a) && is_edge(bs, in_b);
    case 3:
    case 4:
      return is_face(as, in_a) && is_face(bs, in_b);
    default:
      return false;
  }
}

}  // namespace dartcheck::querymodify
