#include "io/map_io.hpp"
#include "io/detail/yaml_readers.hpp"

#include <fmt/format.h>
#include <limits>
#include <ostream>
#include <sstream>

#include "core/limits.hpp"
#include "io/detail/yaml_util.hpp"

namespace dartcheck {
namespace {

Dart as_dart(const std::string& file, const YAML::Node& n, std::size_t darts) {
  if (n.IsNull()) return no_dart;
  return static_cast<Dart>(yaml::as_int(file, n, "dart", 0, static_cast<long long>(darts) - 1));
}

// A dart where a list entry must name one (a loop, a cycle's member): '~'
// (no dart) is an error there, not an index.
Dart as_named_dart(const std::string& file, const YAML::Node& n, std::size_t darts, const char* where) {
  const Dart d = as_dart(file, n, darts);
  if (d == no_dart) fail_at(file, n, fmt::format("{}: expected a dart, found '~' (no dart)", where));
  return d;
}

// The predecessor array a reader derives from the links when none is
// given: for each arc d -> e in dart order, pred(e) = d.
std::vector<Dart> derived_pred(const Map& m, Dim i) {
  std::vector<Dart> pred(m.size(), no_dart);
  for (Dart d = 0; d < m.size(); ++d)
    if (Dart e = m.link(i, d); e != no_dart) pred[e] = d;
  return pred;
}

void read_dimension(const std::string& file, const YAML::Node& spec, Map& m, Dim i) {
  const std::size_t n = m.size();
  if (spec.IsSequence()) {
    if (spec.size() != n) fail_at(file, spec, fmt::format("links of dimension {}: expected {} entries (one per dart), got {}", i, n, spec.size()));
    for (std::size_t d = 0; d < n; ++d) m.set_link_raw(i, static_cast<Dart>(d), as_dart(file, spec[d], n));
    return;
  }
  yaml::expect_map(file, spec, fmt::format("links of dimension {}", i));
  yaml::allow_keys(file, spec, {"pairs", "loops", "cycles"});
  if (auto pairs = spec["pairs"]) {
    if (m.model().is_oriented(i)) fail_at(file, pairs, fmt::format("dimension {} is oriented in {}: use 'cycles' or a list", i, m.model().name));
    yaml::expect_sequence(file, pairs, "pairs");
    for (const auto& p : pairs) {
      if (!p.IsSequence() || p.size() != 2) fail_at(file, p, "a pair: expected [dart, dart]");
      const Dart a = as_named_dart(file, p[0], n, "a pair"), b = as_named_dart(file, p[1], n, "a pair");
      m.set_link_raw(i, a, b);
      m.set_link_raw(i, b, a);
    }
  }
  if (auto loops = spec["loops"]) {
    if (loops.IsScalar() && loops.Scalar() == "all") {
      for (Dart d = 0; d < n; ++d) m.set_link_raw(i, d, d);
    } else {
      yaml::expect_sequence(file, loops, "loops (a list of darts, or 'all')");
      for (const auto& l : loops) {
        const Dart d = as_named_dart(file, l, n, "a loop");
        m.set_link_raw(i, d, d);
      }
    }
  }
  if (auto cycles = spec["cycles"]) {
    if (!m.model().is_oriented(i)) fail_at(file, cycles, fmt::format("dimension {} is non-oriented in {}: use 'pairs'", i, m.model().name));
    yaml::expect_sequence(file, cycles, "cycles");
    for (const auto& c : cycles) {
      yaml::expect_sequence(file, c, "a cycle");
      std::vector<Dart> cycle;
      for (const auto& d : c) cycle.push_back(as_named_dart(file, d, n, "a cycle"));
      for (std::size_t k = 0; k < cycle.size(); ++k) m.set_link_raw(i, cycle[k], cycle[(k + 1) % cycle.size()]);
    }
  }
}

// A preset by name; a custom model inline, so the file reads back without
// the catalog that declared it.
void write_model(std::ostream& out, const Model& model) {
  const auto preset = Model::by_name(model.name);
  if (preset && *preset == model) {
    out << "model: " << model.name << '\n';
    return;
  }
  auto dims = [&](DimSet s) {
    std::vector<Dim> v;
    for (Dim i : model.dims)
      if (has_dim(s, i)) v.push_back(i);
    return fmt::format("[{}]", fmt::join(v, ", "));
  };
  out << "model: {name: " << model.name << ", dims: [" << fmt::format("{}", fmt::join(model.dims, ", "))
      << "], non_oriented: " << dims(model.non_oriented) << ", exchangeable: [";
  for (std::size_t k = 0; k < model.exchangeable.size(); ++k)
    out << (k ? ", " : "") << '[' << model.exchangeable[k].first << ", " << model.exchangeable[k].second << ']';
  out << "], partial: " << dims(model.partial) << ", loop_free: " << (model.loop_free ? "true" : "false") << "}\n";
}

}  // namespace

Map read_map_links(const std::string& file, const YAML::Node& node, const Model& model) {
  const YAML::Node count = yaml::require(file, node, "darts");
  const auto darts = yaml::as_int(file, count, "darts", 0, std::numeric_limits<long long>::max());
  if (static_cast<unsigned long long>(darts) > limits().darts)
    fail_at(file, count, over_limit("darts", static_cast<std::size_t>(darts), limits().darts, "--limit-darts"));
  Map m(model, static_cast<std::size_t>(darts));
  const YAML::Node links = yaml::require(file, node, "links");
  yaml::expect_map(file, links, "links");
  for (const auto& kv : links) {
    const auto i = static_cast<Dim>(yaml::as_int(file, kv.first, "dimension", 0, max_dimension));
    if (!model.contains(i)) fail_at(file, kv.first, fmt::format("dimension {} is not in model {}", i, model.name));
    read_dimension(file, kv.second, m, i);
  }
  for (Dim i : model.dims)
    if (model.is_oriented(i)) {
      const auto pred = derived_pred(m, i);
      for (Dart d = 0; d < m.size(); ++d) m.set_inverse_link_raw(i, d, pred[d]);
    }
  if (const YAML::Node pred = node["pred"]) {
    yaml::expect_map(file, pred, "pred");
    for (const auto& kv : pred) {
      const auto i = static_cast<Dim>(yaml::as_int(file, kv.first, "dimension", 0, max_dimension));
      if (!model.contains(i) || !model.is_oriented(i))
        fail_at(file, kv.first, fmt::format("pred: {} is not an oriented dimension of {}", i, model.name));
      yaml::expect_sequence(file, kv.second, "pred");
      if (kv.second.size() != m.size()) fail_at(file, kv.second, fmt::format("pred of dimension {}: expected {} entries", i, m.size()));
      for (Dart d = 0; d < m.size(); ++d) m.set_inverse_link_raw(i, d, as_dart(file, kv.second[d], m.size()));
    }
  }
  return m;
}

Map read_map_file(const std::string& path) { return read_map(path, load_yaml_file(path)); }

Map read_map_text(const std::string& name, const std::string& text) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw yaml_input_error(name, e);
  }
  return read_map(name, root);
}

Map read_map(const std::string& file, const YAML::Node& node) {
  yaml::expect_map(file, node, "map");
  // `preserved`: written by apply beside the result, read by infer (io/kappa_file.hpp).
  yaml::allow_keys(file, node, {"model", "darts", "links", "pred", "preserved"});
  try {
    return read_map_links(file, node, yaml::as_model(file, yaml::require(file, node, "model")));
  } catch (const YAML::Exception& e) {
    throw yaml_input_error(file, e);
  }
}

void write_map(std::ostream& out, const Map& m) {
  auto row = [&](auto get) {
    out << '[';
    for (Dart d = 0; d < m.size(); ++d) {
      if (d) out << ", ";
      const Dart e = get(d);
      if (e == no_dart)
        out << '~';
      else
        out << e;
    }
    out << "]\n";
  };
  write_model(out, m.model());
  out << "darts: " << m.size() << "\nlinks:\n";
  for (Dim i : m.model().dims) {
    out << "  " << i << ": ";
    row([&](Dart d) { return m.link(i, d); });
  }
  bool header = false;
  for (Dim i : m.model().dims) {
    if (!m.model().is_oriented(i)) continue;
    const auto derived = derived_pred(m, i);
    bool same = true;
    for (Dart d = 0; d < m.size() && same; ++d) same = derived[d] == m.inverse_link(i, d);
    if (same) continue;
    if (!header) out << "pred:\n";
    header = true;
    out << "  " << i << ": ";
    row([&](Dart d) { return m.inverse_link(i, d); });
  }
}

std::string map_to_yaml(const Map& m) {
  std::ostringstream s;
  write_map(s, m);
  return s.str();
}

}  // namespace dartcheck
