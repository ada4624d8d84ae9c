#include "io/kappa_file.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/detail/yaml_util.hpp"
#include "rewriting/jerboa_scheme.hpp"

namespace dartcheck {
namespace {

SourceLocation where(const std::string& file, const YAML::Node& n) { return {file, n.Mark().line + 1, n.Mark().column + 1}; }

constexpr long long most = (1LL << 32) - 2;  // the largest dart

// [[before, after], ...] into spec.pairs, with their positions.
void read_pairs(const std::string& file, const YAML::Node& pairs, KappaSpec& spec) {
  yaml::expect_sequence(file, pairs, "pairs");
  for (const auto& p : pairs) {
    yaml::expect_sequence(file, p, "pair [before, after]");
    if (p.size() != 2) fail_at(file, p, fmt::format("a pair has two darts [before, after], this one {}", p.size()));
    spec.pairs.emplace_back(static_cast<Dart>(yaml::as_int(file, p[0], "before dart", 0, most)),
                            static_cast<Dart>(yaml::as_int(file, p[1], "after dart", 0, most)));
    spec.pair_locations.push_back(where(file, p));
  }
}

KappaSpec read_kappa(const std::string& file, const Model& model) {
  const YAML::Node root = load_yaml_file(file);
  yaml::expect_map(file, root, "kappa file");
  yaml::allow_keys(file, root, {"identity", "pairs", "orbits"});
  KappaSpec spec;
  if (const auto id = root["identity"]) {
    if (!id.IsScalar() || (id.Scalar() != "true" && id.Scalar() != "false")) fail_at(file, id, "identity: expected true or false");
    spec.identity = id.Scalar() == "true";
  }
  if (const auto pairs = root["pairs"]) read_pairs(file, pairs, spec);
  if (const auto orbits = root["orbits"]) {
    yaml::expect_sequence(file, orbits, "orbits");
    for (const auto& o : orbits) {
      yaml::expect_map(file, o, "orbit association {orbit, before, after}");
      yaml::allow_keys(file, o, {"orbit", "before", "after"});
      KappaSpec::OrbitPair pair;
      const auto type = yaml::require(file, o, "orbit");
      try {
        for (const auto& d : parse_orbit_type(yaml::as_string(file, type, "orbit type"))) {
          if (!d || !model.contains(*d)) fail_at(file, type, fmt::format("orbit: expected dimensions of {}, no '_'", model.name));
          pair.orbit.push_back(*d);
        }
      } catch (const ValueError& e) {
        fail_at(file, type, fmt::format("orbit: {}", e.what()));
      }
      pair.before = static_cast<Dart>(yaml::as_int(file, yaml::require(file, o, "before"), "before dart", 0, most));
      pair.after = static_cast<Dart>(yaml::as_int(file, yaml::require(file, o, "after"), "after dart", 0, most));
      spec.orbits.push_back(std::move(pair));
      spec.orbit_locations.push_back(where(file, o));
    }
  }
  if (!root["identity"] && !root["pairs"] && !root["orbits"])
    fail_at(file, root, "the kappa file states no preserved dart (identity, pairs or orbits); an empty κ is 'pairs: []'");
  return spec;
}

}  // namespace

KappaSpec read_kappa_file(const std::string& file, const Model& model) {
  try {
    return read_kappa(file, model);
  } catch (const YAML::Exception& e) {
    throw yaml_input_error(file, e);  // a shape the reader did not foresee: still at its position
  }
}

std::optional<KappaSpec> read_recorded_kappa(const std::string& map_file) {
  const YAML::Node root = load_yaml_file(map_file);
  if (!root.IsMap() || !root["preserved"]) return std::nullopt;
  KappaSpec spec;
  try {
    read_pairs(map_file, root["preserved"], spec);
  } catch (const YAML::Exception& e) {
    throw yaml_input_error(map_file, e);
  }
  return spec;
}

std::string preserved_text(const std::vector<std::pair<Dart, Dart>>& pairs) {
  std::string out =
      "# The darts the application preserved (before dart, after dart): it deleted\n"
      "# darts, so equal ids are not the same dart; infer --kappa identity reads these.\n"
      "preserved: [";
  for (std::size_t k = 0; k < pairs.size(); ++k) out += fmt::format("{}[{}, {}]", k ? ", " : "", pairs[k].first, pairs[k].second);
  return out + "]\n";
}

std::string kappa_file_text(const std::vector<std::pair<Dart, Dart>>& pairs, const std::vector<std::string>& comment) {
  std::string out;
  for (const auto& line : comment) out += fmt::format("# {}\n", line);
  out += "pairs: [";
  for (std::size_t k = 0; k < pairs.size(); ++k) out += fmt::format("{}[{}, {}]", k ? ", " : "", pairs[k].first, pairs[k].second);
  return out + "]\n";
}

}  // namespace dartcheck
