#include "core/yaml_util.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace dartcheck::yaml {

YAML::Node require(const std::string& file, const YAML::Node& map, const char* key) {
  YAML::Node n = map[key];
  if (!n) fail_at(file, map, fmt::format("missing key '{}'", key));
  return n;
}

void expect_map(const std::string& file, const YAML::Node& n, std::string_view what) {
  if (!n.IsMap()) fail_at(file, n, fmt::format("{}: expected a mapping", what));
}

void expect_sequence(const std::string& file, const YAML::Node& n, std::string_view what) {
  if (!n.IsSequence()) fail_at(file, n, fmt::format("{}: expected a list", what));
}

void allow_keys(const std::string& file, const YAML::Node& map, std::initializer_list<std::string_view> allowed) {
  for (const auto& kv : map) {
    const auto key = kv.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      fail_at(file, kv.first, fmt::format("unknown key '{}' (expected one of: {})", key, fmt::join(allowed, ", ")));
  }
}

long long as_int(const std::string& file, const YAML::Node& n, std::string_view what, long long lo, long long hi) {
  long long v = 0;
  if (!n.IsScalar() || !YAML::convert<long long>::decode(n, v))
    fail_at(file, n, fmt::format("{}: expected an integer, got '{}'", what, n.IsScalar() ? n.Scalar() : std::string("a collection")));
  if (v < lo || v > hi) fail_at(file, n, fmt::format("{}: {} is out of range [{}, {}]", what, v, lo, hi));
  return v;
}

std::string as_string(const std::string& file, const YAML::Node& n, std::string_view what) {
  if (!n.IsScalar()) fail_at(file, n, fmt::format("{}: expected a string", what));
  return n.Scalar();
}

Model as_model(const std::string& file, const YAML::Node& n) {
  const std::string name = as_string(file, n, "model");
  auto m = Model::by_name(name);
  if (!m) fail_at(file, n, fmt::format("unknown model '{}' (expected {})", name, Model::known_names()));
  return *m;
}

}  // namespace dartcheck::yaml
