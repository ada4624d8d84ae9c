// Typed access to YAML nodes that reports the file position on any error.
#pragma once

#include <string>
#include <string_view>
#include <vector>
#include <yaml-cpp/yaml.h>

#include "core/input_error.hpp"
#include "core/model.hpp"

namespace dartcheck {

/// Throws an InputError at the position of a YAML node.
[[noreturn]] void fail_at(const std::string& file, const YAML::Node& node, const std::string& message);

/// Loads a YAML file, turning parser errors into InputError.
YAML::Node load_yaml_file(const std::string& file);

/// A yaml-cpp error a reader did not foresee, as an InputError at its mark.
InputError yaml_input_error(const std::string& file, const YAML::Exception& e);

}  // namespace dartcheck

namespace dartcheck::yaml {

/// The value at `key` of a mapping, or an error naming the missing key.
YAML::Node require(const std::string& file, const YAML::Node& map, const char* key);
void expect_map(const std::string& file, const YAML::Node& n, std::string_view what);
void expect_sequence(const std::string& file, const YAML::Node& n, std::string_view what);
/// Rejects keys other than `allowed` (typos must not be silently ignored).
void allow_keys(const std::string& file, const YAML::Node& map, std::initializer_list<std::string_view> allowed);
long long as_int(const std::string& file, const YAML::Node& n, std::string_view what, long long lo, long long hi);
std::string as_string(const std::string& file, const YAML::Node& n, std::string_view what);
/// A list of dimensions (0..max_dimension).
std::vector<Dim> read_dims(const std::string& file, const YAML::Node& n, const char* what);
/// A custom model {dims, non_oriented, exchangeable, partial, loop_free};
/// with `named`, the mapping also carries its `name` (the inline form of a
/// map file).
Model custom_model(const std::string& file, const std::string& name, const YAML::Node& n, bool named = false);
/// A model: a preset name, or an inline custom model {name, dims, ...}.
Model as_model(const std::string& file, const YAML::Node& n);

}  // namespace dartcheck::yaml
