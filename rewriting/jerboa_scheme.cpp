#include "rewriting/jerboa_scheme.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>

#include "core/error.hpp"
#include "core/orbit_notation.hpp"

namespace dartcheck {

void add_implicit_arcs(TopoGraph& g, std::vector<ConjWord>& words, NodeId v, const OrbitType& parameter, const OrbitType& label, const Model& model) {
  if (label.size() != parameter.size())
    throw ValueError(fmt::format("label {} has {} positions but the parameter orbit type {} has {}", orbit_type_str(label), label.size(),
                                 orbit_type_str(parameter), parameter.size()));
  for (std::size_t k = 0; k < label.size(); ++k) {
    if (!parameter[k]) throw ValueError(fmt::format("the parameter orbit type {} contains '_'", orbit_type_str(parameter)));
    if (!model.contains(*parameter[k]))
      throw ValueError(fmt::format("dimension {} of {} is not a dimension of model {}", *parameter[k], orbit_type_str(parameter), model.name));
    if (!label[k]) continue;  // '_': the o_k-links are removed
    if (!model.contains(*label[k]))
      throw ValueError(fmt::format("dimension {} of {} is not a dimension of model {}", *label[k], orbit_type_str(label), model.name));
    // o_k relabeled to label_k: the copy's label_k-link joins the copy of
    // the o_k-neighbour, an (o_k, label_k)-loop.
    g.add_arc(v, v, *label[k]);
    words.push_back(ConjWord::of_dims({*parameter[k]}));
  }
}

}  // namespace dartcheck
