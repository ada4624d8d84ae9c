#include "core/input_error.hpp"

#include <fmt/format.h>
#include <fstream>
#include <yaml-cpp/yaml.h>

namespace dartcheck {

static std::string position(const std::string& file, int line, int column) {
  if (line <= 0) return file;
  return column > 0 ? fmt::format("{}:{}:{}", file, line, column) : fmt::format("{}:{}", file, line);
}

InputError::InputError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(position(file, line, column) + ": " + message), file_(std::move(file)), line_(line), column_(column) {}

void fail_at(const std::string& file, const YAML::Node& node, const std::string& message) {
  const YAML::Mark m = node.Mark();
  throw InputError(file, m.line + 1, m.column + 1, message);
}

YAML::Node load_yaml_file(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file, 0, 0, "cannot open file");
  try {
    return YAML::Load(in);
  } catch (const YAML::ParserException& e) {
    throw InputError(file, e.mark.line + 1, e.mark.column + 1, "malformed YAML: " + e.msg);
  }
}

}  // namespace dartcheck
