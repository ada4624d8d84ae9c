// Random valid maps from recipes, and random link corruptions.
//
// A recipe lists the cells to create and the sewings to perform, with
// indices taken modulo what exists when the step runs. Every recipe builds
// a valid map, so RapidCheck can shrink a recipe (fewer faces, fewer
// sewings) and every shrunk value is still a valid map: no discards.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "core/map.hpp"

namespace dartcheck {

/// One sewing step: join the `a`-th and `b`-th free cells (modulo their
/// number) of dimension `dim`; `twist` picks one of the ways to align them.
struct SewStep {
  std::uint8_t dim;
  std::uint32_t a, b, twist;
};

struct MapRecipe {
  std::vector<std::uint8_t> face_sizes;  // 1..6 edges each
  std::vector<SewStep> sewings;
};

/// Builds the map of a recipe; valid for 1- to 3-G-maps and 2- and 3-O-maps.
///  - G-maps: faces are <0,1>-cycles of 2k darts; 2-sewing joins two free
///    edges, 3-sewing two 3-free faces of the same size with a rotation
///    and reflection, so C(0,3), C(1,3) hold by construction.
///  - 2-O-maps: faces are 1-cycles; 2-sewing pairs two 2-free darts, the
///    rest gets 2-loops.
///  - 3-O-maps: each face size is created twice and every face is 3-sewn
///    to its twin by d_i <-> e_{(r-i) mod k}, which makes every 1313-path a
///    cycle; 2-sewing as in 2-O-maps.
Map build_random_map(const Model& model, const MapRecipe& recipe);

/// True for the models build_random_map builds (1-3-G-maps, 2-3-O-maps).
bool has_random_generator(const Model& model);

/// A recipe drawn from a seeded engine, outside RapidCheck (reproducible
/// host sets for `check` and the scheme theorems): `faces` faces of 1-6
/// edges and up to 2 * faces sewings in dimensions 2..top_dim.
MapRecipe draw_recipe(std::mt19937& rng, std::uint32_t faces, int top_dim);

/// Smaller recipes than `r`, largest steps first: fewer faces, fewer
/// sewings, shorter faces. Every candidate builds a valid map, so a greedy
/// shrinker outside RapidCheck (dartcheck fuzz) keeps validity too.
std::vector<MapRecipe> shrink_candidates(const MapRecipe& r);

/// Overwrite one link array entry: the link (or, with `inverse`, the
/// recorded predecessor) of dart `dart % n` in dimension `dims[dim % |D|]`
/// becomes `target % (n + 1)`, where n means no_dart. With `resew`, the
/// i-links of the two darts are exchanged instead, which keeps every link
/// array a bijection (an involution for a non-oriented dimension) and so
/// breaks only cycle constraints.
struct LinkCorruption {
  std::uint32_t dart, dim, target;
  bool inverse;
  bool resew;
};
void apply_corruption(Map& map, const LinkCorruption& c);

}  // namespace dartcheck
