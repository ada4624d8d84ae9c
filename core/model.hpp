// Topological models (002 Def. 10, Sec. 3.2): a dimension set D, the
// non-oriented dimensions N ⊆ D and the exchangeable pairs E ⊆ D².
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dartcheck {

/// A dimension, i.e. an arc label of a topological graph.
using Dim = int;

/// Largest dimension dartcheck handles; sets of dimensions are bit masks.
inline constexpr Dim max_dimension = 15;

/// A set of dimensions as a bit mask (bit i set iff i is in the set).
using DimSet = std::uint32_t;

constexpr DimSet dim_bit(Dim i) { return DimSet{1} << i; }
constexpr bool has_dim(DimSet s, Dim i) { return (s >> i) & 1U; }

/// A model (D, N, E) plus the two variants of 002 Sec. 3.2.
///
/// A map of the model is a D-topological graph satisfying I(D), O(N) and
/// C(E). `partial` relaxes I on its dimensions to "at most one arc" (open
/// O-maps); `loop_free` additionally forbids loops (closed G-maps).
struct Model {
  std::string name;
  std::vector<Dim> dims;                          // D, ascending
  DimSet non_oriented = 0;                        // N
  std::vector<std::pair<Dim, Dim>> exchangeable;  // E
  DimSet partial = 0;
  bool loop_free = false;

  bool contains(Dim i) const { return i >= 0 && i <= max_dimension && has_dim(dim_set(), i); }
  bool is_oriented(Dim i) const { return !has_dim(non_oriented, i); }
  DimSet dim_set() const;
  /// n for an n-G-map or n-O-map: the largest dimension.
  int dimension() const { return dims.back(); }
  /// True for G-map-like models, whose dimensions start at 0.
  bool is_generalized() const { return dims.front() == 0; }

  /// n-G-map = ([0,n], [0,n], [0,n]+2).
  static Model gmap(int n);
  /// n-O-map = ([1,n], [2,n], [1,n]+2).
  static Model omap(int n);
  /// G-map whose arcs are never loops.
  static Model closed_gmap(int n);
  /// O-map where a dart has at most one n-arc out and in.
  static Model open_omap(int n);

  /// Parses "2-gmap", "3-omap", "2-closed-gmap", "3-open-omap" (n in 0..15).
  static std::optional<Model> by_name(std::string_view name);
  /// The names by_name() accepts, for error messages.
  static std::string_view known_names();

  friend bool operator==(const Model&, const Model&) = default;
};

/// D+2: the pairs (i, j) of `dims` with i + 2 <= j.
std::vector<std::pair<Dim, Dim>> pairs_two_apart(const std::vector<Dim>& dims);

}  // namespace dartcheck
