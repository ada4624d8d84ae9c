#include "rewriting/jerboa_scheme.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>

namespace dartcheck {

OrbitType parse_orbit_type(std::string_view text) {
  auto fail = [&](std::size_t pos, std::string_view what) {
    throw std::invalid_argument(fmt::format("orbit type '{}', at byte {}: {}", text, pos + 1, what));
  };
  std::size_t i = 0;
  auto skip_spaces = [&] {
    while (i < text.size() && text[i] == ' ') ++i;
  };
  auto take = [&](std::string_view s) {
    if (text.substr(i).starts_with(s)) {
      i += s.size();
      return true;
    }
    return false;
  };
  skip_spaces();
  if (!take("<") && !take("\u27e8")) fail(i, "expected '<' or '⟨'");
  OrbitType t;
  skip_spaces();
  if (take(">") || take("\u27e9")) return t;  // <>: the empty orbit type
  for (;;) {
    skip_spaces();
    if (take("_")) {
      t.emplace_back(std::nullopt);
    } else if (i < text.size() && text[i] >= '0' && text[i] <= '9') {
      int d = 0;
      const std::size_t start = i;
      // Saturated: any number above max_dimension is refused below (found
      // by fuzz_word: "09999999999" overflowed int).
      while (i < text.size() && text[i] >= '0' && text[i] <= '9') d = std::min(d * 10 + (text[i++] - '0'), 10 * max_dimension);
      if (d > max_dimension) fail(i - 1, fmt::format("dimension {} is above {}", text.substr(start, i - start), max_dimension));
      if (std::find(t.begin(), t.end(), std::optional<Dim>(static_cast<Dim>(d))) != t.end())
        fail(i - 1, fmt::format("dimension {} appears twice (a relabeling is injective)", d));
      t.emplace_back(static_cast<Dim>(d));
    } else {
      fail(i, "expected a dimension or '_'");
    }
    skip_spaces();
    if (take(",")) continue;
    if (take(">") || take("\u27e9")) break;
    fail(i, "expected ',' or '>'");
  }
  skip_spaces();
  if (i != text.size()) fail(i, "unexpected text after the orbit type");
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
