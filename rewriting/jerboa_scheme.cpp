#include "rewriting/jerboa_scheme.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>

#include "core/orbit_notation.hpp"

namespace dartcheck {

OrbitType parse_orbit_type(std::string_view text) {
  OrbitType t;
  read_orbit_entries(text, [&](const OrbitEntry& e) {
    auto fail = [&](std::string_view what) {
      throw std::invalid_argument(fmt::format("orbit type '{}', at byte {}: {}", text, e.offset + e.text.size(), what));
    };
    if (e.text == "_") {
      t.emplace_back(std::nullopt);
      return;
    }
    // Saturated: any number above max_dimension is refused (found by
    // fuzz_word: "09999999999" overflowed int).
    int d = 0;
    for (char c : e.text) d = std::min(d * 10 + (c - '0'), 10 * max_dimension);
    if (d > max_dimension) fail(fmt::format("dimension {} is above {}", e.text, max_dimension));
    if (std::find(t.begin(), t.end(), std::optional<Dim>(static_cast<Dim>(d))) != t.end())
      fail(fmt::format("dimension {} appears twice (a relabeling is injective)", d));
    t.emplace_back(static_cast<Dim>(d));
  });
  return t;
}

std::string orbit_type_str(const OrbitType& t) {
  std::string s = "<";
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (k) s += ',';
    s += t[k] ? std::to_string(*t[k]) : "_";
  }
  return s + ">";
}

void add_implicit_arcs(TopoGraph& g, std::vector<ConjWord>& words, NodeId v, const OrbitType& parameter, const OrbitType& label, const Model& model) {
  if (label.size() != parameter.size())
    throw std::invalid_argument(fmt::format("label {} has {} positions but the parameter orbit type {} has {}", orbit_type_str(label), label.size(),
                                            orbit_type_str(parameter), parameter.size()));
  for (std::size_t k = 0; k < label.size(); ++k) {
    if (!parameter[k]) throw std::invalid_argument(fmt::format("the parameter orbit type {} contains '_'", orbit_type_str(parameter)));
    if (!model.contains(*parameter[k]))
      throw std::invalid_argument(
          fmt::format("dimension {} of {} is not a dimension of model {}", *parameter[k], orbit_type_str(parameter), model.name));
    if (!label[k]) continue;  // '_': the o_k-links are removed
    if (!model.contains(*label[k]))
      throw std::invalid_argument(fmt::format("dimension {} of {} is not a dimension of model {}", *label[k], orbit_type_str(label), model.name));
    // o_k relabeled to label_k: the copy's label_k-link joins the copy of
    // the o_k-neighbour, an (o_k, label_k)-loop.
    g.add_arc(v, v, *label[k]);
    words.push_back(ConjWord::of_dims({*parameter[k]}));
  }
}

}  // namespace dartcheck
