// Errors in user input, always with the file position and what was
// expected (GUIDE: bad input gets file:line:column and a non-zero exit).
#pragma once

#include <stdexcept>
#include <string>

namespace YAML {
class Node;
}

namespace dartcheck {

class InputError : public std::runtime_error {
 public:
  /// `line` and `column` are 1-based; 0 means unknown.
  InputError(std::string file, int line, int column, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  std::string file_;
  int line_, column_;
};

/// Throws an InputError at the position of a YAML node.
[[noreturn]] void fail_at(const std::string& file, const YAML::Node& node, const std::string& message);

/// Loads a YAML file, turning parser errors into InputError.
YAML::Node load_yaml_file(const std::string& file);

}  // namespace dartcheck
