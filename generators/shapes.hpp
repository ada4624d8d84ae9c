// Shape builders: the small maps every test and example starts from.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/map.hpp"
#include "generators/polygon_soup.hpp"

namespace dartcheck {

/// A named shape with its integer parameters, e.g. {"grid", {3, 4}}.
struct ShapeSpec {
  std::string kind;
  std::vector<int> params;
};

/// Cell complexes of the shapes (vertex cycles, consistently oriented).
std::vector<Polygon> polygon_faces(int k);
std::vector<Polygon> grid_faces(int rows, int cols);
std::vector<Polygon> cube_faces(std::uint32_t first_vertex = 0);
std::vector<Polygon> tetrahedron_faces();
std::vector<Polygon> prism_faces(int k);

/// Builds a shape in a model:
///   polygon K (K >= 3)   one K-gon face
///   grid R C             R x C quads
///   cube, tetrahedron, prism K (K >= 3)
///                        the closed surface in 2D models, the solid volume
///                        in n-G-maps with n >= 3
///   stacked-cubes        two cubes sharing a face (3-G-maps; 96 darts)
/// Throws BuildError on an unknown kind, wrong parameters, or a shape the
/// model cannot hold.
Map build_shape(const Model& model, const ShapeSpec& spec);

/// The shape kinds and their parameters, for help texts and errors.
std::string_view shape_usage();

/// Parses "grid:3x4", "polygon:5", "prism:6", "cube".
ShapeSpec parse_shape(std::string_view text);

}  // namespace dartcheck
