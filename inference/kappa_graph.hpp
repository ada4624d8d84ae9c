// The graph κ(G, H) of 000 Sec. 7: the before map G and the after map H of
// one example side by side, plus κ-arcs joining the darts the operation
// preserves. The folding runs on it as on one G-map with an extra
// dimension κ that never enters a node label.
//
// Darts of κ(G, H) are numbered G first: dart x < |G| is dart x of G, dart
// |G| + y is dart y of H.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/input_error.hpp"
#include "core/map.hpp"
#include "io/kappa_file.hpp"

namespace dartcheck::inference {

/// A partial injective map κ : G -> H and its inverse.
class KappaGraph {
 public:
  /// `kappa[x]` is the image of dart x of G, or no_dart. The caller has
  /// checked (see `make_kappa_graph`) that it is injective and in range.
  KappaGraph(Map before, Map after, std::vector<Dart> kappa);

  const Map& before() const { return before_; }
  const Map& after() const { return after_; }
  const Model& model() const { return before_.model(); }
  /// |G| + |H|.
  std::size_t size() const { return before_.size() + after_.size(); }
  bool in_before(Dart u) const { return u < before_.size(); }
  /// The d-neighbour of u (d a dimension of the model).
  Dart link(Dim d, Dart u) const { return in_before(u) ? before_.link(d, u) : offset(after_.link(d, u - static_cast<Dart>(before_.size()))); }
  /// The κ-neighbour of u: its image in H for a dart of G, its preimage
  /// for a dart of H; no_dart for a dart the operation does not preserve.
  Dart kappa(Dart u) const { return in_before(u) ? offset(kappa_[u]) : inverse_[u - before_.size()]; }
  /// The number of preserved darts.
  std::size_t preserved() const { return preserved_; }
  /// u as a dart of its own map.
  Dart local(Dart u) const { return in_before(u) ? u : u - static_cast<Dart>(before_.size()); }
  /// "G:3" / "H:12".
  std::string name(Dart u) const;

 private:
  Dart offset(Dart h) const { return h == no_dart ? no_dart : h + static_cast<Dart>(before_.size()); }

  Map before_, after_;
  std::vector<Dart> kappa_, inverse_;
  std::size_t preserved_ = 0;
};

/// κ as a file or a caller states it: io/kappa_file.hpp.
using dartcheck::KappaSpec;

/// Builds κ(G, H). Throws ValueError with a sentence when the
/// maps have different models, a model is not a G-map (κ-graphs are
/// defined on n-G-maps), a dart is out of range, κ is not injective or not
/// a function, or two associated orbits differ in shape; an InputError at
/// the entry's position instead when the spec records where it was read.
KappaGraph make_kappa_graph(Map before, Map after, const KappaSpec& spec);

}  // namespace dartcheck::inference
