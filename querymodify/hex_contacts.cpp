#include "querymodify/hex_contacts.hpp"

#include <bit>

namespace dartcheck::querymodify {

namespace {

// The cube corners of `h` at the vertices of `other`, as a mask of bits.
unsigned shared_corners(const HexCorners& h, const HexCorners& other) {
  unsigned mask = 0;
  for (unsigned c = 0; c < 8; ++c)
    for (std::uint32_t v : other)
      if (h[c] == v) mask |= 1u << c;
  return mask;
}

// An edge of the cube: corners that differ in one coordinate. A face:
// four corners that agree in one coordinate.
bool is_edge_or_face(unsigned mask) {
  const int n = std::popcount(mask);
  if (n <= 1) return true;
  if (n != 2 && n != 4) return false;
  for (unsigned axis = 1; axis <= 4; axis <<= 1) {
    unsigned low = 0, high = 0;  // the mask's corners on either side of the axis
    for (unsigned c = 0; c < 8; ++c)
      if (mask >> c & 1) (c & axis ? high : low) |= 1u << c;
    if (n == 2 && low && high && (low << axis) == high) return true;  // an edge along this axis
    if (n == 4 && (!low || !high)) return true;                       // a face across it
  }
  return false;
}

}  // namespace

bool conforming_contact(const HexCorners& a, const HexCorners& b) {
  return is_edge_or_face(shared_corners(a, b)) && is_edge_or_face(shared_corners(b, a));
}

}  // namespace dartcheck::querymodify
