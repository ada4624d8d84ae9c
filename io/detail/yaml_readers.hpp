// The readers of YAML nodes behind io/catalog.hpp and io/map_io.hpp, for
// io's own .cpp files and the tests that feed them nodes: the public headers
// other layers include hold no yaml-cpp.
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/graph.hpp"
#include "core/map.hpp"
#include "io/catalog.hpp"

namespace dartcheck {

/// Reads a map from a YAML mapping with keys model, darts, links[, pred].
/// Every error is an InputError at the offending node of `file`.
Map read_map(const std::string& file, const YAML::Node& node);
/// Same, reusing a model already known (catalog entries may override it).
Map read_map_links(const std::string& file, const YAML::Node& node, const Model& model);

/// Reads one side of a rule: {nodes: [...], arcs: ["a -0- b", ...]}.
/// Arc notation: "a -i- b" is the non-oriented pair a -i-> b, b -i-> a
/// (one loop arc when a == b); "a -i-> b" and "a <-i- b" one oriented arc.
/// With `model` and `words`, arcs may carry scheme labels "(w,i)": `words`
/// receives one word per arc (ε for plain labels) and `has_words` is set if
/// any arc has one. With `jerboa` (the parameter orbit type), nodes are a
/// mapping from names to generalized orbit types and are translated to
/// (W,D) loops (rewriting/jerboa_scheme.hpp).
TopoGraph read_side(const std::string& file, const YAML::Node& side, const char* which, const Model* model = nullptr,
                    std::vector<ConjWord>* words = nullptr, bool* has_words = nullptr, const OrbitType* jerboa = nullptr,
                    std::vector<OrbitType>* orbit_types = nullptr);

/// Reads a model: a preset name, or {dims, non_oriented, exchangeable,
/// partial, loop_free} for a custom one.
Model read_model(const std::string& file, const YAML::Node& node, const std::vector<Model>& custom);

}  // namespace dartcheck
